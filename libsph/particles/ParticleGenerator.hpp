// Initial particles from system/particlesDict (docs/design.md 1.2; lattice and
// wall layers as docs/method.md section 11: fluid at (i + 1/2) d0 from a wall
// line, dummy layers at -(k + 1/2) d0, k = 0..layers-1; curved and STL bodies
// as docs/boundaries.md, "Curved and STL solids").
//
// Keys read (declared once, with defaults and ranges, in ParticleGenerator.cpp;
// the tables in docs/dictionaries.md are generated from those declarations):
//   spacing  d0 (a length, > 0)
//   dimension 2 | 3 (optional; the solver chooses 2D or 3D from it; must equal D)
//   regions { <name> { type fluid|wall|inlet|outlet; shape box|circle|sphere|cylinder|stl; ... } }
//            (in file order; inlets and outlets: OpenBoundaryRegion.hpp, boxes only)
//   periodic { min (..); max (..); directions (x y); }              (optional)
//   maxParticles N (optional, at most 2^31 - 1): the regions
//            are counted before anything is allocated (each region alone,
//            then all together, before overlap removal; a disc, ball, cylinder or
//            STL region by its volume, or its layers' volume, over d0^D; the exact
//            total is checked at the end) and a case over the limit is an
//            InputError naming the region and the count.
//
// Fluid regions
//   shape box:    min, max. Per direction k, with L_k = max_k - min_k:
//                 a whole number n of spacings (within 1e-6 d0): particles at
//                 min_k + (i + 1/2) d0, i = 0 .. n-1 (the d0 lattice);
//                 otherwise m = round(L_k/d0) intervals of s_k = L_k/m
//                 (WallLattice.hpp fluidSpacing), particles at
//                 min_k + (i + 1/2) s_k, so the box is filled to both faces:
//                 against a wall of any size the outer particles sit
//                 s_k/2 = d0/2 (1 +- 1/(2m)) from the wall surface, as on the
//                 d0 lattice (no empty strip at the `max` side), and no two
//                 are closer than 0.75 d0. Not reported.
//   shape circle: centre, radius (a sphere in 3D; `sphere` is accepted as
//                 another name). Lattice: centre + (i + 1/2) d0 in every
//                 direction, i any integer, i.e. the lattice of a box whose
//                 faces lie a whole number of spacings from the centre; points
//                 kept when strictly inside: |x - centre| < radius - 1e-9 d0.
//                 The disc is symmetric under x -> -x, y -> -y about centre.
//   shape cylinder (3D; in 2D an error: a disc is `shape circle`): point1, point2
//                 (the centres of the end caps, on the axis; distinct), radius. Lattice
//                 point1 + (i + 1/2) d0; points kept where phi < -1e-9 d0 (phi: the
//                 signed distance, CylinderShape.hpp), so an axis along a lattice
//                 direction has its first row d0/2 inside each cap.
//   shape stl (3D; in 2D an error): file "<path>" (ASCII or binary STL, read by
//                 VTK's vtkSTLReader, coincident points merged), relative to the case
//                 directory (the folder above system/ holding particlesDict) or
//                 absolute; scale s (> 0, default 1), rotate { axis (..); angle a; }
//                 (degrees, no unit; counter-clockwise seen from the axis's tip, about
//                 the origin; absent: none), translate (..) (default 0): a file point x
//                 goes to R (s x) + translate (scale, then rotate, then translate).
//                 Lattice: the lower corner of the moved surface's bounding box
//                 + (i + 1/2) d0 (an axis-aligned cube of a whole number of spacings gives
//                 exactly the particles of the equivalent box); points kept where the
//                 point is inside (ray parity) and farther than 1e-9 d0 from every triangle.
//   A fluid cylinder or stl region overlapping another fluid region is found on the
//   particles (one of either lies inside the other), after filling.
//   velocity { type uniform; value (..); }                  U = value
//            { type rigidRotation; omega w; centre (..); }  2D: U = w (-(y-cy), x-cx),
//                 counter-clockwise for w > 0 (right-hand rule about +z; the
//                 paper's clockwise rotating patch is omega -1 [1/s]);
//                 3D: omega is a vector, U = omega x (x - c). centre defaults to 0.
//            { type linear; gradient ((a b) (c d)); centre (..); }  U = G (x - c),
//                 G written row by row, centre defaults to 0.
//            { type expression; value ("f_x" "f_y"); }  muParser expressions of
//                 x y z (SI) with the constant pi, one per component.
//            Absent: U = 0.
//
// Wall regions
//   shape box: min, max are the wall SURFACE (the inner faces); `layers N`
//   rows of particles are built outside it, corners included: on the lattice
//   min + (i + 1/2) d0 where the size is a whole number of spacings, else each
//   face its own lattice (WallLattice.hpp: ceil(L/d0) intervals of L/ceil(L/d0)
//   <= d0 along the face, layers at d0 behind it), with a warning naming the
//   region, the axis, L/d0 and the face spacing. `open (top)` lists faces that get no
//   layers: left right bottom top (-x +x -y +y), in 3D also front back
//   (-z +z); on an open side the other walls end at the box edge. Wall particles
//   closer than 0.5 d0 to an earlier wall particle are dropped (walls that
//   share layers do not double them; a moving wall's particles are compared only with
//   those of walls that move the same way). Wall velocity is 0.
//   `motion { type translation|oscillating|rotation; ... }` (any wall shape; WallMotion.hpp)
//   makes the region move: its particles get the fields restPosition (where they are
//   built) and motion (the index of the region's motion + 1); the run moves them
//   (boundaries/MovingWalls.hpp). `motion` on a fluid, inlet or outlet region is an error.
//   `solid yes` makes the box a solid body (an obstacle) instead of a container: its
//   layers lie INSIDE the surface box, on the box's own lattice min + (i + 1/2) s_k
//   (s_k = L_k / ceil(L_k/d0) <= d0, d0 on a whole number of spacings), the points
//   within `layers` coordinates of a face on any axis (the core deeper than that stays
//   empty); the first layer sits s_k/2 behind each face. Every face is closed (`open`
//   is an error); fluid inside the box is removed and the fluid need not lie inside it.
//   shape circle|sphere (centre, radius), cylinder, stl (keys as for fluid): always a
//   solid body (`solid no` and `open` are errors; `solid yes` may be written). Its layers
//   are the lattice points (the shape's lattice, as for fluid) with
//   -(layers + 1e-9) d0 <= phi < -1e-9 d0: within `layers` d0 inside the surface, caps
//   included; the core deeper stays empty. A particle closer than 0.5 d0 to an earlier
//   wall's is dropped, as for boxes, and a curved or STL wall reports how many it lost
//   (a line in the log).
//   STL checks (InputError at `file`, naming the file's full path): missing, unreadable,
//   empty or without a triangle; not closed (the count of open edges: edges used by one
//   triangle or by more than two, vtkFeatureEdges); after scale, a part under 2 d0 or
//   over 1e5 d0 across in EVERY direction (wrong units: `scale 0.001;` for millimetres).
//   At most 10 maxParticles + 1e6 lattice rows may cross a curved or STL region's
//   bounding box (a thin body lying across a huge box), else an error at `shape`.
//
// Fluid particles closer than 0.5 d0 to a wall particle, or inside a wall's
// layer region (the box grown by `layers` d0 on its closed sides, minus the
// open interior; a solid box itself; a curved or STL solid where phi < -1e-9 d0),
// are removed; fluid outside a solid is kept. When the case has container walls,
// every fluid particle left must lie in the closed interior of some container (its surface box, boundary
// included, unbounded on an open side): fluid cut by a wall, with particles
// beyond its layers, is an error naming the region, the wall holding most of
// it, and how many particles lie beyond which of its faces.
// Errors (InputError, naming file, line and keyword): spacing <= 0, two
// fluid regions whose shapes overlap (both are named), a fluid region left
// empty, no fluid at all, a fluid region outside every wall or reaching
// outside the walls' interior (containers only: a solid holds no fluid), the
// curved and STL errors above, a fluid particle
// outside the periodic box in a periodic direction, a periodic length that is
// not a whole number of spacings, more particles than maxParticles, a
// coordinate more than 1e12 spacings from the origin, unknown keywords
// (checkAllRead on particlesDict).
//
// Output: fluid particles first (regions in file order, x fastest), then wall
// particles, then the inlets' and outlets' buffer particles; id = index, nextId the
// count; pressure, density, surface = 0; spacing = d0. Mass and rho0 are set later
// by the solver. `walls` holds every wall region (a curved or STL one with its
// SolidShape, and its bounding box as min, max), for the domain and the leak detector.
#pragma once
#include "core/Dictionary.hpp"
#include "particles/NeighbourList.hpp"
#include "particles/OpenBoundaryRegion.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/WallBox.hpp"
#include "particles/WallMotion.hpp"

namespace shizuku {

template <int D>
struct GeneratedParticles {
  ParticleSet<D> set;
  PeriodicBox<D> periodic;
  std::vector<WallBox<D>> walls;  // the wall regions, in file order
  std::vector<OpenBoundaryRegion<D>> openBoundaries;  // inlets and outlets, in file order
  std::vector<std::shared_ptr<WallMotion<D>>> motions;  // the moving walls' motions, in file order
};

// Default of the `maxParticles` keyword.
constexpr double kDefaultMaxParticles = 1e7;

// particleCap > 0 lowers the dictionary's maxParticles (a program that only
// previews or fuzzes cases uses it); it never raises it.
// The `spacing` keyword as declared (a length > 0), for readers other than the generator.
double readSpacing(const Dictionary& particlesDict);

template <int D>
GeneratedParticles<D> generateParticles(const Dictionary& particlesDict, double particleCap = 0);

}  // namespace shizuku
