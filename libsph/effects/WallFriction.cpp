// Wall friction from the law of the wall (docs/method.md 11.2): the shear stress rho u_tau^2
// of a turbulent boundary layer that the particle spacing does not resolve, applied to the
// first row of water along every wall, as the wall functions of finite-volume codes supply
// the wall's stress at the first cell. For a fluid particle f whose nearest wall particle is
// closer than 1.5 d0 (the first row):
//   n_f                                         (the wall normal f sees, into the fluid: that
//                                                of the wall rows, eq. 11d, seenWallNormal)
//   y_f = n_f . r_fw* - d0/2                    (distance from the wall face, at least d0/4;
//                                                w* the nearest wall particle)
//   u_t = (u_f - U_w*) - n_f (n_f . (u_f - U_w*)) (velocity along the wall)
// all from one pass over f's neighbours.
//   a_f = -min(u_tau(|u_t|, y_f)^2 / d0, |u_t| / dt) u_t / |u_t|
// The stress acts on the particle's share of the wall, d0^(D-1), and d0 is the particle's
// thickness V / d0^(D-1). The cap at |u_t| / dt stops the explicit step from reversing the
// flow, so the effect adds no time-step limit. The walls then show the viscous term free slip
// (constant/physicalProperties wallCondition defaults to slip with wallFriction; noSlip is an
// error): the law of the wall includes the viscous sublayer's stress.
// Reads (constant/physicalProperties): wallFriction { roughness [m]; }; needs nu > 0.
#include "effects/WallFriction.hpp"
#include "boundaries/WallParticles.hpp"
#include "core/Parameter.hpp"
#include "effects/EffectFactories.hpp"
#include "effects/PhysicalProperties.hpp"
#include <cmath>
#include <sstream>

namespace shizuku {

double frictionVelocity(double U, double y, double nu, double roughness) {
  constexpr double kE = 2.718281828459045;  // below it the log layer has no room
  if (!(U > 0)) return 0;
  const double laminar = std::sqrt(nu * U / y);
  if (y * laminar / nu <= 11.0) return laminar;  // the viscous sublayer: hydraulically smooth
  double us = laminar;
  for (int it = 0; it < 100; ++it) {
    const double arg = y / (nu / (9 * us) + roughness / 30);
    const double next = arg > kE ? kVonKarman * U / std::log(arg) : kVonKarman * U;
    if (std::abs(next - us) <= 1e-14 * next) return next;
    us = next;
  }
  return us;
}

namespace {

namespace key {
const ParameterGroup friction("constant/physicalProperties: wallFriction",
    "Wall shear stress from the law of the wall on the first row of water (docs/method.md 11.2).");
const ScalarParameter roughness =
    friction.scalar("roughness", dim::length, "equivalent sand-grain roughness ks of the walls (0: smooth)").def(0).min(0);
}  // namespace key

template <int D>
class WallFriction final : public ForceEffect<D> {
 public:
  WallFriction(double nu, double roughness) : ForceEffect<D>("wallFriction"), nu_(nu), roughness_(roughness) {}
  std::string describe() const override {
    std::ostringstream os;
    os << "law of the wall, roughness " << roughness_ << " m" << (roughness_ == 0 ? " (smooth)" : "") << ", nu = " << nu_
       << " m^2/s";
    return os.str();
  }
  void addAcceleration(const FlowState<D>& s, std::vector<Vec<D>>& acc) override {
    const auto& nl = s.neighbours;
    const auto& P = s.particles;
    const long n = long(s.size());
    const double d0 = s.d0;
    long acted = 0;
#pragma omp parallel for schedule(static) reduction(+ : acted)
    for (long f = 0; f < n; ++f) {
      if (!s.isFluid(std::size_t(f))) continue;
      double nearest = HUGE_VAL;
      Index nearestPair = -1;
      for (Index k = nl.begin(f); k < nl.end(f); ++k) {
        if (!P.isWall(std::size_t(nl.j[k]))) continue;
        const double dist = nl.r(std::size_t(f), k);
        if (dist < nearest) {
          nearest = dist;
          nearestPair = k;
        }
      }
      if (!(nearest < 1.5 * d0)) continue;
      const Vec<D> normal = seenWallNormal(s, std::size_t(f));
      if (normal.squaredNorm() == 0) continue;
      const double y = std::max(normal.dot(nl.rij(std::size_t(f), nearestPair)) - 0.5 * d0, 0.25 * d0);
      const Vec<D> rel = P.velocity[f] - P.velocity[nl.j[nearestPair]];
      const Vec<D> along = rel - normal * normal.dot(rel);
      const double U = along.norm();
      if (!(U > 0)) continue;
      const double us = frictionVelocity(U, y, nu_, roughness_);
      acc[f] -= std::min(us * us / d0, U / s.dt) / U * along;
      ++acted;
    }
    this->actionCount_ = acted;
  }

 private:
  double nu_, roughness_;
};

}  // namespace

template <int D>
std::unique_ptr<Effect<D>> makeWallFriction(const Dictionary& props, const FlowState<D>&) {
  const PhysicalProperties p = readPhysicalProperties(props);
  const Dictionary& d = props.subDict("wallFriction");
  if (!(p.nu > 0)) props.error("wallFriction", "needs the fluid's viscosity: give nu > 0");
  return std::make_unique<WallFriction<D>>(p.nu, key::roughness.read(d));
}

SHIZUKU_EFFECT_FACTORY(makeWallFriction);

}  // namespace shizuku
