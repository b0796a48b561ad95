// postProcessing/<name>/<startTime>/<file> (docs/design.md 1.3): folders created,
// '#' header lines with column names and units, one row per sample flushed at
// once (readable while the writer is still open), a rerun from the same start
// time replaces its own file, a restart with another start time never touches
// earlier files.
#define BOOST_TEST_MODULE io_postProcessing
#include <boost/test/unit_test.hpp>
#include "io/PostProcessingFile.hpp"
#include "test_io_helpers.hpp"
#include <cmath>
#include <fstream>
#include <sstream>

using namespace shizuku;
using namespace shizuku::iotest;

BOOST_AUTO_TEST_CASE(headerAndFlushedRows) {
  ScratchDir c;
  PostProcessingFile f(c.path, "densityError", "0", "densityError.dat");
  BOOST_TEST(f.path() == c.path + "/postProcessing/densityError/0/densityError.dat");
  f.comment("density error of eq. 22 over fluid particles");
  f.columns({"time", "mean", "rms"}, {"s", "%", "%"});
  f.row(0.1, {1.5, std::nan("")});
  // Flushed: the whole content is on disk while f is still open.
  BOOST_TEST(slurp(f.path()) ==
             "# density error of eq. 22 over fluid particles\n"
             "# columns: time mean rms\n"
             "# units:   s    %    %\n"
             "0.1 1.5 nan\n");
  f.row("0.2 " + PostProcessingFile::vector<2>(Vec<2>(1.0 / 3.0, -2e-20)));
  BOOST_TEST(slurp(f.path()).substr(slurp(f.path()).rfind("0.2")) == "0.2 (0.333333333333 -2e-20)\n");
}

BOOST_AUTO_TEST_CASE(startTimesAreSeparate) {
  ScratchDir c;
  { PostProcessingFile f(c.path, "probes", "0", "p"); f.row(0.0, {1}); f.row(0.1, {2}); }
  // A restart from 0.1 writes beside, not over.
  { PostProcessingFile f(c.path, "probes", "0.1", "p"); f.row(0.2, {3}); }
  BOOST_TEST(slurp(c.path + "/postProcessing/probes/0/p") == "0 1\n0.1 2\n");
  BOOST_TEST(slurp(c.path + "/postProcessing/probes/0.1/p") == "0.2 3\n");
  // A rerun from 0 replaces its own file only.
  { PostProcessingFile f(c.path, "probes", "0", "p"); f.row(0.0, {9}); }
  BOOST_TEST(slurp(c.path + "/postProcessing/probes/0/p") == "0 9\n");
  BOOST_TEST(slurp(c.path + "/postProcessing/probes/0.1/p") == "0.2 3\n");
}

BOOST_AUTO_TEST_CASE(subfoldersAndErrors) {
  ScratchDir c;
  { PostProcessingFile f(c.path, "densityError", "0", "histogram/0.1.dat"); f.row("x"); }
  BOOST_TEST(slurp(c.path + "/postProcessing/densityError/0/histogram/0.1.dat") == "x\n");
  std::ofstream(c.path + "/postProcessing/blocked") << "a file where a folder should go";
  BOOST_CHECK_EXCEPTION(PostProcessingFile(c.path, "blocked", "0", "a.dat"), std::runtime_error,
                        [&](const std::runtime_error& e) {
                          return std::string(e.what()).find(c.path + "/postProcessing/blocked") != std::string::npos;
                        });
  BOOST_CHECK_THROW(PostProcessingFile f(c.path, "x", "0", "a.dat"); f.columns({"a", "b"}, {"s"}), std::runtime_error);
}
