// Free-surface detection, classes and normals: docs/method.md 5.1-5.3.
// Reads system/sphSchemes freeSurface { candidateThreshold; splashThreshold;
// vicinityRadius; enabled; scanRegion; pressureCondition; } through the declarations below
// (pressureCondition is handed to the pressure equation, docs/method.md 4.4).
#include "surface/FreeSurface.hpp"
#include "core/Parameter.hpp"
#include <Eigen/Eigenvalues>
#include <cmath>

namespace shizuku {

namespace {

namespace key {

// The indicator is 2 for a full neighbourhood in 2D and 3D alike, so thresholds above 2
// would mark every particle.
const ParameterGroup freeSurface("system/sphSchemes: freeSurface",
    "Free-surface detection (docs/method.md 5): indicator thresholds, vicinity, scan region.");
const ScalarParameter candidateThreshold = freeSurface.scalar("candidateThreshold", dim::none,
    "surface indicator (divR in 2D) below this: free-surface candidate (stage 1)").def(1.75).min(0).max(2);
const ScalarParameter splashThreshold = freeSurface.scalar("splashThreshold", dim::none,
    "surface indicator below this: splash particle (<= candidateThreshold)").def(0.4).min(0).max(2);
const ScalarParameter vicinityRadius = freeSurface.scalar("vicinityRadius", dim::none,
    "vicinity of the surface, times h").def(2).above(0).max(2);
const SwitchParameter enabled = freeSurface.onOff("enabled",
    "off for a closed domain without free surface (pressure level pinned)").def(true);
const SwitchParameter scanRegion = freeSurface.onOff("scanRegion",
    "stage 2, Marrone's scan region, on the candidates (off: stage 1 alone)").def(false);
const OptionParameter pressureCondition = freeSurface.option("pressureCondition", {"surface", "particles"},
    "where p = 0: on the surface, d0/2 (or the fit's distance) outside the free-surface particles "
    "(eq. 6b), or on the particles").def("surface");


}  // namespace key
}  // namespace

FreeSurfaceParameters FreeSurfaceParameters::read(const Dictionary* dict) {
  FreeSurfaceParameters p;
  // The indicator (docs/method.md 5.1) is the same number in 2D and 3D: one set of thresholds.
  // An absent sub-dictionary gives every default (still listed for -dryRun).
  p.candidateThreshold = key::candidateThreshold.read(dict);
  p.splashThreshold = key::splashThreshold.read(dict);
  p.vicinityRadius = key::vicinityRadius.read(dict);
  p.enabled = key::enabled.read(dict);
  p.scanRegion = key::scanRegion.read(dict);
  p.zeroPressureOnSurface = key::pressureCondition.read(dict) == "surface";
  if (!dict) return p;
  if (p.splashThreshold > p.candidateThreshold)
    dict->error("splashThreshold", "must not exceed candidateThreshold");
  return p;
}

namespace {

// The surface indicator s of docs/method.md 5.1 from divR and L (L is read only in 3D).
template <int D>
double surfaceIndicator(double divR, const Mat<D>& L) {
  if constexpr (D == 2) {
    (void)L;
    return divR;  // the trace of L: both eigenvalues
  } else {
    // The two smallest eigenvalues: trace less the largest (closed form for a symmetric 3x3).
    Eigen::SelfAdjointEigenSolver<Mat<3>> eig;
    eig.computeDirect(L, Eigen::EigenvaluesOnly);
    return L.trace() - eig.eigenvalues()(2);
  }
}

}  // namespace

template <int D>
void FreeSurfaceDetector<D>::detect(FlowState<D>& s) const {
  auto& P = s.particles;
  const auto& nl = s.neighbours;
  const long n = long(s.size());
  const double V = s.V(), h = s.h;
  s.divR.resize(n);
  s.gradC.resize(n);
  P.normal.resize(n);

  // Stage 1: indicators for every fluid particle.
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    P.normal[i].setZero();
    if (!s.isFluid(i)) { s.divR[i] = D; s.gradC[i].setZero(); P.surface[i] = 0; continue; }
    double div = 0;
    Vec<D> gc = Vec<D>::Zero();
    Mat<D> L = Mat<D>::Zero();                       // position-gradient matrix, 3D only
    for (Index k = nl.begin(i); k < nl.end(i); ++k) {
      const Vec<D> rij = nl.rij(std::size_t(i), k);
      const double r = rij.norm();
      const double dw = s.kernel.dwdr(r);
      div -= V * dw * r;                             // -V r_ij . (dw/dr r_ij / r)
      gc += V * (dw / r) * rij;                      // sum V gradW_ij: points toward the neighbours
      if constexpr (D == 3) L.noalias() -= (V * dw / r) * rij * rij.transpose();
    }
    s.divR[i] = div;
    const double indicator = surfaceIndicator<D>(div, L);
    s.gradC[i] = gc;                                  // inward (into the fluid)
    const double g = gc.norm();
    if (g > 0) P.normal[i] = -gc / g;                 // outward unit normal
    SurfaceClass c = SurfaceClass::interior;
    if (par_.enabled) {
      if (indicator < par_.splashThreshold) c = SurfaceClass::splash;
      else if (indicator < par_.candidateThreshold) c = SurfaceClass::free;  // candidate, stage 2 decides
    }
    P.surface[i] = std::uint8_t(c);
  }
  if (!par_.enabled) {
    s.exchange(P.normal);
    s.exchange(s.divR);
    s.exchange(s.gradC);
    return;
  }

  // Stage 2: the scan-region test on candidates (reads only stage-1 results).
  const double coneRadius2 = 2.0 * h * h, cosCone = std::cos(M_PI / 4.0);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    if (!par_.scanRegion || P.surface[i] != std::uint8_t(SurfaceClass::free)) continue;
    const Vec<D>& ni = P.normal[i];
    if (ni.squaredNorm() == 0) continue;
    bool covered = false;
    for (Index k = nl.begin(i); k < nl.end(i) && !covered; ++k) {
      const Vec<D> rji = -nl.rij(std::size_t(i), k);
      const double r = rji.norm(), r2 = r * r;
      if (r2 < coneRadius2) {
        covered = ni.dot(rji) > cosCone * r;
      } else {
        covered = (rji - h * ni).squaredNorm() < h * h;
      }
    }
    // Stage 2 reads only positions and normals, never neighbours' classes, so
    // writing the class here is order-independent.
    if (covered) P.surface[i] = std::uint8_t(SurfaceClass::interior);
  }

  // Vicinity: non-free fluid particles with a free (or splash) neighbour within vicinityRadius*h.
  s.exchange(P.surface);  // the vicinity pass reads the neighbours' classes
  const double rv = par_.vicinityRadius * h;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    if (!s.isFluid(i) || P.surface[i] != std::uint8_t(SurfaceClass::interior)) continue;
    for (Index k = nl.begin(i); k < nl.end(i); ++k) {
      const std::uint8_t cj = P.surface[nl.j[k]];
      if ((cj == std::uint8_t(SurfaceClass::free) || cj == std::uint8_t(SurfaceClass::splash)) &&
          nl.r(std::size_t(i), k) < rv) {
        P.surface[i] = 4;  // provisional mark, resolved below (keeps the scan order-independent)
        break;
      }
    }
  }
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    if (P.surface[i] == 4) P.surface[i] = std::uint8_t(SurfaceClass::vicinity);
    else if (P.surface[i] == std::uint8_t(SurfaceClass::interior)) P.normal[i].setZero();
  }
  s.exchange(P.surface);
  s.exchange(P.normal);
  s.exchange(s.divR);
  s.exchange(s.gradC);
}

template class FreeSurfaceDetector<2>;
template class FreeSurfaceDetector<3>;

}  // namespace shizuku
