// Limits of the dictionary reader, each an InputError naming file, line and
// keyword instead of a crash: numbers a double cannot hold (written, or made
// by a unit), unit powers beyond 99 (found by fuzz_dictionary: a long power
// made std::stoi throw), nesting beyond 200 levels (stack), macro copies
// beyond 5e5 values (memory) and more than 1000 #includes (time).
#define BOOST_TEST_MODULE core_dictionaryLimits
#include <boost/test/unit_test.hpp>

#include "core/Dictionary.hpp"
#include "../support/ErrorOf.hpp"
#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace shizuku;

namespace {
std::string errorOf(const std::string& text) {
  return test::errorOf([&] { Dictionary::fromString(text, "case/system/controlDict"); });
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
  const Dictionary d = Dictionary::fromString("a 1.7e308; b 1e305 [kPa]; c 2.3e-308; z 0e-400;");
  BOOST_TEST(d.getScalar("a", dim::none) == 1.7e308);
  BOOST_TEST(d.getScalar("b", dim::pressure) == 1e308);
  BOOST_TEST(d.getScalar("c", dim::none) == 2.3e-308);  // the smallest normal doubles still read
  BOOST_TEST(d.getScalar("z", dim::none) == 0.0);       // a written zero is zero
}

BOOST_AUTO_TEST_CASE(underflowing_numbers_are_out_of_range) {
  // A nonzero number that would read as 0 or a denormal is refused, not silently zero.
  for (const char* text : {"c 1e-400;", "c 1e-310;", "c 1e-306 [mm];"}) {
    std::string m;
    try {
      Dictionary::fromString(text);
    } catch (const InputError& e) {
      m = e.what();
    }
    BOOST_TEST(m.find("keyword 'c': the number") != std::string::npos, text << ": " << m);
    BOOST_TEST(m.find("out of range") != std::string::npos, text << ": " << m);
  }
}

BOOST_AUTO_TEST_CASE(unit_powers_are_bounded) {
  BOOST_TEST(contains(errorOf("nu 1 [m^2000000000000000000000/s];"), "keyword 'nu': unit [m^2000000000000000000000/s]: power ^2000000000000000000000 is larger than 99"));
  BOOST_TEST(contains(errorOf("x 1 [(m^99)^2];"), "powers of the units add up to more than 99"));
  BOOST_TEST(contains(errorOf("x 1 [m^99 m];"), "powers of the units add up to more than 99"));
  BOOST_TEST(contains(errorOf("x 1 [((((((((((((((((((m))))))))))))))))))];"), "parentheses nested more than 16 deep"));
  // Within the bounds all is as before.
  const Dictionary d = Dictionary::fromString("a 1 [m^99 / m^98]; b 2 [(cm)^-2]; c 1 [((m))];");
  BOOST_TEST(d.getScalar("a", dim::length) == 1.0);
  BOOST_TEST(d.getScalar("b", dim::inverseLength.pow(2)) == 2e4);
}

BOOST_AUTO_TEST_CASE(nesting_is_bounded) {
  const std::string deepList = "x " + std::string(100000, '(') + std::string(100000, ')') + ";";
  const std::string m = errorOf(deepList);
  BOOST_TEST_INFO(m);
  BOOST_TEST(contains(m, "case/system/controlDict:1:"));
  BOOST_TEST(contains(m, "keyword 'x': dictionaries and lists nested more than 200 deep"));
  std::string deepDict;
  for (int i = 0; i < 50000; ++i) deepDict += "a { ";
  BOOST_TEST(contains(errorOf(deepDict), "nested more than 200 deep"));
  // 200 levels read.
  BOOST_TEST(errorOf("x " + std::string(200, '(') + std::string(200, ')') + ";").empty());
}

BOOST_AUTO_TEST_CASE(macro_copies_are_bounded) {
  // Each level doubles the previous one: 2^30 values without a bound.
  std::string text = "a0 (1 2);\n";
  for (int i = 1; i <= 30; ++i) text += "a" + std::to_string(i) + " ($a" + std::to_string(i - 1) + " $a" + std::to_string(i - 1) + ");\n";
  const std::string m = errorOf(text);
  BOOST_TEST_INFO(m);
  BOOST_TEST(contains(m, "more than 500000 values (do macros copy each other over and over?)"));
}

BOOST_AUTO_TEST_CASE(includes_are_bounded) {
  // A file that includes itself twice would be read 2^32 times without the
  // depth bound; 1001 includes of one empty file pass it but not the count bound.
  const auto dir = std::filesystem::temp_directory_path() / "shizuku-dictionaryLimits";
  std::filesystem::create_directories(dir);
  std::ofstream((dir / "twice").string()) << "#include \"twice\"\n#include \"twice\"\n";
  std::ofstream((dir / "leaf").string()) << "";
  std::string many;
  for (int i = 0; i < 1001; ++i) many += "#include \"leaf\"\n";
  std::ofstream((dir / "many").string()) << many;
  auto errorOfFile = [&](const char* name) { return test::errorOf([&] { Dictionary::fromFile((dir / name).string()); }); };
  const std::string twice = errorOfFile("twice"), m = errorOfFile("many");
  std::filesystem::remove_all(dir);
  BOOST_TEST_INFO(twice);
  BOOST_TEST(contains(twice, "nested more than 32 deep"));
  BOOST_TEST_INFO(m);
  BOOST_TEST(contains(m, "many:1001:1: more than 1000 #include directives in one dictionary"));
}

// A UTF-8 byte-order mark at the start of a file is skipped (editors on Windows write
// one); any other non-ASCII character outside comments and strings is named.
BOOST_AUTO_TEST_CASE(byte_order_mark_is_skipped_other_non_ascii_is_named) {
  const Dictionary d = Dictionary::fromString("\xef\xbb\xbf" "deltaT 1e-3; // caf\xc3\xa9\nname \"caf\xc3\xa9\";", "f");
  BOOST_TEST(d.getScalar("deltaT", dim::none) == 1e-3);
  BOOST_TEST(contains(errorOf("deltaT\xc2\xa0 1e-3;"),
                      "case/system/controlDict:1:7: non-ASCII character U+00A0 (no-break space) after 'deltaT'"));
  BOOST_TEST(contains(errorOf("a 1;\n\xef\xbb\xbf" "b 2;"), ":2:1: non-ASCII character U+FEFF (byte-order mark)"));
}

// A huge token is quoted in at most 80 characters, and the did-you-mean search skips it.
BOOST_AUTO_TEST_CASE(huge_tokens_are_quoted_short) {
  const std::string word(1000000, 'a');
  const std::string m = test::errorOf([&] {
    const Dictionary d = Dictionary::fromString(word + " 1; deltaT 1;", "f");
    d.getScalar("deltaT", dim::none);
    d.checkAllRead();
  });
  BOOST_TEST_INFO(m.substr(0, 300));
  BOOST_TEST(contains(m, "unknown keyword '" + std::string(60, 'a') + "... (1000000 characters)'"));
  BOOST_TEST(m.size() < 300u);
  BOOST_TEST(echoed(std::string(80, 'b')) == std::string(80, 'b'));
  BOOST_TEST(closestMatch("deltT", {"endTime", "deltaT"}) == "deltaT");
  BOOST_TEST(closestMatch(std::string(100, 'x'), {std::string(100, 'x')}).empty());
}
