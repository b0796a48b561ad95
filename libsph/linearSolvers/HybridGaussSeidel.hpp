// The AMG's smoother (docs/method.md 4.2): Gauss-Seidel sweeps over the rows of a sparse
// matrix, split between OpenMP threads without giving up Gauss-Seidel's coupling. The n rows
// are cut into one contiguous block per thread. A row whose entries all lie inside its own
// block is an interior row; the others (whose entries reach another block) are interface
// rows. A forward sweep visits every block's interior rows in ascending order, the blocks
// in parallel (no interior row reads another block), and then the interface rows in
// ascending order on one thread; a backward sweep is the exact reverse. Either is plain
// Gauss-Seidel in that row order, whatever the thread count: no value of another block is
// read out of date. (A block-Jacobi split, which reads other blocks' values from before the
// sweep, took 7.25 BiCGSTAB iterations instead of 5.75 on the 3D 100k dam break's systems
// on two threads; a block red-black order, 2 T blocks with the even ones swept before the
// odd ones and no serial part, took 6.6. The interface rows are 1.8 % of the rows of the
// K&O 20k systems and 17 % of the 3D 100k ones on two threads.) Where the interface rows are
// many, as with many threads across a thin domain (every thread adds a cut), their serial
// sweep would cost more than the iterations it saves: interfaceOrderPays decides, and the
// other sweeps below are the block-Jacobi split (each block reads the others' values from
// before the sweep; deterministic, fully parallel). With one thread, or `threads` 1, it is Gauss-Seidel in the rows' own
// order. Matrices are compressed row-major with ascending columns; inv holds 1 / a_ii (0
// where a_ii = 0: the row gets x_i = 0). No allocation but interfaceRows growing its list;
// reads no dictionary keys.
#pragma once
#include "linearSolvers/Preconditioner.hpp"
#include <vector>

namespace shizuku {
namespace hybridGaussSeidel {

// Thread t's row block of n rows split among T threads.
inline void rowBlock(int n, int t, int T, int& lo, int& hi) {
  lo = int(long(n) * t / T);
  hi = int(long(n) * (t + 1) / T);
}

// The interface rows of A split among `threads` blocks, ascending (none for one thread).
void interfaceRows(const SparseMatrixR& A, int threads, std::vector<int>& rows);

// One sweep (forward or backward) on x, in the order above; `interface` is
// interfaceRows(A, threads).
void sweep(const SparseMatrixR& A, const double* inv, const double* b, double* x, const std::vector<int>& interface,
           int threads, bool forward);

// The forward sweep from x = 0, writing x (its values on entry are not read): the same values
// as sweep(forward) on x = 0, each interior row stopping at its diagonal.
void sweepFromZero(const SparseMatrixR& A, const double* inv, const double* b, double* x,
                   const std::vector<int>& interface, int threads);

// Whether the interface rows' serial sweep costs less than the iterations a block-Jacobi
// split loses: with f the interface rows' share, a sweep takes (1 - f)/T + f of a serial
// one against 1/T, and the split cost 26 % more iterations in 3D and 12 % in 2D (two
// threads, the dam breaks above); so the interface order pays while f (T - 1) <= 0.2.
bool interfaceOrderPays(std::size_t interfaceRows, int n, int threads);

// The block-Jacobi split: Gauss-Seidel inside each of the `threads` blocks, the other
// blocks' values from before the sweep (old: n scratch values).
void sweepAcrossBlocks(const SparseMatrixR& A, const double* inv, const double* b, double* x, double* old,
                       int threads, bool forward);
// Its forward sweep from x = 0 (each row stops at its diagonal and reads only its block).
void sweepFromZeroAcrossBlocks(const SparseMatrixR& A, const double* inv, const double* b, double* x, int threads);

// One matrix's split between threads, decided once per solve: prepare() finds the interface
// rows and whether their order pays; the sweeps then take the order or the block-Jacobi split.
class ThreadSplit {
 public:
  void prepare(const SparseMatrixR& A, int threads);
  void sweep(const SparseMatrixR& A, const double* inv, const double* b, double* x, bool forward) const;
  void sweepFromZero(const SparseMatrixR& A, const double* inv, const double* b, double* x) const;
  // r = b - A x right after sweepFromZero wrote x. A row the sweep solved from its final
  // neighbours' values (every row on one thread; an interior row with no interface row
  // before its diagonal on several) has sum_{j<=i} a_ij x_j = b_i up to the rounding of
  // x_i = s / a_ii, so its residual is -sum_{j>i} a_ij x_j: the entries after the diagonal
  // alone, about half the row. The other rows (interface rows, interior rows that read an
  // interface row's value while it was still zero, rows with a zero diagonal, and the
  // block-Jacobi split's rows) take the whole row.
  void residualAfterSweepFromZero(const SparseMatrixR& A, const double* b, const double* x, double* r,
                                  bool parallel) const;
  bool acrossBlocks() const { return acrossBlocks_; }

 private:
  int threads_ = 1;
  bool acrossBlocks_ = false;
  std::vector<int> interface_;
  std::vector<int> upper_;            // per row: its first entry after the diagonal, or -1: the whole row
  std::vector<char> interfaceMask_;   // prepare's scratch: which rows are interface rows
  mutable std::vector<double> old_;  // the block-Jacobi split's values from before a sweep
};

}  // namespace hybridGaussSeidel
}  // namespace shizuku
