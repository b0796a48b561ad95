// The curved and triangulated regions of system/particlesDict (docs/boundaries.md, "Curved
// and STL solids"): their SolidShape (SolidShape.hpp) and where their lattice sits, and
// the lattice points a fluid region fills (phi < 0) or a solid wall's layers hold
// (-layers d0 <= phi < 0). ParticleGenerator.hpp states the rules; this file reads the keys
// of the cylinder and the STL surface:
//   shape cylinder: point1 (..); point2 (..) (the axis, end caps through them; radius is
//                   read by the generator). 3D only.
//   shape stl:      file "constant/triSurface/part.stl" (relative to the case directory,
//                   or absolute; ASCII or binary), scale s (default 1), rotate { axis (..);
//                   angle a; } (degrees, right-handed about the axis through the origin),
//                   translate (..) (default 0): x = R(axis, angle) (s x_file) + translate.
//                   3D only. The surface must be closed; a part under 2 d0 or over 1e5 d0
//                   across in every direction is refused as wrong units.
// Errors are InputError naming file, line and keyword.
#pragma once
#include "core/Dictionary.hpp"
#include "particles/SolidShape.hpp"
#include <memory>
#include <string>
#include <vector>

namespace shizuku {

// A file named in a case dictionary: relative to the case directory, or absolute.
std::string resolveCasePath(const std::string& caseDir, const std::string& file);

template <int D>
struct ShapeRegion {
  std::shared_ptr<const SolidShape<D>> shape;
  Vec<D> anchor = Vec<D>::Zero();  // the lattice: anchor + (i + 1/2) d0 along every axis
};

// A disc or ball on the lattice centred on it (centre + (i + 1/2) d0).
template <int D>
ShapeRegion<D> ballRegion(const Vec<D>& centre, double radius);

// `shape cylinder`: point1, point2 from r; the lattice point1 + (i + 1/2) d0. 2D: an error.
template <int D>
ShapeRegion<D> readCylinderRegion(const Dictionary& r, double radius, double d0);

// `shape stl`: the surface read, checked (closed, units) and moved; the lattice from the
// lower corner of its bounding box. reach: how far phi is exact; voxel > 0: the side of its
// phi voxels (a solid wall: d0; StlShape.hpp). caseDir: where a relative `file` is looked
// for. 2D: an error.
template <int D>
ShapeRegion<D> readStlRegion(const Dictionary& r, double d0, double reach, double voxel, const std::string& caseDir);

// The lattice rows (lines along x) the region's bounding box spans must stay below
// 10 maxParticles + 1e6 (a thin body lying across the lattice), else an error at `shape`.
template <int D>
void checkLatticeRows(const Dictionary& r, const std::string& name, const ShapeRegion<D>& s, double d0, double limit);

// Appends the lattice points with phiMin <= phi < phiMax, x fastest, visiting only the
// span of each row that may hold points inside (SolidShape::rowSpan).
template <int D>
void shapeLatticePoints(const ShapeRegion<D>& s, double d0, double phiMin, double phiMax, std::vector<Vec<D>>& points);

}  // namespace shizuku
