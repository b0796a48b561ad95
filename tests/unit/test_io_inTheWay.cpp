// A time directory is never written over something that is not one
// (TimeDirectory.hpp): a regular file, a non-empty folder without both
// particles.vtp and uniform/time, or a time directory holding a file Shizuku
// does not write, at the time's path, is an error naming the path, and stays
// byte for byte; an empty folder or an earlier time directory is replaced.
// Leftovers of killed writers (*.tmp-<pid>, *.old-<pid> of a dead pid) are
// swept by the next successful write.
#define BOOST_TEST_MODULE io_inTheWay
#include <boost/test/unit_test.hpp>

#include "io/TimeDirectory.hpp"
#include "test_io_helpers.hpp"
#include "../support/ErrorOf.hpp"
#include <fstream>
#include <algorithm>
#include <sstream>
#include <unistd.h>

using namespace shizuku;
using namespace shizuku::iotest;
namespace fs = std::filesystem;

namespace {
bool throwsNaming(const std::function<void()>& f, const std::string& part1, const std::string& part2) {
  const std::string m = test::errorOf<std::runtime_error>(f);
  return m.find(part1) != std::string::npos && m.find(part2) != std::string::npos;
}
}  // namespace

BOOST_AUTO_TEST_CASE(regular_file_at_the_time_path_stays) {
  ScratchDir c;
  std::ofstream(c.path + "/0.5") << "my notes\n";
  BOOST_TEST(throwsNaming([&] { writeTimeDirectory<2>(c.path, "0.5", randomSet<2>(5, false, 1), TimeState{0.5, 5, 0.1, 0.1, ""}, false); },
                          c.path + "/0.5", "a file that is not a folder"));
  BOOST_TEST(slurp(c.path + "/0.5") == "my notes\n");
  BOOST_TEST(listTimeDirectories(c.path).empty());
  for (const auto& e : fs::directory_iterator(c.path)) BOOST_TEST(e.path().filename() == "0.5");  // no tmp left
}

BOOST_AUTO_TEST_CASE(foreign_folder_at_the_time_path_stays) {
  ScratchDir c;
  fs::create_directories(c.path + "/1");
  std::ofstream(c.path + "/1/data.csv") << "1,2,3\n";
  BOOST_TEST(throwsNaming([&] { writeTimeDirectory<2>(c.path, "1", randomSet<2>(5, false, 1), TimeState{1, 5, 0.1, 0.1, ""}, false); },
                          c.path + "/1", "holds no particles.vtp"));
  BOOST_TEST(slurp(c.path + "/1/data.csv") == "1,2,3\n");
}

BOOST_AUTO_TEST_CASE(incomplete_or_extended_time_directory_stays) {
  ScratchDir c;
  // The user's own particles.vtp without uniform/time, beside notes of theirs.
  fs::create_directories(c.path + "/0");
  std::ofstream(c.path + "/0/particles.vtp") << "<VTKFile/>\n";
  std::ofstream(c.path + "/0/notes.txt") << "mine\n";
  BOOST_TEST(throwsNaming([&] { writeTimeDirectory<2>(c.path, "0", randomSet<2>(5, false, 1), TimeState{}, false); },
                          c.path + "/0", "holds particles.vtp but no uniform/time"));
  BOOST_TEST(slurp(c.path + "/0/notes.txt") == "mine\n");
  BOOST_TEST(slurp(c.path + "/0/particles.vtp") == "<VTKFile/>\n");
  // A complete time directory (with ascii fields) is replaced; once the user has put a
  // file of theirs into it, it is not, and the file is named.
  writeTimeDirectory<2>(c.path, "1", randomSet<2>(5, false, 1), TimeState{1, 5, 0.1, 0.1, ""}, true);
  writeTimeDirectory<2>(c.path, "1", randomSet<2>(6, false, 2), TimeState{1, 6, 0.1, 0.1, ""}, true);
  std::ofstream(c.path + "/1/uniform/mine") << "x\n";
  std::ofstream(c.path + "/1/plot.png") << "png\n";
  BOOST_TEST(whyNotReplaceable(c.path + "/1").find("files Shizuku does not write (plot.png, uniform/mine)") !=
             std::string::npos);
  BOOST_TEST(throwsNaming([&] { writeTimeDirectory<2>(c.path, "1", randomSet<2>(7, false, 3), TimeState{1, 7, 0.1, 0.1, ""}, true); },
                          c.path + "/1", "which writing it would delete"));
  TimeState s;
  BOOST_TEST(readTimeDirectory<2>(c.path, "1", s).size() == 6u);
}

BOOST_AUTO_TEST_CASE(empty_folder_and_earlier_time_are_replaced) {
  ScratchDir c;
  fs::create_directories(c.path + "/2");
  writeTimeDirectory<2>(c.path, "2", randomSet<2>(5, false, 1), TimeState{2, 5, 0.1, 0.1, ""}, false);
  TimeState s;
  BOOST_TEST(readTimeDirectory<2>(c.path, "2", s).size() == 5u);
  writeTimeDirectory<2>(c.path, "2", randomSet<2>(8, false, 2), TimeState{2, 6, 0.1, 0.1, ""}, false);
  BOOST_TEST(readTimeDirectory<2>(c.path, "2", s).size() == 8u);
  BOOST_TEST(s.step == 6);
}

BOOST_AUTO_TEST_CASE(leftovers_of_dead_writers_are_swept_by_the_next_write) {
  ScratchDir c;
  // A pid that does not exist: above the kernel's pid_max (at most 2^22).
  const std::string dead = "99999999";
  fs::create_directories(c.path + "/0.2.tmp-" + dead + "/uniform");
  std::ofstream(c.path + "/0.2.tmp-" + dead + "/particles.vtp") << "<?xml half";
  std::ofstream(c.path + "/particles.pvd.tmp-" + dead) << "<?xml";
  fs::create_directories(c.path + "/0.1.old-" + dead);
  // Entries of a live process (this one's parent) and other names stay.
  const std::string live = std::to_string(::getppid());
  fs::create_directories(c.path + "/0.3.tmp-" + live);
  fs::create_directories(c.path + "/notes.tmp-abc");
  writeTimeDirectory<2>(c.path, "0", randomSet<2>(5, false, 1), TimeState{}, false);
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(c.path)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  BOOST_TEST(names == (std::vector<std::string>{"0", "0.3.tmp-" + live, "notes.tmp-abc", "particles.pvd"}),
             boost::test_tools::per_element());
  BOOST_TEST(removeStaleTemporaries(c.path).empty());
}
