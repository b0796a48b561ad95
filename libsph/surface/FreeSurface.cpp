// Free-surface detection, classes and normals: methods.md 5.1-5.3.
#include "surface/FreeSurface.hpp"
#include <cmath>

namespace shizuku {

FreeSurfaceParameters FreeSurfaceParameters::read(const Dictionary* dict, int dimension) {
  FreeSurfaceParameters p;
  p.candidateThreshold *= dimension / 2.0;
  p.splashThreshold *= dimension / 2.0;
  if (!dict) return p;
  p.candidateThreshold = dict->getScalarOr("candidateThreshold", p.candidateThreshold, dim::none);
  p.splashThreshold = dict->getScalarOr("splashThreshold", p.splashThreshold, dim::none);
  p.vicinityRadius = dict->getScalarOr("vicinityRadius", p.vicinityRadius, dim::none);
  p.enabled = dict->getSwitchOr("enabled", true);
  p.scanRegion = dict->getSwitchOr("scanRegion", false);
  if (p.splashThreshold > p.candidateThreshold)
    dict->error("splashThreshold", "must not exceed candidateThreshold");
  if (p.vicinityRadius <= 0 || p.vicinityRadius > 2.0)
    dict->error("vicinityRadius", "must be in (0, 2] (times h; the neighbour search radius is 2h)");
  return p;
}

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
    for (Index k = nl.begin(i); k < nl.end(i); ++k) {
      const double dw = s.kernel.dwdr(nl.r[k]);
      div -= V * dw * nl.r[k];                       // -V r_ij . (dw/dr r_ij / r)
      gc += V * (dw / nl.r[k]) * nl.rij[k];          // sum V gradW_ij: points toward the neighbours
    }
    s.divR[i] = div;
    s.gradC[i] = gc;                                  // inward (into the fluid)
    const double g = gc.norm();
    if (g > 0) P.normal[i] = -gc / g;                 // outward unit normal
    SurfaceClass c = SurfaceClass::interior;
    if (par_.enabled) {
      if (div < par_.splashThreshold) c = SurfaceClass::splash;
      else if (div < par_.candidateThreshold) c = SurfaceClass::free;  // candidate, stage 2 decides
    }
    P.surface[i] = std::uint8_t(c);
  }
  if (!par_.enabled) return;

  // Stage 2: the scan-region test on candidates (reads only stage-1 results).
  const double coneRadius2 = 2.0 * h * h, cosCone = std::cos(M_PI / 4.0);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    if (!par_.scanRegion || P.surface[i] != std::uint8_t(SurfaceClass::free)) continue;
    const Vec<D>& ni = P.normal[i];
    if (ni.squaredNorm() == 0) continue;
    bool covered = false;
    for (Index k = nl.begin(i); k < nl.end(i) && !covered; ++k) {
      const Vec<D> rji = -nl.rij[k];
      const double r2 = nl.r[k] * nl.r[k];
      if (r2 < coneRadius2) {
        covered = ni.dot(rji) > cosCone * nl.r[k];
      } else {
        covered = (rji - h * ni).squaredNorm() < h * h;
      }
    }
    // Stage 2 reads only positions and normals, never neighbours' classes, so
    // writing the class here is order-independent.
    if (covered) P.surface[i] = std::uint8_t(SurfaceClass::interior);
  }

  // Vicinity: non-free fluid particles with a free (or splash) neighbour within vicinityRadius*h.
  const double rv = par_.vicinityRadius * h;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    if (!s.isFluid(i) || P.surface[i] != std::uint8_t(SurfaceClass::interior)) continue;
    for (Index k = nl.begin(i); k < nl.end(i); ++k) {
      const std::uint8_t cj = P.surface[nl.j[k]];
      if ((cj == std::uint8_t(SurfaceClass::free) || cj == std::uint8_t(SurfaceClass::splash)) &&
          nl.r[k] < rv) {
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
}

template class FreeSurfaceDetector<2>;
template class FreeSurfaceDetector<3>;

}  // namespace shizuku
