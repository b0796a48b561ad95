// Pressure-solver benchmark: records the PPE systems (A, b and
// the warm-start guess) that a real run of a case produces, then solves the same
// sequence with every candidate backend and thread count, timing each solve
// (wall: best of `passes` passes; CPU: process clock, all threads, mean).
// The case (2D or 3D, from its particlesDict) is run by Simulation::run (so particles are reordered by cell as in a
// real run) with the case's own sphSolution; systems of steps > warmup are kept.
// Usage:
//   bench_pressure CASE WARMUP RECORD OUT.csv THREADS(1,2) PASSES LABEL=DICT [LABEL=DICT ...]
//   e.g. "ILU0=solver BiCGSTAB; preconditioner ILU0;"  "KLU=solver KLU;"  "AMG=solver BiCGSTAB; preconditioner AMG; amgReuse 1;"
// Appends one CSV row per (label, threads): case,unknowns,nnz,label,threads,
// wallMs,cpuMs,iterations,maxResidual,failures.
#include "core/Log.hpp"
#include "isph/CaseFiles.hpp"
#include "isph/Simulation.hpp"
#include "linearSolvers/LinearSolver.hpp"
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <omp.h>
#include <sstream>

using namespace shizuku;

namespace {

struct System {
  SparseMatrixR A;
  Eigen::VectorXd b, x0;
};

std::vector<System> recorded;
long calls = 0, warmup = 0, toRecord = 0;

class RecordingSolver final : public LinearSolver {
 public:
  explicit RecordingSolver(std::unique_ptr<LinearSolver> s) : s_(std::move(s)) {}
  std::string name() const override { return s_->name(); }
  std::string describe() const override { return s_->describe() + " [recording]"; }
  LinearSolveResult solve(const SparseMatrixR& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    ++calls;
    if (calls > warmup && long(recorded.size()) < toRecord) recorded.push_back({A, b, x});
    return s_->solve(A, b, x);
  }

 private:
  std::unique_ptr<LinearSolver> s_;
};

double cpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}
double wallSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 8) {
    std::fprintf(stderr, "usage: bench_pressure CASE WARMUP RECORD OUT.csv THREADS PASSES LABEL=DICT...\n");
    return 1;
  }
  const std::string caseDir = argv[1];
  warmup = std::atol(argv[2]);
  toRecord = std::atol(argv[3]);
  const std::string out = argv[4];
  std::vector<int> threads;
  {
    std::stringstream ss(argv[5]);
    std::string t;
    while (std::getline(ss, t, ',')) threads.push_back(std::stoi(t));
  }
  const int passes = std::max(1, std::atoi(argv[6]));
  LinearSolver::setCreateHook([](const Dictionary* d) {
    return std::make_unique<RecordingSolver>(LinearSolver::createBuiltin(d));
  });
  Log::get().quiet = true;
  {
    SimulationOptions opt;
    opt.functionObjects = false;
    opt.threads = threads.back();
    if (caseDimension(caseDir) == 3) Simulation<3>(caseDir, opt).run();
    else Simulation<2>(caseDir, opt).run();
  }
  LinearSolver::setCreateHook({});
  if (recorded.empty()) { std::fprintf(stderr, "no system recorded\n"); return 1; }
  const long n = recorded.back().A.rows(), nnz = recorded.back().A.nonZeros();
  std::ofstream csv(out, std::ios::app);
  for (int a = 7; a < argc; ++a) {
    const std::string spec = argv[a];
    const auto eq = spec.find('=');
    const std::string label = spec.substr(0, eq);
    const Dictionary dict = Dictionary::fromString(spec.substr(eq + 1), label);
    for (int T : threads) {
      omp_set_num_threads(T);
      auto solver = LinearSolver::createBuiltin(&dict);
      std::vector<double> best(recorded.size(), 1e300);
      double cpu = 0, its = 0, maxRes = 0;
      long failures = 0;
      Eigen::VectorXd x;
      for (int pass = 0; pass < passes; ++pass)
        for (std::size_t k = 0; k < recorded.size(); ++k) {
          const System& s = recorded[k];
          x = s.x0;
          const double w0 = wallSeconds(), c0 = cpuSeconds();
          const LinearSolveResult r = solver->solve(s.A, s.b, x);
          const double w1 = wallSeconds(), c1 = cpuSeconds();
          best[k] = std::min(best[k], w1 - w0);
          if (pass == passes - 1) {
            cpu += c1 - c0;
            its += r.iterations;
            maxRes = std::max(maxRes, r.residual);
            failures += !r.ok || r.usedFallback;
          }
        }
      double wall = 0;
      for (double b : best) wall += b;
      const double m = double(recorded.size());
      std::printf("%-10s n %7ld nnz %8ld %-14s T %d  wall %9.3f ms  cpu %9.3f ms  it %6.1f  res %.1e%s\n",
                  caseDir.substr(caseDir.find_last_of('/') + 1).c_str(), n, nnz, label.c_str(), T,
                  1e3 * wall / m, 1e3 * cpu / m, its / m, maxRes, failures ? "  FAILED" : "");
      std::fflush(stdout);
      csv << caseDir.substr(caseDir.find_last_of('/') + 1) << ',' << n << ',' << nnz << ',' << label << ',' << T
          << ',' << 1e3 * wall / m << ',' << 1e3 * cpu / m << ',' << its / m << ',' << maxRes << ',' << failures
          << '\n';
    }
  }
  return 0;
}
