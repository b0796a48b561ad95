// Declared parameters (core/Parameter.hpp): defaults, ranges (below, above,
// non-finite, sane magnitude; the message names keyword and file:line), old
// spellings read with a warning, option lists with did-you-mean, the values in
// effect and the generated tables.
#define BOOST_TEST_MODULE core_parameter
#include "core/Log.hpp"
#include "core/Parameter.hpp"
#include <boost/test/unit_test.hpp>
#include <functional>
#include <iostream>
#include <sstream>

using namespace shizuku;

namespace {

const ParameterGroup group("test/testDict: sub", "Parameters of this test.");
const ScalarParameter deltaT = group.scalar("deltaT", dim::time, "time step").required().min(1e-12);
const ScalarParameter maxCo = group.scalar("maxCo", dim::none, "Courant number").def(0.2).above(0).max(10);
const ScalarParameter nu = group.scalar("nu", dim::kinematicViscosity, "viscosity").def(0).min(0);
const IntParameter reuse = group.integer("amgReuse", "steps").def(10).min(1).oldName("reuseSteps");
const SwitchParameter scan = group.onOff("scanRegion", "stage 2").def(false);
const VectorParameter centre = group.vector("centre", dim::length, "centre").defZero("0 (the origin)");
const OptionParameter solver = group.option("solver", {"BiCGSTAB", "UMFPACK", "KLU"}, "solver").def("BiCGSTAB");

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// The message of reading parameter p from a dictionary "testDict" holding `text`.
template <class P>
std::string errorOfReading(const P& p, const char* text) {
  const Dictionary d = Dictionary::fromString(text, "testDict");
  return messageOf([&] { p.read(d); });
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// Standard output while running f (the log writes warnings there).
std::string captureLog(const std::function<void()>& f) {
  std::ostringstream out;
  auto* old = std::cout.rdbuf(out.rdbuf());
  f();
  std::cout.rdbuf(old);
  return out.str();
}

}  // namespace

BOOST_AUTO_TEST_CASE(defaults_when_absent) {
  const Dictionary d = Dictionary::fromString("deltaT 1e-3;\n", "testDict");
  BOOST_TEST(deltaT.read(d) == 1e-3);
  BOOST_TEST(maxCo.read(d) == 0.2);
  BOOST_TEST(reuse.read(d) == 10);
  BOOST_TEST(scan.read(d) == false);
  BOOST_TEST(solver.read(d) == "BiCGSTAB");
  BOOST_TEST(maxCo.read(nullptr) == 0.2);  // an absent sub-dictionary
  d.checkAllRead();
  // Recorded for -dryRun: value with unit, and whether defaulted.
  const std::string described = describeParametersInEffect();
  BOOST_TEST(contains(described, "[test/testDict: sub]"));
  BOOST_TEST(contains(described, "deltaT = 0.001 s\n"));
  BOOST_TEST(contains(described, "maxCo = 0.2 (default)"));
  BOOST_TEST(contains(described, "scanRegion = off (default)"));
}

BOOST_AUTO_TEST_CASE(required_missing_names_keyword) {
  const std::string m = errorOfReading(deltaT, "maxCo 0.5;\n");
  BOOST_TEST(contains(m, "testDict: keyword 'deltaT': missing"), m);
}

BOOST_AUTO_TEST_CASE(below_minimum_names_keyword_file_and_line) {
  const std::string m = errorOfReading(deltaT, "maxCo 0.5;\ndeltaT 1e-13;\n");
  BOOST_TEST(contains(m, "testDict:2:"), m);
  BOOST_TEST(contains(m, "keyword 'deltaT': 1e-13 is below the smallest allowed 1e-12 s"), m);
}

BOOST_AUTO_TEST_CASE(exclusive_minimum_and_maximum) {
  const Dictionary zero = Dictionary::fromString("maxCo 0;\n", "testDict");
  BOOST_TEST(contains(messageOf([&] { maxCo.read(zero); }), "testDict:1:1: keyword 'maxCo': 0 must be greater than 0"));
  const Dictionary big = Dictionary::fromString("maxCo 11;\n", "testDict");
  BOOST_TEST(contains(messageOf([&] { maxCo.read(big); }), "keyword 'maxCo': 11 is above the largest allowed 10"));
  const Dictionary ints = Dictionary::fromString("amgReuse 0;\n", "testDict");
  BOOST_TEST(contains(messageOf([&] { reuse.read(ints); }), "keyword 'amgReuse': 0 is below the smallest allowed 1"));
}

BOOST_AUTO_TEST_CASE(sane_magnitude_and_units) {
  const std::string m = errorOfReading(nu, "nu 1e300;\n");
  BOOST_TEST(contains(m, "keyword 'nu': 1e300 is beyond the physically sane magnitude 1e12 m^2/s"), m);
  // A unit is converted before the check and shown with the SI value.
  const Dictionary u = Dictionary::fromString("deltaT 1e-10 [ms];\n", "testDict");
  const std::string mu = messageOf([&] { deltaT.read(u); });
  BOOST_TEST(contains(mu, "keyword 'deltaT': 1e-10 [ms] (1e-13 s) is below the smallest allowed 1e-12 s"), mu);
}

BOOST_AUTO_TEST_CASE(non_finite_and_underflow_rejected_at_parse_time) {
  const std::string inf = messageOf([] { Dictionary::fromString("deltaT 1e999;\n", "testDict"); });
  BOOST_TEST(contains(inf, "testDict:1:8: keyword 'deltaT': the number 1e999 is out of range"), inf);
  const std::string tiny = messageOf([] { Dictionary::fromString("deltaT 1e-400;\n", "testDict"); });
  BOOST_TEST(contains(tiny, "testDict:1:8: keyword 'deltaT': the number 1e-400 is out of range (too small"), tiny);
  const std::string denormal = messageOf([] { Dictionary::fromString("deltaT 1e-310;\n", "testDict"); });
  BOOST_TEST(contains(denormal, "keyword 'deltaT': the number 1e-310 is out of range"), denormal);
  BOOST_TEST(Dictionary::fromString("x 0.0e-5;\n").getScalar("x", dim::none) == 0.0);  // a written zero stays zero
  const std::string nan = messageOf([] {
    const Dictionary d = Dictionary::fromString("maxCo nan;\n", "testDict");
    maxCo.read(d);
  });
  BOOST_TEST(contains(nan, "keyword 'maxCo': expected a dimensionless number"), nan);
}

BOOST_AUTO_TEST_CASE(old_spelling_reads_with_warning) {
  const Dictionary d = Dictionary::fromString("reuseSteps 4;\n", "testDict");
  int value = 0;
  const std::string log = captureLog([&] { value = reuse.read(d); });
  BOOST_TEST(value == 4);
  BOOST_TEST(contains(log, "Warning: testDict:1:1: keyword 'reuseSteps' is an old spelling; write 'amgReuse'"), log);
  d.checkAllRead();  // the old keyword counts as read
  const std::string m = errorOfReading(reuse, "reuseSteps 4;\namgReuse 5;\n");
  BOOST_TEST(contains(m, "keyword 'reuseSteps': is the old spelling of 'amgReuse', which is also given"), m);
}

BOOST_AUTO_TEST_CASE(option_list_did_you_mean) {
  const std::string m = errorOfReading(solver, "solver BiCGSTABB;\n");
  BOOST_TEST(contains(m, "testDict:1:1: keyword 'solver': 'BiCGSTABB' is not one of: BiCGSTAB | UMFPACK | KLU; "
                         "did you mean 'BiCGSTAB'?"), m);
  const Dictionary s = Dictionary::fromString("scanRegion maybe;\n", "testDict");
  BOOST_TEST(contains(messageOf([&] { scan.read(s); }), "keyword 'scanRegion': expected a switch"));
}

BOOST_AUTO_TEST_CASE(catalogue_and_table) {
  bool found = false;
  for (const auto& s : parameterScopes()) found = found || s == "test/testDict: sub";
  BOOST_TEST(found);
  const std::string t = keywordTableMarkdown("test/testDict: sub");
  BOOST_TEST(contains(t, "| keyword | default | range | meaning |"), t);
  BOOST_TEST(contains(t, "| `deltaT` | required | [1e-12, 1e12] s | time step |"), t);
  BOOST_TEST(contains(t, "| `maxCo` | 0.2 | (0, 10] | Courant number |"), t);
  BOOST_TEST(contains(t, "| `nu` | 0 m^2/s | [0, 1e12] m^2/s | viscosity |"), t);
  BOOST_TEST(contains(t, "| `amgReuse` | 10 | >= 1 | steps (old spelling `reuseSteps` still read) |"), t);
  BOOST_TEST(contains(t, "| `solver` | BiCGSTAB | BiCGSTAB \\| UMFPACK \\| KLU | solver |"), t);
  BOOST_TEST(keywordTableMarkdown("no such scope").empty());
}

BOOST_AUTO_TEST_CASE(vectors_default_and_range) {
  const Dictionary absent = Dictionary::fromString("", "testDict");
  BOOST_TEST(centre.read<2>(absent).isZero());
  const Dictionary d = Dictionary::fromString("centre (1 2) [cm];\n", "testDict");
  BOOST_TEST(centre.read<2>(d)[1] == 0.02);
  const Dictionary far = Dictionary::fromString("centre (0 1e13);\n", "testDict");
  const std::string m = messageOf([&] { centre.read<2>(far); });
  BOOST_TEST(contains(m, "testDict:1:1: keyword 'centre': 1e13 m is beyond the physically sane magnitude 1e12 m"), m);
  BOOST_TEST(contains(keywordTableMarkdown("test/testDict: sub"), "| `centre` | 0 (the origin) | [-1e12, 1e12] m | centre |"));
}
