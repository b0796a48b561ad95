// Time directories read back bit for bit (docs/design.md 1.3: restart reads
// particles.vtp back exactly): random ParticleSet<2> and <3> with awkward
// doubles (denormals, -0, 1e+-300, DBL_MAX) and full-range 64-bit ids,
// optional fields absent and present, the TimeState of uniform/time, and
// clear InputErrors for missing, corrupt or wrong-dimension files.
#define BOOST_TEST_MODULE io_roundTrip
#include <boost/test/unit_test.hpp>
#include "io/TimeDirectory.hpp"
#include "io/TimeName.hpp"
#include "test_io_helpers.hpp"
#include <fstream>

using namespace shizuku;
using namespace shizuku::iotest;

namespace {

template <int D>
void checkRoundTrip(bool optional) {
  ScratchDir c;
  ParticleSet<D> p = randomSet<D>(1000, optional, 42 + D + optional);
  TimeState s;
  s.time = 0.1 + 0.2;  // 0.30000000000000004: the name is "0.3", the value must stay exact
  s.step = 3000000000L;
  s.deltaT = 1.0 / 3.0 * 1e-4;
  s.deltaT0 = std::nextafter(s.deltaT, 1.0);
  s.note = "a \"quoted\" note \\ with backslash";
  const std::string name = timeName(s.time);
  BOOST_TEST(name == "0.3");
  writeTimeDirectory<D>(c.path, name, p, s, false);

  TimeState r;
  ParticleSet<D> q = readTimeDirectory<D>(c.path, name, r);
  BOOST_TEST(q.size() == p.size());
  checkSameState(q, p);  // a shift that is absent stays empty
  BOOST_TEST(sameBits(q.density, p.density));
  BOOST_TEST(sameBits(q.type, p.type));
  BOOST_TEST(sameBits(q.surface, p.surface));
  BOOST_TEST(sameBits(q.id, p.id));
  BOOST_TEST(q.normal.empty());
  BOOST_TEST(q.shift.empty() == !optional);
  BOOST_TEST(sameBits(q.mass, p.mass));
  BOOST_TEST(sameBits(q.rho0, p.rho0));
  BOOST_TEST(sameBits(q.spacing, p.spacing));
  BOOST_TEST(sameBits(r.time, s.time));
  BOOST_TEST(r.step == s.step);
  BOOST_TEST(sameBits(r.deltaT, s.deltaT));
  BOOST_TEST(sameBits(r.deltaT0, s.deltaT0));
  BOOST_TEST(r.note == s.note);
}

}  // namespace

BOOST_AUTO_TEST_CASE(roundTrip2D) { checkRoundTrip<2>(false); checkRoundTrip<2>(true); }
BOOST_AUTO_TEST_CASE(roundTrip3D) { checkRoundTrip<3>(false); checkRoundTrip<3>(true); }

BOOST_AUTO_TEST_CASE(allOptionalFields) {
  ScratchDir c;
  ParticleSet<2> p = randomSet<2>(50, true, 7);
  p.normal.assign(50, Vec<2>(0.6, -0.8));
  writeTimeDirectory<2>(c.path, "1", p, TimeState{1, 10, 1e-3, 1e-3, ""}, false);
  TimeState r;
  auto q = readTimeDirectory<2>(c.path, "1", r);
  BOOST_TEST(sameBits(q.normal, p.normal));
  BOOST_TEST(sameBits(q.shift, p.shift));
}

BOOST_AUTO_TEST_CASE(emptySet) {
  ScratchDir c;
  ParticleSet<3> p;
  p.resize(0);
  p.mass = 2;
  p.spacing = 0.1;
  writeTimeDirectory<3>(c.path, "0", p, TimeState{}, true);
  TimeState r;
  auto q = readTimeDirectory<3>(c.path, "0", r);
  BOOST_TEST(q.size() == 0u);
  BOOST_TEST(q.mass == 2.0);
}

BOOST_AUTO_TEST_CASE(wrongDimensionIsInputError) {
  ScratchDir c;
  writeTimeDirectory<3>(c.path, "0", randomSet<3>(10, false, 1), TimeState{}, false);
  TimeState r;
  BOOST_CHECK_EXCEPTION(readTimeDirectory<2>(c.path, "0", r), InputError, [](const InputError& e) {
    std::string m = e.what();
    return m.find("particles.vtp") != std::string::npos && m.find("3D") != std::string::npos;
  });
}

BOOST_AUTO_TEST_CASE(missingAndCorruptFilesAreInputErrors) {
  ScratchDir c;
  TimeState r;
  BOOST_CHECK_THROW(readTimeDirectory<2>(c.path, "5", r), InputError);
  writeTimeDirectory<2>(c.path, "5", randomSet<2>(200, false, 3), TimeState{5, 1, 1, 1, ""}, false);
  const std::string vtp = c.path + "/5/particles.vtp";
  auto names = [&](const std::string& file) {
    return [file](const InputError& e) { return std::string(e.what()).find(file) != std::string::npos; };
  };
  // Truncated vtp (a crash mid-write without the atomic rename would leave this).
  std::filesystem::resize_file(vtp, std::filesystem::file_size(vtp) / 2);
  BOOST_CHECK_EXCEPTION(readTimeDirectory<2>(c.path, "5", r), InputError, names(vtp));
  // Not XML at all.
  std::ofstream(vtp) << "garbage\n";
  BOOST_CHECK_EXCEPTION(readTimeDirectory<2>(c.path, "5", r), InputError, names(vtp));
  // Missing vtp.
  std::filesystem::remove(vtp);
  BOOST_CHECK_EXCEPTION(readTimeDirectory<2>(c.path, "5", r), InputError, names(vtp));
  // uniform/time: missing entry, bad number.
  writeTimeDirectory<2>(c.path, "6", randomSet<2>(20, false, 4), TimeState{6, 1, 1, 1, ""}, false);
  const std::string tf = c.path + "/6/uniform/time";
  std::ofstream(tf) << "value 6;\nindex 1;\n";
  BOOST_CHECK_EXCEPTION(readTimeDirectory<2>(c.path, "6", r), InputError, names(tf));
  std::ofstream(tf) << "value 6;\nindex 1;\ndeltaT 1e-3x;\n";
  BOOST_CHECK_EXCEPTION(readTimeDirectory<2>(c.path, "6", r), InputError, names(tf));
  // deltaT0 absent: defaults to deltaT; comments are fine (the values agree with the vtp's).
  std::ofstream(tf) << "/* header */ value 6; // s\nindex 1;\ndeltaT 1;\n";
  readTimeDirectory<2>(c.path, "6", r);
  BOOST_TEST(r.time == 6.0);
  BOOST_TEST(r.step == 1);
  BOOST_TEST(r.deltaT0 == 1.0);
}
