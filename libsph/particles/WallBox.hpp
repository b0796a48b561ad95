// A wall region as the generator built it (particlesDict `type wall;`: a box, or a curved
// or STL solid), kept for the pieces that need the solid's geometry after set-up: the
// domain (its default bounds), the leak detector (the layer region and the closed faces) and
// the wall normals (layerDepth: which wall holds a wall particle; outwardNormal: its wall
// surface's normal there, docs/method.md 11, eq. 11d).
//   min, max:            the wall surface (inner faces), m
//   layers, d0:          rows of wall particles outside the surface, spacing
//   open[2k], open[2k+1]: faces -x_k, +x_k without layers (left right bottom top front back)
//   outerMin, outerMax:  the surface grown by the layers on its closed faces
//   solid:               an obstacle (`solid yes`): the layers lie inside [min, max] behind
//                        its faces, the fluid outside; outerMin, outerMax = min, max and
//                        every face is closed
//   body:                a curved or STL solid (`shape circle|sphere|cylinder|stl`, always
//                        solid): its shape (SolidShape.hpp); min, max, outerMin, outerMax
//                        are its bounding box and its layers lie within `layers` d0 inside
//                        its surface; null for a box
//   motion:              the index of the region's motion in GeneratedParticles::motions (-1:
//                        fixed); the fields above are its rest position, where particlesDict
//                        builds it
//   covered:             a solid box's faces that lie against another wall (an obstacle's
//                        bottom on the tank's floor): fluid cannot reach the box through
//                        them, so depth inside the box is measured from its other faces,
//                        and its normals point through those (set by markCoveredFaces)
// Reads no dictionary keys.
#pragma once
#include "core/types.hpp"
#include "particles/SolidShape.hpp"
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace shizuku {

// The face a leak through a curved or STL solid is reported on (its surface), after the
// box faces 0..5 (-x +x -y +y -z +z).
constexpr int kBodySurface = 6;

template <int D>
struct WallBox {
  std::string name;
  Vec<D> min = Vec<D>::Zero(), max = Vec<D>::Zero();
  Vec<D> outerMin = Vec<D>::Zero(), outerMax = Vec<D>::Zero();
  std::array<bool, 2 * D> open{};
  int layers = 0;
  double d0 = 0;
  bool solid = false;
  std::shared_ptr<const SolidShape<D>> body;
  std::array<bool, 2 * D> covered{};
  int motion = -1;

  // Inside the layer region deeper than `depth` past the surface: within the outer box,
  // more than `depth` outside the surface box across a closed face k, and more than
  // `depth` inside the outer box along every other axis. The last condition keeps a
  // particle that skirts the outside of a wall box's corner (an obstacle's, where the
  // layers of two faces meet) from counting: its centre may come within d0/2 of the
  // outer rows there as it may of the surface, while in a wall's thickness (across k) any
  // depth counts.
  // A solid's layer region is the box itself: inside it deeper than `depth` past every face
  // that is not covered; a body's is the body: phi < -depth.
  bool inLayers(const Vec<D>& x, double depth) const {
    if (body) return body->deeperThan(x, depth);
    if (solid) {
      for (int k = 0; k < D; ++k)
        if (x[k] <= min[k] + (covered[2 * k] ? 0 : depth) || x[k] >= max[k] - (covered[2 * k + 1] ? 0 : depth))
          return false;
      return true;
    }
    for (int k = 0; k < D; ++k)
      if (x[k] <= outerMin[k] || x[k] >= outerMax[k]) return false;
    for (int k = 0; k < D; ++k) {
      if (!((!open[2 * k] && x[k] < min[k] - depth) || (!open[2 * k + 1] && x[k] > max[k] + depth))) continue;
      bool within = true;
      for (int j = 0; j < D; ++j)
        if (j != k) within &= x[j] > outerMin[j] + depth && x[j] < outerMax[j] - depth;
      if (within) return true;
    }
    return false;
  }

  // How far x lies behind the wall's surface when it is in the wall's layer region (a
  // particle of this wall), else infinity: a container's distance to the surface box, a solid
  // box's to its nearest uncovered face, a body's -phi. Which wall a particle belongs to.
  double layerDepth(const Vec<D>& x) const {
    const double slack = 1e-6 * d0;
    if (body) {
      for (int k = 0; k < D; ++k)
        if (x[k] < min[k] - slack || x[k] > max[k] + slack) return INFINITY;
      const double p = body->phi(x);
      return p <= slack ? std::max(0.0, -p) : INFINITY;
    }
    if (solid) {
      double depth = INFINITY;
      for (int f = 0; f < 2 * D; ++f) {
        const int k = f / 2;
        const double d = f % 2 ? max[k] - x[k] : x[k] - min[k];
        if (d < -slack) return INFINITY;
        if (!covered[f]) depth = std::min(depth, std::max(0.0, d));
      }
      return depth;
    }
    double d2 = 0;
    for (int k = 0; k < D; ++k) {
      if (x[k] < outerMin[k] - slack || x[k] > outerMax[k] + slack) return INFINITY;
      const double g = std::max({min[k] - x[k], x[k] - max[k], 0.0});
      d2 += g * g;
    }
    return d2 > 0 ? std::sqrt(d2) : INFINITY;
  }

  // The unit normal of the wall's surface seen from x in its layer region, pointing out of the
  // wall (into the fluid's side; docs/method.md 11, eq. 11d): a container's toward the nearest
  // point of its surface box (a face normal behind a face, diagonal behind an edge or corner);
  // a solid box's through its nearest uncovered face (faces tied for nearest summed); a body's
  // grad phi (central differences). Zero where it has none.
  Vec<D> outwardNormal(const Vec<D>& x) const {
    Vec<D> n = Vec<D>::Zero();
    if (body) {
      const double e = 1e-3 * d0;
      for (int k = 0; k < D; ++k) {
        Vec<D> a = x, b = x;
        a[k] += e;
        b[k] -= e;
        n[k] = body->phi(a) - body->phi(b);
      }
    } else if (solid) {
      const double depth = layerDepth(x), tie = 1e-6 * d0;
      for (int f = 0; f < 2 * D && std::isfinite(depth); ++f) {
        const int k = f / 2;
        const double d = f % 2 ? max[k] - x[k] : x[k] - min[k];
        if (!covered[f] && d <= depth + tie) n[k] += f % 2 ? 1.0 : -1.0;
      }
    } else {
      for (int k = 0; k < D; ++k) n[k] = std::clamp(x[k], min[k], max[k]) - x[k];
    }
    const double len = n.norm();
    return len > 0 ? Vec<D>(n / len) : Vec<D>::Zero();
  }

  // The face a particle in the layers came through: a container's closed face it lies
  // beyond, a solid's uncovered face nearest to it (0..2D-1: -x +x -y +y -z +z; -1: none), a
  // body's surface (kBodySurface).
  int faceOf(const Vec<D>& x) const {
    if (body) return kBodySurface;
    int face = -1;
    double nearest = INFINITY;
    for (int f = 0; f < 2 * D; ++f) {
      const int k = f / 2;
      if (!solid) {
        if (!open[f] && (f % 2 ? x[k] > max[k] : x[k] < min[k])) return f;
        continue;
      }
      const double depth = f % 2 ? max[k] - x[k] : x[k] - min[k];
      if (!covered[f] && depth < nearest) { nearest = depth; face = f; }
    }
    return face;
  }
};

// Marks each solid box's faces that lie against another wall region (`covered`: the point
// d0/2 outside the face's centre is in that wall's layers, as an obstacle's bottom on a
// tank's floor). Idempotent.
template <int D>
void markCoveredFaces(std::vector<WallBox<D>>& walls) {
  for (std::size_t w = 0; w < walls.size(); ++w) {
    WallBox<D>& b = walls[w];
    if (!b.solid || b.body) continue;
    for (int f = 0; f < 2 * D; ++f) {
      const int k = f / 2;
      Vec<D> outside = 0.5 * (b.min + b.max);
      outside[k] = f % 2 ? b.max[k] + 0.5 * b.d0 : b.min[k] - 0.5 * b.d0;
      for (std::size_t o = 0; o < walls.size() && !b.covered[std::size_t(f)]; ++o)
        if (o != w) b.covered[std::size_t(f)] = walls[o].inLayers(outside, 0.0);
    }
  }
}

}  // namespace shizuku
