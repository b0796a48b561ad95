// A closed STL surface as a SolidShape (SolidShape.hpp): particlesDict `shape stl;`, the
// triangles already scaled, rotated and translated (ShapeRegion.cpp). phi is the distance
// to the nearest triangle, searched within reach() (beyond: +-reach), negative inside
// (ray parity, TriangleSurface.hpp). A row of the lattice finds its crossings once
// (rowSpan, phiRow): from the first to the last crossing, inside where an odd number lie
// beyond the point. Reads no keys.
#pragma once
#include "particles/SolidShape.hpp"
#include "particles/TriangleSurface.hpp"
#include <algorithm>
#include <vector>

namespace shizuku {

class StlShape final : public SolidShape<3> {
 public:
  // reach: how far phi is exact (the generator needs the wall layers' depth).
  StlShape(TriangleSurface surface, std::string file, double reach)
      : surface_(std::move(surface)), file_(std::move(file)), reach_(reach) {
    lower_ = surface_.lower();
    upper_ = surface_.upper();
  }
  double phi(const Vec<3>& x) const override {
    const double d = surface_.distance(x, reach_);
    return surface_.inside(x) ? -d : d;
  }
  bool deeperThan(const Vec<3>& x, double depth) const override {
    return inBox(x, 0) && surface_.inside(x) && !(surface_.distance(x, depth) < depth);
  }
  double reach() const override { return reach_; }
  std::string kind() const override { return "STL surface '" + file_ + "'"; }
  double volume() const override { return surface_.volume(); }
  double shellVolume(double depth) const override { return std::min(volume(), surface_.area() * depth); }
  bool rowSpan(const Vec<3>& rowPoint, double margin, double& lo, double& hi) const override {
    std::vector<double> xs;
    surface_.crossings(rowPoint[1], rowPoint[2], xs);
    if (xs.empty()) return false;
    lo = xs.front() - margin;
    hi = xs.back() + margin;
    return true;
  }
  void phiRow(const Vec<3>& rowPoint, const double* xs, long n, double* out) const override {
    std::vector<double> crossing;
    surface_.crossings(rowPoint[1], rowPoint[2], crossing);
    Vec<3> x = rowPoint;
    for (long j = 0; j < n; ++j) {
      x[0] = xs[j];
      const auto beyond = crossing.end() - std::upper_bound(crossing.begin(), crossing.end(), x[0]);
      const double d = surface_.distance(x, reach_);
      out[j] = beyond % 2 ? -d : d;
    }
  }
  const TriangleSurface& surface() const { return surface_; }

 private:
  TriangleSurface surface_;
  std::string file_;
  double reach_;
};

}  // namespace shizuku
