// Advective dynamic stabilization (docs/method.md 9); formula in ADS.hpp.
#include "effects/ADS.hpp"
#include "effects/EffectFactories.hpp"
#include "core/Parameter.hpp"
#include <stdexcept>

namespace shizuku {

namespace {
namespace key {
// 0.95 d0, not the paper's d0: ADS only pushes pairs apart, and at d0 it spreads the
// near-surface band of a disordered arrangement whose nearest neighbours sit on both
// sides of d0 (docs/shifting.md, "ADS distance": interior density error 2.6 % -> 0.6 %
// in the dam break; 0.9 d0 let the rotating patch blow up at omega t = 4.2).
const ParameterGroup ads("system/sphSchemes: ads", "Advective dynamic stabilization near the free surface (docs/method.md 9).");
const ScalarParameter distance = ads.scalar("distance", dim::none, "pairs closer than this are pushed apart, times d0")
    .def(0.95).above(0).max(2);
const ScalarParameter wallDistance = ads.scalar("wallDistance", dim::none, "the same for a wall partner, times d0")
    .def(0.95).shownDefault("distance").above(0).max(2);
const ScalarParameter C = ads.scalar("C", dim::none, "fraction of the overlap restored per step (1: all)").def(1).above(0).max(1);
const OptionParameter partners = ads.option("partners", {"surface", "pair"},
    "surface: only near-surface particles move; pair: both fluid partners move by half").def("surface");
const SwitchParameter approaching = ads.onOff("approaching", "act only on pairs closing in").def(false);
}  // namespace key
}  // namespace

template <int D>
std::unique_ptr<Effect<D>> makeADS(const Dictionary& d, const FlowState<D>&) {
  const double distance = key::distance.read(d);
  typename ADS<D>::Options o;
  o.pairwise = key::partners.read(d) == "pair";
  o.approachingOnly = key::approaching.read(d);
  o.wallDistance = key::wallDistance.readOr(d, distance);
  return std::make_unique<ADS<D>>(distance, key::C.read(d), o);
}

template <int D>
std::string ADS<D>::describe() const {
  return cat("distance = ", distance_, " d0 (wall partners ", o_.wallDistance, " d0), C = ", C_, ", partners ", o_.pairwise ? "pair" : "surface",
             o_.approachingOnly ? ", approaching pairs only" : "", ", on free-surface and vicinity particles");
}

template <int D>
void ADS<D>::correctPositions(FlowState<D>& s) {
  if (delta_.size() != s.size()) throw std::logic_error("ads: allocate() was not called for this particle count");
  const auto& nl = s.neighbours;
  const double dFluid = distance_ * s.d0, dWall = o_.wallDistance * s.d0;
  // This rank's own particles (a ghost's position comes from its owner: IsphStep exchanges
  // the positions after the corrections).
  const long n = long(s.numOwned());
  const auto& u = s.particles.velocity;
  auto moved = [&](Index j) { return s.isFluid(j) && nearSurface(s.surfaceClass(j)); };
  long count = 0;
#pragma omp parallel for schedule(static) reduction(+ : count)
  for (long i = 0; i < n; ++i) {
    Vec<D> d = Vec<D>::Zero();
    const bool mi = moved(Index(i));
    // A pair acts when one of its particles is near the surface; with partners pair an
    // interior fluid particle takes its half of a pair it shares with one.
    if (mi || (o_.pairwise && s.isFluid(Index(i)))) {
      for (Index k = nl.begin(i); k < nl.end(i); ++k) {
        const Index j = nl.j[k];
        const Vec<D> rij = nl.rij(std::size_t(i), k);
        const double r = rij.norm(), dAds = s.isFluid(j) ? dFluid : dWall;
        if (!(r < dAds) || !(r > 0)) continue;
        const bool mj = moved(j);
        if (!mi && !mj) continue;
        if (o_.approachingOnly && (u[i] - u[j]).dot(rij) >= 0) continue;
        double omega;
        if (!s.isFluid(j)) omega = 1.0;                  // a wall: the fluid particle takes it all
        else if (o_.pairwise || mj) omega = 0.5;         // both partners move
        else omega = 1.0;                                // partners surface: interior j stays
        d += (omega * (dAds - r) / r) * rij;
      }
    }
    delta_[i] = C_ * d;
    if (d.squaredNorm() > 0) ++count;
  }
  auto& x = s.particles.position;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) x[i] += delta_[i];
  this->actionCount_ = count;
}

SHIZUKU_EFFECT(ADS, makeADS);

}  // namespace shizuku
