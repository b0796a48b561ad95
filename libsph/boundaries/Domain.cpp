// The domain of a run: see Domain.hpp.
#include "boundaries/Domain.hpp"
#include "parallel/Communicator.hpp"
#include "core/Log.hpp"
#include "core/Parameter.hpp"
#include <algorithm>

namespace shizuku {

namespace {
namespace key {
const ParameterGroup domain("system/controlDict: domain",
    "The box fluid particles must stay in; one that leaves it is removed and logged "
    "(default: the walls' box extended beyond each open face by its own size; no walls: unbounded).");
const VectorParameter min = domain.vector("min", dim::length, "lower corner").required();
const VectorParameter max = domain.vector("max", dim::length, "upper corner").required();
}  // namespace key

template <int D>
std::string box(const Vec<D>& lo, const Vec<D>& hi) {
  std::string s = "min (";
  for (int k = 0; k < D; ++k) s += cat(k ? " " : "", lo[k]);
  s += ") max (";
  for (int k = 0; k < D; ++k) s += cat(k ? " " : "", hi[k]);
  return s + ") m";
}
}  // namespace

template <int D>
void Domain<D>::wallBounds(const WallBox<D>& w, Vec<D>& lo, Vec<D>& hi) {
  lo = w.outerMin;
  hi = w.outerMax;
  for (int k = 0; k < D; ++k) {
    const double size = w.outerMax[k] - w.outerMin[k];
    if (w.open[2 * k]) lo[k] -= size;
    if (w.open[2 * k + 1]) hi[k] += size;
  }
}

template <int D>
Domain<D> Domain<D>::read(const Dictionary& controlDict, const std::vector<WallBox<D>>& walls, const ParticleSet<D>& p) {
  Domain<D> d;
  const Dictionary* dict = controlDict.subDictPtr("domain");
  if (dict) {
    d = Domain<D>(key::min.read<D>(*dict), key::max.read<D>(*dict));
    for (int k = 0; k < D; ++k)
      if (!(d.max_[k] > d.min_[k]))
        dict->error("max", cat("the domain's max must exceed its min in every direction (", "xyz"[k], ": min ",
                               d.min_[k], ", max ", d.max_[k], ")"));
    d.describe_ = cat(box<D>(d.min_, d.max_), " (controlDict domain)");
  } else if (std::any_of(walls.begin(), walls.end(), [](const WallBox<D>& w) { return !w.solid; })) {
    Vec<D> lo, hi;
    wallBounds(walls[0], lo, hi);
    for (const auto& w : walls) {
      Vec<D> a, b;
      wallBounds(w, a, b);
      lo = lo.cwiseMin(a);
      hi = hi.cwiseMax(b);
    }
    d = Domain<D>(lo, hi);
    d.describe_ = cat(box<D>(lo, hi), " (the walls' box, extended beyond each open face by its size)");
  }
  if (dict) {
    // The first fluid particle outside, of the lowest rank that holds one: every rank
    // reports it (each holds its share of the particles).
    std::string outside;
    for (std::size_t i = 0; i < p.size() && outside.empty(); ++i)
      if (p.isFluid(i) && !d.contains(p.position[i])) {
        std::string where;
        for (int k = 0; k < D; ++k) where += cat(k ? " " : "", p.position[i][k]);
        outside = cat(d.side(p.position[i]).find('-') != std::string::npos ? "min" : "max",
                      "the domain does not hold the fluid: particle id ", p.id[i], " at (", where, ") lies outside ",
                      box<D>(d.min_, d.max_));
      }
    // The message carries the keyword to blame ("min" or "max") in its first three letters.
    outside = Communicator::world().firstMessage(outside);
    if (!outside.empty()) dict->error(outside.substr(0, 3), outside.substr(3));
  }
  return d;
}

template <int D>
std::string Domain<D>::side(const Vec<D>& x) const {
  static const char* names[6] = {"left (-x)", "right (+x)", "bottom (-y)", "top (+y)", "front (-z)", "back (+z)"};
  for (int k = 0; k < D; ++k) {
    if (!(x[k] >= min_[k])) return names[2 * k];
    if (!(x[k] <= max_[k])) return names[2 * k + 1];
  }
  return "inside";
}

template class Domain<2>;
template class Domain<3>;

}  // namespace shizuku
