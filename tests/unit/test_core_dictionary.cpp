// Tests of the case-dictionary reader (docs/design.md 1.2): every syntax element,
// unit conversion to SI, dimension checks, macros, includes, read tracking and
// every error path (the message must name file, line, column, keyword and,
// where there is one, the "did you mean" suggestion).
#define BOOST_TEST_MODULE core_dictionary
#include <boost/test/unit_test.hpp>

#include "core/Dictionary.hpp"
#include "../support/ErrorOf.hpp"
#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace shizuku;
namespace fs = std::filesystem;

namespace {

using test::errorOf;

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

#define CHECK_ERROR(expr, ...)                                                 \
  do {                                                                         \
    const std::string msg_ = errorOf([&] { (void)(expr); });                   \
    BOOST_TEST_INFO("message: " << msg_);                                      \
    BOOST_CHECK(!msg_.empty());                                                \
    for (const std::string& part_ : std::vector<std::string>{__VA_ARGS__}) {                                  \
      BOOST_TEST_INFO("message: '" << msg_ << "' should contain '" << part_ << "'"); \
      BOOST_CHECK(contains(msg_, part_));                                      \
    }                                                                          \
  } while (0)

// A fresh temporary folder, removed at the end of the test.
struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() / ("shizuku_dict_" + std::to_string(::getpid()) + "_" + std::to_string(counter()++));
    fs::create_directories(path);
  }
  ~TempDir() { std::error_code ec; fs::remove_all(path, ec); }
  std::string write(const std::string& name, const std::string& text) const {
    const fs::path p = path / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  static int& counter() { static int c = 0; return c; }
};

Dictionary parse(const std::string& text) { return Dictionary::fromString(text, "case/system/testDict"); }

}  // namespace

// --------------------------------------------------------------------------- syntax

BOOST_AUTO_TEST_CASE(entries_words_numbers_strings_switches) {
  const Dictionary d = parse(R"(
FoamFile { version 2.0; format ascii; class dictionary; object testDict; }
// a line comment
startFrom   latestTime;   /* a block
   comment over lines */
endTime     4.3;
deltaT      1e-4;
count       12;
negative    -0.5e+2;
title       "a string with spaces; and // no comment";
quote       "say \"hi\"";
adjust      yes;  a on; b off; c no; e true; f false;
)");
  BOOST_TEST(d.getWord("startFrom") == "latestTime");
  BOOST_TEST(d.getScalar("endTime", dim::time) == 4.3);
  BOOST_TEST(d.getScalar("deltaT", dim::time) == 1e-4);
  BOOST_TEST(d.getInt("count") == 12);
  BOOST_TEST(d.getScalar("negative", dim::none) == -50.0);
  BOOST_TEST(d.getWord("title") == "a string with spaces; and // no comment");
  BOOST_TEST(d.getWord("quote") == "say \"hi\"");
  BOOST_TEST(d.getSwitch("adjust"));
  BOOST_TEST(d.getSwitch("a"));
  BOOST_TEST(!d.getSwitch("b"));
  BOOST_TEST(!d.getSwitch("c"));
  BOOST_TEST(d.getSwitch("e"));
  BOOST_TEST(!d.getSwitch("f"));
  BOOST_TEST((d.value("count").kind == DictValue::Kind::number));
  BOOST_TEST((d.value("title").kind == DictValue::Kind::string));
  // keys in file order; the FoamFile header is marked read
  const std::vector<std::string> expected = {"FoamFile", "startFrom", "endTime", "deltaT", "count", "negative",
                                             "title", "quote", "adjust", "a", "b", "c", "e", "f"};
  BOOST_TEST(d.keys() == expected, boost::test_tools::per_element());
  BOOST_CHECK_NO_THROW(d.checkAllRead());
}

BOOST_AUTO_TEST_CASE(empty_file_and_comment_only_file) {
  BOOST_TEST(parse("").empty());
  BOOST_TEST(parse("  // nothing\n/* at all */\n").empty());
  BOOST_CHECK_NO_THROW(parse("").checkAllRead());
}

BOOST_AUTO_TEST_CASE(sub_dictionaries_and_names) {
  const Dictionary d = parse(R"(
functions
{
    centre       { type probes; fields (p U); points ((0 0) (0.5 -0.25)); }
    densityError { type densityError; }
}
ads { }
)");
  BOOST_TEST(d.isDict("functions"));
  BOOST_TEST(!d.isDict("nothere"));
  const Dictionary& f = d.subDict("functions");
  BOOST_TEST(f.name() == "case/system/testDict/functions");
  const std::vector<std::string> fk = {"centre", "densityError"};
  BOOST_TEST(f.keys() == fk, boost::test_tools::per_element());
  const Dictionary& c = f.subDict("centre");
  BOOST_TEST(c.name() == "case/system/testDict/functions/centre");
  BOOST_TEST(c.getWord("type") == "probes");
  const std::vector<std::string> fields = {"p", "U"};
  BOOST_TEST(c.getWordList("fields") == fields, boost::test_tools::per_element());
  const auto pts = c.getVectorList<2>("points", dim::length);
  BOOST_REQUIRE(pts.size() == 2u);
  BOOST_TEST(pts[1][0] == 0.5);
  BOOST_TEST(pts[1][1] == -0.25);
  BOOST_TEST(d.subDict("ads").empty());
  BOOST_TEST(d.subDictPtr("absent") == nullptr);
  BOOST_TEST(d.subDictPtr("ads") != nullptr);
  // location of a keyword: file:line:column
  BOOST_TEST(c.location("type").str() == "case/system/testDict:4:20");
}

BOOST_AUTO_TEST_CASE(lists_vectors_matrices_and_multi_token_values) {
  const Dictionary d = parse(R"(
v2      (1 2);
v3      (1 2 3);
gradient ((1 2) (3 4));
nested  ((a (b c)) d);
several 1 2 3;
words   left right;
points
(
    (0 0)
    (1 1)
);
scalars (1 2.5 -3);
)");
  const Vec<2> v2 = d.getVector<2>("v2", dim::none);
  BOOST_TEST(v2[0] == 1.0);
  BOOST_TEST(v2[1] == 2.0);
  BOOST_TEST(d.getVector<3>("v3", dim::none)[2] == 3.0);
  const Mat<2> g = d.getMatrix<2>("gradient", dim::inverseTime);
  BOOST_TEST(g(0, 0) == 1.0);
  BOOST_TEST(g(0, 1) == 2.0);  // row by row
  BOOST_TEST(g(1, 0) == 3.0);
  BOOST_TEST(g(1, 1) == 4.0);
  const DictValue& n = d.value("nested");
  BOOST_REQUIRE((n.kind == DictValue::Kind::list));
  BOOST_REQUIRE(n.items.size() == 2u);
  BOOST_TEST(n.items[0].items[1].items[1].text == "c");
  // several tokens: stored as a list value
  const DictValue& s = d.value("several");
  BOOST_TEST((s.kind == DictValue::Kind::list));
  BOOST_TEST(s.items.size() == 3u);
  BOOST_TEST(d.getVector<3>("several", dim::none)[1] == 2.0);
  const std::vector<std::string> w = {"left", "right"};
  BOOST_TEST(d.getWordList("words") == w, boost::test_tools::per_element());
  BOOST_TEST(d.getVectorList<2>("points", dim::length).size() == 2u);
  const std::vector<double> sc = {1, 2.5, -3};
  BOOST_TEST(d.getScalarList("scalars", dim::none) == sc, boost::test_tools::per_element());
}

// --------------------------------------------------------------------------- units

BOOST_AUTO_TEST_CASE(unit_conversion_to_si) {
  const Dictionary d = parse(R"(
spacing 1 [cm];
rho     1 [g/cm^3];
g       (0 -980) [cm/s^2];
nu      1 [cm^2/s];
p       1 [kPa];
pa      3 [Pa];
mm      5 [mm];
ms      2 [ms];
mass    2 [g];
omega   2 [rad/s];
rate    3 [1/s];
u       (1 2) [m/s];
none    4 [-];
empty   5 [];
kgm3    7 [kg/m^3];
paren   2 [kg/(m s^2)];
)");
  BOOST_TEST(d.getScalar("spacing", dim::length) == 0.01);
  BOOST_TEST(d.getScalar("rho", dim::density) == 1000.0, boost::test_tools::tolerance(1e-14));
  const Vec<2> g = d.getVector<2>("g", dim::acceleration);
  BOOST_TEST(g[0] == 0.0);
  BOOST_TEST(g[1] == -9.8, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(d.getScalar("nu", dim::kinematicViscosity) == 1e-4, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(d.getScalar("p", dim::pressure) == 1000.0);
  BOOST_TEST(d.getScalar("pa", dim::pressure) == 3.0);
  BOOST_TEST(d.getScalar("mm", dim::length) == 5e-3, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(d.getScalar("ms", dim::time) == 2e-3, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(d.getScalar("mass", dim::mass) == 2e-3, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(d.getScalar("omega", dim::inverseTime) == 2.0);
  BOOST_TEST(d.getScalar("rate", dim::inverseTime) == 3.0);
  BOOST_TEST(d.getVector<2>("u", dim::velocity)[1] == 2.0);
  BOOST_TEST(d.getScalar("none", dim::none) == 4.0);
  BOOST_TEST(d.getScalar("empty", dim::none) == 5.0);
  BOOST_TEST(d.getScalar("kgm3", dim::density) == 7.0);
  BOOST_TEST(d.getScalar("paren", dim::pressure) == 2.0);
  // the value keeps the unit as written
  BOOST_TEST(d.value("spacing").unitText == "cm");
  BOOST_TEST(d.value("spacing").hasUnit);
  // a number without a unit is SI already and passes any dimension check
  BOOST_TEST(parse("x 2;").getScalar("x", dim::density) == 2.0);
}

BOOST_AUTO_TEST_CASE(parse_unit_directly) {
  BOOST_TEST(parseUnit("cm").factor == 0.01);
  BOOST_TEST((parseUnit("g/cm^3").dim == dim::density));
  BOOST_TEST(parseUnit("g/cm^3").factor == 1000.0, boost::test_tools::tolerance(1e-14));
  BOOST_TEST((parseUnit("m/s/s").dim == dim::acceleration));
  BOOST_TEST((parseUnit("m s^-2").dim == dim::acceleration));
  BOOST_TEST((parseUnit("kg*m^-3").dim == dim::density));
  BOOST_TEST((parseUnit("rad/s").dim == dim::inverseTime));
  BOOST_TEST((parseUnit("-").dim == dim::none));
  BOOST_TEST(dim::acceleration.str() == "[m/s^2]");
  BOOST_TEST(dim::density.str() == "[kg/m^3]");
  BOOST_TEST(dim::kinematicViscosity.str() == "[m^2/s]");
  BOOST_TEST(dim::inverseTime.str() == "[1/s]");
  BOOST_TEST(dim::none.str() == "[-]");
  BOOST_TEST(dim::pressure.str() == "[Pa]");
  BOOST_TEST((Dimension{1, 0, -1}.str() == "[kg/s]"));
  BOOST_TEST((Dimension{0, -1, -1}.str() == "[1/(m s)]"));
  // str() round-trips through parseUnit
  for (Dimension dd : {dim::none, dim::length, dim::velocity, dim::acceleration, dim::density, dim::pressure,
                       dim::kinematicViscosity, dim::inverseTime, Dimension{1, -2, -1}}) {
    const std::string s = dd.str();
    BOOST_TEST((parseUnit(s.substr(1, s.size() - 2)).dim == dd), s);
  }
  CHECK_ERROR(parseUnit("cn/s"), "unknown unit 'cn'", "did you mean 'cm'?");
  CHECK_ERROR(parseUnit("m^"), "integer power");
  CHECK_ERROR(parseUnit("2/s"), "may only be 1");
}

BOOST_AUTO_TEST_CASE(dimension_mismatch) {
  const Dictionary d = parse("\nspacing 1 [s];\nmin (-50 -50) [cm/s];\n");
  CHECK_ERROR(d.getScalar("spacing", dim::length),
              "case/system/testDict:2:1: keyword 'spacing': unit [s] has dimension [s] but a length [m] is expected");
  CHECK_ERROR(d.getVector<2>("min", dim::length), "testDict:3:1", "keyword 'min'", "unit [cm/s]",
              "dimension [m/s]", "a length [m] is expected");
  CHECK_ERROR(parse("x 1 [cn];"), "testDict:1:5", "keyword 'x'", "unknown unit 'cn'", "did you mean 'cm'?");
  CHECK_ERROR(parse("x word [cm];"), "testDict:1:8", "keyword 'x'", "must follow a number or a list");
  CHECK_ERROR(parse("x 1 [cm;"), "testDict:1:5", "never closed");
  CHECK_ERROR(parse("x (1 a) [cm];"), "keyword 'x'", "applies to numbers", "'a'");
}

// --------------------------------------------------------------------------- typed getters

BOOST_AUTO_TEST_CASE(getter_errors_name_file_line_and_keyword) {
  const Dictionary d = parse(R"(a 1;
v (1 2 3);
w word;
s maybe;
i 2.5;
m ((1 2) (3));
startFrom latestTim;
sub { x 1; }
)");
  CHECK_ERROR(d.getVector<2>("v", dim::none), "testDict:2:1: keyword 'v'", "2 components", "found 3");
  CHECK_ERROR(d.getScalar("w", dim::length), "testDict:3:1: keyword 'w'", "expected a length [m]", "'word'");
  CHECK_ERROR(d.getSwitch("s"), "testDict:4:1: keyword 's'", "expected a switch");
  CHECK_ERROR(parse("s of;").getSwitch("s"), "did you mean 'on'?");
  CHECK_ERROR(d.getInt("i"), "testDict:5:1: keyword 'i'", "expected an integer");
  CHECK_ERROR(d.getMatrix<2>("m", dim::none), "keyword 'm'", "row 2 must have 2 numbers, found 1");
  CHECK_ERROR(d.getOption("startFrom", {"startTime", "latestTime"}), "testDict:7:1: keyword 'startFrom'",
              "'latestTim' is not one of: startTime | latestTime", "did you mean 'latestTime'?");
  CHECK_ERROR(d.getScalar("absent", dim::length), "case/system/testDict: keyword 'absent': missing",
              "a length [m]");
  CHECK_ERROR(d.subDict("sub").getScalar("y", dim::none), "testDict:8:1: keyword 'y': missing in dictionary 'case/system/testDict/sub'");
  CHECK_ERROR(d.subDict("a"), "keyword 'a'", "expected a sub-dictionary");
  // a missing keyword points at a present, unread keyword that looks like it misspelt
  CHECK_ERROR(parse("\nspacng 1;").getScalar("spacing", dim::length), "keyword 'spacing': missing",
              "'spacng' (line 2) looks like a misspelling of it");
  CHECK_ERROR(d.getWord("sub"), "keyword 'sub'", "expected a word");
  CHECK_ERROR(d.error("a", "custom problem"), "testDict:1:1: keyword 'a': custom problem");
  BOOST_TEST(d.getOption("w", {"word", "other"}) == "word");
}

BOOST_AUTO_TEST_CASE(defaults_are_recorded_once) {
  Dictionary::defaultsUsed().clear();
  const Dictionary d = parse("present 2;\nsub { }\n");
  BOOST_TEST(d.getScalarOr("present", 5, dim::none) == 2.0);
  BOOST_TEST(d.getScalarOr("maxCo", 0.2, dim::none) == 0.2);
  BOOST_TEST(d.getScalarOr("maxCo", 0.2, dim::none) == 0.2);
  BOOST_TEST(d.getIntOr("layers", 3) == 3);
  BOOST_TEST(d.getWordOr("writeFormat", "binary") == "binary");
  BOOST_TEST(d.getOptionOr("stopAt", {"endTime", "writeNow"}, "endTime") == "endTime");
  BOOST_TEST(!d.getSwitchOr("adjustTimeStep", false));
  const Vec<2> c = d.subDict("sub").getVectorOr<2>("centre", Vec<2>(0, 1), dim::length);
  BOOST_TEST(c[1] == 1.0);
  BOOST_TEST(d.getScalarOr("dt", 1e-3, dim::time) == 1e-3);
  const std::vector<std::string> expected = {
      "case/system/testDict: maxCo default 0.2",
      "case/system/testDict: layers default 3",
      "case/system/testDict: writeFormat default binary",
      "case/system/testDict: stopAt default endTime",
      "case/system/testDict: adjustTimeStep default off",
      "case/system/testDict/sub: centre default (0 1) [m]",
      "case/system/testDict: dt default 0.001 [s]",
  };
  BOOST_TEST(Dictionary::defaultsUsed() == expected, boost::test_tools::per_element());
  // a default looked up through found() first is still recorded by the getter
  BOOST_CHECK_NO_THROW(d.checkAllRead());
}

// --------------------------------------------------------------------------- macros

BOOST_AUTO_TEST_CASE(macros) {
  const Dictionary d = parse(R"(
L       2 [cm];
width   $L;
box     { min (0 0); max ($L 1); }
copy    $box;
common  { type fluid; shape box; }
regions
{
    a { $common; extra 1; }
    b { h $width; deep $box/max; }
}
)");
  BOOST_TEST(d.getScalar("width", dim::length) == 0.02);
  CHECK_ERROR(d.getScalar("width", dim::time), "unit [cm]");  // the unit travels with the value
  const Dictionary& copy = d.subDict("copy");
  BOOST_TEST(copy.name() == "case/system/testDict/copy");
  BOOST_TEST(copy.getVector<2>("max", dim::length)[0] == 0.02);
  const Dictionary& a = d.subDict("regions").subDict("a");
  BOOST_TEST(a.getWord("type") == "fluid");
  BOOST_TEST(a.getWord("shape") == "box");
  BOOST_TEST(a.getInt("extra") == 1);
  const Dictionary& b = d.subDict("regions").subDict("b");
  BOOST_TEST(b.getScalar("h", dim::length) == 0.02);
  BOOST_TEST(b.getVector<2>("deep", dim::length)[1] == 1.0);
  // the macro sources (L, box, common) count as read
  d.subDict("copy").getVector<2>("min", dim::length);
  BOOST_CHECK_NO_THROW(d.checkAllRead());
}

BOOST_AUTO_TEST_CASE(macro_errors) {
  CHECK_ERROR(parse("spacing 1;\nd $spacng;"), "testDict:2:3: keyword 'd'", "macro $spacng not found",
              "did you mean '$spacing'?");
  CHECK_ERROR(parse("box { min 1; }\nd $box/mn;"), "testDict:2:3", "macro $box/mn not found",
              "did you mean '$box/min'?");
  CHECK_ERROR(parse("x 1;\nd $x/y;"), "'x' is not a dictionary");
  CHECK_ERROR(parse("x 1;\n$x;"), "testDict:2:1", "$x names a value, not a dictionary");
  // a macro refers to entries defined before it
  CHECK_ERROR(parse("d $later;\nlater 1;"), "macro $later not found");
  // a sub-dictionary does not see its own later siblings' contents
  CHECK_ERROR(parse("a { x $y; }\nb { y 1; }"), "macro $y not found");
}

// --------------------------------------------------------------------------- includes

BOOST_AUTO_TEST_CASE(includes) {
  TempDir tmp;
  tmp.write("system/common", "nu 1 [cm^2/s];\nrho 1000;\n");
  tmp.write("system/sub/more", "extra 3;\n");
  const std::string main = tmp.write("system/controlDict",
                                     "#include \"common\"\n"
                                     "rho 998;                 // overrides the included value\n"
                                     "#includeIfPresent \"absent\"\n"
                                     "sub { #include \"sub/more\" }\n"
                                     "twice $nu;\n");
  const Dictionary d = Dictionary::fromFile(main);
  BOOST_TEST(d.getScalar("nu", dim::kinematicViscosity) == 1e-4, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(d.getScalar("rho", dim::density) == 998.0);
  BOOST_TEST(d.subDict("sub").getInt("extra") == 3);
  BOOST_TEST(d.getScalar("twice", dim::kinematicViscosity) == 1e-4, boost::test_tools::tolerance(1e-14));
  // the order keeps the first place of a repeated keyword
  const std::vector<std::string> k = {"nu", "rho", "sub", "twice"};
  BOOST_TEST(d.keys() == k, boost::test_tools::per_element());
  // a location inside an included file names that file and the #include
  BOOST_TEST(d.location("nu").str() == (tmp.path / "system/common").string() + ":1:1 (included from " + main + ":1:1)");
  BOOST_TEST(d.location("rho").str() == main + ":2:1");
  BOOST_CHECK_NO_THROW(d.checkAllRead());
}

BOOST_AUTO_TEST_CASE(include_errors) {
  TempDir tmp;
  const std::string main = tmp.write("controlDict", "a 1;\n\n  #include \"missingFile\"\n");
  CHECK_ERROR(Dictionary::fromFile(main), main + ":3:3", "#include \"missingFile\"", "cannot open file");
  const std::string self = tmp.write("loop", "#include \"loop\"\n");
  CHECK_ERROR(Dictionary::fromFile(self), "nested more than 32 deep");
  const std::string bad = tmp.write("bad", "#inclde \"x\"\n");
  CHECK_ERROR(Dictionary::fromFile(bad), bad + ":1:1", "unknown directive '#inclde'", "did you mean '#include'?");
  // a syntax error inside an included file names the included file
  tmp.write("broken", "x 1\ny 2;\n");
  const std::string outer = tmp.write("outer", "#include \"broken\"\n");
  CHECK_ERROR(Dictionary::fromFile(outer), (tmp.path / "broken").string() + ":1:4", "keyword 'x'", "expected ';'");
}

BOOST_AUTO_TEST_CASE(missing_empty_and_binary_files) {
  TempDir tmp;
  const std::string missing = (tmp.path / "system/nothere").string();
  CHECK_ERROR(Dictionary::fromFile(missing), "cannot open file '" + missing + "'");
  CHECK_ERROR(Dictionary::fromFile(tmp.path.string()), "cannot open file");  // a folder
  const Dictionary absent = Dictionary::fromFileIfPresent(missing);
  BOOST_TEST(absent.empty());
  BOOST_TEST(absent.name() == missing);
  BOOST_TEST(Dictionary::fromFile(tmp.write("empty", "")).empty());
  const std::string bin = tmp.write("binary", std::string("a 1;\nb \0\x01\x02;\n", 12));
  CHECK_ERROR(Dictionary::fromFile(bin), "file '" + bin + "' is not a text file", "line 2");
  const std::string latin1 = tmp.write("latin1", "title caf\xe9;\n");
  CHECK_ERROR(Dictionary::fromFile(latin1), "file '" + latin1 + "' is not a text file", "UTF-8");
  // valid UTF-8 is fine, and columns count characters, not bytes
  const Dictionary u = Dictionary::fromFile(tmp.write("utf8", "title \"café\"; x 1;\n"));
  BOOST_TEST(u.getWord("title") == "café");
  BOOST_TEST(u.location("x").str().substr(u.location("x").str().size() - 5) == ":1:15");
}

// --------------------------------------------------------------------------- syntax errors

BOOST_AUTO_TEST_CASE(syntax_errors) {
  // missing ';' before the next line / before '}' / at the end of the file
  CHECK_ERROR(parse("deltaT 1e-4\nendTime 1;"), "case/system/testDict:1:12: keyword 'deltaT'",
              "expected ';' after the value", "'endTime' on the next line");
  CHECK_ERROR(parse("sub { a 1 }"), "testDict:1:10: keyword 'a'", "expected ';'", "found '}'");
  CHECK_ERROR(parse("a 1"), "testDict:1:4: keyword 'a'", "expected ';'", "end of the file");
  CHECK_ERROR(parse("a;"), "testDict:1:2: keyword 'a'", "expected a value before ';'");
  // unbalanced braces and parentheses
  CHECK_ERROR(parse("\nregions\n{\n  a { x 1; }\n"), "testDict:3:1: keyword 'regions'", "'{' is never closed");
  CHECK_ERROR(parse("a 1;\n}\n"), "testDict:2:1", "unexpected '}'");
  CHECK_ERROR(parse("v (1 2;\n"), "testDict:1:7: keyword 'v'", "expected ')'", "found ';'");
  CHECK_ERROR(parse("v (1 (2 3)\n"), "testDict:1:3: keyword 'v'", "'(' is never closed");
  CHECK_ERROR(parse("v 1 2);"), "testDict:1:6: keyword 'v'", "unexpected ')'");
  CHECK_ERROR(parse("v ]"), "testDict:1:3", "unexpected ']'");
  // unterminated string and comment
  CHECK_ERROR(parse("a 1;\ntitle \"never closed;\nb 2;\n"), "testDict:2:7", "string is never closed");
  CHECK_ERROR(parse("a 1;\n  /* never closed\n b 2;"), "testDict:2:3", "comment '/*' is never closed");
  // a value where a keyword should be
  CHECK_ERROR(parse("(1 2);"), "testDict:1:1", "expected a keyword, found '('");
  CHECK_ERROR(parse("a 1 { b 2; }"), "keyword 'a'", "expected ';'", "found '{'");
}

// --------------------------------------------------------------------------- read tracking

BOOST_AUTO_TEST_CASE(check_all_read_with_did_you_mean) {
  const Dictionary d = Dictionary::fromString(R"(
startTime 0;
endTime   1;
deltaT    0.1;
maxCO     0.2;
)", "system/controlDict");
  d.getScalar("startTime", dim::time);
  d.getScalar("endTime", dim::time);
  d.getScalar("deltaT", dim::time);
  d.getScalarOr("maxCo", 0.5, dim::none);  // looked up, absent: a candidate for the suggestion
  CHECK_ERROR(d.checkAllRead(), "system/controlDict:5:1: unknown keyword 'maxCO'; did you mean 'maxCo'?");
}

BOOST_AUTO_TEST_CASE(check_all_read_walks_sub_dictionaries_in_file_order) {
  const Dictionary d = parse(R"(
kernel { type cubicSpline; smoothingLengthRato 1.2; }
zzz 1;
)");
  // kernel never looked up: the keyword itself is unknown
  CHECK_ERROR(d.checkAllRead(), "testDict:2:1: unknown keyword 'kernel'");
  const Dictionary& k = d.subDict("kernel");
  k.getWord("type");
  k.getScalarOr("smoothingLengthRatio", 1.2, dim::none);
  // now the first unread keyword in file order is inside kernel
  CHECK_ERROR(d.checkAllRead(), "testDict:2:28: unknown keyword 'smoothingLengthRato'",
              "did you mean 'smoothingLengthRatio'?");
  k.markRead("smoothingLengthRato");
  CHECK_ERROR(d.checkAllRead(), "testDict:3:1: unknown keyword 'zzz'");
  // no close candidate: the keywords read here are listed instead
  const std::string msg = errorOf([&] { d.checkAllRead(); });
  BOOST_TEST(contains(msg, "keywords read here: kernel"));
  BOOST_TEST(!contains(msg, "did you mean"));
  d.found("zzz");
  BOOST_CHECK_NO_THROW(d.checkAllRead());
}

BOOST_AUTO_TEST_CASE(mark_all_read_silences_a_whole_tree) {
  const Dictionary d = parse("functions { a { type probes; typo 1; } b { x 1; } }\nother 1;\n");
  d.subDict("functions").markAllRead();
  CHECK_ERROR(d.checkAllRead(), "unknown keyword 'other'");
  d.found("other");
  BOOST_CHECK_NO_THROW(d.checkAllRead());
}

BOOST_AUTO_TEST_CASE(closest_match_rules) {
  const std::vector<std::string> c = {"maxCo", "maxDeltaT", "writeInterval"};
  BOOST_TEST(closestMatch("maxCO", c) == "maxCo");           // case-insensitive: distance 0
  BOOST_TEST(closestMatch("mxaCo", c) == "maxCo");           // a swap counts 1
  BOOST_TEST(closestMatch("writeIntervl", c) == "writeInterval");
  BOOST_TEST(closestMatch("wrteIntrvl", c) == "writeInterval");  // distance 3 <= 10/3
  BOOST_TEST(closestMatch("banana", c) == "");
  BOOST_TEST(closestMatch("ab", {"xy"}) == "xy");             // distance 2 <= max(2, 0)
  BOOST_TEST(closestMatch("abc", {"xyz"}) == "");             // distance 3 > 2
  BOOST_TEST(closestMatch("x", {}) == "");
}

BOOST_AUTO_TEST_CASE(repeated_keywords_and_merged_sub_dictionaries) {
  const Dictionary d = parse("a 1;\ns { x 1; y 2; }\na 2;\ns { y 3; z 4; }\n");
  BOOST_TEST(d.getInt("a") == 2);
  BOOST_TEST(d.location("a").line == 3);
  const Dictionary& s = d.subDict("s");
  BOOST_TEST(s.getInt("x") == 1);
  BOOST_TEST(s.getInt("y") == 3);
  BOOST_TEST(s.getInt("z") == 4);
  const std::vector<std::string> k = {"a", "s"};
  BOOST_TEST(d.keys() == k, boost::test_tools::per_element());
}
