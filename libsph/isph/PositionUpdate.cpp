// The advection stage's position update, eqs. 7 and 7b: see PositionUpdate.hpp.
#include "isph/PositionUpdate.hpp"
#include "boundaries/WallParticles.hpp"

namespace shizuku {

template <int D>
void PositionUpdate<D>::allocate(std::size_t n) {
  if (rule_ == Rule::midpoint) gradient_.resize(n);
}

template <int D>
void PositionUpdate<D>::move(FlowState<D>& s, const std::vector<Vec<D>>& du) {
  auto& P = s.particles;
  const long n = long(s.size());
  const double dt = s.dt;
  const bool extra = !du.empty(), midpoint = rule_ == Rule::midpoint;
  if (midpoint) velocityGradientWithShepardWalls(s, gradient_);
  const bool periodic = s.periodic.any();
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    if (!s.isFluid(i)) continue;
    Vec<D> v = extra ? Vec<D>(P.velocity[i] + du[i]) : P.velocity[i];
    const SurfaceClass c = P.surfaceClass(i);
    if (midpoint && (c == SurfaceClass::interior || c == SurfaceClass::vicinity)) {
      const Mat<D> B = (0.5 * dt) * gradient_[i];
      if (B.squaredNorm() < 0.25) v = (Mat<D>::Identity() - B).inverse() * v;
    }
    P.position[i] += dt * v;
    if (periodic) s.periodic.wrap(P.position[i]);
  }
}

template <int D>
std::string PositionUpdate<D>::describe() const {
  return rule_ == Rule::midpoint
             ? "advection: r = r + dt (I - dt/2 <grad u>)^-1 u on interior and vicinity particles (implicit midpoint, "
               "eq. 7b), r = r + dt u on free and splash (eq. 7)"
             : "advection: r = r + dt u (eq. 7)";
}

template class PositionUpdate<2>;
template class PositionUpdate<3>;

}  // namespace shizuku
