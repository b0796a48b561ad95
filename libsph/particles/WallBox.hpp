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

  // Inside the layer region deeper than `depth` past the surface: within the outer box and
  // more than `depth` outside the surface box across a closed face.
  bool inLayers(const Vec<D>& x, double depth) const {
    bool deep = false;
    for (int k = 0; k < D; ++k) {
      if (x[k] <= outerMin[k] || x[k] >= outerMax[k]) return false;
      deep |= (!open[2 * k] && x[k] < min[k] - depth) || (!open[2 * k + 1] && x[k] > max[k] + depth);
    }
    return deep;
  }
};

}  // namespace shizuku
