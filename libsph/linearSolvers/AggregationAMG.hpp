// Smoothed-aggregation algebraic multigrid preconditioner for the PPE
// (docs/method.md 4.2), OpenMP-parallel in every per-cycle
// operation, no external library. One V-cycle per application:
//   setup (every `reuse` steps, or when the numbering or size changes, or when
//   the iteration count grew past 1.5x (+2) the count right after a setup):
//     strong couplings: |a_ij| >= 0.25 max_k |a_ik| row by row (none in rows whose
//     off-diagonal mass is below 0.1 |a_ii|); greedy aggregation (root + strong
//     neighbours, then leftovers join the aggregate of their largest-coupled
//     neighbour); tentative prolongation P0 = aggregate indicator; smoothed
//     P = (I - omega D^-1 A) P0, omega = 0.8, each row truncated to its entries of
//     at least 0.2 of its largest (and its own aggregate's, so that no aggregate loses
//     its column) and rescaled to its sum; restriction R = P^T; coarse
//     A_c = R A P; recursively until <= 400 unknowns, or until the aggregation
//     stalls on a larger level (a flow broken into many small clusters: a dispersed
//     splash); the coarsest level is solved by a sparse LU (KLU, KLUFactor.hpp: on the
//     K&O 20k systems' coarsest level, about 300 rows of 17 entries, 0.40-0.60 ms a
//     factorisation against 1.09-1.60 for a dense LU, 8-11 us a solve against 14-22).
//     Rows with no off-diagonal entry (p = 0 rows) are left out of the coarse grids.
//   cycle: one Gauss-Seidel sweep forward before and backward after the coarse
//     correction, split between the threads by row blocks, the rows that couple blocks
//     visited last where that pays (HybridGaussSeidel.hpp); the residual after the first
//     sweep from the entries after each row's diagonal where the sweep makes that exact
//     (about half the matrix: K&O 20k systems, two threads, 9 % less time a solve). The finest level always uses the current
//     matrix; the coarse levels are kept from the last setup (the matrix changes
//     little from one step to the next).
// Levels below 2048 rows run on one thread. The setup's products (P, R = P^T and
// A_c = R (A P), the last without storing A P) are SparseProducts' row-parallel ones,
// equal to Eigen's bit for bit and built in place (the setup allocates its levels); a
// cycle allocates nothing: the finest level's right-hand side and result are the
// caller's vectors, and the first sweep from x = 0 stops each row at its diagonal.
// Keys: preconditioner AMG; amgReuse 10.
#pragma once
#include "linearSolvers/HybridGaussSeidel.hpp"
#include "linearSolvers/KLUFactor.hpp"
#include "linearSolvers/Preconditioner.hpp"
#include <algorithm>

namespace shizuku {

class AggregationAMG final : public Preconditioner {
 public:
  explicit AggregationAMG(int reuse = 10) : reuse_(std::max(1, reuse)) {}
  std::string describe() const override;
  bool setup(const SparseMatrixR& A) override;
  std::string setupFailure() const override { return failure_; }
  void apply(const double* r, double* z) const override;
  bool nextSetupRebuilds() const override { return stale_ || sinceSetup_ >= reuse_ || levels_.empty(); }
  void rebuildAtNextSetup() override { stale_ = true; }
  void solved(int iterations) override;
  void nextSetupCorrects() override { correcting_ = true; }
  int levels() const { return int(levels_.size()); }
  long setups() const { return setups_; }
  // Sum of the nonzeros of all levels over those of the finest (last setup).
  double operatorComplexity() const;
  // Rows of the coarsest level, and whether it is coarsest because the aggregation
  // stalled (rather than because it is small enough).
  int coarsestRows() const { return coarsestRows_; }
  bool coarsestStalled() const { return coarsestStalled_; }

 private:
  struct Level {
    SparseMatrixR A;                   // coarse levels: R A P (level 0: unused, see fine_)
    SparseMatrixR P, R;                // to / from the next coarser level
    std::vector<double> invDiag;
    mutable std::vector<double> x, b, r;  // x, b: levels below the finest
    hybridGaussSeidel::ThreadSplit split;  // the smoother's split between threads (this solve)
  };
  // Returns false if the coarsest level's factorisation failed.
  bool build(const SparseMatrixR& A);
  // One V-cycle from level l down: x = (approximately) A^-1 b.
  void cycle(int l, const SparseMatrixR& A, const double* b, double* x) const;

  int reuse_;
  bool stale_ = true;
  int n_ = 0, sinceSetup_ = 0, setupIterations_ = 0;
  bool correcting_ = false;  // this setup and solve correct the last one (nextSetupCorrects)
  long setups_ = 0;
  const SparseMatrixR* fine_ = nullptr;  // this step's matrix (alive during the solve)
  std::vector<Level> levels_;
  std::vector<double> diag_;  // setup scratch: the diagonal of the level being built
  std::vector<int> agg_;      // setup scratch: its aggregates
  std::vector<double> threshold_;  // setup scratch: each row's strong-coupling threshold
  std::vector<int> firstAgg_;      // setup scratch: the aggregates before leftovers join
  int coarsestRows_ = 0;
  bool coarsestStalled_ = false;
  KLUFactor coarse_;  // the coarsest level's LU
  std::string failure_;  // why the last setup failed
};

}  // namespace shizuku
