// The lattice of a wall box of any size: see WallLattice.hpp.
#include "particles/WallLattice.hpp"
#include "particles/PointGrid.hpp"
#include <algorithm>
#include <cmath>

namespace shizuku {

WallSpacing wallSpacing(double min, double max, double d0) {
  WallSpacing a;
  a.spacings = (max - min) / d0;
  const double n = std::round(a.spacings);
  a.whole = n >= 1 && std::abs(a.spacings - n) <= 1e-6;
  a.intervals = a.whole ? long(n) : long(std::ceil(a.spacings));
  a.spacing = a.whole ? d0 : (max - min) / double(a.intervals);
  return a;
}

WallSpacing fluidSpacing(double min, double max, double d0) {
  WallSpacing a = wallSpacing(min, max, d0);
  if (a.whole) return a;
  a.intervals = std::max(1L, std::lround(a.spacings));
  a.spacing = (max - min) / double(a.intervals);
  return a;
}

WallAxis wallAxis(double min, double max, double d0, int layers, bool openLow, bool openHigh) {
  WallAxis a;
  static_cast<WallSpacing&>(a) = wallSpacing(min, max, d0);
  const long lo = openLow ? 0 : layers, hi = openHigh ? 0 : layers;
  a.x.reserve(lo + a.intervals + hi);
  // The whole-number axis keeps one lattice from min (the form every whole box used).
  for (long i = -lo; i < 0; ++i) a.x.push_back(min + (double(i) + 0.5) * d0);
  a.innerBegin = long(a.x.size());
  for (long i = 0; i < a.intervals; ++i) a.x.push_back(min + (double(i) + 0.5) * a.spacing);
  a.innerEnd = long(a.x.size());
  for (long i = 0; i < hi; ++i)
    a.x.push_back(a.whole ? min + (double(a.intervals + i) + 0.5) * d0 : max + (double(i) + 0.5) * d0);
  return a;
}

template <int D>
void wallBoxPoints(const std::array<WallAxis, D>& axes, std::vector<Vec<D>>& points) {
  std::array<long, D> i{};
  for (int k = 0; k < D; ++k)
    if (axes[k].x.empty()) return;
  for (;;) {
    bool inside = true;
    Vec<D> x;
    for (int k = 0; k < D; ++k) {
      inside = inside && i[k] >= axes[k].innerBegin && i[k] < axes[k].innerEnd;
      x[k] = axes[k].x[i[k]];
    }
    if (!inside) points.push_back(x);
    int k = 0;
    for (; k < D; ++k) {
      if (++i[k] < long(axes[k].x.size())) break;
      i[k] = 0;
    }
    if (k == D) return;
  }
}

template <int D>
void solidBoxPoints(const std::array<WallAxis, D>& axes, int layers, std::vector<Vec<D>>& points) {
  std::array<long, D> lo{}, hi{};
  for (int k = 0; k < D; ++k) {
    hi[k] = long(axes[k].x.size());
    if (hi[k] == 0) return;
  }
  forEachIndex<D>(lo, hi, [&](const std::array<long, D>& i) {
    bool band = false;
    Vec<D> x;
    for (int k = 0; k < D; ++k) {
      band = band || i[k] < layers || i[k] >= hi[k] - layers;
      x[k] = axes[k].x[std::size_t(i[k])];
    }
    if (band) points.push_back(x);
  });
}

template void solidBoxPoints<2>(const std::array<WallAxis, 2>&, int, std::vector<Vec<2>>&);
template void solidBoxPoints<3>(const std::array<WallAxis, 3>&, int, std::vector<Vec<3>>&);
template void wallBoxPoints<2>(const std::array<WallAxis, 2>&, std::vector<Vec<2>>&);
template void wallBoxPoints<3>(const std::array<WallAxis, 3>&, std::vector<Vec<3>>&);

}  // namespace shizuku
