// Which rank owns which particle (docs/parallel.md 3): Zoltan's geometric partitioners,
// recursive coordinate bisection (RCB, the default) or the Hilbert space-filling curve
// (HSFC), on the particles' positions, every particle weighing one (the cost of a step
// is nearly proportional to the particle count). The cuts are kept, so that a particle
// that moved is assigned to the rank whose region now holds it without a new partition
// (point assignment); a repartition starts from the current one and moves few particles.
// Knows coordinates and ids, not particles. Reads no dictionary keys (the method comes
// from system/decomposeParDict through DomainDecomposition).
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace shizuku {

class ZoltanPartitioner {
 public:
  // method: "RCB" or "HSFC"; dim: 2 or 3. Needs MPI started (Communicator::start).
  ZoltanPartitioner(const std::string& method, int dim);
  ~ZoltanPartitioner();
  ZoltanPartitioner(const ZoltanPartitioner&) = delete;
  ZoltanPartitioner& operator=(const ZoltanPartitioner&) = delete;

  // The rank each of this rank's n objects belongs to (coordinates x[k*dim + a], ids
  // unique across ranks). `fromScratch`: a first partition; otherwise a repartition
  // that moves as few objects as it can. Collective.
  void partition(const std::vector<double>& x, const std::vector<std::int64_t>& ids, bool fromScratch,
                 std::vector<int>& owner);
  // The rank whose region holds point x (the cuts of the last partition); local.
  int ownerOf(const double* x) const;
  const std::string& method() const { return method_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string method_;
};

}  // namespace shizuku
