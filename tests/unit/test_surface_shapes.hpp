// Curved lattice bodies with a known surface for the free-surface, surface-fit and
// shifting tests: the lattice points (spacing 1) of a ball |x| <= R (a disc in 2D) or, in
// 3D, of a cylinder x^2 + y^2 <= R^2 periodic along z. Each site carries its depth below
// the exact surface and two geometric surface flags: a lattice neighbour site along an
// axis lies outside (the outermost layer, the disc test's definition in
// test_effects_surfaceFit.cpp), or any of the 3^D - 1 neighbour sites lies outside.
#pragma once
#include "test_effects_fixture.hpp"
#include <limits>
#include <vector>

namespace shizuku::testing {

struct BodySite {
  std::array<int, 3> idx;
  double depth;      // R - distance from the centre (ball) or the axis (cylinder)
  bool axisOutside;  // an axis neighbour site is outside the body
  bool anyOutside;   // a site of the 3^D block around it is outside the body
};

// The part of x that is curved: all of it for a ball, (x, y, 0) for a cylinder.
template <int D>
Vec<D> curvedPart(const Vec<D>& x, bool cylinder) {
  Vec<D> y = x;
  if (cylinder) y[D - 1] = 0;
  return y;
}

// Sites of the ball (cylinder = false) or of the cylinder of length `length` (3D), keeping
// only those with depth < maxDepth (a shell: a fluid particle's SPH(2) weights depend
// only on sites within the support 2h = 2.4 of it).
template <int D>
std::vector<BodySite> bodySites(double R, bool cylinder = false, int length = 0,
                                double maxDepth = std::numeric_limits<double>::infinity()) {
  const int curved = cylinder ? 2 : D;
  auto inside = [&](const std::array<int, 3>& idx) {
    double r2 = 0;
    for (int k = 0; k < curved; ++k) r2 += double(idx[k]) * idx[k];
    return r2 <= R * R;
  };
  const int m = int(R) + 1;
  std::array<int, 3> lo{-m, -m, -m}, hi{m, m, m};
  if (cylinder) lo[2] = 0, hi[2] = length - 1;
  std::vector<BodySite> sites;
  forBox<D>(lo, hi, [&](const std::array<int, 3>& idx) {
    if (!inside(idx)) return;
    BodySite s{idx, R - curvedPart<D>(latticePoint<D>(idx, 1.0), cylinder).norm(), false, false};
    if (!(s.depth < maxDepth)) return;
    forBox<D>({-1, -1, -1}, {1, 1, 1}, [&](const std::array<int, 3>& o) {
      std::array<int, 3> j = idx;
      int steps = 0;
      for (int k = 0; k < D; ++k) j[k] += o[k], steps += o[k] != 0;
      if (inside(j)) return;
      s.anyOutside = true;
      s.axisOutside = s.axisOutside || steps == 1;
    });
    sites.push_back(s);
  });
  return sites;
}

// Makes a cylinder periodic along its axis (z over [-0.5, length - 0.5)).
template <int D>
void periodicAxis(Fixture<D>& f, int length) {
  f.s.periodic.periodic[D - 1] = true;
  f.s.periodic.lo = Vec<D>::Constant(-0.5);
  f.s.periodic.hi = Vec<D>::Constant(length - 0.5);
}

// Angle in degrees between two vectors (0 for parallel, 180 for opposite).
template <int D>
double angleDegrees(const Vec<D>& a, const Vec<D>& b) {
  const double c = a.dot(b) / (a.norm() * b.norm());
  return std::acos(std::max(-1.0, std::min(1.0, c))) * 180.0 / M_PI;
}

}  // namespace shizuku::testing
