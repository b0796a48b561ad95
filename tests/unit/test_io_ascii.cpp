// writeFormat ascii (docs/design.md 1.3): one plain-text file per field in the
// time directory, '#' header lines (field, unit, time, count, columns), then
// one line per particle whose numbers read back to exactly the written values.
#define BOOST_TEST_MODULE io_ascii
#include <boost/test/unit_test.hpp>
#include "io/TimeDirectory.hpp"
#include "io/TimeName.hpp"
#include "test_io_helpers.hpp"
#include <fstream>
#include <sstream>

using namespace shizuku;
using namespace shizuku::iotest;

namespace {

struct TextField {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
};

TextField readText(const std::string& path) {
  TextField f;
  std::ifstream in(path);
  BOOST_REQUIRE_MESSAGE(in, "cannot open " << path);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] == '#') {
      f.header.push_back(line);
      continue;
    }
    std::istringstream s(line);
    std::vector<double> row;
    std::string tok;
    while (s >> tok) row.push_back(parseNumber(tok).value());
    f.rows.push_back(row);
  }
  return f;
}

bool hasLine(const TextField& f, const std::string& line) {
  return std::find(f.header.begin(), f.header.end(), line) != f.header.end();
}

}  // namespace

BOOST_AUTO_TEST_CASE(oneFilePerFieldWithExactValues) {
  ScratchDir c;
  auto p = randomSet<3>(100, true, 9);
  p.id[0] = 9007199254740993LL;  // 2^53 + 1: would be mangled by a double on the way
  writeTimeDirectory<3>(c.path, "0.5", p, TimeState{0.5, 10, 1e-3, 1e-3, ""}, true);
  const std::string d = c.path + "/0.5/";
  for (const char* name : {"position", "U", "p", "rhoN", "type", "surface", "id", "shift"})
    BOOST_TEST(std::filesystem::exists(d + name), name);
  BOOST_TEST(!std::filesystem::exists(d + "normal"));  // absent optional field: no file

  auto pos = readText(d + "position");
  BOOST_TEST(hasLine(pos, "# unit m"));
  BOOST_TEST(hasLine(pos, "# time 0.5"));
  BOOST_TEST(hasLine(pos, "# particles 100"));
  BOOST_TEST(hasLine(pos, "# columns position_x position_y position_z"));
  BOOST_REQUIRE(pos.rows.size() == 100u);
  auto U = readText(d + "U");
  BOOST_TEST(hasLine(U, "# unit m/s"));
  auto pr = readText(d + "p");
  BOOST_TEST(hasLine(pr, "# unit Pa"));
  BOOST_TEST(hasLine(readText(d + "rhoN"), "# unit kg/m^3"));
  auto type = readText(d + "type");
  for (std::size_t i = 0; i < 100; ++i) {
    BOOST_REQUIRE(pos.rows[i].size() == 3u);
    for (int k = 0; k < 3; ++k) {
      BOOST_TEST(sameBits(pos.rows[i][k], p.position[i][k]));
      BOOST_TEST(sameBits(U.rows[i][k], p.velocity[i][k]));
    }
    BOOST_REQUIRE(pr.rows[i].size() == 1u);
    BOOST_TEST(sameBits(pr.rows[i][0], p.pressure[i]));
    BOOST_TEST(type.rows[i][0] == double(p.type[i]));
  }
  // Integers are written as integers, not through a double.
  std::ifstream ids(d + "id");
  std::string line;
  while (std::getline(ids, line) && line[0] == '#') {}
  BOOST_TEST(line == "9007199254740993");
}

BOOST_AUTO_TEST_CASE(twoDimensionalVectorsHaveTwoColumns) {
  ScratchDir c;
  auto p = randomSet<2>(10, false, 3);
  writeTimeDirectory<2>(c.path, "1e-05", p, TimeState{1e-5, 1, 1e-5, 1e-5, ""}, true);
  auto U = readText(c.path + "/1e-05/U");
  BOOST_TEST(hasLine(U, "# columns U_x U_y"));
  BOOST_TEST(hasLine(readText(c.path + "/1e-05/rhoN"), "# unit kg/m^2"));
  for (std::size_t i = 0; i < 10; ++i) {
    BOOST_REQUIRE(U.rows[i].size() == 2u);
    BOOST_TEST(sameBits(U.rows[i][1], p.velocity[i][1]));
  }
}

BOOST_AUTO_TEST_CASE(binaryWritesNoTextFiles) {
  ScratchDir c;
  writeTimeDirectory<2>(c.path, "2", randomSet<2>(10, false, 3), TimeState{2, 1, 1, 1, ""}, false);
  BOOST_TEST(!std::filesystem::exists(c.path + "/2/p"));
  BOOST_TEST(!std::filesystem::exists(c.path + "/2/position"));
}
