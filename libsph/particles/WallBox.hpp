// A wall region as the generator built it (particlesDict `type wall; shape box;`), kept
// for the pieces that need the solid's geometry after set-up: the domain (its default
// bounds) and the leak detector (the layer region and the closed faces).
//   min, max:            the wall surface (inner faces), m
//   layers, d0:          rows of wall particles outside the surface, spacing
//   open[2k], open[2k+1]: faces -x_k, +x_k without layers (left right bottom top front back)
//   outerMin, outerMax:  the surface grown by the layers on its closed faces
// Reads no dictionary keys.
#pragma once
#include "core/types.hpp"
#include <array>
#include <string>

namespace shizuku {

template <int D>
struct WallBox {
  std::string name;
  Vec<D> min = Vec<D>::Zero(), max = Vec<D>::Zero();
  Vec<D> outerMin = Vec<D>::Zero(), outerMax = Vec<D>::Zero();
  std::array<bool, 2 * D> open{};
  int layers = 0;
  double d0 = 0;

  // Inside the layer region deeper than `depth` past the surface: within the outer box,
  // more than `depth` outside the surface box across a closed face k, and more than
  // `depth` inside the outer box along every other axis. The last condition keeps a
  // particle that skirts the outside of a wall box's corner (an obstacle's, where the
  // layers of two faces meet) from counting: its centre may come within d0/2 of the
  // outer rows there as it may of the surface, while in a wall's thickness (across k) any
  // depth counts.
  bool inLayers(const Vec<D>& x, double depth) const {
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
};

}  // namespace shizuku
