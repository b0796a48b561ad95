// A closed STL surface as a SolidShape (SolidShape.hpp): particlesDict `shape stl;`, the
// triangles already scaled, rotated and translated (ShapeRegion.cpp). phi is the distance
// to the nearest triangle, searched within reach() (beyond: +-reach), negative inside
// (ray parity, TriangleSurface.hpp). A row of the lattice finds its crossings once
// (rowSpan, bandRow): from the first to the last crossing, inside where an odd number lie
// beyond the point; a band -a <= phi < -b inside is "a triangle within a, none within b",
// each search stopping at the first triangle found. A solid wall also samples phi on
// voxels of the spacing (PhiGrid.hpp), which answers deeperThan (the leak detector's
// question, every step) for all but the points within a voxel of the level asked for.
// Reads no keys.
#pragma once
#include "particles/PhiGrid.hpp"
#include "particles/SolidShape.hpp"
#include "particles/TriangleSurface.hpp"
#include <algorithm>
#include <vector>

namespace shizuku {

class StlShape final : public SolidShape<3> {
 public:
  // reach: how far phi is exact (the generator needs the wall layers' depth); voxel > 0:
  // the side of the voxels of the PhiGrid (none for 0).
  StlShape(TriangleSurface surface, std::string file, double reach, double voxel = 0)
      : surface_(std::move(surface)), file_(std::move(file)), reach_(reach) {
    lower_ = surface_.lower();
    upper_ = surface_.upper();
    // The voxels settle questions about depths up to about a voxel: they hold phi to 2 voxels.
    if (voxel > 0)
      grid_ = PhiGrid(lower_, upper_, voxel, 2 * voxel, [this, voxel](const Vec<3>& p, const std::vector<double>& xs,
                                                                     std::vector<double>& out) {
        phiRow(p, xs, 2 * voxel, out);
      });
  }
  double phi(const Vec<3>& x) const override {
    const double d = surface_.distance(x, reach_);
    return surface_.inside(x) ? -d : d;
  }
  bool deeperThan(const Vec<3>& x, double depth) const override {
    if (!inBox(x, 0)) return false;
    const int sure = grid_.empty() ? -1 : grid_.deeperThan(x, depth);
    if (sure >= 0) return sure == 1;
    return surface_.inside(x) && !surface_.anyWithin(x, depth);
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
  // Bands inside the surface (phiMax <= 0) by parity and two bounded searches; others by phi.
  void bandRow(const Vec<3>& rowPoint, const double* xs, long n, double phiMin, double phiMax,
               char* keep) const override {
    if (phiMax > 0) return SolidShape<3>::bandRow(rowPoint, xs, n, phiMin, phiMax, keep);
    std::vector<double> crossing;
    surface_.crossings(rowPoint[1], rowPoint[2], crossing);
    Vec<3> x = rowPoint;
    for (long j = 0; j < n; ++j) {
      x[0] = xs[j];
      const bool inside = (crossing.end() - std::upper_bound(crossing.begin(), crossing.end(), x[0])) % 2;
      keep[j] = inside && !surface_.anyWithin(x, -phiMax) && (phiMin == -INFINITY || surface_.anyWithin(x, -phiMin));
    }
  }
  const TriangleSurface& surface() const { return surface_; }
  bool hasGrid() const { return !grid_.empty(); }

 private:
  // phi at the points xs of the row through p, its crossings found once, clamped to +-reach.
  void phiRow(const Vec<3>& p, const std::vector<double>& xs, double reach, std::vector<double>& out) const {
    std::vector<double> crossing;
    surface_.crossings(p[1], p[2], crossing);
    out.resize(xs.size());
    Vec<3> x = p;
    for (std::size_t j = 0; j < xs.size(); ++j) {
      x[0] = xs[j];
      const bool inside = (crossing.end() - std::upper_bound(crossing.begin(), crossing.end(), x[0])) % 2;
      const double d = surface_.distance(x, reach);
      out[j] = inside ? -d : d;
    }
  }

  TriangleSurface surface_;
  std::string file_;
  double reach_;
  PhiGrid grid_;
};

}  // namespace shizuku
