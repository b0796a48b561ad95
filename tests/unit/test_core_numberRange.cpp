// Numbers a double cannot hold are input errors of the dictionary reader
// (naming file, line, column and keyword), written directly or produced by a
// unit; the largest finite values still read.
#define BOOST_TEST_MODULE core_numberRange
#include <boost/test/unit_test.hpp>

#include "core/Dictionary.hpp"

using namespace shizuku;

namespace {
std::string errorOf(const std::string& text) {
  try {
    Dictionary::fromString(text, "case/system/controlDict");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }
}  // namespace

BOOST_AUTO_TEST_CASE(overflowing_numbers_are_errors) {
  const std::string m = errorOf("a 1;\nendTime 1e999;\n");
  BOOST_TEST_INFO(m);
  BOOST_TEST(contains(m, "case/system/controlDict:2:9: keyword 'endTime': the number 1e999 is out of range"));
  BOOST_TEST(contains(errorOf("v (0 -1e400);"), "keyword 'v': the number -1e400 is out of range"));
  // Finite, but not after the unit: 1e306 kPa = 1e309 Pa.
  BOOST_TEST(contains(errorOf("p 1e306 [kPa];"), "keyword 'p': the number 1e306 [kPa] is out of range in SI units"));
  BOOST_TEST(contains(errorOf("v (1 1e306) [kPa];"), "is out of range in SI units"));
}

BOOST_AUTO_TEST_CASE(large_finite_numbers_read) {
  const Dictionary d = Dictionary::fromString("a 1.7e308; b 1e305 [kPa]; c 1e-400;");
  BOOST_TEST(d.getScalar("a", dim::none) == 1.7e308);
  BOOST_TEST(d.getScalar("b", dim::pressure) == 1e308);
  BOOST_TEST(d.getScalar("c", dim::none) == 0.0);  // underflow reads as zero
}
