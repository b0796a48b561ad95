// The particle lattice of one wall box of any size, and the spacing of a fluid box
// of any size (fluidSpacing below) (docs/method.md 11, "Wall boxes of any size";
// docs/boundaries.md). Along each axis k the wall box's surface
// [min_k, max_k] has length L_k:
//  - if L_k is a whole number n of spacings (within 1e-6 d0), the axis is the plain
//    lattice min_k + (i + 1/2) d0, i = -layers .. n + layers - 1 (bit for bit what
//    a whole box always gave);
//  - otherwise the faces ALONG k (the faces whose tangent has k) use m = ceil(L_k/d0)
//    intervals of s_k = L_k/m <= d0 at min_k + (i + 1/2) s_k, i = 0..m-1, and the
//    layers BEHIND the faces normal to k sit at d0 from the surface:
//    min_k - (a + 1/2) d0 and max_k + (a + 1/2) d0, a = 0..layers-1.
// The wall particles are the tensor product of the D axis coordinate lists minus the
// interior (every coordinate inside the surface); an open face has no layer
// coordinates on its side. Corners and edges are therefore rectilinear blocks at d0
// normal spacing whichever faces meet there.
// Properties (held by construction, tested on sweeps of sizes in 2D and 3D):
//   neighbouring coordinates on an axis are between 0.5 d0 and d0 apart (s_k <= d0;
//   s_k > d0/2 when L_k > d0; a box thinner than d0 has one coordinate, (d0 + L)/2
//   from the layers), so no gap wider than d0 opens along any lattice line, every
//   point of the layer region lies within sqrt(D)/2 d0 of a particle (as on the d0
//   lattice), and no two particles of one box are closer than 0.5 d0.
// Each wall particle carries the fluid particle's mass whatever its spacing (method.md 11).
// Reads no keys: the generator hands it the box.
#pragma once
#include "core/types.hpp"
#include <array>
#include <vector>

namespace shizuku {

// How the faces along one axis of length L = max - min are spaced (allocates nothing:
// the generator counts a box's particles with it before building any).
struct WallSpacing {
  double spacings = 0;     // L/d0
  bool whole = true;       // L/d0 within 1e-6 of a whole number n >= 1
  long intervals = 0;      // m: n, or ceil(L/d0)
  double spacing = 0;      // s = L/m (exactly d0 on a whole-number axis)
};
WallSpacing wallSpacing(double min, double max, double d0);

// How a FLUID box fills one axis of length L = max - min: d0 on a whole number n of
// spacings (as wallSpacing); otherwise m = round(L/d0) >= 1 intervals of s = L/m, so
// the particles at min + (i + 1/2) s sit s/2 = d0/2 (1 +- 1/(2m)) from both faces
// and no strip opens against a wall at either side. Nearest, not ceil: the fluid
// keeps its number density within 1/(2m) of the d0 lattice the mass is calibrated
// on (ceil would make it up to 1/m over-dense and, in 3D, class the top row next to
// the walls interior). Spacing between 0.75 d0 and 1.5 d0 (m = 1 up to L = 1.5 d0).
WallSpacing fluidSpacing(double min, double max, double d0);

// The coordinates of one axis of a wall box, in increasing order.
struct WallAxis : WallSpacing {
  std::vector<double> x;   // every coordinate: lower layers, face (inner) ones, upper layers
  long innerBegin = 0;     // x[innerBegin .. innerEnd) lie inside [min, max]
  long innerEnd = 0;
};

WallAxis wallAxis(double min, double max, double d0, int layers, bool openLow, bool openHigh);

// Appends the wall particles of the box with these axes (x fastest) to `points`.
template <int D>
void wallBoxPoints(const std::array<WallAxis, D>& axes, std::vector<Vec<D>>& points);

// A solid box (an obstacle): the axes hold only the inner coordinates (wallAxis with no
// layers, min + (i + 1/2) s_k); the points within `layers` coordinates of a face on any
// axis are appended (x fastest), the core deeper than that is left empty. The first
// layer sits s_k/2 <= d0/2 behind each face, as a container's does in front of it.
template <int D>
void solidBoxPoints(const std::array<WallAxis, D>& axes, int layers, std::vector<Vec<D>>& points);

}  // namespace shizuku
