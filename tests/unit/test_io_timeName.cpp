// Time directory names (docs/design.md 1.3): the %g general format at 8
// significant digits, parsed back to the same time; directory names that are
// not numbers are rejected; exactNumber() text reads back bit for bit.
#define BOOST_TEST_MODULE io_timeName
#include <boost/test/unit_test.hpp>
#include "io/TimeName.hpp"
#include <cstring>
#include <limits>
#include <random>

using namespace shizuku;

BOOST_AUTO_TEST_CASE(knownNamesRoundTrip) {
  const std::vector<std::pair<double, std::string>> cases = {
      {0, "0"}, {1e-4, "0.0001"}, {0.1, "0.1"}, {4.3, "4.3"}, {1234.5, "1234.5"}, {1e-05, "1e-05"},
      {0.25, "0.25"}, {100, "100"}, {2.5e-7, "2.5e-07"}, {123456789.0, "1.2345679e+08"}};
  for (auto& [t, name] : cases) {
    BOOST_TEST(timeName(t) == name);
    auto back = parseTimeName(name);
    BOOST_TEST(back.has_value());
    BOOST_TEST(*back == std::stod(name));
    if (name != "1.2345679e+08") BOOST_TEST(*back == t);  // exact when t has <= 8 digits
  }
}

BOOST_AUTO_TEST_CASE(accumulatedTimesGetTheIntendedName) {
  // 43000 steps of 1e-4 do not add up to exactly 4.3; the name must still be "4.3".
  double t = 0;
  for (int i = 0; i < 43000; ++i) t += 1e-4;
  BOOST_TEST(t != 4.3);
  BOOST_TEST(timeName(t) == "4.3");
  BOOST_TEST(timeName(0.1 + 0.2) == "0.3");
  BOOST_TEST(timeName(-0.0) == "0");
  BOOST_TEST(timeName(1234.5, 3) == "1.23e+03");
  BOOST_TEST(timeName(-0.5) == "-0.5");
  BOOST_CHECK_THROW(timeName(std::numeric_limits<double>::infinity()), std::runtime_error);
}

BOOST_AUTO_TEST_CASE(nonTimeNamesAreRejected) {
  for (const char* s : {"", "system", "constant", "0.1.tmp-42", "0.1.old-3", "inf", "nan", "1e", "0x10", "1 ",
                        "postProcessing", "1e999", "."})
    BOOST_TEST(!parseTimeName(s).has_value(), "'" << s << "' taken as a time");
  BOOST_TEST(parseTimeName("+2").value() == 2.0);
  BOOST_TEST(parseTimeName("-1.5").value() == -1.5);
}

BOOST_AUTO_TEST_CASE(exactNumberReadsBackBitForBit) {
  std::mt19937_64 g(1);
  int bad = 0;
  for (int i = 0; i < 200000; ++i) {
    std::uint64_t bits = g();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    if (v != v) continue;  // NaN payloads are not kept as text
    auto back = parseNumber(exactNumber(v));
    if (!back || std::memcmp(&*back, &v, sizeof v) != 0) ++bad;
  }
  BOOST_TEST(bad == 0);
  BOOST_TEST(exactNumber(0.1) == "0.1");
  BOOST_TEST(exactNumber(1.0 / 3.0) == "0.3333333333333333");
  BOOST_TEST(exactNumber(-0.0) == "-0");
}
