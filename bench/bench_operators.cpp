// Benchmark of the per-step numerics (docs/method.md 13 steps 1 and 4): nanoseconds
// per particle for the cell-linked-list neighbour search and for the SPH2
// weights (FI with fallback chain), at ~10k and ~100k particles, 1 and 2
// threads, 2D and 3D, on a lattice with +-0.1 d0 random disorder, h = 1.2 d0,
// cubic spline, particles reordered by cellOrder() first (as the solver does).
// Wall time is the best of `repeats` runs; CPU time (all threads, process
// clock) is reported too, since on a shared machine the wall time of the
// 2-thread runs depends on the load.
// Prints a table and writes CSV to argv[1] (default bench_operators.csv).
// Usage: bench_operators [out.csv] [repeats]
#include "kernels/Kernel.hpp"
#include "operators/DerivativeOperator.hpp"
#include "particles/NeighbourList.hpp"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <omp.h>
#include <random>
#include <ctime>
#include <string>

using namespace shizuku;

namespace {

template <int D>
std::vector<Vec<D>> disorderedLattice(std::size_t target, double d0, double eps) {
  const int n = int(std::lround(std::pow(double(target), 1.0 / D)));
  std::mt19937 gen(42);
  std::uniform_real_distribution<double> u(-eps * d0, eps * d0);
  std::vector<Vec<D>> x;
  const int nz = D == 3 ? n : 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        Vec<D> p;
        p[0] = i * d0 + u(gen);
        p[1] = j * d0 + u(gen);
        if constexpr (D == 3) p[2] = k * d0 + u(gen);
        x.push_back(p);
      }
  return x;
}

double cpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

struct Timing {
  double wall, cpu;  // best wall seconds, mean CPU seconds per run
};

template <class F>
Timing measure(int repeats, F&& f) {
  double best = 1e300;
  const double c0 = cpuSeconds();
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    const auto t1 = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double>(t1 - t0).count());
  }
  return {best, (cpuSeconds() - c0) / repeats};
}

struct Row {
  int dim, threads;
  std::size_t particles;
  double neighbours, searchNs, weightsNs, searchCpuNs, weightsCpuNs;
};

template <int D>
Row bench(std::size_t target, int threads, int repeats) {
  const double d0 = 0.01;
  auto x = disorderedLattice<D>(target, d0, 0.1);
  Kernel<D> kernel(KernelType::cubicSpline, 1.2 * d0);
  NeighbourSearch<D> search(kernel.support());
  const auto perm = search.cellOrder(x);
  std::vector<Vec<D>> y(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) y[k] = x[perm[k]];
  x.swap(y);
  omp_set_num_threads(threads);
  NeighbourList<D> nl;
  PairWeights<D> pw;
  auto op = DerivativeOperator<D>::create(DerivativeScheme::SPH2);
  const double V = std::pow(d0, D);
  search.build(x, nl);  // warm-up: buffers reach their capacity
  op->computeWeights(kernel, V, nl, {}, pw);
  const Timing ts = measure(repeats, [&] { search.build(x, nl); });
  const Timing tw = measure(repeats, [&] { op->computeWeights(kernel, V, nl, {}, pw); });
  const double n = double(x.size()), ns = 1e9 / n;
  return {D, threads, x.size(), double(nl.numPairs()) / n, ts.wall * ns, tw.wall * ns, ts.cpu * ns, tw.cpu * ns};
}

}  // namespace

int main(int argc, char** argv) {
  const std::string csv = argc > 1 ? argv[1] : "bench_operators.csv";
  const int repeats = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
  std::vector<Row> rows;
  for (int dim : {2, 3})
    for (std::size_t n : {10000u, 100000u})
      for (int threads : {1, 2}) rows.push_back(dim == 2 ? bench<2>(n, threads, repeats) : bench<3>(n, threads, repeats));
  std::printf("%-4s %-10s %-8s %-11s %-13s %-13s %-13s %-11s %-11s\n", "dim", "particles", "threads", "neighbours",
              "search ns/p", "SPH2 ns/p", "total ns/p", "search cpu", "SPH2 cpu");
  std::ofstream out(csv);
  out << "dim,particles,threads,neighbours_per_particle,search_ns_per_particle,sph2_weights_ns_per_particle,"
         "total_ns_per_particle,search_cpu_ns_per_particle,sph2_weights_cpu_ns_per_particle\n";
  for (const Row& r : rows) {
    std::printf("%-4d %-10zu %-8d %-11.1f %-13.1f %-13.1f %-13.1f %-11.1f %-11.1f\n", r.dim, r.particles, r.threads,
                r.neighbours, r.searchNs, r.weightsNs, r.searchNs + r.weightsNs, r.searchCpuNs, r.weightsCpuNs);
    out << r.dim << ',' << r.particles << ',' << r.threads << ',' << r.neighbours << ',' << r.searchNs << ','
        << r.weightsNs << ',' << r.searchNs + r.weightsNs << ',' << r.searchCpuNs << ',' << r.weightsCpuNs << '\n';
  }
  std::printf("CSV written to %s\n", csv.c_str());
  return 0;
}
