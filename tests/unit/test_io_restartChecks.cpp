// A restart refuses a damaged time directory with an InputError naming the
// file and the particle, array, attribute or keyword (docs/reliability.md,
// "Restart files are validated before they are read"): the pre-scan of the
// vtp header (VtpLayout), the particle values (RestartChecks), uniform/time
// (TimeFile) and their agreement; files of older versions (no particle
// counts, no nextId) and sparse ids are still read.
#define BOOST_TEST_MODULE io_restartChecks
#include <boost/test/unit_test.hpp>
#include "io/TimeDirectory.hpp"
#include "io/TimeName.hpp"
#include "test_io_helpers.hpp"
#include <cmath>
#include <fstream>

using namespace shizuku;
using namespace shizuku::iotest;

namespace {

// A small valid 2D set: ids 0..n-1, fluid then wall, finite values.
ParticleSet<2> smallSet(std::size_t n = 12) {
  ParticleSet<2> p;
  p.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    p.position[i] = Vec<2>(0.01 * double(i), 0.02);
    p.velocity[i] = Vec<2>(0.1, -0.2);
    p.pressure[i] = 100.0 * double(i);
    p.density[i] = 1000;
    p.type[i] = std::uint8_t(i < n / 2 ? ParticleType::fluid : ParticleType::wall);
    p.id[i] = std::int64_t(i);
  }
  p.mass = 0.1;
  p.spacing = 0.01;
  return p;
}

const TimeState kState{0.002, 2, 1e-3, 1e-3, ""};

struct Restart {
  ScratchDir c;
  std::string dir() const { return c.path + "/0.002"; }
  std::string vtp() const { return dir() + "/particles.vtp"; }
  std::string timeFile() const { return dir() + "/uniform/time"; }
  explicit Restart(const ParticleSet<2>& p = smallSet(), const TimeState& s = kState) {
    writeTimeDirectory<2>(c.path, "0.002", p, s, false);
  }
  ParticleSet<2> read() const {
    TimeState s;
    return readTimeDirectory<2>(c.path, "0.002", s);
  }
  // The vtp with its first `from` replaced by `to` (the header's text).
  void edit(const std::string& from, const std::string& to) const {  // to: any length
    std::string bytes = slurp(vtp());
    const std::size_t at = bytes.find(from);
    BOOST_REQUIRE(at != std::string::npos);
    bytes.replace(at, from.size(), to);
    std::ofstream(vtp(), std::ios::binary) << bytes;
  }
  void setTimeFile(const std::string& text) const { std::ofstream(timeFile()) << text; }
};

// The read throws an InputError whose message holds every one of `parts`.
void refused(const Restart& r, std::initializer_list<std::string> parts) {
  try {
    r.read();
    BOOST_ERROR("no InputError; expected one naming " << *parts.begin());
  } catch (const InputError& e) {
    const std::string m = e.what();
    for (const auto& part : parts) BOOST_TEST(m.find(part) != std::string::npos, "'" << m << "' lacks '" << part << "'");
  }
}

// Hide field data arrays from the reader by renaming them (a file of an older version).
void dropFieldData(const Restart& r, std::initializer_list<std::string> names) {
  for (const auto& n : names) r.edit("Name=\"" + n + "\"", "Name=\"" + n + "X\"");
}

// Overwrite the single Int64 value of field data `name` in the appended data.
void setFieldValue(const Restart& r, const std::string& name, std::int64_t value) {
  std::string bytes = slurp(r.vtp());
  const std::size_t at = bytes.find("Name=\"" + name + "\"");
  BOOST_REQUIRE(at != std::string::npos);
  const std::size_t off = bytes.find("offset=\"", at) + 8;
  const std::size_t data = bytes.find('_', bytes.find("<AppendedData")) + 1;
  std::memcpy(&bytes[data + std::stoul(bytes.substr(off, 20)) + 8], &value, sizeof value);
  std::ofstream(r.vtp(), std::ios::binary) << bytes;
}

}  // namespace

BOOST_AUTO_TEST_CASE(validAndOlderFilesAreRead) {
  Restart r;
  BOOST_TEST(r.read().size() == 12u);
  dropFieldData(r, {"fluidParticles", "wallParticles", "nextId", "time", "TimeValue", "timeIndex", "deltaT", "deltaT0"});
  BOOST_TEST(r.read().size() == 12u);
}

BOOST_AUTO_TEST_CASE(sparseIdsBelowNextIdAreRead) {
  ParticleSet<2> p = smallSet();
  for (std::size_t i = 0; i < p.size(); ++i) p.id[i] = std::int64_t(7 * i + 3);  // particles left, new ones released
  Restart r(p);
  BOOST_TEST(r.read().id[11] == 80);
}

BOOST_AUTO_TEST_CASE(headerDamageIsRefusedBeforeVtk) {
  const std::string n = "NumberOfPoints=\"12\"";
  for (auto [from, to, part] : std::vector<std::tuple<std::string, std::string, std::string>>{
           {n, "NumberOfPoints=\"-5\"", "NumberOfPoints is '-5'"},
           {n, "NumberOfPoints=\"10\"", "NumberOfVerts 12 and 0 other cells for NumberOfPoints 10"},
           {n, "NumberOfPoints=\"99999999999999999999\"", "not a count"},
           {"header_type=\"UInt64\"", "header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\"", "compressed"},
           {"<VTKFile", "<!DOCTYPE x [<!ENTITY a \"b\">]><VTKFile", "<!DOCTYPE"},
           {"Name=\"U\" NumberOfComponents=\"3\"", "Name=\"U\" NumberOfComponents=\"0\"", "array 'U' (<PointData>) has 0 components"},
           {"type=\"UInt8\" Name=\"type\"", "type=\"String\" Name=\"type\"", "array 'type' (<PointData>) has type 'String'"},
           {"<PointData>", "<PointData><Piece>", "<Piece> inside <PointData>"},
           {"</VTKFile>", "</VTKFile>trailing", "bytes after </VTKFile>"},
       }) {
    Restart r;
    r.edit(from, to);
    refused(r, {r.vtp(), part});
  }
}

BOOST_AUTO_TEST_CASE(blockSizesAndTailAreChecked) {
  Restart r;
  std::filesystem::resize_file(r.vtp(), std::filesystem::file_size(r.vtp()) - 30);
  refused(r, {r.vtp(), "after the last data block"});
  Restart big(smallSet(400));  // cut in the data, not the header
  std::filesystem::resize_file(big.vtp(), std::filesystem::file_size(big.vtp()) / 2);
  refused(big, {big.vtp(), "past the end of the file"});
}

BOOST_AUTO_TEST_CASE(particleValuesNameTheParticle) {
  auto with = [](auto change) {
    ParticleSet<2> p = smallSet();
    change(p);
    return p;
  };
  const double nan = std::nan(""), inf = INFINITY;
  refused(Restart(with([](auto& p) { p.type[4] = 7; })), {"particle id 4 (point 4): type 7 is none of fluid (0), wall (1), inlet (2), outlet (3)"});
  refused(Restart(with([](auto& p) { p.surface[4] = 9; })), {"particle id 4 (point 4): surface class 9"});
  refused(Restart(with([&](auto& p) { p.position[2][1] = nan; })), {"particle id 2 (point 2): position is (0.02 nan), not finite"});
  refused(Restart(with([&](auto& p) { p.velocity[3][0] = inf; })), {"particle id 3 (point 3): U is (inf -0.2)"});
  refused(Restart(with([&](auto& p) { p.pressure[5] = -inf; })), {"particle id 5 (point 5): p is -inf"});
  refused(Restart(with([&](auto& p) { p.density[6] = nan; })), {"particle id 6 (point 6): rhoN is nan"});
  refused(Restart(with([&](auto& p) { p.shift.assign(12, Vec<2>(0, 0)); p.shift[7][1] = nan; })), {"particle id 7 (point 7): shift"});
  refused(Restart(with([](auto& p) { p.id[8] = p.id[2]; })), {"id 2 is held by points 2 and 8"});
  refused(Restart(with([](auto& p) { p.id[8] = -3; })), {"point 8: id -3 is not in 0.."});
  refused(Restart(with([](auto& p) { p.mass = 0; })), {"field data 'mass' is 0, not positive"});
}

BOOST_AUTO_TEST_CASE(idsAboveNextIdAndLostParticlesAreRefused) {
  ParticleSet<2> p = smallSet();
  p.id[3] = std::int64_t(1) << 40;
  Restart huge(p);
  dropFieldData(huge, {"nextId"});  // an older file: ids must be below the count
  refused(huge, {huge.vtp(), "point 3: id 1099511627776 is not in 0..11 (nextId 12)"});
  Restart lost;
  setFieldValue(lost, "wallParticles", 7);
  refused(lost, {lost.vtp(), "field data 'wallParticles' states 7, the file holds 6 (particles lost or added)"});
  Restart nextId;
  setFieldValue(nextId, "nextId", 11);
  refused(nextId, {nextId.vtp(), "point 11: id 11 is not in 0..10 (nextId 11)"});
}

BOOST_AUTO_TEST_CASE(timeFileRangesNameTheKeyword) {
  auto text = [](const std::string& value, const std::string& index, const std::string& dt, const std::string& dt0) {
    return "value " + value + ";\nname \"0.002\";\nindex " + index + ";\ndeltaT " + dt + ";\ndeltaT0 " + dt0 + ";\n";
  };
  Restart r;
  r.setTimeFile(text("nan", "2", "1e-3", "1e-3"));
  refused(r, {r.timeFile() + ":1: keyword 'value': nan is not a finite time"});
  r.setTimeFile(text("0.002", "-2", "1e-3", "1e-3"));
  refused(r, {r.timeFile() + ":3: keyword 'index': -2 is negative"});
  r.setTimeFile(text("0.002", "2", "0", "1e-3"));
  refused(r, {r.timeFile() + ":4: keyword 'deltaT': 0 is not a positive finite time step"});
  r.setTimeFile(text("0.002", "2", "1e-3", "inf"));
  refused(r, {r.timeFile() + ":5: keyword 'deltaT0': inf is not"});
  r.setTimeFile(text("0.003", "2", "1e-3", "1e-3"));
  refused(r, {r.timeFile() + ":1: keyword 'value': time 0.003 does not belong in folder '0.002'"});
  r.setTimeFile("value 0.002;\nname \"5\";\nindex 2;\ndeltaT 1e-3;\n");
  refused(r, {r.timeFile() + ":2: keyword 'name': '5' is not the folder's name '0.002'"});
  // The initial state is written before any dt was chosen: 0 is fine at index 0.
  Restart initial(smallSet(), TimeState{0.002, 0, 0, 0, ""});
  BOOST_TEST(initial.read().size() == 12u);
}

BOOST_AUTO_TEST_CASE(vtpAndTimeFileMustAgree) {
  Restart r;
  r.setTimeFile("value 0.002;\nindex 3;\ndeltaT 1e-3;\n");
  refused(r, {r.vtp() + "' field data 'timeIndex' is 2, but '" + r.timeFile() + "' keyword 'index' is 3"});
  r.setTimeFile("value 0.002;\nindex 2;\ndeltaT 1e-3;\ndeltaT0 2e-3;\n");
  refused(r, {"field data 'deltaT0' is 0.001", "keyword 'deltaT0' is 0.002"});
}

BOOST_AUTO_TEST_CASE(folderOfAnotherTimeIsRefused) {
  Restart r;
  std::filesystem::rename(r.dir(), r.c.path + "/5");
  TimeState s;
  BOOST_CHECK_EXCEPTION(readTimeDirectory<2>(r.c.path, "5", s), InputError, [&](const InputError& e) {
    return std::string(e.what()).find(r.c.path + "/5/uniform/time:") != std::string::npos &&
           std::string(e.what()).find("time 0.002 does not belong in folder '5'") != std::string::npos;
  });
}
