// A closed triangulated surface: inside test and distance, see TriangleSurface.hpp.
#include "particles/TriangleSurface.hpp"
#include <algorithm>
#include <cmath>
#include <utility>

namespace shizuku {

namespace {

constexpr double kMaxCells = 4e6;

// The side of p of the directed edge u -> v in the (y, z) plane (> 0: left), as the raw
// cross product `w` and its sign with the tie w = 0 broken by p + (eps, eps^2). The
// endpoints are taken in lexicographic order and the result negated when swapped, so the
// two triangles sharing an edge compute the same number and always disagree on the side.
struct Side {
  double w;
  int sign;
};

Side side(const Vec<2>& u, const Vec<2>& v, const Vec<2>& p) {
  const bool swap = v[0] < u[0] || (v[0] == u[0] && v[1] < u[1]);
  const Vec<2>& a = swap ? v : u;
  const Vec<2>& b = swap ? u : v;
  const double w = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
  // w(p + (eps, eps^2)) = w(p) - (b_z - a_z) eps + (b_y - a_y) eps^2.
  const double tie = b[1] != a[1] ? a[1] - b[1] : b[0] - a[0];
  const double s = w != 0 ? w : tie;
  const int sign = s > 0 ? 1 : s < 0 ? -1 : 0;
  return swap ? Side{-w, -sign} : Side{w, sign};
}

double segmentDistance2(const Vec<3>& p, const Vec<3>& a, const Vec<3>& b) {
  const Vec<3> ab = b - a, ap = p - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0 ? std::clamp(ap.dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (ap - t * ab).squaredNorm();
}

// Squared distance from p to the triangle abc: to its plane when p projects inside it (on
// the inner side of the three edges, seen along the normal), else to the nearest edge.
double triangleDistance2(const Vec<3>& p, const Vec<3>& a, const Vec<3>& b, const Vec<3>& c) {
  const Vec<3> n = (b - a).cross(c - a);
  const double nn = n.squaredNorm();
  if (nn > 0 && (b - a).cross(p - a).dot(n) >= 0 && (c - b).cross(p - b).dot(n) >= 0 &&
      (a - c).cross(p - c).dot(n) >= 0) {
    const double h = (p - a).dot(n);
    return h * h / nn;
  }
  return std::min({segmentDistance2(p, a, b), segmentDistance2(p, b, c), segmentDistance2(p, c, a)});
}

// CSR lists from (bin, triangle) pairs: start[b] .. start[b + 1] index into items.
void toCsr(std::vector<std::pair<long, int>>& pairs, long bins, std::vector<long>& start, std::vector<int>& items) {
  std::sort(pairs.begin(), pairs.end());
  start.assign(std::size_t(bins) + 1, 0);
  for (const auto& p : pairs) ++start[std::size_t(p.first) + 1];
  for (long b = 0; b < bins; ++b) start[std::size_t(b) + 1] += start[std::size_t(b)];
  items.resize(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) items[i] = pairs[i].second;
}

}  // namespace

TriangleSurface::TriangleSurface(std::vector<Vec<3>> vertices, std::vector<Triangle> triangles, double cell)
    : v_(std::move(vertices)), tri_(std::move(triangles)) {
  lo_ = Vec<3>::Constant(INFINITY);
  hi_ = Vec<3>::Constant(-INFINITY);
  for (const auto& t : tri_)
    for (int i : t) {
      lo_ = lo_.cwiseMin(v_[std::size_t(i)]);
      hi_ = hi_.cwiseMax(v_[std::size_t(i)]);
    }
  if (tri_.empty()) lo_ = hi_ = Vec<3>::Zero();
  for (const auto& t : tri_) {
    const Vec<3>&a = v_[std::size_t(t[0])], &b = v_[std::size_t(t[1])], &c = v_[std::size_t(t[2])];
    area_ += 0.5 * (b - a).cross(c - a).norm();
    volume_ += a.dot(b.cross(c)) / 6;
    centre_.push_back((a + b + c) / 3);
    radius_.push_back(std::sqrt(std::max({(a - centre_.back()).squaredNorm(), (b - centre_.back()).squaredNorm(),
                                          (c - centre_.back()).squaredNorm()})));
  }
  volume_ = std::abs(volume_);
  const Vec<3> extent = hi_ - lo_;
  cell_ = std::max({cell, std::cbrt(extent.prod() / kMaxCells), 1e-300});
  for (int k = 0; k < 3; ++k) n_[k] = std::max(1L, long(std::ceil(extent[k] / cell_)));
  double edges = 0;
  for (const auto& t : tri_)
    for (int e = 0; e < 3; ++e) edges += (v_[std::size_t(t[std::size_t(e)])] - v_[std::size_t(t[std::size_t((e + 1) % 3)])]).norm();
  const double meanEdge = tri_.empty() ? 0 : edges / double(3 * tri_.size());
  column_ = std::max({2 * meanEdge, std::sqrt(extent[1] * extent[2] / kMaxCells), 1e-300});
  for (int k = 1; k < 3; ++k) m_[k] = std::max(1L, long(std::ceil(extent[k] / column_)));
  binCells();
  binColumns();
}

long TriangleSurface::cellOf(double x, int k) const {
  return std::clamp(long(std::floor((x - lo_[k]) / cell_)), 0L, n_[k] - 1);
}

long TriangleSurface::columnOf(double x, int k) const {
  return std::clamp(long(std::floor((x - lo_[k]) / column_)), 0L, m_[k] - 1);
}

// Each triangle goes into the cells of its bounding box whose centre lies within half a
// cell diagonal of its plane (every cell it meets, and a few near it).
void TriangleSurface::binCells() {
  std::vector<std::pair<long, int>> pairs;
  const double halfDiagonal = 0.5 * std::sqrt(3.0) * cell_ * (1 + 1e-9);
  for (std::size_t t = 0; t < tri_.size(); ++t) {
    const Vec<3>&a = v_[std::size_t(tri_[t][0])], &b = v_[std::size_t(tri_[t][1])], &c = v_[std::size_t(tri_[t][2])];
    Vec<3> n = (b - a).cross(c - a);
    const double nn = n.norm();
    if (nn > 0) n /= nn;
    std::array<long, 3> i0, i1;
    for (int k = 0; k < 3; ++k) {
      i0[k] = cellOf(std::min({a[k], b[k], c[k]}), k);
      i1[k] = cellOf(std::max({a[k], b[k], c[k]}), k);
    }
    for (long z = i0[2]; z <= i1[2]; ++z)
      for (long y = i0[1]; y <= i1[1]; ++y)
        for (long x = i0[0]; x <= i1[0]; ++x) {
          const Vec<3> centre = lo_ + cell_ * Vec<3>(double(x) + 0.5, double(y) + 0.5, double(z) + 0.5);
          if (nn > 0 && std::abs(n.dot(centre - a)) > halfDiagonal) continue;
          pairs.emplace_back((z * n_[1] + y) * n_[0] + x, int(t));
        }
  }
  toCsr(pairs, n_[0] * n_[1] * n_[2], cellStart_, cellTri_);
}

// Each triangle goes into the (y, z) columns of its bounding box.
void TriangleSurface::binColumns() {
  std::vector<std::pair<long, int>> pairs;
  for (std::size_t t = 0; t < tri_.size(); ++t) {
    const Vec<3>&a = v_[std::size_t(tri_[t][0])], &b = v_[std::size_t(tri_[t][1])], &c = v_[std::size_t(tri_[t][2])];
    const long y0 = columnOf(std::min({a[1], b[1], c[1]}), 1), y1 = columnOf(std::max({a[1], b[1], c[1]}), 1);
    const long z0 = columnOf(std::min({a[2], b[2], c[2]}), 2), z1 = columnOf(std::max({a[2], b[2], c[2]}), 2);
    for (long z = z0; z <= z1; ++z)
      for (long y = y0; y <= y1; ++y) pairs.emplace_back(z * m_[1] + y, int(t));
  }
  toCsr(pairs, m_[1] * m_[2], columnStart_, columnTri_);
}

// f(x) for every crossing of the line (., y, z) with a triangle: the perturbed point lies on
// the same side of its three edges; x is the barycentric mean of the vertices' x.
template <class F>
void TriangleSurface::forEachCrossing(double y, double z, F&& f) const {
  if (!(y >= lo_[1] && y <= hi_[1] && z >= lo_[2] && z <= hi_[2])) return;
  const long column = columnOf(z, 2) * m_[1] + columnOf(y, 1);
  const Vec<2> p(y, z);
  for (long i = columnStart_[std::size_t(column)]; i < columnStart_[std::size_t(column) + 1]; ++i) {
    const Triangle& t = tri_[std::size_t(columnTri_[std::size_t(i)])];
    const Vec<3>&a = v_[std::size_t(t[0])], &b = v_[std::size_t(t[1])], &c = v_[std::size_t(t[2])];
    const Vec<2> A(a[1], a[2]), B(b[1], b[2]), C(c[1], c[2]);
    const Side ab = side(A, B, p), bc = side(B, C, p), ca = side(C, A, p);
    if (ab.sign == 0 || ab.sign != bc.sign || bc.sign != ca.sign) continue;
    const double sum = ab.w + bc.w + ca.w;
    if (sum == 0) continue;
    f((bc.w * a[0] + ca.w * b[0] + ab.w * c[0]) / sum);
  }
}

bool TriangleSurface::inside(const Vec<3>& x) const {
  bool in = false;
  forEachCrossing(x[1], x[2], [&](double xc) { in ^= xc > x[0]; });
  return in;
}

void TriangleSurface::crossings(double y, double z, std::vector<double>& xs) const {
  xs.clear();
  forEachCrossing(y, z, [&](double xc) { xs.push_back(xc); });
  std::sort(xs.begin(), xs.end());
}

// f(t) for the triangles t of the cells within r of x (the cell holding x first; a
// triangle in several cells comes several times) until f returns true; whether it did.
template <class F>
bool TriangleSurface::forEachNear(const Vec<3>& x, double r, F&& f) const {
  for (int k = 0; k < 3; ++k)
    if (!(x[k] >= lo_[k] - r && x[k] <= hi_[k] + r)) return false;
  std::array<long, 3> i0, i1;
  for (int k = 0; k < 3; ++k) {
    i0[k] = cellOf(x[k] - r, k);
    i1[k] = cellOf(x[k] + r, k);
  }
  auto visit = [&](long c) {
    for (long i = cellStart_[std::size_t(c)]; i < cellStart_[std::size_t(c) + 1]; ++i)
      if (f(cellTri_[std::size_t(i)])) return true;
    return false;
  };
  const long own = (cellOf(x[2], 2) * n_[1] + cellOf(x[1], 1)) * n_[0] + cellOf(x[0], 0);
  if (visit(own)) return true;
  for (long z = i0[2]; z <= i1[2]; ++z)
    for (long y = i0[1]; y <= i1[1]; ++y)
      for (long c = (z * n_[1] + y) * n_[0] + i0[0], end = c + i1[0] - i0[0]; c <= end; ++c)
        if (c != own && visit(c)) return true;
  return false;
}

double TriangleSurface::sphereGap(const Vec<3>& x, int t) const {
  return (x - centre_[std::size_t(t)]).norm() - radius_[std::size_t(t)];
}

double TriangleSurface::distance(const Vec<3>& x, double reach) const {
  double best = reach * reach;
  forEachNear(x, reach, [&](int i) {
    const double gap = sphereGap(x, i);
    if (gap > 0 && gap * gap >= best) return false;
    const Triangle& t = tri_[std::size_t(i)];
    best = std::min(best, triangleDistance2(x, v_[std::size_t(t[0])], v_[std::size_t(t[1])], v_[std::size_t(t[2])]));
    return false;
  });
  return std::sqrt(best);
}

bool TriangleSurface::anyWithin(const Vec<3>& x, double r) const {
  return forEachNear(x, r, [&](int i) {
    if (sphereGap(x, i) > r) return false;
    const Triangle& t = tri_[std::size_t(i)];
    return triangleDistance2(x, v_[std::size_t(t[0])], v_[std::size_t(t[1])], v_[std::size_t(t[2])]) <= r * r;
  });
}

}  // namespace shizuku
