// Crash safety of time-directory writes (docs/design.md 1.3: "a crash never leaves
// a half-written time directory"). Every file-system step of a write is made
// to fail in turn (the failure hook returns ENOSPC, as a full disk would); after
// each failure the previous directory of the same name must be bit-identical,
// no temporary folder may remain, and the pvd must still be whole. Also: a
// case path that is a regular file, a leftover *.tmp-* folder, replacing an
// existing directory (atomic exchange and the two-rename fallback).
#define BOOST_TEST_MODULE io_atomic
#include <boost/test/unit_test.hpp>
#include "io/TimeDirectory.hpp"
#include "test_io_helpers.hpp"
#include <cerrno>
#include <fstream>
#include <sstream>

using namespace shizuku;
using namespace shizuku::iotest;
namespace fs = std::filesystem;

namespace {

// Every entry of the case folder, to find leftovers.
std::vector<std::string> entries(const std::string& dir) {
  std::vector<std::string> v;
  for (auto& e : fs::directory_iterator(dir)) v.push_back(e.path().filename().string());
  std::sort(v.begin(), v.end());
  return v;
}

struct HookReset {
  ~HookReset() { detail::setWriteFailureHook(nullptr); }
};

}  // namespace

BOOST_AUTO_TEST_CASE(everyFailingStepLeavesOldDirectoryIntact) {
  HookReset reset;
  for (bool fallback : {false, true}) {
    ScratchDir c;
    const auto oldSet = randomSet<2>(300, false, 1);
    const auto newSet = randomSet<2>(300, true, 2);
    writeTimeDirectory<2>(c.path, "0.1", oldSet, TimeState{0.1, 1000, 1e-4, 1e-4, ""}, false);
    const std::string oldVtp = slurp(c.path + "/0.1/particles.vtp");
    const std::string oldTime = slurp(c.path + "/0.1/uniform/time");
    const auto before = entries(c.path);

    // Count the hooked steps of one successful replacement write.
    int steps = 0;
    {
      ScratchDir d;
      writeTimeDirectory<2>(d.path, "0.1", oldSet, TimeState{0.1, 1000, 1e-4, 1e-4, ""}, false);
      detail::setWriteFailureHook([&](const std::string& stage) {
        if (stage == "exchange") return fallback ? EINVAL : 0;
        ++steps;
        return 0;
      });
      writeTimeDirectory<2>(d.path, "0.1", newSet, TimeState{0.1, 1001, 1e-4, 1e-4, ""}, true);
      detail::setWriteFailureHook(nullptr);
    }
    BOOST_TEST_MESSAGE("hooked steps of one write (fallback " << fallback << "): " << steps);
    BOOST_TEST(steps >= 20);  // folders, vtp, time, 9 ascii files, syncs, renames, pvd

    int failedBeforeMove = 0;
    for (int k = 1; k <= steps; ++k) {
      int call = 0;
      detail::setWriteFailureHook([&](const std::string& stage) {
        if (stage == "exchange") return fallback ? EINVAL : 0;
        return ++call == k ? ENOSPC : 0;
      });
      bool threw = false;
      try {
        writeTimeDirectory<2>(c.path, "0.1", newSet, TimeState{0.1, 1001, 1e-4, 1e-4, ""}, true);
      } catch (const std::runtime_error& e) {
        threw = true;
        std::string m = e.what();
        BOOST_TEST(m.find(c.path) != std::string::npos, "message names the path: " << m);
        BOOST_TEST(m.find("No space left on device") != std::string::npos, m);
      }
      detail::setWriteFailureHook(nullptr);
      BOOST_TEST(threw, "step " << k << " failed silently");
      // Either the old directory, untouched, or the complete new one.
      TimeState s;
      auto q = readTimeDirectory<2>(c.path, "0.1", s);
      if (s.step == 1000) {
        ++failedBeforeMove;
        BOOST_TEST(slurp(c.path + "/0.1/particles.vtp") == oldVtp);
        BOOST_TEST(slurp(c.path + "/0.1/uniform/time") == oldTime);
        BOOST_TEST(entries(c.path) == before, "leftovers after failing step " << k);
      } else {
        BOOST_TEST(s.step == 1001);
        BOOST_TEST(sameBits(q.shift, newSet.shift));
        BOOST_TEST(fs::exists(c.path + "/0.1/p"));
        // Put the old one back for the next k.
        writeTimeDirectory<2>(c.path, "0.1", oldSet, TimeState{0.1, 1000, 1e-4, 1e-4, ""}, false);
        BOOST_TEST(slurp(c.path + "/0.1/particles.vtp") == oldVtp);
      }
      BOOST_TEST(listTimeDirectories(c.path).size() == 1u);
      BOOST_TEST(slurp(c.path + "/particles.pvd").find("</VTKFile>") != std::string::npos);
    }
    // Only the last 6 steps come after the swap: case-folder sync, the pvd's
    // create, write, sync, rename, and the case-folder sync again.
    BOOST_TEST(failedBeforeMove == steps - 6);
  }
}

BOOST_AUTO_TEST_CASE(newDirectoryFailureLeavesNothing) {
  HookReset reset;
  ScratchDir c;
  writeTimeDirectory<3>(c.path, "0", randomSet<3>(10, false, 1), TimeState{}, false);
  const auto before = entries(c.path);
  detail::setWriteFailureHook([](const std::string& stage) { return stage == "write vtp" ? ENOSPC : 0; });
  BOOST_CHECK_THROW(writeTimeDirectory<3>(c.path, "0.5", randomSet<3>(10, false, 2), TimeState{0.5, 5, 0.1, 0.1, ""}, false),
                    std::runtime_error);
  detail::setWriteFailureHook(nullptr);
  BOOST_TEST(entries(c.path) == before);
  BOOST_TEST(listTimeDirectories(c.path).size() == 1u);
}

BOOST_AUTO_TEST_CASE(caseThatIsAFileThrowsNamingIt) {
  ScratchDir c;
  const std::string notADir = c.path + "/case";
  std::ofstream(notADir) << "I am a file\n";
  BOOST_CHECK_EXCEPTION(writeTimeDirectory<2>(notADir, "0", randomSet<2>(5, false, 1), TimeState{}, false),
                        std::runtime_error, [&](const std::runtime_error& e) {
                          std::string m = e.what();
                          return m.find(notADir) != std::string::npos && m.find("Not a directory") != std::string::npos;
                        });
  BOOST_TEST(slurp(notADir) == "I am a file\n");
}

BOOST_AUTO_TEST_CASE(leftoverTemporaryFolderIsIgnored) {
  ScratchDir c;
  writeTimeDirectory<2>(c.path, "0", randomSet<2>(5, false, 1), TimeState{}, false);
  // What a crash in the middle of writing 0.2 leaves behind.
  fs::create_directories(c.path + "/0.2.tmp-99999/uniform");
  std::ofstream(c.path + "/0.2.tmp-99999/particles.vtp") << "<?xml half";
  std::ofstream(c.path + "/0.2.tmp-99999/uniform/time") << "value 0.2;";
  // An incomplete folder with a time name (no uniform/time) is not a time either.
  fs::create_directories(c.path + "/0.3");
  std::ofstream(c.path + "/0.3/particles.vtp") << "x";
  fs::create_directories(c.path + "/system");
  writeTimeDirectory<2>(c.path, "0.1", randomSet<2>(5, false, 2), TimeState{0.1, 1, 0.1, 0.1, ""}, false);
  auto list = listTimeDirectories(c.path);
  BOOST_TEST(list.size() == 2u);
  BOOST_TEST(list[0].second == "0");
  BOOST_TEST(list[1].second == "0.1");
  std::string pvd = slurp(c.path + "/particles.pvd");
  BOOST_TEST(pvd.find("tmp") == std::string::npos);
  BOOST_TEST(pvd.find("0.3") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(replaceExistingDirectory) {
  HookReset reset;
  for (bool fallback : {false, true}) {
    ScratchDir c;
    detail::setWriteFailureHook([&](const std::string& stage) { return stage == "exchange" && fallback ? EINVAL : 0; });
    writeTimeDirectory<2>(c.path, "1", randomSet<2>(5, false, 1), TimeState{1, 1, 1, 1, ""}, true);
    BOOST_TEST(fs::exists(c.path + "/1/p"));
    writeTimeDirectory<2>(c.path, "1", randomSet<2>(7, false, 2), TimeState{1, 2, 1, 1, ""}, false);
    detail::setWriteFailureHook(nullptr);
    TimeState s;
    BOOST_TEST(readTimeDirectory<2>(c.path, "1", s).size() == 7u);
    BOOST_TEST(s.step == 2);
    BOOST_TEST(!fs::exists(c.path + "/1/p"));  // the whole old folder went, not merged
    BOOST_TEST(entries(c.path) == (std::vector<std::string>{"1", "particles.pvd"}));
  }
}

BOOST_AUTO_TEST_CASE(badTimeNameIsRejected) {
  ScratchDir c;
  BOOST_CHECK_THROW(writeTimeDirectory<2>(c.path, "constant", randomSet<2>(2, false, 1), TimeState{}, false),
                    std::runtime_error);
}
