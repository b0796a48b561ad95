// Wall leaks: see LeakDetector.hpp.
#include "boundaries/LeakDetector.hpp"
#include "core/Log.hpp"
#include <algorithm>

namespace shizuku {

const char* faceLabel(int face) {
  static const char* names[7] = {"left (-x)", "right (+x)", "bottom (-y)", "top (+y)", "front (-z)", "back (+z)",
                                 "surface (of a curved or STL solid)"};
  return face >= 0 && face <= kBodySurface ? names[face] : "?";
}

template <int D>
LeakDetector<D>::LeakDetector(std::vector<WallBox<D>> walls) : walls_(std::move(walls)) {
  markCoveredFaces(walls_);
}

// Whether the segment from -> to passes through the layers of closed face `face`: one end
// on the inner side of the surface, the other beyond the outer layer, and the point where
// it meets the surface plane within the face (layers included).
template <int D>
bool LeakDetector<D>::crossed(const WallBox<D>& w, int face, const Vec<D>& from, const Vec<D>& to) const {
  const int k = face / 2;
  const bool plus = face % 2;
  const double surface = plus ? w.max[k] : w.min[k], outer = plus ? w.outerMax[k] : w.outerMin[k];
  auto inner = [&](const Vec<D>& x) { return plus ? x[k] <= surface : x[k] >= surface; };
  auto beyond = [&](const Vec<D>& x) { return plus ? x[k] >= outer : x[k] <= outer; };
  if (!((inner(from) && beyond(to)) || (beyond(from) && inner(to)))) return false;
  const double t = (surface - from[k]) / (to[k] - from[k]);
  for (int j = 0; j < D; ++j) {
    if (j == k) continue;
    const double y = from[j] + t * (to[j] - from[j]);
    if (y < w.outerMin[j] || y > w.outerMax[j]) return false;
  }
  return true;
}

template <int D>
void LeakDetector<D>::find(const ParticleSet<D>& p, const std::vector<Vec<D>>& previous,
                           const PeriodicBox<D>& periodic, std::vector<Leak>& leaks, const std::vector<Pose<D>>& poses,
                           const std::vector<Pose<D>>& previousPoses) const {
  leaks.clear();
  if (walls_.empty()) return;
  const long n = long(p.size());
  const bool withPrevious = previous.size() == p.size();
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    if (!p.isFluid(std::size_t(i))) continue;
    const Vec<D>& now = p.position[std::size_t(i)];
    for (int w = 0; w < int(walls_.size()); ++w) {
      const WallBox<D>& b = walls_[std::size_t(w)];
      const bool moving = b.motion >= 0;
      const Vec<D> x = moving ? poses[std::size_t(b.motion)].restPosition(now) : now;
      Leak l{Index(i), w, -1, false};
      if (b.inLayers(x, 0.5 * b.d0)) {
        l.face = b.faceOf(x);
      } else if (withPrevious && !b.solid) {
        // The minimum image of the previous position: a periodic wrap is no crossing.
        const Vec<D> before = now - periodic.difference(now, previous[std::size_t(i)]);
        const Vec<D> from = moving ? previousPoses[std::size_t(b.motion)].restPosition(before) : before;
        for (int f = 0; f < 2 * D && l.face < 0; ++f)
          if (!b.open[f] && crossed(b, f, from, x)) { l.face = f; l.crossed = true; }
      }
      if (l.face >= 0) {
#pragma omp critical(shizukuLeaks)
        leaks.push_back(l);
        break;
      }
    }
  }
  std::sort(leaks.begin(), leaks.end(), [](const Leak& a, const Leak& b) { return a.particle < b.particle; });
}

template <int D>
std::string LeakDetector<D>::describe(const Leak& l) const {
  const WallBox<D>& w = walls_[std::size_t(l.wall)];
  if (w.body) return cat("wall '", w.name, "' (", w.body->kind(), ")");
  return cat("wall '", w.name, "', face ", faceLabel(l.face));
}

template class LeakDetector<2>;
template class LeakDetector<3>;

}  // namespace shizuku
