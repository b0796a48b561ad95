// The named SPH operators of the step, applied with the pair weights of the step
// (docs/method.md 3.2): every derivative the solver takes goes through these.
//   <grad f>_i = sum_j V (f_j - f_i) tilde gradW_ij
//   <div u>_i  = sum_j V (u_j - u_i) . tilde gradW_ij
//   <grad u>_i = sum_j V (u_j - u_i) (x) tilde gradW_ij
//   <lap f>_i  = sum_j V (f_j - f_i) tilde lapW_ij
//   <lap u>_i with walls (docs/method.md 11): a wall neighbour j shows u_j' = 2 u_j - u_i
//              (no slip: the mirror velocity) or u_i (free slip).
// Each takes a `scale` (V, or V times the stage's constant: the product is formed once,
// so a stage's result does not depend on where the constant is applied) and an optional
// row mask: rows with mask 0 are set to zero (or left alone when accumulating).
// All share one neighbour-loop form, sumOverNeighbours(). OpenMP over rows; outputs are
// resized to the particle count (no allocation once large enough). Reads no dictionary keys.
#pragma once
#include "operators/DerivativeOperator.hpp"
#include <type_traits>
#include <vector>

namespace shizuku {

using RowMask = std::vector<std::uint8_t>;

template <class T>
inline T zeroValue() {
  if constexpr (std::is_arithmetic_v<T>) return T(0);
  else return T::Zero();
}

// out[i] (=, or += when accumulate) scale * sum_{k in row i} term(i, k), for every row i
// selected by `rows` (all rows when rows is null).
template <class T, class NL, class Term>
inline void sumOverNeighbours(const NL& nl, const RowMask* rows, double scale, bool accumulate,
                              std::vector<T>& out, Term term) {
  const long n = long(nl.numParticles());
  out.resize(std::size_t(n));
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    if (rows && !(*rows)[i]) {
      if (!accumulate) out[i] = zeroValue<T>();
      continue;
    }
    T sum = zeroValue<T>();
    for (Index k = nl.begin(i); k < nl.end(i); ++k) sum += term(i, k);
    if (accumulate) out[i] += scale * sum;
    else out[i] = scale * sum;
  }
}

enum class WallVelocity { noSlip, freeSlip };

template <int D>
struct Ops {
  static void gradient(const NeighbourList<D>& nl, const PairWeights<D>& pw, double scale,
                       const std::vector<double>& f, std::vector<Vec<D>>& out, const RowMask* rows = nullptr);
  // out[i] += scale <grad f>_i on the rows `rows` selects.
  static void addGradient(const NeighbourList<D>& nl, const PairWeights<D>& pw, double scale,
                          const std::vector<double>& f, std::vector<Vec<D>>& out, const RowMask& rows);
  static void divergence(const NeighbourList<D>& nl, const PairWeights<D>& pw, double scale,
                         const std::vector<Vec<D>>& u, std::vector<double>& out, const RowMask* rows = nullptr);
  static void laplacian(const NeighbourList<D>& nl, const PairWeights<D>& pw, double scale,
                        const std::vector<double>& f, std::vector<double>& out, const RowMask* rows = nullptr);
  static void laplacian(const NeighbourList<D>& nl, const PairWeights<D>& pw, double scale,
                        const std::vector<Vec<D>>& u, std::vector<Vec<D>>& out, const RowMask* rows = nullptr);
  // out[i] += scale <lap u>_i on fluid rows (isFluid), wall neighbours as `walls` says;
  // inlet and outlet neighbours (isBuffer, when given) with their own velocity.
  static void addVelocityLaplacian(const NeighbourList<D>& nl, const PairWeights<D>& pw, double scale,
                                   const std::vector<Vec<D>>& u, const RowMask& isFluid, WallVelocity walls,
                                   std::vector<Vec<D>>& out, const RowMask* isBuffer = nullptr);
  static void velocityGradient(const NeighbourList<D>& nl, const PairWeights<D>& pw, double scale,
                               const std::vector<Vec<D>>& u, std::vector<Mat<D>>& out);  // out(a,b) = d u_a / d x_b
  // Full Hessian of f at particle i by the FI system (SPH2 only; on demand, not per step).
  static Mat<D> hessian(const Kernel<D>& kernel, double V, const NeighbourList<D>& nl,
                        const std::vector<double>& f, std::size_t i);
};

}  // namespace shizuku
