// PPE assembly and solve, docs/method.md 4.2, 4.4 (eq. 6b) and 11 (option A).
#include "pressure/PressureEquation.hpp"
#include "pressure/FreeSurfaceRow.hpp"
#include "boundaries/OpenBoundaryRows.hpp"
#include "boundaries/WallParticles.hpp"
#include "parallel/Communicator.hpp"
#include <algorithm>

namespace shizuku {

template <int D>
void PressureEquation<D>::assemble(const FlowState<D>& s, const std::vector<double>& source, double diagonal) {
  const bool anyDirichlet = countRows(s);
  // The particle order changed (cell reordering): a preconditioner kept from an
  // earlier step no longer matches the rows.
  const auto& P = s.particles;
  const std::size_t owned = s.numOwned();
  if (Communicator::world().any(numberingChanged(P, owned))) {  // on any rank: the global rows moved
    ids_.assign(P.id.begin(), P.id.begin() + long(owned));
    solver_->startAfreshAtNextSolve();
  }
  // The compressibility term (diagonal > 0) fixes the level itself: nothing is pinned.
  pinned_ = !anyDirichlet && numUnknowns_ > 0 && diagonal == 0;
  if (hasWallRows_) contacts_.update(s);  // the wall normals the wall rows use (eq. 11a)
  ambient_.assign(s.size(), 0);
  fillRows(s, source, diagonal);
}

// Which particles are unknowns (fluid not on the free surface; free-surface particles with
// an eq. 6b row; walls and inlet particles with a fluid neighbour), and where each row
// starts. Outlet particles are known: their prescribed pressure (docs/boundaries.md).
// Returns whether the pressure level is fixed (a free-surface particle, an outlet particle).
template <int D>
bool PressureEquation<D>::countRows(const FlowState<D>& s) {
  const auto& P = s.particles;
  const auto& nl = s.neighbours;
  const long n = long(s.size());
  unknown_.resize(n);
  rowStart_.resize(n + 1);
  if (onSurface_) {
    inward_.resize(n);
    delta_.resize(n);
  }

  // Counted over this rank's own particles (ghosts are another rank's rows), then summed.
  const long owned = long(s.numOwned());
  long anyDirichlet = 0, m = 0, wallRows = 0;
#pragma omp parallel for schedule(static) reduction(+ : anyDirichlet, m, wallRows)
  for (long i = 0; i < n; ++i) {
    const long mine = i < owned;
    std::uint8_t isUnknown;
    if (s.isFluid(i)) {
      const auto c = P.surfaceClass(i);
      const bool onSurface = c == SurfaceClass::free || c == SurfaceClass::splash;
      isUnknown = !onSurface;
      anyDirichlet += mine * onSurface;
      if (c == SurfaceClass::free && onSurface_ && FreeSurfaceRow<D>::frame(s, i, inward_[i], delta_[i]) &&
          FreeSurfaceRow<D>::depthMoment(s, i, inward_[i]) > 0)
        isUnknown = 2;
    } else if (hasPrescribedPressure(s, i)) {
      isUnknown = false;
      anyDirichlet += mine;
    } else {
      isUnknown = false;
      for (Index k = nl.begin(i); k < nl.end(i); ++k)
        if (s.isFluid(nl.j[k])) { isUnknown = true; break; }
      wallRows += mine * isUnknown;
    }
    unknown_[i] = isUnknown;
    m += mine * (isUnknown != 0);
  }
  s.exchange(unknown_);  // a row's columns are its neighbours that are unknowns
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    Index c = 1;  // diagonal
    double d = 0;
    if (unknown_[i] == 2)
      for (Index k = nl.begin(i); k < nl.end(i); ++k)
        c += unknown_[nl.j[k]] && FreeSurfaceRow<D>::weight(s, std::size_t(i), k, inward_[i], d) > 0;
    else if (unknown_[i])
      for (Index k = nl.begin(i); k < nl.end(i); ++k) {
        const Index j = nl.j[k];
        if (!unknown_[j]) continue;
        if (!s.isFluid(i) && !s.isFluid(j)) continue;  // wall rows couple to fluid only
        ++c;
      }
    rowStart_[i + 1] = c;
  }
  rowStart_[0] = 0;
  for (long i = 0; i < n; ++i) rowStart_[i + 1] += rowStart_[i];
  const auto& world = Communicator::world();
  numUnknowns_ = world.sum(m);
  hasWallRows_ = world.sum(wallRows) > 0;
  return world.sum(anyDirichlet) > 0;
}

// The compressed rows (columns ascending: each neighbour row is sorted by j). Storage
// grows with 25 % headroom, so the changing number of pairs does not reallocate every step.
template <int D>
void PressureEquation<D>::fillRows(const FlowState<D>& s, const std::vector<double>& source, double diagonal) {
  const auto& nl = s.neighbours;
  const long n = long(s.size());
  const double V = s.V();
  A_.resize(n, n);
  A_.data().resize(rowStart_[n], 0.25);
  b_.resize(n);
  std::copy(rowStart_.begin(), rowStart_.end(), A_.outerIndexPtr());
  int* col = A_.innerIndexPtr();
  double* val = A_.valuePtr();
  long fallbacks = 0;
  // Dynamic: a wall row costs several fluid rows, and walls are not spread evenly.
#pragma omp parallel for schedule(dynamic, 256) reduction(+ : fallbacks)
  for (long i = 0; i < n; ++i) {
    Index pos = rowStart_[i];
    if (!unknown_[i]) {
      col[pos] = int(i);
      val[pos] = 1.0;
      b_[i] = 0;
      continue;
    }
    if (unknown_[i] == 2) {
      fillSurfaceRow(s, i, pos, col, val);
      continue;
    }
    Index diagPos = -1;
    double diag = diagonal, rhs = 0, known = 0;
    auto putDiag = [&]() { diagPos = pos; col[pos] = int(i); val[pos++] = 0; };
    if (s.isFluid(i)) {
      // -sum_j V L_ij (p_j - p_i) = -b_i. A row whose weights break the M-matrix
      // sign pattern (a negative neighbour weight or a non-positive diagonal, seen
      // on strongly one-sided stencils near a free surface meeting a wall) would
      // make the system indefinite; it takes the always-positive standard
      // (Brookshaw/Morris) weights -2 W'(r)/r instead (docs/method.md 3.3, 3.4).
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
        const double r = mMatrix ? 0.0 : nl.r(std::size_t(i), k);
        const double c = V * (mMatrix ? s.weights.lapW[k] : -2.0 * s.kernel.dwdr(r) / r);
        diag += c;
        if (!unknown_[j]) {
          if (hasPrescribedPressure(s, j)) known += c * s.particles.pressure[j];
          continue;
        }
        if (diagPos < 0 && j > i) putDiag();
        col[pos] = int(j);
        val[pos++] = -c;
      }
      rhs = -source[i];
      if (known != 0) rhs += known;  // outlet neighbours' prescribed pressure
    } else {
      fillWallRow(s, i, AdamiRow<D>::compute(s, contacts_, i), col, val);
      continue;
    }
    if (diagPos < 0) putDiag();
    val[diagPos] = diag;
    b_[i] = rhs;
  }
  standardRows_ = fallbacks;
  if (pinned_) {
    // Fix the pressure level: the first fluid unknown gets p = 0 (in a distributed run,
    // the first of the lowest rank that has one).
    const auto& world = Communicator::world();
    const long owned = long(s.numOwned());
    long first = -1;
    for (long i = 0; i < owned && first < 0; ++i)
      if (unknown_[i] && s.isFluid(i)) first = i;
    const int pinRank = int(world.min(first >= 0 ? double(world.rank()) : double(world.size())));
    if (pinRank == world.rank()) {
      for (Index k = rowStart_[first]; k < rowStart_[first + 1]; ++k) val[k] = (col[k] == first) ? 1.0 : 0.0;
      b_[first] = 0;
    }
  }
}

// Eq. 6b divided by sum_j a_ij d_ij (> 0 by countRows), right-hand side 0: diagonal 1 + delta sum a / sum a d,
// off-diagonals -delta a_ij / sum a d. Neighbours with a known p (= 0) add only to the sums.
template <int D>
void PressureEquation<D>::fillSurfaceRow(const FlowState<D>& s, long i, Index pos, int* col, double* val) {
  b_[i] = 0;
  const auto& nl = s.neighbours;
  const Vec<D>& inward = inward_[i];
  double sumA = 0, sumAD = 0, d = 0;
  for (Index k = nl.begin(i); k < nl.end(i); ++k) {
    const double a = FreeSurfaceRow<D>::weight(s, std::size_t(i), k, inward, d);
    sumA += a;
    sumAD += a * d;
  }
  const double scale = delta_[i] / sumAD;
  Index diagPos = -1;
  for (Index k = nl.begin(i); k < nl.end(i); ++k) {
    const Index j = nl.j[k];
    const double a = FreeSurfaceRow<D>::weight(s, std::size_t(i), k, inward, d);
    if (!(a > 0) || !unknown_[j]) continue;
    if (diagPos < 0 && j > i) { diagPos = pos; col[pos++] = int(i); }
    col[pos] = int(j);
    val[pos++] = -scale * a;
  }
  if (diagPos < 0) { diagPos = pos; col[pos] = int(i); }
  val[diagPos] = 1.0 + scale * sumA;
}

template <int D>
LinearSolveResult PressureEquation<D>::solve(FlowState<D>& s, bool correction) {
  if (correction) solver_->nextSolveCorrectsTheLast();
  auto& p = s.particles.pressure;
  const long n = long(A_.rows());
  x_.resize(n);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) x_[i] = unknown_[i] ? p[i] : 0.0;  // warm start
  LinearSolveResult res{true, 0, 0, ""};
  if (numUnknowns_ > 0) res = s.halo ? solveDistributed(s) : solver_->solve(A_, b_, x_);
  if (numUnknowns_ == 0) x_.setZero();
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) p[i] = unknown_[i] ? x_[i] : hasPrescribedPressure(s, i) ? p[i] : 0.0;
  s.exchange(p);
  return res;
}

// The Adami row of wall particle i (eqs. 11a, 11b): diagonal 1, -W_wf / sum W for each fluid
// neighbour (0 where eq. 11b binds: p_w = 0), columns ascending.
template <int D>
void PressureEquation<D>::fillWallRow(const FlowState<D>& s, long i, const AdamiRow<D>& row, int* col, double* val) {
  const auto& nl = s.neighbours;
  Index pos = rowStart_[i];
  bool diagonal = false;
  for (Index k = nl.begin(i); k < nl.end(i); ++k) {
    const Index j = nl.j[k];
    if (!unknown_[j] || !s.isFluid(j)) continue;
    if (!diagonal && j > i) {
      col[pos] = int(i);
      val[pos++] = 1.0;
      diagonal = true;
    }
    col[pos] = int(j);
    val[pos++] = row.ambient ? 0.0 : -s.w(std::size_t(i), k) / row.weightSum;
  }
  if (!diagonal) {
    col[pos] = int(i);
    val[pos] = 1.0;
  }
  b_[i] = row.rhs;
  ambient_[i] = row.ambient;
}

template <int D>
bool PressureEquation<D>::redecideWallRows(const FlowState<D>& s) {
  const long n = long(ambient_.size()), owned = long(std::min(s.numOwned(), ambient_.size()));
  int* col = A_.innerIndexPtr();
  double* val = A_.valuePtr();
  long changed = 0;
#pragma omp parallel for schedule(dynamic, 256) reduction(+ : changed)
  for (long i = 0; i < n; ++i) {
    if (unknown_[i] != 1 || s.isFluid(i)) continue;
    const AdamiRow<D> row = AdamiRow<D>::compute(s, contacts_, i);
    if (i < owned && row.ambient != bool(ambient_[i])) ++changed;
    fillWallRow(s, i, row, col, val);
  }
  return Communicator::world().sum(double(changed)) > 0;
}

// This rank's rows (its own particles, the first numOwned) with global column numbers:
// row i of rank r is global row offset_r + i, and a ghost's column is its owner's row
// number, fetched through the halo. Ghost rows are not solved for here.
template <int D>
LinearSolveResult PressureEquation<D>::solveDistributed(const FlowState<D>& s) {
  const auto& world = Communicator::world();
  const long n = long(A_.rows()), owned = long(s.numOwned());
  const long offset = world.exclusivePrefixSum(owned), total = world.sum(owned);
  globalRow_.resize(n);
  for (long i = 0; i < owned; ++i) globalRow_[i] = offset + i;
  s.exchange(globalRow_);
  const Index nnz = rowStart_[owned];
  Aowned_.resize(owned, total);
  Aowned_.data().resize(nnz, 0.25);
  std::copy(rowStart_.begin(), rowStart_.begin() + owned + 1, Aowned_.outerIndexPtr());
  const int* col = A_.innerIndexPtr();
  for (Index k = 0; k < nnz; ++k) Aowned_.innerIndexPtr()[k] = int(globalRow_[col[k]]);
  std::copy(A_.valuePtr(), A_.valuePtr() + nnz, Aowned_.valuePtr());
  bOwned_ = b_.head(owned);
  xOwned_ = x_.head(owned);
  const LinearSolveResult res = solver_->solve(Aowned_, bOwned_, xOwned_);
  x_.head(owned) = xOwned_;
  return res;
}

template class PressureEquation<2>;
template class PressureEquation<3>;

}  // namespace shizuku
