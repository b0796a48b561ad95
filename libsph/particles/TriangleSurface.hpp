// A closed triangulated surface (an STL part after scale, rotate and translate) and the
// two queries a solid body needs, each O(1) per point in practice through two uniform
// grids over its bounding box, each of at most 4e6 cells: cubic cells the size of the
// search reach for the distance, and (y, z) columns twice the mean edge long for the
// crossings (a column then holds a few triangles wherever the surface is not grazing):
//  - inside(x): the parity of the crossings of the ray from x along +x with the triangles
//    of the (y, z) column holding x. Where the ray meets an edge or a vertex exactly (a
//    lattice aligned with the mesh's edges, as for a cube), the tie is broken by one
//    symbolic perturbation of the ray, (y, z) + (eps, eps^2), and each edge's side is
//    computed from its endpoints in a fixed (lexicographic) order, so the two triangles
//    sharing an edge agree and a closed surface is crossed an odd number of times from any
//    point inside it. A crossing's x is the barycentric mean of the triangle's vertices, so
//    it lies within the triangle whatever its slope;
//  - distance(x, reach): the distance to the nearest triangle (closest point on the
//    triangle: the projection onto its plane when that falls inside, else the nearest point
//    of its edges), searched among the triangles of the cells within `reach` of x; `reach`
//    when none is closer; anyWithin(x, r): is a triangle at most r away? (stops at the
//    first). Both look at the cell holding x first and skip a triangle whose bounding
//    sphere lies farther than the distance sought.
// crossings(y, z) lists the crossings of a whole lattice row at once (the generator's fill).
// Orientation of the triangles does not matter. Reads no keys.
#pragma once
#include "core/types.hpp"
#include <array>
#include <vector>

namespace shizuku {

class TriangleSurface {
 public:
  using Triangle = std::array<int, 3>;  // indices into the vertices
  TriangleSurface(std::vector<Vec<3>> vertices, std::vector<Triangle> triangles, double cell);

  bool inside(const Vec<3>& x) const;
  // The x of every crossing of the line (., y, z) with the surface, sorted.
  void crossings(double y, double z, std::vector<double>& xs) const;
  double distance(const Vec<3>& x, double reach) const;
  bool anyWithin(const Vec<3>& x, double r) const;

  const Vec<3>& lower() const { return lo_; }
  const Vec<3>& upper() const { return hi_; }
  double area() const { return area_; }
  // Enclosed, by the divergence theorem: right for a consistently oriented surface (as STL
  // requires); used only to estimate particle counts.
  double volume() const { return volume_; }
  std::size_t size() const { return tri_.size(); }

 private:
  template <class F> void forEachCrossing(double y, double z, F&& f) const;
  template <class F> bool forEachNear(const Vec<3>& x, double r, F&& f) const;
  double sphereGap(const Vec<3>& x, int t) const;  // |x - centre| - radius of triangle t's sphere
  long cellOf(double x, int k) const;
  long columnOf(double x, int k) const;  // k = 1 (y) or 2 (z)
  void binCells();
  void binColumns();

  std::vector<Vec<3>> v_;
  std::vector<Triangle> tri_;
  Vec<3> lo_, hi_;
  double cell_ = 0, area_ = 0, volume_ = 0;
  std::array<long, 3> n_{};                  // cells per axis
  double column_ = 0;                        // the columns' side
  std::array<long, 3> m_{};                  // columns along y (m_[1]) and z (m_[2])
  std::vector<long> cellStart_, columnStart_;  // CSR offsets: 3D cells, (y, z) columns
  std::vector<int> cellTri_, columnTri_;       // the triangles of each cell, of each column
  std::vector<Vec<3>> centre_;                 // each triangle's bounding sphere: its centroid
  std::vector<double> radius_;                 // and the farthest vertex from it
};

}  // namespace shizuku
