// Deterministic parallel sums over particles: particles are cut into fixed
// blocks of 4096, each block is summed in index order (blocks in parallel,
// OpenMP), then the block sums are added in block order. The result is the
// same to the last bit for any number of threads, so a live run and
// shizukuPostProcess print identical numbers from identical states.
// `partial` is a reused buffer (no allocation once it has the capacity).
// Acc must value-initialise to zero and provide operator+=.
// Dictionary keys read: none.
#pragma once
#include <algorithm>
#include <cstddef>
#include <vector>

namespace shizuku {

template <class Acc, class AddFn>
Acc blockReduce(std::size_t n, std::vector<Acc>& partial, AddFn&& add) {
  constexpr std::size_t block = 4096;
  const long nb = long((n + block - 1) / block);
  partial.assign(std::size_t(nb), Acc{});
#pragma omp parallel for schedule(static)
  for (long b = 0; b < nb; ++b) {
    Acc a{};
    const std::size_t end = std::min(n, std::size_t(b + 1) * block);
    for (std::size_t i = std::size_t(b) * block; i < end; ++i) add(a, i);
    partial[std::size_t(b)] = a;
  }
  Acc total{};
  for (const Acc& a : partial) total += a;
  return total;
}

}  // namespace shizuku
