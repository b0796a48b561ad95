// The geometry of a curved or triangulated body of system/particlesDict (a wall region
// `shape circle|sphere|cylinder|stl`, a solid body; a fluid region `shape cylinder|stl`),
// behind one interface shared by the generator (which lattice points are fluid, which are
// wall layers) and, at run time, the leak detector (is a fluid particle past the first
// layer of a solid?) (docs/boundaries.md, "Curved and STL solids"):
//   phi(x)        signed distance to the surface, < 0 inside, > 0 outside; exact where
//                 |phi| <= reach() (an analytic shape: everywhere), beyond that of the
//                 right sign and at least reach() in magnitude (a triangulated surface
//                 searches its triangles only that far);
//   deeperThan(x, depth)  phi(x) < -depth, searched no farther than depth;
//   lower(), upper()      the bounding box of the body;
//   rowSpan       the part of a lattice row (a line along x) that may hold points inside:
//                 the generator visits only those (O(points), not O(bounding box));
//   bandRow       which points of one row have phiMin <= phi < phiMax (a surface that
//                 finds the crossings of a row once, and only needs to know whether a
//                 triangle lies within a distance, overrides it);
//   kind()        "solid ball", "solid cylinder", "STL surface '<file>'" for messages;
//   volume(), shellVolume(depth)  for the particle count before anything is allocated.
// One class per shape: BallShape.hpp (circle, sphere), CylinderShape.hpp, StlShape.hpp.
// Reads no keys (ShapeRegion.cpp reads them).
#pragma once
#include "core/types.hpp"
#include <cmath>
#include <string>

namespace shizuku {

template <int D>
class SolidShape {
 public:
  virtual ~SolidShape() = default;
  virtual double phi(const Vec<D>& x) const = 0;
  virtual bool deeperThan(const Vec<D>& x, double depth) const { return inBox(x, 0) && phi(x) < -depth; }
  virtual double reach() const { return INFINITY; }
  virtual std::string kind() const = 0;
  virtual double volume() const = 0;
  // Volume of the layer -depth <= phi < 0 (an estimate for a triangulated surface).
  virtual double shellVolume(double depth) const = 0;

  // The interval [lo, hi] of x, widened by `margin` on both sides, outside which the row
  // through `rowPoint` (its coordinates other than x) holds no point with phi < 0; false
  // when the row misses the body. Default: the bounding box.
  virtual bool rowSpan(const Vec<D>& rowPoint, double margin, double& lo, double& hi) const {
    for (int k = 1; k < D; ++k)
      if (rowPoint[k] < lower_[k] - margin || rowPoint[k] > upper_[k] + margin) return false;
    lo = lower_[0] - margin;
    hi = upper_[0] + margin;
    return true;
  }
  // keep[j] = phiMin <= phi < phiMax at rowPoint with x = xs[j], j < n.
  virtual void bandRow(const Vec<D>& rowPoint, const double* xs, long n, double phiMin, double phiMax,
                       char* keep) const {
    Vec<D> x = rowPoint;
    for (long j = 0; j < n; ++j) {
      x[0] = xs[j];
      const double p = phi(x);
      keep[j] = p >= phiMin && p < phiMax;
    }
  }

  const Vec<D>& lower() const { return lower_; }
  const Vec<D>& upper() const { return upper_; }
  // Within the bounding box grown by `margin`.
  bool inBox(const Vec<D>& x, double margin) const {
    for (int k = 0; k < D; ++k)
      if (!(x[k] >= lower_[k] - margin && x[k] <= upper_[k] + margin)) return false;
    return true;
  }

 protected:
  Vec<D> lower_ = Vec<D>::Zero(), upper_ = Vec<D>::Zero();
};

}  // namespace shizuku
