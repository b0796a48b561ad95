// Inlets and outlets at run time: see OpenBoundaries.hpp.
#include "boundaries/OpenBoundaries.hpp"
#include "core/Log.hpp"
#include "parallel/AgreedFailure.hpp"
#include <cmath>

namespace shizuku {

namespace {
std::string fmt(double x) { return formatNumber(x); }
template <int D> std::string fmt(const Vec<D>& v) { return formatNumber<D>(v); }
}  // namespace

template <int D>
OpenBoundaries<D>::OpenBoundaries(std::vector<OpenBoundaryRegion<D>> regions, const FlowState<D>& s,
                                  const Domain<D>& domain)
    : regions_(std::move(regions)), d0_(s.d0) {
  const double support = s.kernel.support();
  for (const auto& b : regions_) {
    const char* kind = b.inlet ? "inlet" : "outlet";
    const bool faceAtMax = b.face == b.max[b.axis];
    if (b.length() < support * (1 - 1e-9)) {
      const double spacings = std::ceil(support / s.d0 - 1e-9);
      Vec<D> longer = faceAtMax ? b.min : b.max;
      longer[b.axis] = b.face + (faceAtMax ? -1 : 1) * spacings * s.d0;
      b.dict->error(faceAtMax ? "min" : "max",
                    cat(kind, " '", b.name, "' is ", fmt(b.length()), " m = ", fmt(b.length() / s.d0),
                        " spacings long along its direction; it must cover the kernel support 2h = ", fmt(support),
                        " m (", spacings, " spacings), so that fluid at its face has all its neighbours: did you mean ",
                        faceAtMax ? "min " : "max ", fmt<D>(longer), "?"));
    }
    if (domain.bounded() && !(domain.contains(b.min) && domain.contains(b.max)))
      b.dict->error(domain.contains(b.min) ? "max" : "min",
                    cat(kind, " '", b.name, "' box ", fmt<D>(b.min), "-", fmt<D>(b.max), " reaches outside the domain ",
                        domain.describe(), ": give the walls or controlDict's domain room for it"));
    velocity_.push_back(b.inlet ? std::make_unique<InletVelocity<D>>(b) : nullptr);
    crossings_.push_back({b.name, b.inlet, 0});
  }
}

template <int D>
OpenBoundaries<D>::~OpenBoundaries() = default;

template <int D>
std::vector<std::string> OpenBoundaries<D>::describe() const {
  std::vector<std::string> v;
  for (const auto& b : regions_)
    v.push_back(b.describe() + (b.inlet ? "; releases fluid at its face, pressure by the wall rule"
                                        : "; captures fluid at its face, velocity from the fluid (zero gradient)"));
  return v;
}

// The region of a buffer particle: the nearest box of its kind (the particle is in it, or
// has just crossed its face by less than a step's travel).
template <int D>
int OpenBoundaries<D>::regionOf(const Vec<D>& x, bool inlet) const {
  int best = -1;
  double bestD = INFINITY;
  for (std::size_t r = 0; r < regions_.size(); ++r) {
    const auto& b = regions_[r];
    if (b.inlet != inlet) continue;
    const double d = (x - x.cwiseMax(b.min).cwiseMin(b.max)).squaredNorm();
    if (d < bestD) { bestD = d; best = int(r); }
  }
  return best;
}

// Inlet r's velocity at x and t; an expression that fails or is not finite is a
// numerical failure (exit 2, last good state).
template <int D>
Vec<D> OpenBoundaries<D>::inletVelocity(int r, const Vec<D>& x, double t) const {
  Vec<D> u;
  try {
    u = (*velocity_[r])(x, t);
  } catch (const VelocityExpressionError& e) {
    throw NumericalError(cat("inlet '", regions_[r].name, "': ", e.what(), " at ", fmt<D>(x), " m, t = ", t, " s"));
  }
  if (!u.allFinite())
    throw NumericalError(cat("inlet '", regions_[r].name, "': the velocity expressions give ", fmt<D>(u), " at ",
                             fmt<D>(x), " m, t = ", t, " s"));
  return u;
}

template <int D>
void OpenBoundaries<D>::prescribe(FlowState<D>& s) {
  auto& P = s.particles;
  agreeOnFailure<NumericalError, NumericalError>([&] {
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (P.isInlet(i)) P.velocity[i] = inletVelocity(regionOf(P.position[i], true), P.position[i], s.time);
      else if (P.isOutlet(i)) P.pressure[i] = regions_[regionOf(P.position[i], false)].pressure;
    }
  });
}

template <int D>
bool OpenBoundaries<D>::afterStep(FlowState<D>& s) {
  auto& P = s.particles;
  const double dt = s.dt;
  const std::size_t n = P.size();
  bool changed = false;
  bool anyRemoved = false;
  remove_.assign(n, 0);
  released_.clear();
  // An inlet velocity that is not finite on one rank stops every rank (before the
  // ranks number the released particles together).
  agreeOnFailure<NumericalError, NumericalError>([&] {
    for (std::size_t i = 0; i < n; ++i) {
      if (P.isInlet(i)) {
        P.position[i] += dt * P.velocity[i];
        const int r = regionOf(P.position[i], true);
        const auto& b = regions_[r];
        if (b.pastFace(P.position[i]) <= 0) {
          P.velocity[i] = inletVelocity(r, P.position[i], s.time);
          continue;
        }
        // Released: it becomes fluid (keeping its velocity); its replacement goes one buffer
        // length upstream.
        P.type[i] = std::uint8_t(ParticleType::fluid);
        const std::size_t k = P.addCopy(i);
        P.type[k] = std::uint8_t(ParticleType::inlet);
        P.position[k][b.axis] -= b.sign * b.length();
        P.velocity[k] = inletVelocity(r, P.position[k], s.time);
        released_.push_back(k);
        remove_.push_back(0);
        ++crossings_[r].count;
        ++s.balance.released;
        changed = true;
      } else if (P.isOutlet(i)) {
        P.position[i] += dt * P.velocity[i];
        const int r = regionOf(P.position[i], false);
        if (regions_[r].pastFarFace(P.position[i]) > 0) {
          remove_[i] = 1;
          anyRemoved = true;
        } else if (regions_[r].pastFace(P.position[i]) < -0.5 * d0_) {
          // Carried back upstream by a backflow (its velocity is its fluid neighbours'): it
          // rejoins the fluid. Left an outlet particle, it would wander through the fluid
          // and into the walls as a p = 0 point the walls do not hold.
          P.type[i] = std::uint8_t(ParticleType::fluid);
          --crossings_[r].count;
          --s.balance.captured;
          changed = true;
        }
      } else if (P.isFluid(i)) {
        for (std::size_t r = 0; r < regions_.size(); ++r) {
          const auto& b = regions_[r];
          if (b.inlet || b.pastFace(P.position[i]) <= 0 || !b.acrossInside(P.position[i], 0.5 * d0_)) continue;
          P.type[i] = std::uint8_t(ParticleType::outlet);
          P.pressure[i] = b.pressure;
          ++crossings_[r].count;
          ++s.balance.captured;
          changed = true;
          if (b.pastFarFace(P.position[i]) > 0) { remove_[i] = 1; anyRemoved = true; }
          break;
        }
      }
    }
  });
  numberReleased(P);
  if (anyRemoved) P.removeMarked(remove_);
  return changed || anyRemoved;
}

// The new inlet particles' ids, in order from nextId, the ranks' in rank order, so that ids
// stay unique across ranks (in serial: nextId, nextId + 1, ...). Collective.
template <int D>
void OpenBoundaries<D>::numberReleased(ParticleSet<D>& P) const {
  const auto& world = Communicator::world();
  const long mine = long(released_.size());
  const std::int64_t first = P.nextId + world.exclusivePrefixSum(mine);
  for (std::size_t k = 0; k < released_.size(); ++k) P.id[released_[k]] = first + std::int64_t(k);
  P.nextId += world.sum(mine);
}

template class OpenBoundaries<2>;
template class OpenBoundaries<3>;

}  // namespace shizuku
