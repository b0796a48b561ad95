// Leave-one-out weighted line/plane fit of the free surface and the curvature of
// eq. 20 (docs/method.md 8.2, 8.4); see SurfaceFit.hpp for the formulas.
// Reads no dictionary keys.
#include "surface/SurfaceFit.hpp"
#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

namespace shizuku {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool isFitted(SurfaceClass c) { return isFreeSurfaceClass(c) || c == SurfaceClass::vicinity; }

// A normal is defined when it is (close to) a unit vector; undefined normals are zero.
template <int D>
bool isUnit(const Vec<D>& n) { return n.squaredNorm() > 0.25; }

// Fit for particle i; returns false when the quality gate rejects it.
template <int D>
bool fitOne(const FlowState<D>& s, std::size_t i, const SurfaceFitSettings& set, Vec<D>& normal,
            double& distance) {
  const auto& nl = s.neighbours;
  // Pass 1: weighted centroid of Q relative to r_i (r_j - r_i = -r_ij).
  double sumW = 0;
  int count = 0;
  Vec<D> c = Vec<D>::Zero();
  for (Index k = nl.begin(i); k < nl.end(i); ++k) {
    const Index j = nl.j[k];
    if (!s.isFluid(j) || !isFreeSurfaceClass(s.surfaceClass(j))) continue;
    const Vec<D> rij = nl.rij(i, k);
    const double w = s.kernel.w(rij.norm());
    if (!(w > 0)) continue;
    sumW += w;
    c -= w * rij;
    ++count;
  }
  if (count < D) return false;
  c /= sumW;
  // Pass 2: weighted covariance about the centroid.
  Mat<D> cov = Mat<D>::Zero();
  for (Index k = nl.begin(i); k < nl.end(i); ++k) {
    const Index j = nl.j[k];
    if (!s.isFluid(j) || !isFreeSurfaceClass(s.surfaceClass(j))) continue;
    const Vec<D> rij = nl.rij(i, k);
    const double w = s.kernel.w(rij.norm());
    if (!(w > 0)) continue;
    const Vec<D> y = -rij - c;
    cov.noalias() += w * y * y.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Mat<D>> es(cov);
  if (es.info() != Eigen::Success) return false;
  const auto& lambda = es.eigenvalues();  // ascending
  const double lmax = lambda(D - 1);
  if (!(lmax > 0)) return false;
  if (lambda(0) > set.maxEigenRatio * lmax) return false;
  if (D == 3 && lambda(1) < set.minSpreadRatio * lmax) return false;
  Vec<D> n = es.eigenvectors().col(0);
  if (n.dot(normal) < 0) n = -n;
  normal = n.normalized();
  distance = -c.dot(normal) / s.d0;
  return true;
}

}  // namespace

template <int D>
double curvatureSum(const FlowState<D>& s, std::size_t i) {
  const auto& nrm = s.fitNormal;
  if (nrm.size() != s.size() || !isUnit<D>(nrm[i])) return kNaN;
  const auto& nl = s.neighbours;
  const bool corrected = !s.weights.order.empty() && s.weights.order[i] != 255 && !s.weights.gradW.empty();
  double sum = 0;
  for (Index k = nl.begin(i); k < nl.end(i); ++k) {
    const Index j = nl.j[k];
    if (!s.isFluid(j) || !isFreeSurfaceClass(s.surfaceClass(j)) || !isUnit<D>(nrm[j])) continue;
    const Vec<D> g = corrected ? s.weights.gradW[k] : s.kernel.gradW(nl.rij(i, k), nl.r(i, k));
    sum += (nrm[j] - nrm[i]).dot(g);
  }
  return sum * s.V() * s.d0;
}

template <int D>
void computeSurfaceFit(FlowState<D>& s, const SurfaceFitSettings& set) {
  const std::size_t N = s.size();
  if (s.fitDistance.size() != N) s.fitDistance.resize(N);
  if (s.curvature.size() != N) s.curvature.resize(N);
  if (s.particles.normal.size() != N) s.particles.normal.resize(N, Vec<D>::Zero());
  if (s.fitNormal.size() != N) s.fitNormal.resize(N);
  auto& nrm = s.fitNormal;
  const long n = long(N);
  // Fit: starts from the detector's normal (for the orientation).
#pragma omp parallel for schedule(dynamic, 64)
  for (long i = 0; i < n; ++i) {
    s.fitDistance[i] = kNaN;
    nrm[i] = s.particles.normal[i];
    if (!s.isFluid(i) || !isFitted(s.surfaceClass(i)) || !isUnit<D>(nrm[i])) continue;
    Vec<D> normal = nrm[i];
    double distance = kNaN;
    if (fitOne(s, std::size_t(i), set, normal, distance)) {
      nrm[i] = normal;
      s.fitDistance[i] = distance;
    }
  }
  s.exchange(nrm);  // the curvature reads the neighbours' fitted normals
  s.exchange(s.fitDistance);
  // Curvature from the fitted normals of the free-surface neighbours (eq. 20).
#pragma omp parallel for schedule(dynamic, 64)
  for (long i = 0; i < n; ++i) {
    s.curvature[i] = kNaN;
    if (!s.isFluid(i) || !isFitted(s.surfaceClass(i))) continue;
    s.curvature[i] = set.curvatureFactor * curvatureSum(s, std::size_t(i));
  }
  s.exchange(s.curvature);
}

template void computeSurfaceFit<2>(FlowState<2>&, const SurfaceFitSettings&);
template void computeSurfaceFit<3>(FlowState<3>&, const SurfaceFitSettings&);
template double curvatureSum<2>(const FlowState<2>&, std::size_t);
template double curvatureSum<3>(const FlowState<3>&, std::size_t);

}  // namespace shizuku
