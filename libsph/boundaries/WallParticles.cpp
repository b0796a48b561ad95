// Dummy wall particles: Shepard velocity, the wall normals fluid particles see and the
// Adami pressure row (docs/method.md 4.2, 11).
#include "boundaries/WallParticles.hpp"
#include "operators/Ops.hpp"

#include <algorithm>

namespace shizuku {

template <int D>
void shepardFluidVelocity(const FlowState<D>& s, std::vector<Vec<D>>& u, bool outletsOnly) {
  const auto& nl = s.neighbours;
  const long n = long(s.size());
#pragma omp parallel for schedule(static)
  for (long w = 0; w < n; ++w) {
    if (s.isFluid(w) || s.particles.isInlet(std::size_t(w))) continue;  // an inlet shows its prescribed velocity
    if (outletsOnly && !s.particles.isOutlet(std::size_t(w))) continue;
    Vec<D> sum = Vec<D>::Zero();
    double ws = 0;
    for (Index k = nl.begin(w); k < nl.end(w); ++k) {
      const Index f = nl.j[k];
      if (!s.isFluid(f)) continue;
      const double wk = s.w(std::size_t(w), k);
      sum += wk * u[f];
      ws += wk;
    }
    u[w] = ws > 0 ? Vec<D>(sum / ws) : s.particles.velocity[w];
  }
  s.exchange(u);
}

template <int D>
Vec<D> seenWallNormal(const FlowState<D>& s, std::size_t f) {
  const auto& nl = s.neighbours;
  const auto& P = s.particles;
  Vec<D> centre = Vec<D>::Zero();
  bool walls = false;
  for (Index k = nl.begin(f); k < nl.end(f); ++k)
    if (P.isWall(std::size_t(nl.j[k]))) {
      centre += s.w(f, k) * nl.rij(f, k);
      walls = true;
    }
  if (!walls) return Vec<D>::Zero();
  Vec<D> sum = Vec<D>::Zero();
  if (!P.wallNormal.empty())
    for (Index k = nl.begin(f); k < nl.end(f); ++k) {
      const std::size_t w = std::size_t(nl.j[k]);
      if (!P.isWall(w)) continue;
      const Vec<D>& n = P.wallNormal[w];
      sum += (n.dot(centre) >= 0 ? s.w(f, k) : -s.w(f, k)) * n;
    }
  const Vec<D>& dir = sum.norm() > 0 ? sum : centre;
  const double len = dir.norm();
  return len > 0 ? Vec<D>(dir / len) : Vec<D>::Zero();
}

template <int D>
void WallContacts<D>::update(const FlowState<D>& s) {
  const auto& nl = s.neighbours;
  const long n = long(s.size());
  normal.resize(std::size_t(n));
  lone.resize(std::size_t(n));
#pragma omp parallel for schedule(static)
  for (long f = 0; f < n; ++f) {
    if (!s.isFluid(std::size_t(f))) continue;
    bool alone = true;
    for (Index k = nl.begin(f); k < nl.end(f) && alone; ++k) {
      const Index j = nl.j[k];
      alone = !(s.isFluid(std::size_t(j)) && j != f);
    }
    normal[f] = seenWallNormal(s, std::size_t(f));
    lone[f] = alone;
  }
  s.exchange(normal);  // a wall row reads its fluid neighbours' contacts
  s.exchange(lone);
}

template <int D>
AdamiRow<D> AdamiRow<D>::compute(const FlowState<D>& s, const WallContacts<D>& contacts, std::size_t w) {
  const auto& nl = s.neighbours;
  AdamiRow row;
  double sum = 0;
  const Vec<D>& Uw = s.particles.velocity[w];
  const double invDt = 1.0 / s.dt;
  const bool inlet = s.particles.isInlet(w);
  double velocitySum = 0;      // sum_f W n_f.(u_f - U_w) n_f.r_wf
  double previousPressure = 0; // sum_f W p_f from the last step, the estimate for the cap
  for (Index k = nl.begin(w); k < nl.end(w); ++k) {
    const Index f = nl.j[k];
    if (!s.isFluid(f)) continue;
    const Vec<D>& n = contacts.normal[f];
    const Vec<D> forces = (s.uStar[f] - s.particles.velocity[f]) * invDt;
    const Vec<D> a = inlet ? Vec<D>((s.uStar[f] - Uw) * invDt)
                           : Vec<D>(contacts.lone[f] ? Vec<D>(n * n.dot(forces)) : forces);
    const Vec<D> rwf = nl.rij(w, k);
    const double wk = s.kernel.w(rwf.norm());
    row.weightSum += wk;
    sum += wk * a.dot(rwf);
    if (!inlet) velocitySum += wk * n.dot(s.particles.velocity[f] - Uw) * n.dot(rwf);
    previousPressure += wk * s.particles.pressure[f];
  }
  if (row.weightSum > 0) {
    const double forcesPart = s.rho0 * sum / row.weightSum;
    const double velocityPart = s.rho0 * velocitySum * invDt / row.weightSum;
    // Eq. 11b: the velocity term may lower the wall to ambient pressure, not below. Where it
    // would, the row is p_w = 0 itself; the bound's value taken as a right-hand side,
    // -sum W p^n_f / sum W, gave p_w the change of the fluid's pressure over the step, a lag
    // that alternated from step to step at small steps (docs/validation.md, "Wall pressure").
    // Where the forces alone already put the wall at or below ambient (above a waterline),
    // the velocity term may only raise it.
    const double floor = std::max(0.0, previousPressure / row.weightSum + forcesPart);
    row.ambient = floor > 0 && velocityPart < -floor;
    row.rhs = row.ambient ? 0.0 : forcesPart + std::max(velocityPart, -floor);
  }
  return row;
}

template <int D>
void velocityGradientWithShepardWalls(FlowState<D>& s, std::vector<Mat<D>>& out) {
  const auto& u = s.particles.velocity;
  const long n = long(s.size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) s.uStar[i] = u[i];
  shepardFluidVelocity(s, s.uStar);
  Ops<D>::velocityGradient(s.neighbours, s.weights, s.V(), s.uStar, out);
}

template void velocityGradientWithShepardWalls<2>(FlowState<2>&, std::vector<Mat<2>>&);
template void velocityGradientWithShepardWalls<3>(FlowState<3>&, std::vector<Mat<3>>&);
template Vec<2> seenWallNormal<2>(const FlowState<2>&, std::size_t);
template Vec<3> seenWallNormal<3>(const FlowState<3>&, std::size_t);
template void shepardFluidVelocity<2>(const FlowState<2>&, std::vector<Vec<2>>&, bool);
template void shepardFluidVelocity<3>(const FlowState<3>&, std::vector<Vec<3>>&, bool);
template struct WallContacts<2>;
template struct WallContacts<3>;
template struct AdamiRow<2>;
template struct AdamiRow<3>;

}  // namespace shizuku
