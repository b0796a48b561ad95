// PPE assembly and solve, methods.md 4.2 and 11 (option A).
#include "pressure/PressureEquation.hpp"
#include "boundaries/WallParticles.hpp"

namespace shizuku {

template <int D>
void PressureEquation<D>::assemble(const FlowState<D>& s, const std::vector<double>& source) {
  const auto& P = s.particles;
  const auto& nl = s.neighbours;
  const long n = long(s.size());
  const double V = s.V();
  unknown_.resize(n);

  // 1. Which particles are unknowns, and how many entries each row has.
  bool anyDirichlet = false;
  for (long i = 0; i < n; ++i) {
    bool isUnknown;
    if (s.isFluid(i)) {
      const auto c = P.surfaceClass(i);
      isUnknown = !(c == SurfaceClass::free || c == SurfaceClass::splash);
      anyDirichlet |= !isUnknown;
    } else {
      isUnknown = false;
      for (Index k = nl.begin(i); k < nl.end(i); ++k)
        if (s.isFluid(nl.j[k])) { isUnknown = true; break; }
    }
    unknown_[i] = isUnknown ? 1 : -1;
  }
  Index m = 0;
  rowParticle_.clear();
  for (long i = 0; i < n; ++i)
    if (unknown_[i] >= 0) { unknown_[i] = m++; rowParticle_.push_back(Index(i)); }
  rowStart_.resize(m + 1);
  rowStart_[0] = 0;
  for (Index r = 0; r < m; ++r) {
    const Index i = rowParticle_[r];
    Index c = 1;  // diagonal
    for (Index k = nl.begin(i); k < nl.end(i); ++k) {
      const Index j = nl.j[k];
      if (unknown_[j] < 0) continue;
      if (!s.isFluid(i) && !s.isFluid(j)) continue;  // wall rows couple to fluid only
      ++c;
    }
    rowStart_[r + 1] = rowStart_[r] + c;
  }

  // 2. Fill the compressed rows (columns ascending: unknown ids follow particle order,
  //    and each neighbour row is sorted by j).
  A_.resize(m, m);
  A_.resizeNonZeros(rowStart_[m]);
  b_.resize(m);
  std::copy(rowStart_.begin(), rowStart_.end(), A_.outerIndexPtr());
  int* col = A_.innerIndexPtr();
  double* val = A_.valuePtr();
  pinned_ = !anyDirichlet && m > 0;
  long fallbacks = 0;
#pragma omp parallel for schedule(static) reduction(+ : fallbacks)
  for (Index r = 0; r < m; ++r) {
    const Index i = rowParticle_[r];
    Index pos = rowStart_[r];
    Index diagPos = -1;
    double diag = 0, rhs = 0;
    auto putDiag = [&]() { diagPos = pos; col[pos] = r; val[pos++] = 0; };
    if (s.isFluid(i)) {
      // -sum_j V L_ij (p_j - p_i) = -b_i. A row whose weights break the M-matrix
      // sign pattern (a negative neighbour weight or a non-positive diagonal, seen
      // on strongly one-sided stencils near a free surface meeting a wall) would
      // make the system indefinite; it takes the always-positive standard
      // (Brookshaw/Morris) weights -2 W'(r)/r instead (methods.md 3.3, 3.4).
      bool mMatrix = true;
      double sum = 0;
      for (Index k = nl.begin(i); k < nl.end(i); ++k) {
        mMatrix &= s.weights.lapW[k] >= 0;
        sum += s.weights.lapW[k];
      }
      mMatrix &= sum > 0;
      if (!mMatrix) ++fallbacks;
      for (Index k = nl.begin(i); k < nl.end(i); ++k) {
        const Index j = nl.j[k];
        const double c = V * (mMatrix ? s.weights.lapW[k] : -2.0 * s.kernel.dwdr(nl.r[k]) / nl.r[k]);
        diag += c;
        if (unknown_[j] < 0) continue;
        if (diagPos < 0 && j > i) putDiag();
        col[pos] = unknown_[j];
        val[pos++] = -c;
      }
      rhs = -source[i];
    } else {
      const AdamiRow<D> row = AdamiRow<D>::compute(s, i);
      for (Index k = nl.begin(i); k < nl.end(i); ++k) {
        const Index j = nl.j[k];
        if (unknown_[j] < 0 || !s.isFluid(j)) continue;
        if (diagPos < 0 && j > i) putDiag();
        col[pos] = unknown_[j];
        val[pos++] = -s.weights.w[k] / row.weightSum;
      }
      diag = 1.0;
      rhs = row.rhs;
    }
    if (diagPos < 0) putDiag();
    val[diagPos] = diag;
    b_[r] = rhs;
  }
  standardRows_ = fallbacks;
  if (pinned_) {
    // Fix the pressure level: the first fluid unknown gets p = 0.
    for (Index r = 0; r < m; ++r)
      if (s.isFluid(rowParticle_[r])) {
        for (Index k = rowStart_[r]; k < rowStart_[r + 1]; ++k) val[k] = (col[k] == r) ? 1.0 : 0.0;
        b_[r] = 0;
        break;
      }
  }
}

template <int D>
LinearSolveResult PressureEquation<D>::solve(FlowState<D>& s) {
  auto& p = s.particles.pressure;
  const Index m = Index(A_.rows());
  x_.resize(m);
  for (Index r = 0; r < m; ++r) x_[r] = p[rowParticle_[r]];  // warm start
  LinearSolveResult res = m > 0 ? solver_->solve(A_, b_, x_) : LinearSolveResult{true, 0, 0, ""};
  const long n = long(s.size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) p[i] = unknown_[i] >= 0 ? x_[unknown_[i]] : 0.0;
  return res;
}

template class PressureEquation<2>;
template class PressureEquation<3>;

}  // namespace shizuku
