// Function objects as the solver drives them (docs/design.md 1.3): built only when
// listed in `functions`, unknown types and misspelt keys rejected, sampling by
// their own writeControl/writeInterval, files under
// postProcessing/<name>/<startTime>/ with `#` column and unit headers and rows
// of the expected values, histogram folders at write times, a restarted run
// writing under its own start time without touching the old files, timing rows
// from the stage timers (and nothing in post-processing).
#define BOOST_TEST_MODULE functionObjects_files
#include <boost/test/unit_test.hpp>

#include "functionObjects/FunctionObjectFactory.hpp"
#include "functionObjects/Probes.hpp"
#include "functionObjects/SampleControl.hpp"
#include "particles/NeighbourList.hpp"
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace shizuku;
namespace fs = std::filesystem;

namespace {

Dictionary dict(const std::string& text) { return Dictionary::fromString(text); }

// 6 x 6 fluid lattice, spacing 0.1, centred at the origin, uniform velocity (1 2),
// pressure 7, density rho0 (so every density error is 0), all interior.
FlowState<2> smallState() {
  FlowState<2> s;
  s.d0 = 0.1;
  s.h = 0.12;
  s.kernel = Kernel<2>(KernelType::cubicSpline, s.h);
  s.rho0 = 1000;
  auto& p = s.particles;
  for (int k = 0; k < 36; ++k) p.position.push_back(Vec<2>((k % 6 - 2.5) * 0.1, (k / 6 - 2.5) * 0.1));
  p.resize(36);
  for (std::size_t i = 0; i < 36; ++i) {
    p.type[i] = std::uint8_t(ParticleType::fluid);
    p.surface[i] = std::uint8_t(SurfaceClass::interior);
    p.velocity[i] = Vec<2>(1, 2);
    p.pressure[i] = 7;
    p.density[i] = s.rho0;
  }
  p.rho0 = s.rho0;
  p.mass = s.rho0 / s.kernel.latticeSum(s.d0);
  s.isFluidMask.assign(36, 1);
  return s;
}

struct TempCase {
  std::string dir;
  TempCase() {
    dir = (fs::temp_directory_path() / ("shizuku_fo_" + std::to_string(getpid()))).string();
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~TempCase() { fs::remove_all(dir); }
};

std::string readFile(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

// Data rows (non-# lines).
std::vector<std::string> rows(const std::string& path) {
  std::vector<std::string> out;
  std::istringstream in(readFile(path));
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') out.push_back(line);
  return out;
}

std::string columnsLine(const std::string& path) {
  std::istringstream in(readFile(path));
  for (std::string line; std::getline(in, line);)
    if (line.rfind("# columns:", 0) == 0) return line;
  return "";
}

// Drive a list through steps 0..n-1 at t = step dt, write times every `writeEvery` steps.
void run(std::vector<std::unique_ptr<FunctionObject<2>>>& list, FlowState<2>& s, const RunInfo& base, long first,
         long n, double dt, long writeEvery) {
  RunInfo info = base;
  s.dt = dt;
  for (auto& fo : list) {
    s.step = first;
    s.time = first * dt;
    fo->start(s, info);
  }
  for (long k = first; k < first + n; ++k) {
    s.step = k;
    s.time = k * dt;
    info.isWriteTime = k % writeEvery == 0;
    for (auto& fo : list) fo->execute(s, info);
  }
  for (auto& fo : list) fo->end();
}

}  // namespace

BOOST_AUTO_TEST_CASE(only_listed_objects_are_built) {
  BOOST_TEST(createFunctionObjects<2>(nullptr).empty());
  auto empty = dict("");
  BOOST_TEST(createFunctionObjects<2>(&empty).empty());
  auto d = dict("functions { cons { type conservation; } box { type fluidExtent; writeControl writeTime; } }");
  auto list = createFunctionObjects<2>(&d.subDict("functions"));
  BOOST_REQUIRE(list.size() == 2);
  BOOST_TEST(list[0]->name() == "cons");
  BOOST_TEST(list[0]->type() == "conservation");
  BOOST_TEST(list[1]->type() == "fluidExtent");
  BOOST_TEST(list[1]->describe().find("at write times") != std::string::npos);
  d.checkAllRead();  // every key was read
  auto l3 = createFunctionObjects<3>(&d.subDict("functions"));
  BOOST_TEST(l3.size() == 2);
}

BOOST_AUTO_TEST_CASE(bad_function_dictionaries) {
  auto unknownType = dict("functions { a { type conservaton; } }");
  try {
    createFunctionObjects<2>(&unknownType.subDict("functions"));
    BOOST_FAIL("unknown type accepted");
  } catch (const InputError& e) {
    BOOST_TEST_MESSAGE(e.what());
    BOOST_TEST(std::string(e.what()).find("conservation") != std::string::npos);  // did you mean
  }
  auto notDict = dict("functions { a conservation; }");
  BOOST_CHECK_THROW(createFunctionObjects<2>(&notDict.subDict("functions")), InputError);
  auto misspelt = dict("functions { a { type conservation; writeIntervall 3; } }");
  auto l = createFunctionObjects<2>(&misspelt.subDict("functions"));
  BOOST_CHECK_THROW(misspelt.checkAllRead(), InputError);
  auto badControl = dict("functions { a { type conservation; writeControl sometimes; } }");
  BOOST_CHECK_THROW(createFunctionObjects<2>(&badControl.subDict("functions")), InputError);
  auto badInterval = dict("functions { a { type conservation; writeControl timeStep; writeInterval 0; } }");
  BOOST_CHECK_THROW(createFunctionObjects<2>(&badInterval.subDict("functions")), InputError);
  auto badHist = dict("functions { a { type densityError; histogram { min 1; max -1; } } }");
  BOOST_CHECK_THROW(createFunctionObjects<2>(&badHist.subDict("functions")), InputError);
}

BOOST_AUTO_TEST_CASE(sample_control) {
  // timeStep 3: steps 0, 3, 6, 9 (and the first call, here step 0)
  {
    auto d = dict("writeControl timeStep; writeInterval 3;");
    auto c = SampleControl::read(d);
    std::vector<long> got;
    for (long k = 0; k < 10; ++k)
      if (c.due(k * 0.1, 0.1, k, false)) got.push_back(k);
    BOOST_TEST(got == std::vector<long>({0, 3, 6, 9}), boost::test_tools::per_element());
  }
  // runTime 0.1 with dt 0.03 accumulated by addition: 0, then the first time at or past each multiple
  {
    auto d = dict("writeControl runTime; writeInterval 0.1;");
    auto c = SampleControl::read(d);
    std::vector<long> got;
    double t = 0;
    for (long k = 0; k < 12; ++k, t += 0.03)
      if (c.due(t, 0.03, k, false)) got.push_back(k);
    // t_k = 0.03 k: 0 | 0.12 (k=4) | 0.21 (k=7) | 0.30 (k=10, 0.29999999999999999 by addition)
    BOOST_TEST(got == std::vector<long>({0, 4, 7, 10}), boost::test_tools::per_element());
  }
  // restart at step 7 (t = 0.7): its first call samples, then every 0.5 s multiple
  {
    auto d = dict("writeControl adjustableRunTime; writeInterval 0.5;");
    auto c = SampleControl::read(d);
    std::vector<long> got;
    for (long k = 7; k < 16; ++k)
      if (c.due(k * 0.1, 0.1, k, false)) got.push_back(k);
    BOOST_TEST(got == std::vector<long>({7, 10, 15}), boost::test_tools::per_element());
  }
  // writeTime
  {
    auto d = dict("writeControl writeTime;");
    auto c = SampleControl::read(d);
    std::vector<long> got;
    for (long k = 0; k < 10; ++k)
      if (c.due(k * 0.1, 0.1, k, k == 5)) got.push_back(k);
    BOOST_TEST(got == std::vector<long>({0, 5}), boost::test_tools::per_element());
  }
}

BOOST_AUTO_TEST_CASE(files_headers_rows_and_restart) {
  TempCase tc;
  auto s = smallState();
  auto d = dict(
      "functions {\n"
      "  probe { type probes; fields (p U); points ((0.05 0.05) (3 3)); }\n"
      "  dErr  { type densityError; writeControl timeStep; writeInterval 2; }\n"
      "  cons  { type conservation; writeControl runTime; writeInterval 0.25; }\n"
      "  box   { type fluidExtent; writeControl writeTime; }\n"
      "}");
  auto list = createFunctionObjects<2>(&d.subDict("functions"));
  RunInfo info;
  info.caseDir = tc.dir;
  info.startTimeName = "0";
  run(list, s, info, 0, 10, 0.1, 4);  // steps 0..9, t = 0..0.9, write times at steps 0, 4, 8
  const std::string pp = tc.dir + "/postProcessing/";

  // probes: one file per field; every step; (x y) vectors; nan outside
  BOOST_TEST(columnsLine(pp + "probe/0/p") == "# columns: time point0 point1");
  BOOST_TEST(readFile(pp + "probe/0/p").find("# units:   s    Pa     Pa") != std::string::npos);
  auto pr = rows(pp + "probe/0/p");
  BOOST_REQUIRE(pr.size() == 10);
  BOOST_TEST(pr[3] == "0.3 7 nan");  // Shepard interpolation of a constant is the constant (to round-off)
  auto ur = rows(pp + "probe/0/U");
  BOOST_REQUIRE(ur.size() == 10);
  BOOST_TEST(ur[0] == "0 (1 2) (nan nan)");
  BOOST_TEST(readFile(pp + "probe/0/U").find("point1 (3 3) m") != std::string::npos);

  // densityError: every 2 steps; all errors 0; mode = centre of the bin holding 0
  BOOST_TEST(columnsLine(pp + "dErr/0/densityError.dat") ==
             "# columns: time mean rms max mode meanAll rmsAll maxAll modeAll");
  auto dr = rows(pp + "dErr/0/densityError.dat");
  BOOST_REQUIRE(dr.size() == 5);
  BOOST_TEST(dr[1] == "0.2 0 0 0 0.125 0 0 0 0.125");
  // histograms at the samples that are write times: steps 0, 4, 8
  for (const char* t : {"0", "0.4", "0.8"}) {
    const std::string h = pp + "dErr/0/" + t + "/histogram.dat";
    BOOST_TEST_REQUIRE(fs::exists(h), h);
    auto hr = rows(h);
    BOOST_REQUIRE(hr.size() == 80);
    BOOST_TEST(hr[40] == "0.125 36 36");
    BOOST_TEST(hr[0] == "-9.875 0 0");
    BOOST_TEST(columnsLine(h) == "# columns: binCentre countInterior countAll");
  }
  BOOST_TEST(!fs::exists(pp + "dErr/0/0.2"));

  // conservation: runTime 0.25 -> t = 0, 0.3, 0.5, 0.8
  BOOST_TEST(columnsLine(pp + "cons/0/conservation.dat") ==
             "# columns: time volume nominalVolume kineticEnergy momentum angularMomentum fluidMass removedMass "
             "fluidVolume");
  BOOST_TEST(readFile(pp + "cons/0/conservation.dat").find("m^2") != std::string::npos);
  auto cr = rows(pp + "cons/0/conservation.dat");
  BOOST_REQUIRE(cr.size() == 4);
  BOOST_TEST(cr[2].rfind("0.5 ", 0) == 0);
  {
    // values: KE = 0.5 m 36 |(1 2)|^2, momentum 36 m (1 2), angular momentum sum m x cross u = 0 (symmetric)
    const double m = s.particles.mass;
    std::istringstream in(cr[2]);
    double t, vol, nom, ke, px, py, lz;
    char paren;
    in >> t >> vol >> nom >> ke >> paren >> px >> py >> paren >> lz;
    BOOST_TEST(std::abs(vol - 36 * m / 1000) < 1e-11 * vol);  // printed with 12 digits
    BOOST_TEST(std::abs(nom - vol) < 1e-11 * vol);
    BOOST_TEST(std::abs(ke - 0.5 * m * 36 * 5) < 1e-11 * ke);
    BOOST_TEST(std::abs(px - 36 * m) < 1e-11 * px);
    BOOST_TEST(std::abs(py - 72 * m) < 1e-11 * py);
    BOOST_TEST(std::abs(lz) < 1e-12 * m);
  }

  // fluidExtent at write times
  auto er = rows(pp + "box/0/extent.dat");
  BOOST_REQUIRE(er.size() == 3);
  BOOST_TEST(er[1] == "0.4 (-0.25 -0.25) (0.25 0.25)");
  BOOST_TEST(columnsLine(pp + "box/0/extent.dat") == "# columns: time min max");

  // restart from t = 0.5: a new folder; the old files are untouched
  const std::string before = readFile(pp + "cons/0/conservation.dat");
  const std::string beforeP = readFile(pp + "probe/0/p");
  auto list2 = createFunctionObjects<2>(&d.subDict("functions"));
  info.startTimeName = "0.5";
  run(list2, s, info, 5, 3, 0.1, 4);
  BOOST_TEST(readFile(pp + "cons/0/conservation.dat") == before);
  BOOST_TEST(readFile(pp + "probe/0/p") == beforeP);
  auto r2 = rows(pp + "cons/0.5/conservation.dat");
  BOOST_REQUIRE(r2.size() == 1);  // t = 0.5 (the start), then 0.6, 0.7 in the same interval
  BOOST_TEST(r2[0].rfind("0.5 ", 0) == 0);
  BOOST_TEST(rows(pp + "probe/0.5/p").size() == 3);
  BOOST_TEST(rows(pp + "dErr/0.5/densityError.dat").size() == 2);  // steps 5 (start), 6
}

BOOST_AUTO_TEST_CASE(post_processing_samples_every_call) {
  TempCase tc;
  auto s = smallState();
  auto d = dict("functions { e { type fluidExtent; writeControl runTime; writeInterval 100; } "
                "t { type timing; } }");
  auto list = createFunctionObjects<2>(&d.subDict("functions"));
  RunInfo info;
  info.caseDir = tc.dir;
  info.startTimeName = "0.2";
  info.postProcessing = true;
  info.isWriteTime = true;
  run(list, s, info, 2, 3, 0.1, 1);
  BOOST_TEST(rows(tc.dir + "/postProcessing/e/0.2/extent.dat").size() == 3);
  // timing without timers (post-processing): no file at all
  BOOST_TEST(!fs::exists(tc.dir + "/postProcessing/t"));
}

BOOST_AUTO_TEST_CASE(timing_rows) {
  TempCase tc;
  auto s = smallState();
  auto d = dict("functions { cpu { type timing; writeControl timeStep; writeInterval 2; } }");
  auto list = createFunctionObjects<2>(&d.subDict("functions"));
  StageTimers timers;
  const int a = timers.stage("neighbours"), b = timers.stage("pressure");
  RunInfo info;
  info.caseDir = tc.dir;
  info.startTimeName = "0";
  info.timers = &timers;
  s.dt = 0.1;
  list[0]->start(s, info);
  for (long k = 0; k <= 4; ++k) {
    s.step = k;
    s.time = 0.1 * k;
    info.wallSeconds = 0.5 * k;
    info.particleSteps = 36.0 * k;
    list[0]->execute(s, info);  // samples at 0 (baseline only), 2, 4
    timers.add(a, 0.125);       // the step k -> k+1
    timers.add(b, 0.25);
  }
  const std::string f = tc.dir + "/postProcessing/cpu/0/timing.dat";
  BOOST_TEST(columnsLine(f) == "# columns: time neighbours pressure particleStepsPerSecond");
  auto r = rows(f);
  BOOST_REQUIRE(r.size() == 2);
  // two steps per interval: 0.25 s and 0.5 s in the stages; 72 particle-steps in 1 s of wall time
  BOOST_TEST(r[0] == "0.2 0.25 0.5 72");
  BOOST_TEST(r[1] == "0.4 0.25 0.5 72");
  BOOST_TEST(timers.sinceLastSample()[0] == 0.625);  // the shared timers are not reset
}
