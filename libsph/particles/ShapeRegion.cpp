// Curved and STL regions of system/particlesDict: see ShapeRegion.hpp.
#include "particles/ShapeRegion.hpp"
#include "core/Parameter.hpp"
#include "particles/BallShape.hpp"
#include "particles/CylinderShape.hpp"
#include "particles/StlFile.hpp"
#include "particles/StlShape.hpp"
#include <array>
#include <filesystem>

namespace shizuku {

namespace key {
namespace {
const ParameterGroup cylinder("system/particlesDict: regions/<name> (shape cylinder)",
    "A cylinder (3D): fluid inside it, or as a wall a solid body, its layers inside; radius as above.");
const VectorParameter point1 = cylinder.vector("point1", dim::length, "centre of one end cap, on the axis").required();
const VectorParameter point2 = cylinder.vector("point2", dim::length, "centre of the other end cap").required();

const ParameterGroup stl("system/particlesDict: regions/<name> (shape stl)",
    "A closed STL surface (3D): fluid inside it, or as a wall a solid body, its layers inside.");
const OptionParameter file = stl.option("file", {},
    "the STL file, ASCII or binary, relative to the case directory (or absolute)").required();
const ScalarParameter scale = stl.scalar("scale", dim::none,
    "factor from the file's units to metres (0.001: millimetres), applied first").def(1).above(0);
const VectorParameter translate = stl.vector("translate", dim::length,
    "shift applied last, after scale and rotate").defZero("0");

const ParameterGroup rotate("system/particlesDict: regions/<name>/rotate (shape stl)",
    "Rotation of the STL surface about an axis through the origin, after scale, before translate (absent: none).");
const VectorParameter axis = rotate.vector("axis", dim::none, "the axis (any length but zero)").required();
const ScalarParameter angle = rotate.scalar("angle", dim::none,
    "degrees, counter-clockwise seen from the tip of the axis (right-hand rule); no unit").required();
}  // namespace
}  // namespace key

namespace {

constexpr double kMaxSpacingsFromOrigin = 1e12;  // as the generator: lattice indices stay exact
constexpr double kSmallestPart = 2, kLargestPart = 1e5;  // spacings across, for the units check

// The bounding box [lo, hi] of a body must lie within kMaxSpacingsFromOrigin spacings of the origin.
template <int D>
void checkBoxReach(const Dictionary& r, const std::string& key, const Vec<D>& lo, const Vec<D>& hi, double d0) {
  for (int k = 0; k < D; ++k)
    if (!(std::max(std::abs(lo[k]), std::abs(hi[k])) / d0 <= kMaxSpacingsFromOrigin))
      r.error(key, "the body reaches " + formatNumber<D>(lo) + " .. " + formatNumber<D>(hi) + ", more than " +
                       formatNumber(kMaxSpacingsFromOrigin) + " spacings (d0 = " + formatNumber(d0) +
                       " m) from the origin");
}

// `rotate { axis (..); angle a; }`: the rotation matrix, identity when absent.
Mat<3> readRotation(const Dictionary& r) {
  const Dictionary* rot = r.subDictPtr("rotate");
  if (!rot) return Mat<3>::Identity();
  const Vec<3> axis = key::axis.read<3>(*rot);
  if (!(axis.norm() > 0)) rot->error("axis", "(0 0 0) has no direction: give the rotation axis, e.g. (0 0 1)");
  if (rot->found("angle") && rot->value("angle").hasUnit)
    rot->error("angle", "is in degrees, written without a unit (e.g. angle 90;)");
  const double degrees = key::angle.read(*rot);
  return Eigen::AngleAxisd(degrees * M_PI / 180, axis.normalized()).toRotationMatrix();
}

// A part under 2 d0 or over 1e5 d0 across in every direction was drawn in other units.
void checkUnits(const Dictionary& r, const std::string& path, const Vec<3>& lo, const Vec<3>& hi, double scale,
                double d0) {
  const Vec<3> size = hi - lo;
  const std::string across = "the part is " + formatNumber<3>(size) + " m across (after scale " +
                             formatNumber(scale) + ")";
  const std::string spacing = " spacings (d0 = " + formatNumber(d0) + " m) in every direction: wrong units? ";
  if ((size.array() < kSmallestPart * d0).all())
    r.error("file", "'" + path + "': " + across + ", less than " + formatNumber(kSmallestPart) + spacing +
                        "`scale` turns the file's units into metres (none for a part drawn in metres); "
                        "or the spacing is too coarse for it");
  if ((size.array() > kLargestPart * d0).all())
    r.error("file", "'" + path + "': " + across + ", more than " + formatNumber(kLargestPart) + spacing +
                        "a part drawn in millimetres needs `scale 0.001;`");
}

}  // namespace

std::string resolveCasePath(const std::string& caseDir, const std::string& file) {
  const std::filesystem::path p(file);
  return p.is_absolute() || caseDir.empty() ? file : (std::filesystem::path(caseDir) / p).string();
}

template <int D>
ShapeRegion<D> ballRegion(const Vec<D>& centre, double radius) {
  return {std::make_shared<BallShape<D>>(centre, radius), centre};
}

template <int D>
ShapeRegion<D> readCylinderRegion(const Dictionary& r, double radius, double d0) {
  if constexpr (D == 2) {
    r.error("shape", "a cylinder is a 3D body; in 2D a disc is `shape circle` (centre, radius)");
  } else {
    const Vec<3> p1 = key::point1.read<3>(r), p2 = key::point2.read<3>(r);
    if (!((p2 - p1).norm() > 1e-9 * d0))
      r.error("point2", "coincides with point1 " + formatNumber<3>(p1) + ": the cylinder has no length");
    ShapeRegion<3> s{std::make_shared<CylinderShape>(p1, p2, radius), p1};
    checkBoxReach<3>(r, "point2", s.shape->lower(), s.shape->upper(), d0);
    return s;
  }
}

template <int D>
ShapeRegion<D> readStlRegion(const Dictionary& r, double d0, double reach, double voxel, const std::string& caseDir) {
  if constexpr (D == 2) {
    r.error("shape", "an STL surface is a 3D body; this case is 2D (set `dimension 3;` for a 3D case)");
  } else {
    const std::string file = r.getWord(key::file.keyword());
    recordParameter(key::file.info(), &r, file, false);
    const std::string path = resolveCasePath(caseDir, file);
    StlMesh mesh;
    const std::string why = readStl(path, mesh);
    if (!why.empty()) r.error("file", "the STL file '" + path + "' " + why);
    if (mesh.openEdges > 0)
      r.error("file", "the STL surface '" + path + "' is not closed: " + std::to_string(mesh.openEdges) +
                          " open edge(s) (used by one triangle, or by more than two); a fluid or solid body needs "
                          "a closed surface to tell inside from outside");
    const double scale = key::scale.read(r);
    const Mat<3> rotation = readRotation(r);
    const Vec<3> shift = key::translate.read<3>(r);
    Vec<3> lo = Vec<3>::Constant(INFINITY), hi = Vec<3>::Constant(-INFINITY);
    for (auto& x : mesh.points) {
      x = rotation * (scale * x) + shift;
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
    checkUnits(r, path, lo, hi, scale, d0);
    checkBoxReach<3>(r, "file", lo, hi, d0);
    auto shape = std::make_shared<StlShape>(TriangleSurface(std::move(mesh.points), std::move(mesh.triangles), reach),
                                            file, reach, voxel);
    return {shape, shape->lower()};
  }
}

template <int D>
void checkLatticeRows(const Dictionary& r, const std::string& name, const ShapeRegion<D>& s, double d0, double limit) {
  double rows = 1;
  for (int k = 1; k < D; ++k) rows *= (s.shape->upper()[k] - s.shape->lower()[k]) / d0 + 2;
  const double most = 10 * limit + 1e6;
  if (rows > most)
    r.error("shape", "region '" + name + "': its bounding box spans " + formatNumber(std::round(rows)) +
                         " lattice rows (spacing " + formatNumber(d0) + " m), more than " + formatNumber(most) +
                         " (10 maxParticles + 1e6): use a larger spacing");
}

// The lattice points of the row through p (along x, indices lo0 .. lo0 + count0 - 1) with
// phiMin <= phi < phiMax, within the row's span.
template <int D>
void rowPoints(const SolidShape<D>& body, Vec<D> p, long lo0, long count0, double a0, double d0, double phiMin,
               double phiMax, std::vector<Vec<D>>& out) {
  double from = 0, to = 0;
  if (!body.rowSpan(p, d0, from, to) || !(from <= to)) return;
  const long i0 = std::max(lo0, long(std::ceil((from - a0) / d0 - 0.5)));
  const long i1 = std::min(lo0 + count0 - 1, long(std::floor((to - a0) / d0 - 0.5)));
  if (i1 < i0) return;
  const long n = i1 - i0 + 1;
  std::vector<double> xs(static_cast<std::size_t>(n));
  std::vector<char> keep(static_cast<std::size_t>(n));
  for (long j = 0; j < n; ++j) xs[std::size_t(j)] = a0 + (double(i0 + j) + 0.5) * d0;
  body.bandRow(p, xs.data(), n, phiMin, phiMax, keep.data());
  for (std::size_t j = 0; j < xs.size(); ++j)
    if (keep[j]) {
      p[0] = xs[j];
      out.push_back(p);
    }
}

template <int D>
void shapeLatticePoints(const ShapeRegion<D>& s, double d0, double phiMin, double phiMax, std::vector<Vec<D>>& points) {
  const SolidShape<D>& body = *s.shape;
  const Vec<D>& a = s.anchor;
  std::array<long, D> lo, count;  // the lattice indices of the bounding box, one more each side
  long rows = 1;
  for (int k = 0; k < D; ++k) {
    lo[k] = long(std::floor((body.lower()[k] - a[k]) / d0 - 0.5)) - 1;
    count[k] = long(std::ceil((body.upper()[k] - a[k]) / d0 - 0.5)) + 2 - lo[k];
    if (k > 0) rows *= count[k];
  }
  // Rows in parallel, each into its own list; joined in row order (x fastest, then y, z).
  std::vector<std::vector<Vec<D>>> found(static_cast<std::size_t>(rows));
#pragma omp parallel for schedule(dynamic, 16)
  for (long row = 0; row < rows; ++row) {
    Vec<D> p = a;
    long rest = row;
    for (int k = 1; k < D; ++k) {
      p[k] = a[k] + (double(lo[k] + rest % count[k]) + 0.5) * d0;
      rest /= count[k];
    }
    rowPoints<D>(body, p, lo[0], count[0], a[0], d0, phiMin, phiMax, found[std::size_t(row)]);
  }
  std::size_t n = points.size();
  for (const auto& f : found) n += f.size();
  points.reserve(n);
  for (const auto& f : found) points.insert(points.end(), f.begin(), f.end());
}

template ShapeRegion<2> ballRegion<2>(const Vec<2>&, double);
template ShapeRegion<3> ballRegion<3>(const Vec<3>&, double);
template ShapeRegion<2> readCylinderRegion<2>(const Dictionary&, double, double);
template ShapeRegion<3> readCylinderRegion<3>(const Dictionary&, double, double);
template ShapeRegion<2> readStlRegion<2>(const Dictionary&, double, double, double, const std::string&);
template ShapeRegion<3> readStlRegion<3>(const Dictionary&, double, double, double, const std::string&);
template void checkLatticeRows<2>(const Dictionary&, const std::string&, const ShapeRegion<2>&, double, double);
template void checkLatticeRows<3>(const Dictionary&, const std::string&, const ShapeRegion<3>&, double, double);
template void shapeLatticePoints<2>(const ShapeRegion<2>&, double, double, double, std::vector<Vec<2>>&);
template void shapeLatticePoints<3>(const ShapeRegion<3>&, double, double, double, std::vector<Vec<3>>&);

}  // namespace shizuku
