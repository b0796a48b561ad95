// Builds the initial particle set from system/particlesDict: fluid boxes and
// circles on the lattice (i + 1/2) d0, wall boxes with `layers` rows outside
// the wall surface (docs/method.md 11), curved and STL regions through their
// SolidShape (ShapeRegion.hpp), removal of fluid that overlaps walls (a
// cell grid, O(N)), the check that the fluid left lies inside the walls,
// initial velocities (uniform, rigid rotation, linear, muParser expression),
// and the periodic box. Every rule and key is listed in
// ParticleGenerator.hpp.
#include "particles/ParticleGenerator.hpp"
#include "particles/MemoryCheck.hpp"
#include "particles/OpenBoundaryRegion.hpp"
#include "particles/PointGrid.hpp"
#include "particles/ShapeRegion.hpp"
#include "particles/VelocityExpression.hpp"
#include "particles/WallLattice.hpp"
#include "particles/WallMotion.hpp"
#include "core/Log.hpp"
#include "core/Parameter.hpp"
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <unordered_map>

namespace shizuku {

namespace {

constexpr double kSlack = 1e-9;  // round-off slack, in units of d0
// Coordinates farther than this many spacings from the origin are refused:
// lattice indices must stay exact in a double and fit a long.
constexpr double kMaxSpacingsFromOrigin = 1e12;

// Numbers in messages as the dictionary prints them (formatNumber).
std::string fmt(double x) { return formatNumber(x); }
template <int D> std::string fmt(const Vec<D>& v) { return formatNumber<D>(v); }
// A particle count in full digits (a user compares it with maxParticles digit by digit).
std::string countText(double n) { return n < 1e15 ? std::to_string(std::llround(n)) : formatNumber(n); }
// The particlesDict keys, declared once (ParticleGenerator.hpp explains what each
// builds). Coordinates have the sane bound 1e12 m; the reach check below ties them
// to the spacing as well.
const ParameterGroup particles("system/particlesDict", "Spacing, particle limit and dimension of the initial particles.");
const ScalarParameter spacing = particles.scalar("spacing", dim::length, "particle spacing d0").required().above(0)
    .saneMin(1e-9);  // below a nanometre 1/d0^3 and 1/h^D overflow; no continuum case is that fine
const ScalarParameter maxParticles = particles.scalar("maxParticles", dim::none,
    "largest particle count, checked before anything is allocated").def(kDefaultMaxParticles).min(1).max(2147483647.0);
const IntParameter dimensionKey = particles.integer("dimension", "2 or 3; selects the 2D or 3D solver")
    .def(2).min(2).max(3);

const ParameterGroup region("system/particlesDict: regions/<name>", "One fluid or wall region (in file order).");
const OptionParameter regionType = region.option("type", {"fluid", "wall", "inlet", "outlet"},
    "fluid particles, wall layers, or an inlet's or outlet's buffer (docs/boundaries.md)").required();
const OptionParameter shape = region.option("shape", {"box", "circle", "sphere", "cylinder", "stl"},
    "box; circle, sphere (a disc, a ball); cylinder, stl (3D): fluid inside, or as a wall a solid body").required();
const VectorParameter boxMin = region.vector("min", dim::length, "box: lower corner (wall: inner surface)").required();
const VectorParameter boxMax = region.vector("max", dim::length, "box: upper corner (wall: inner surface)").required();
const VectorParameter centre = region.vector("centre", dim::length, "circle, sphere: centre").required();
const ScalarParameter radius = region.scalar("radius", dim::length, "circle, sphere, cylinder: radius").required().above(0);
const IntParameter layers = region.integer("layers",
    "wall: rows of particles outside the surface (a solid's: inside it, within layers d0)").def(3).min(1);
const WordListParameter openFaces = region.wordList("open", "wall: faces without layers (left right bottom top front back)")
    .def("() (every face closed)");
const SwitchParameter solid = region.onOff("solid",
    "wall box: a solid body (an obstacle): layers inside the box behind its faces, fluid outside "
    "(a circle, sphere, cylinder or stl wall always is one)").def(false);

const ParameterGroup velocity("system/particlesDict: regions/<name>/velocity",
    "Initial velocity of a fluid region (absent: at rest).");
const OptionParameter velocityType = velocity.option("type", {"uniform", "rigidRotation", "linear", "expression"},
    "uniform value, rigid rotation omega about centre, linear gradient, or muParser expressions").required();
const VectorParameter velocityCentre = velocity.vector("centre", dim::length,
    "rigidRotation, linear: the centre c of U = omega x (x - c), U = G (x - c)").defZero("0 (the origin)");

const ParameterGroup periodic("system/particlesDict: periodic", "Periodic box (absent: no periodic direction).");
const VectorParameter periodicMin = periodic.vector("min", dim::length, "lower corner of the periodic box").required();
const VectorParameter periodicMax = periodic.vector("max", dim::length, "upper corner of the periodic box").required();
const WordListParameter directions = periodic.wordList("directions", "periodic directions").def("all (x y, or x y z)");

const char* axisName(int k) { return k == 0 ? "x" : k == 1 ? "y" : "z"; }

// Names of the box faces in the order -x +x -y +y -z +z.
std::vector<std::string> faceNames(int D) {
  std::vector<std::string> f = {"left", "right", "bottom", "top", "front", "back"};
  f.resize(2 * D);
  return f;
}

template <int D>
struct Region {
  std::string name;
  const Dictionary* dict = nullptr;
  bool fluid = true, circle = false;
  bool solid = false;                     // wall: an obstacle (layers inside the box), not a container
  ShapeRegion<D> body;                    // cylinder, stl; a wall circle or sphere (solid); else no shape
  Vec<D> min = Vec<D>::Zero(), max = Vec<D>::Zero();  // fluid box: the filled cells; wall: its surface
  Vec<D> centre = Vec<D>::Zero();
  double radius = 0;
  std::array<long, D> cells{};            // box: cells per direction
  Vec<D> step = Vec<D>::Zero();           // fluid box: the spacing per direction (fluidSpacing)
  int layers = 0;
  std::array<bool, 2 * D> open{};         // wall faces -x +x -y +y -z +z
  Vec<D> outerMin = Vec<D>::Zero(), outerMax = Vec<D>::Zero();  // wall: surface grown by the layers
  std::vector<Vec<D>> points;
  std::shared_ptr<WallMotion<D>> motion;  // wall: its prescribed motion (null: fixed)

  // Inside the wall's layer region: within the grown box, not strictly inside the surface
  // (a container); strictly inside the box (a solid box); phi < -tol (a curved or STL solid).
  bool inLayers(const Vec<D>& x, double tol) const {
    if (body.shape) return body.shape->deeperThan(x, tol);
    if (solid) {
      for (int k = 0; k < D; ++k)
        if (x[k] <= min[k] + tol || x[k] >= max[k] - tol) return false;
      return true;
    }
    bool inner = true;
    for (int k = 0; k < D; ++k) {
      if (x[k] <= outerMin[k] + tol || x[k] >= outerMax[k] - tol) return false;
      if (x[k] <= min[k] + tol || x[k] >= max[k] - tol) inner = false;
    }
    return !inner;
  }
};

template <int D>
bool hasKey(const Dictionary& d, const std::string& key) {
  const auto k = d.keys();
  return std::find(k.begin(), k.end(), key) != k.end();
}

// A point of the geometry must lie within kMaxSpacingsFromOrigin spacings of the origin.
template <int D>
void checkReach(const Dictionary& r, const std::string& key, const Vec<D>& x, double d0) {
  for (int k = 0; k < D; ++k)
    if (!(std::abs(x[k]) / d0 <= kMaxSpacingsFromOrigin))
      r.error(key, fmt<D>(x) + " lies more than " + fmt(kMaxSpacingsFromOrigin) + " spacings (d0 = " + fmt(d0) +
                       " m) from the origin");
}

template <int D>
void readBox(const Dictionary& r, Region<D>& reg, double d0) {
  reg.min = boxMin.read<D>(r);
  reg.max = boxMax.read<D>(r);
  checkReach<D>(r, "min", reg.min, d0);
  checkReach<D>(r, "max", reg.max, d0);
  for (int k = 0; k < D; ++k)
    if (!(reg.max[k] > reg.min[k]))
      r.error("max", "max " + fmt<D>(reg.max) + " must exceed min " + fmt<D>(reg.min) + " in every direction (" +
                         axisName(k) + ")");
}

// "fluid region 'water' would hold 100000000 particles, more than maxParticles 10000000 ..."
[[noreturn]] void tooMany(const Dictionary& regions, const std::string& name, const char* kind, double count,
                          double limit, double d0) {
  regions.error(name, std::string(kind) + " region '" + name + "' would hold " + countText(count) +
                          " particles, more than maxParticles " + countText(limit) + " (spacing " + fmt(d0) +
                          " m): use a larger spacing, or raise maxParticles in particlesDict");
}

// An empty region named `name`, read from r: fluid or wall.
template <int D>
Region<D> newRegion(const Dictionary& r, const std::string& name, bool fluid) {
  Region<D> reg;
  reg.name = name;
  reg.dict = &r;
  reg.fluid = fluid;
  return reg;
}

// `radius`, at most kMaxSpacingsFromOrigin spacings.
double readRadius(const Dictionary& r, double d0) {
  const double R = radius.read(r);
  if (!(R / d0 <= kMaxSpacingsFromOrigin))
    r.error("radius", fmt(R) + " m is more than " + fmt(kMaxSpacingsFromOrigin) + " spacings");
  return R;
}

// A curved or STL region (ShapeRegion.hpp): its shape and lattice; min, max (and outerMin,
// outerMax) its bounding box. reach: how far an STL surface's phi must be exact.
template <int D>
void readBody(const Dictionary& r, Region<D>& reg, const std::string& kind, double d0, double reach,
              const std::string& caseDir, double limit) {
  if (kind == "stl") {
    reg.body = readStlRegion<D>(r, d0, reach, reg.fluid ? 0.0 : d0, caseDir);
  } else if (kind == "cylinder") {
    reg.body = readCylinderRegion<D>(r, D == 3 ? readRadius(r, d0) : 0.0, d0);  // 2D: an error first
  } else {
    reg.centre = centre.read<D>(r);
    checkReach<D>(r, "centre", reg.centre, d0);
    reg.radius = readRadius(r, d0);
    reg.body = ballRegion<D>(reg.centre, reg.radius);
  }
  checkLatticeRows<D>(r, reg.name, reg.body, d0, limit);
  reg.min = reg.outerMin = reg.body.shape->lower();
  reg.max = reg.outerMax = reg.body.shape->upper();
}

// About the lattice points of a curved or STL region: its volume (fluid), its layer's
// volume (wall) over d0^D.
template <int D>
double bodyCount(const Region<D>& reg, double d0) {
  const SolidShape<D>& s = *reg.body.shape;
  return (reg.fluid ? s.volume() : s.shellVolume(reg.layers * d0)) / std::pow(d0, D);
}

template <int D>
Region<D> readFluid(const Dictionary& r, const std::string& name, double d0, const Dictionary& regions,
                    double limit, const std::string& caseDir) {
  Region<D> reg = newRegion<D>(r, name, true);
  for (const char* k : {"layers", "open", "motion"})
    if (hasKey<D>(r, k)) r.error(k, std::string("only wall regions take '") + k + "'");
  const std::string kind = shape.read(r);
  if (kind == "cylinder" || kind == "stl") {
    readBody<D>(r, reg, kind, d0, d0, caseDir, limit);
    const double count = bodyCount(reg, d0);
    if (count > limit) tooMany(regions, name, "fluid", std::round(count), limit, d0);
  } else if (kind == "box") {
    readBox<D>(r, reg, d0);
    double count = 1;
    for (int k = 0; k < D; ++k) {
      const WallSpacing a = fluidSpacing(reg.min[k], reg.max[k], d0);
      if (a.spacings < 1 - 1e-6)
        r.error("max", std::string("the box is thinner than one spacing (d0 = ") + fmt(d0) + " m) in " +
                           axisName(k));
      reg.cells[k] = a.intervals;
      reg.step[k] = a.spacing;
      count *= double(reg.cells[k]);
    }
    if (count > limit) tooMany(regions, name, "fluid", count, limit, d0);
  } else {
    reg.circle = true;
    reg.centre = centre.read<D>(r);
    checkReach<D>(r, "centre", reg.centre, d0);
    reg.radius = readRadius(r, d0);
    // Lattice points inside: about the disc area (sphere volume) over d0^D.
    const double a = reg.radius / d0;
    const double count = D == 2 ? M_PI * a * a : 4.0 / 3.0 * M_PI * a * a * a;
    if (count > limit) tooMany(regions, name, "fluid", std::round(count), limit, d0);
  }
  return reg;
}

// "system/particlesDict:8:5: wall box 'tank': size 4 m in x is 133.33 spacings (d0 = 0.03 m);
// faces along x use spacing 0.029851 m (134 intervals)"
void warnWallResidual(const Dictionary& r, const std::string& name, int k, double size, double d0,
                       const WallSpacing& a) {
  std::ostringstream n;
  n.precision(5);
  n << a.spacings;
  Log::get().warning(r.location("max").str() + ": wall box '" + name + "': size " + fmt(size) + " m in " + axisName(k) +
                     " is " + n.str() + " spacings (d0 = " + fmt(d0) + " m); faces along " + axisName(k) +
                     " use spacing " + fmt(a.spacing) + " m (" + std::to_string(a.intervals) + " intervals)");
}

// The `open` faces of a wall box, each checked against the face names.
template <int D>
void readOpenFaces(const Dictionary& r, Region<D>& reg) {
  const auto faces = faceNames(D);
  for (const auto& w : openFaces.read(r)) {
    auto it = std::find(faces.begin(), faces.end(), w);
    if (it == faces.end()) {
      std::string list;
      for (const auto& f : faces) list += (list.empty() ? "" : " ") + f;
      const std::string near = closestMatch(w, faces);
      r.error("open", "'" + w + "' is not a face (" + list + ")" + (near.empty() ? "" : "; did you mean '" + near + "'?"));
    }
    reg.open[it - faces.begin()] = true;
  }
}

// Wall particles of a box: a container's layers outside the surface (outer box minus the
// surface box), a solid's inside it (the box minus its core `layers` cells in from
// every face). An upper bound before overlap removal, allocating nothing.
template <int D>
double wallCount(const Region<D>& reg) {
  double inner = 1, outer = 1;
  for (int k = 0; k < D; ++k) {
    const double cells = double(reg.cells[k]);
    if (reg.solid) {
      outer *= cells;
      inner *= std::max(0.0, cells - 2.0 * reg.layers);
    } else {
      inner *= cells;
      outer *= cells + double(reg.layers) * (int(!reg.open[2 * k]) + int(!reg.open[2 * k + 1]));
    }
  }
  return outer - inner;
}

// A wall region `shape circle|sphere|cylinder|stl`: always a solid body, its layers within
// `layers` d0 inside its surface.
template <int D>
Region<D> readSolidBody(const Dictionary& r, Region<D> reg, const std::string& kind, double d0,
                        const Dictionary& regions, double limit, const std::string& caseDir) {
  if (hasKey<D>(r, "open")) r.error("open", "a " + kind + " wall is a solid body: it has no open faces");
  if (r.found("solid") && !solid.read(r))
    r.error("solid", "a " + kind + " wall is always a solid body (its layers inside it, the fluid outside); "
                     "`solid no` (a container) is for boxes");
  reg.solid = true;
  reg.layers = layers.read(r);
  readBody<D>(r, reg, kind, d0, (reg.layers + 1) * d0, caseDir, limit);
  const double count = bodyCount(reg, d0);
  if (count > limit) tooMany(regions, reg.name, "wall", std::round(count), limit, d0);
  return reg;
}

template <int D>
Region<D> readWall(const Dictionary& r, const std::string& name, double d0, const Dictionary& regions,
                   double limit, const std::string& caseDir) {
  Region<D> reg = newRegion<D>(r, name, false);
  if (hasKey<D>(r, "velocity"))
    r.error("velocity", "a wall's velocity comes from its motion (`motion { type ...; }`); velocity is for fluid regions");
  if (const Dictionary* m = r.subDictPtr("motion")) reg.motion = WallMotion<D>::read(*m, caseDir);
  else if (hasKey<D>(r, "motion")) r.error("motion", "expected a sub-dictionary: motion { type translation|oscillating|rotation; ... }");
  const std::string kind = shape.read(r);
  if (kind != "box") return readSolidBody<D>(r, reg, kind, d0, regions, limit, caseDir);
  readBox<D>(r, reg, d0);
  reg.layers = layers.read(r);
  reg.solid = solid.read(r);
  if (reg.solid && hasKey<D>(r, "open"))
    r.error("open", "a solid wall box (an obstacle) has no open faces: fluid lies outside every face");
  readOpenFaces<D>(r, reg);
  for (int k = 0; k < D; ++k) {
    const WallSpacing a = wallSpacing(reg.min[k], reg.max[k], d0);
    if (!a.whole) warnWallResidual(r, name, k, reg.max[k] - reg.min[k], d0, a);
    reg.cells[k] = a.intervals;
  }
  const double count = wallCount(reg);
  if (count > limit) tooMany(regions, name, "wall", count, limit, d0);
  for (int k = 0; k < D; ++k) {
    const double grow = reg.solid ? 0 : reg.layers * d0;
    reg.outerMin[k] = reg.min[k] - (reg.open[2 * k] ? 0 : grow);
    reg.outerMax[k] = reg.max[k] + (reg.open[2 * k + 1] ? 0 : grow);
  }
  return reg;
}

template <int D>
void fillFluid(Region<D>& reg, double d0) {
  if (reg.body.shape) {  // the lattice points strictly inside
    shapeLatticePoints<D>(reg.body, d0, -INFINITY, -kSlack * d0, reg.points);
    return;
  }
  if (!reg.circle) {
    std::array<long, D> lo{};
    forEachIndex<D>(lo, reg.cells, [&](const std::array<long, D>& i) {
      Vec<D> x;
      for (int k = 0; k < D; ++k) x[k] = reg.min[k] + (double(i[k]) + 0.5) * reg.step[k];
      reg.points.push_back(x);
    });
    return;
  }
  const long m = long(std::ceil(reg.radius / d0)) + 1;
  std::array<long, D> lo, hi;
  lo.fill(-m);
  hi.fill(m);
  const double rMax = reg.radius - kSlack * d0;
  forEachIndex<D>(lo, hi, [&](const std::array<long, D>& i) {
    Vec<D> x;
    for (int k = 0; k < D; ++k) x[k] = reg.centre[k] + (double(i[k]) + 0.5) * d0;
    if ((x - reg.centre).norm() < rMax) reg.points.push_back(x);
  });
}

// The wall particles of one box: each face its own lattice (WallLattice.hpp); a solid's
// inside the box (solidBoxPoints).
template <int D>
void fillWall(Region<D>& reg, double d0) {
  if (reg.body.shape) {  // a curved or STL solid: the lattice points with -layers d0 <= phi < 0
    shapeLatticePoints<D>(reg.body, d0, -(reg.layers + kSlack) * d0, -kSlack * d0, reg.points);
    return;
  }
  std::array<WallAxis, D> axes;
  for (int k = 0; k < D; ++k)
    axes[k] = reg.solid ? wallAxis(reg.min[k], reg.max[k], d0, 0, true, true)
                        : wallAxis(reg.min[k], reg.max[k], d0, reg.layers, reg.open[2 * k], reg.open[2 * k + 1]);
  if (reg.solid)
    solidBoxPoints<D>(axes, reg.layers, reg.points);
  else
    wallBoxPoints<D>(axes, reg.points);
}

// Do the shapes of two fluid regions overlap (more than round-off)? Regions with a curved
// or STL shape are checked on their particles instead (checkBodyOverlap).
template <int D>
bool overlap(const Region<D>& a, const Region<D>& b, double tol) {
  if (a.body.shape || b.body.shape) return false;
  if (!a.circle && !b.circle) {
    for (int k = 0; k < D; ++k)
      if (std::min(a.max[k], b.max[k]) - std::max(a.min[k], b.min[k]) <= tol) return false;
    return true;
  }
  if (a.circle && b.circle) return (a.centre - b.centre).norm() < a.radius + b.radius - tol;
  const Region<D>& box = a.circle ? b : a;
  const Region<D>& c = a.circle ? a : b;
  const Vec<D> nearest = c.centre.cwiseMax(box.min).cwiseMin(box.max);
  return (nearest - c.centre).norm() < c.radius - tol;
}

template <int D>
void expressionVelocity(const Dictionary& v, const std::vector<Vec<D>>& x, std::vector<Vec<D>>& u) {
  const std::vector<std::string> text = v.getWordList("value");
  if (int(text.size()) != D)
    v.error("value", "expected " + std::to_string(D) + " expressions, one per velocity component, found " +
                         std::to_string(text.size()));
  try {  // syntax errors first, once, even for an empty region
    VelocityExpression<D> e(text);
    e(Vec<D>::Zero());
  } catch (const VelocityExpressionError& err) {
    v.error("value", err.what());
  }
  // Evaluation errors: the one at the lowest particle index is reported.
  std::size_t firstBad = x.size();
  std::string failure;
#pragma omp parallel
  {
    VelocityExpression<D> e(text);
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < x.size(); ++i) {
      std::string m;
      try {
        u[i] = e(x[i]);
        if (!u[i].allFinite()) m = "the expressions give " + fmt<D>(u[i]) + " at " + fmt<D>(x[i]);
      } catch (const VelocityExpressionError& err) {
        m = err.what();
      }
      if (!m.empty()) {
#pragma omp critical(shizuku_expression_failure)
        if (i < firstBad) { firstBad = i; failure = m; }
      }
    }
  }
  if (!failure.empty()) v.error("value", failure);
}

// Each number read was range-checked, but a rotation rate or gradient times a coordinate,
// or an expression, can still give an absurd speed: every initial speed is held to the
// sane magnitude of a velocity (1e12 m/s), the error naming the keyword that gave it.
template <int D>
void checkInitialSpeeds(const Dictionary& v, const std::string& type, const std::vector<Vec<D>>& x,
                        const std::vector<Vec<D>>& u) {
  constexpr double kSaneSpeed = 1e12;
  for (std::size_t i = 0; i < u.size(); ++i)
    if (!(u[i].norm() <= kSaneSpeed))
      v.error(type == "rigidRotation" ? "omega" : type == "linear" ? "gradient" : "value",
              "gives the initial velocity " + fmt<D>(u[i]) + " m/s at " + fmt<D>(x[i]) +
                  " m, beyond the physically sane magnitude " + fmt(kSaneSpeed) + " m/s");
}

template <int D>
void assignVelocity(const Region<D>& reg, std::vector<Vec<D>>& u) {
  u.assign(reg.points.size(), Vec<D>::Zero());
  const Dictionary* v = reg.dict->subDictPtr("velocity");
  if (!v) return;
  const std::vector<Vec<D>>& x = reg.points;
  const long n = long(x.size());
  const std::string type = velocityType.read(*v);
  if (type == "uniform") {
    const Vec<D> value = v->getVector<D>("value", dim::velocity);
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) u[i] = value;
  } else if (type == "rigidRotation") {
    const Vec<D> c = velocityCentre.read<D>(*v);
    if constexpr (D == 2) {
      const double w = v->getScalar("omega", dim::inverseTime);
#pragma omp parallel for schedule(static)
      for (long i = 0; i < n; ++i) u[i] = Vec<2>(-w * (x[i][1] - c[1]), w * (x[i][0] - c[0]));
    } else if constexpr (D == 3) {
      const Vec<3> w = v->getVector<3>("omega", dim::inverseTime);
#pragma omp parallel for schedule(static)
      for (long i = 0; i < n; ++i) u[i] = w.cross(x[i] - c);
    } else {
      v->error("type", "rigidRotation needs 2 or 3 dimensions");
    }
  } else if (type == "linear") {
    const Mat<D> G = v->getMatrix<D>("gradient", dim::inverseTime);
    const Vec<D> c = velocityCentre.read<D>(*v);
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) u[i] = G * (x[i] - c);
  } else {
    expressionVelocity<D>(*v, x, u);
  }
  checkInitialSpeeds<D>(*v, type, x, u);
}

template <int D>
PeriodicBox<D> readPeriodic(const Dictionary& dict, double d0) {
  PeriodicBox<D> box;
  const Dictionary* p = dict.subDictPtr("periodic");
  if (!p) return box;
  box.lo = periodicMin.read<D>(*p);
  box.hi = periodicMax.read<D>(*p);
  checkReach<D>(*p, "min", box.lo, d0);
  checkReach<D>(*p, "max", box.hi, d0);
  std::vector<std::string> axes;
  for (int k = 0; k < D; ++k) axes.push_back(axisName(k));
  std::vector<std::string> dirs = axes;
  if (p->found("directions")) dirs = directions.read(*p);
  for (const auto& w : dirs) {
    auto it = std::find(axes.begin(), axes.end(), w);
    if (it == axes.end()) {
      const std::string near = closestMatch(w, axes);
      p->error("directions", "'" + w + "' is not a direction of this " + std::to_string(D) + "D case" +
                                 (near.empty() ? "" : "; did you mean '" + near + "'?"));
    }
    box.periodic[it - axes.begin()] = true;
  }
  for (int k = 0; k < D; ++k) {
    if (!(box.hi[k] > box.lo[k]))
      p->error("max", "max " + fmt<D>(box.hi) + " must exceed min " + fmt<D>(box.lo) + " in every direction");
    const double n = (box.hi[k] - box.lo[k]) / d0;
    if (box.periodic[k] && std::abs(n - std::round(n)) > 1e-6)
      p->error("max", std::string("the periodic length in ") + axisName(k) + " (" + fmt(box.hi[k] - box.lo[k]) +
                          " m) is not a whole number of spacings (d0 = " + fmt(d0) + " m)");
  }
  return box;
}

}  // namespace

// The closed face of w (0..2D-1: -x +x -y +y -z +z) that x lies beyond, or -1
// when x is in the wall's closed interior: its surface box, boundary included,
// unbounded on an open side.
template <int D>
int faceCrossed(const Region<D>& w, const Vec<D>& x, double tol) {
  for (int k = 0; k < D; ++k) {
    if (!w.open[2 * k] && x[k] < w.min[k] - tol) return 2 * k;
    if (!w.open[2 * k + 1] && x[k] > w.max[k] + tol) return 2 * k + 1;
  }
  return -1;
}

// "the right face (x > 0.1 m)"
template <int D>
std::string faceText(const Region<D>& w, int face) {
  const int k = face / 2;
  return "the " + faceNames(D)[face] + " face (" + axisName(k) + (face % 2 ? " > " + fmt(w.max[k]) : " < " + fmt(w.min[k])) +
         " m)";
}

// With walls present, every fluid particle left after the removal of those in
// the layers must lie in the closed interior of some wall (open faces extend
// it). The error names the region, the wall holding most of its particles, the
// faces of that wall the others lie beyond and how many. O(N x walls).
template <int D>
void checkAgainstWalls(const Dictionary& regions, const Region<D>& f, const std::vector<Region<D>>& allWalls, double tol) {
  std::vector<const Region<D>*> walls;  // the containers: a solid holds no fluid
  for (const auto& w : allWalls)
    if (!w.solid) walls.push_back(&w);
  if (walls.empty()) return;
  auto inAnyWall = [&](const Vec<D>& x) {
    return std::any_of(walls.begin(), walls.end(), [&](const Region<D>* w) { return faceCrossed(*w, x, tol) < 0; });
  };
  std::vector<std::size_t> inside(walls.size(), 0);
  std::size_t outside = 0;
  for (const auto& x : f.points) {
    bool in = false;
    for (std::size_t w = 0; w < walls.size(); ++w)
      if (faceCrossed(*walls[w], x, tol) < 0) { ++inside[w]; in = true; }
    if (!in) ++outside;
  }
  if (outside == 0) return;
  const std::size_t home = std::max_element(inside.begin(), inside.end()) - inside.begin();
  if (inside[home] == 0) {
    std::string names;
    for (const auto* w : walls) names += (names.empty() ? "'" : ", '") + w->name + "'";
    regions.error(f.name, "fluid region '" + f.name + "' lies outside every wall (" + names +
                              "): no particle of it is inside a wall box (open sides extend the box)");
  }
  const Region<D>& w = *walls[home];
  std::array<std::size_t, 2 * D> beyond{};
  for (const auto& x : f.points)
    if (!inAnyWall(x)) ++beyond[faceCrossed(w, x, tol)];
  std::string faces;
  for (int face = 0; face < 2 * D; ++face)
    if (beyond[face] > 0) faces += (faces.empty() ? "" : ", ") + std::to_string(beyond[face]) + " beyond " + faceText(w, face);
  regions.error(f.name, "fluid region '" + f.name + "' reaches outside wall '" + w.name + "': " + std::to_string(outside) +
                            " of its " + std::to_string(f.points.size()) +
                            " fluid particles lie outside the interior of every wall (" + faces +
                            "); fluid must start inside the walls (open faces extend a wall's interior): "
                            "shrink or move the region");
}

// Each region was checked alone; now all of them together (upper bounds: before overlap removal).
template <int D>
void checkTotalCount(const Dictionary& regionsDict, const std::vector<Region<D>>& fluids,
                     const std::vector<Region<D>>& walls, double d0, double limit) {
  double total = 0;
  for (const auto* list : {&fluids, &walls})
    for (const auto& r : *list) {
      double cells = 1;
      for (int k = 0; k < D; ++k) cells *= double(r.cells[k]);
      const double a = r.radius / d0;
      total += r.body.shape ? bodyCount(r, d0)
               : r.circle   ? (D == 2 ? M_PI * a * a : 4.0 / 3.0 * M_PI * a * a * a)
               : r.fluid    ? cells
                            : wallCount(r);
    }
  if (total > limit)
    regionsDict.error("regions", "the regions would hold " + countText(total) + " particles, more than maxParticles " +
                                     countText(limit) + " (spacing " + fmt(d0) +
                                     " m): use a larger spacing, or raise maxParticles in particlesDict");
  checkMemoryFor(regionsDict, "regions", total, D);
}

// The wall particles of every wall region, in file order, without duplicates: a particle
// closer than d0/2 to an earlier one (where boxes meet) is dropped, unless the two move
// differently (a moving wall keeps all its particles; group: the motion's index + 1, 0 fixed).
// A curved or STL solid reports how many of its particles were dropped (it meets another
// wall: a cylinder on a floor).
template <int D>
void fillWalls(std::vector<Region<D>>& walls, double d0, std::vector<Vec<D>>& wallPoints, PointGrid<D>& wallGrid,
               std::vector<std::uint8_t>& wallGroup) {
  const double tol = kSlack * d0;
  int moving = 0;
  for (auto& w : walls) {
    fillWall(w, d0);
    const std::uint8_t group = w.motion ? std::uint8_t(++moving) : 0;
    wallPoints.reserve(wallPoints.size() + w.points.size());
    std::size_t dropped = 0;
    for (const auto& x : w.points) {
      const Index near = wallGrid.closest(x, 0.5 * d0 - tol);
      if (near >= 0 && wallGroup[std::size_t(near)] == group) {
        ++dropped;
        continue;
      }
      wallPoints.push_back(x);
      wallGroup.push_back(group);
      wallGrid.insert(Index(wallPoints.size() - 1));
    }
    if (w.body.shape && dropped > 0)
      info(w.dict->location("shape").str() + ": wall '" + w.name + "' (" + w.body.shape->kind() + "): " +
           std::to_string(dropped) + " of its " + std::to_string(w.points.size()) +
           " particles lie closer than 0.5 d0 to an earlier wall's and were dropped");
  }
}

namespace {
[[noreturn]] void overlapError(const Dictionary& regionsDict, const std::string& earlier, const std::string& later) {
  regionsDict.error(later, "fluid region '" + later + "' overlaps fluid region '" + earlier + "' (" +
                               regionsDict.location(earlier).str() + ")");
}
}  // namespace

// Whether x lies strictly inside the shape of fluid region f.
template <int D>
bool regionHolds(const Region<D>& f, const Vec<D>& x, double tol) {
  if (f.body.shape) return f.body.shape->deeperThan(x, tol);
  if (f.circle) return (x - f.centre).norm() < f.radius - tol;
  for (int k = 0; k < D; ++k)
    if (x[k] <= f.min[k] + tol || x[k] >= f.max[k] - tol) return false;
  return true;
}

// Fluid region fluids[b], just filled, against each earlier one where either has a curved or
// STL shape: they overlap when a particle of b lies inside a, or one of a (what the walls
// left of it) inside b. An overlap thinner than the lattice can go unseen.
template <int D>
void checkBodyOverlap(const Dictionary& regionsDict, const std::vector<Region<D>>& fluids, std::size_t b, double tol) {
  const Region<D>& B = fluids[b];
  for (std::size_t a = 0; a < b; ++a) {
    const Region<D>& A = fluids[a];
    if (!A.body.shape && !B.body.shape) continue;
    const bool hit =
        std::any_of(B.points.begin(), B.points.end(), [&](const Vec<D>& x) { return regionHolds(A, x, tol); }) ||
        std::any_of(A.points.begin(), A.points.end(), [&](const Vec<D>& x) { return regionHolds(B, x, tol); });
    if (hit) overlapError(regionsDict, A.name, B.name);
  }
}

// Fluid particles inside a wall's layers or closer than d0/2 to a wall particle are removed.
template <int D>
void removeFluidInWalls(const Dictionary& regionsDict, Region<D>& f, const std::vector<Region<D>>& walls,
                        const PointGrid<D>& wallGrid, double d0) {
  const double tol = kSlack * d0;
  const long n = long(f.points.size());
  std::vector<char> keep(n, 1);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    const Vec<D>& x = f.points[i];
    for (const auto& w : walls)
      if (w.inLayers(x, tol)) keep[i] = 0;
    if (keep[i] && wallGrid.anyCloserThan(x, 0.5 * d0 - tol)) keep[i] = 0;
  }
  std::vector<Vec<D>> kept;
  for (long i = 0; i < n; ++i)
    if (keep[i]) kept.push_back(f.points[i]);
  if (kept.empty())
    regionsDict.error(f.name, "fluid region '" + f.name + "' lies entirely inside walls: all " +
                                  std::to_string(n) + " of its particles were removed");
  f.points = std::move(kept);
}

// The inlet and outlet regions named in `names`, read once the fluid and walls are known
// (their direction is checked against the walls' centre, or the fluid's without walls).
template <int D>
std::vector<OpenBoundaryRegion<D>> readOpenBoundaries(const Dictionary& regionsDict, const std::vector<std::string>& names,
                                                      const std::vector<Region<D>>& fluids,
                                                      const std::vector<Region<D>>& walls, double d0) {
  Vec<D> lo = Vec<D>::Constant(INFINITY), hi = Vec<D>::Constant(-INFINITY);
  for (const auto& w : walls.empty() ? fluids : walls) {
    const Vec<D> a = w.circle ? Vec<D>(w.centre.array() - w.radius) : w.min;
    const Vec<D> b = w.circle ? Vec<D>(w.centre.array() + w.radius) : w.max;
    lo = lo.cwiseMin(a);
    hi = hi.cwiseMax(b);
  }
  std::vector<OpenBoundaryRegion<D>> out;
  for (const auto& name : names) {
    const Dictionary& r = regionsDict.subDict(name);
    const bool inlet = regionType.read(r) == "inlet";
    if (shape.read(r) != "box")
      r.error("shape", std::string("an ") + (inlet ? "inlet" : "outlet") + " is a box; circle and sphere are for fluid regions");
    Region<D> box;
    readBox<D>(r, box, d0);
    out.push_back(readOpenBoundaryRegion<D>(r, name, inlet, box.min, box.max, d0, Vec<D>(0.5 * (lo + hi))));
  }
  return out;
}

// No initial fluid particle may lie inside an inlet's or outlet's box.
template <int D>
void checkNoFluidInside(const OpenBoundaryRegion<D>& b, const std::vector<Vec<D>>& fluid, double tol) {
  for (const auto& x : fluid) {
    bool inside = true;
    for (int k = 0; k < D; ++k) inside &= x[k] > b.min[k] + tol && x[k] < b.max[k] - tol;
    if (inside)
      b.dict->error("min", std::string(b.inlet ? "inlet" : "outlet") + " '" + b.name + "' overlaps the fluid: the fluid particle at " +
                               fmt<D>(x) + " lies inside its box; the buffer must lie beside the fluid, its face against it");
  }
}

// The buffer particles of every inlet and outlet (OpenBoundaryRegion.hpp), with their
// velocities and types, after checking that no fluid lies inside a buffer.
template <int D>
void fillOpenBoundaries(const Dictionary& regionsDict, const std::vector<OpenBoundaryRegion<D>>& regions,
                        const std::vector<Vec<D>>& fluidPoints, const std::vector<Vec<D>>& fluidVelocity,
                        const PointGrid<D>& wallGrid, double d0, std::vector<Vec<D>>& points,
                        std::vector<Vec<D>>& velocity, std::vector<std::uint8_t>& type) {
  for (const auto& b : regions) {
    checkNoFluidInside<D>(b, fluidPoints, kSlack * d0);
    const std::size_t before = points.size();
    fillOpenBoundaryRegion<D>(b, d0, fluidPoints, fluidVelocity,
                              [&](const Vec<D>& x) { return wallGrid.anyCloserThan(x, 0.5 * d0); }, points, velocity);
    type.resize(points.size(), std::uint8_t(b.inlet ? ParticleType::inlet : ParticleType::outlet));
    if (b.inlet && points.size() == before)
      regionsDict.error(b.name, "inlet '" + b.name + "' holds no particle: its box lies within the walls' layers");
  }
}

// The fluid particles of every fluid region, in file order: filled, checked against earlier
// regions of curved or STL shape, cleared of what lies in or next to a wall, checked
// against the walls and the periodic box; their initial velocities.
template <int D>
void fillFluids(const Dictionary& regionsDict, std::vector<Region<D>>& fluids, const std::vector<Region<D>>& walls,
                const PointGrid<D>& wallGrid, const PeriodicBox<D>& periodic, double d0,
                std::vector<Vec<D>>& fluidPoints, std::vector<Vec<D>>& fluidVelocity) {
  const double tol = kSlack * d0;
  for (std::size_t i = 0; i < fluids.size(); ++i) {
    Region<D>& f = fluids[i];
    fillFluid(f, d0);
    if (f.points.empty())
      regionsDict.error(f.name, "fluid region '" + f.name + "' holds no particle (" +
                                    (f.body.shape ? std::string("no lattice point lies inside it,")
                                                  : "radius " + fmt(f.radius) + " m") +
                                    " against spacing " + fmt(d0) + " m)");
    checkBodyOverlap<D>(regionsDict, fluids, i, tol);
    removeFluidInWalls<D>(regionsDict, f, walls, wallGrid, d0);
    checkAgainstWalls(regionsDict, f, walls, tol);
    for (const auto& x : f.points)
      for (int k = 0; k < D; ++k)
        if (periodic.periodic[k] && (x[k] < periodic.lo[k] - tol || x[k] >= periodic.hi[k] - tol))
          regionsDict.error(f.name, "fluid region '" + f.name + "' has a particle at " + fmt<D>(x) +
                                        ", outside the periodic box in " + axisName(k) + " [" +
                                        fmt(periodic.lo[k]) + ", " + fmt(periodic.hi[k]) + ")");
    std::vector<Vec<D>> u;
    assignVelocity(f, u);
    fluidPoints.insert(fluidPoints.end(), f.points.begin(), f.points.end());
    fluidVelocity.insert(fluidVelocity.end(), u.begin(), u.end());
  }
}

namespace {
// The case directory, against which an STL `file` is found: the folder above system/ that
// holds particlesDict (the dictionary's own folder otherwise).
std::string caseDirectory(const Dictionary& particlesDict) {
  const std::filesystem::path folder = std::filesystem::path(particlesDict.name()).parent_path();
  return (folder.filename() == "system" ? folder.parent_path() : folder).string();
}
}  // namespace

double readSpacing(const Dictionary& particlesDict) { return spacing.read(particlesDict); }

template <int D>
GeneratedParticles<D> generateParticles(const Dictionary& dict, double particleCap) {
  GeneratedParticles<D> out;
  const double d0 = spacing.read(dict);
  const double tol = kSlack * d0;
  // maxParticles: a bound on the particle count checked before anything is
  // allocated (Index is 32-bit); a caller's cap may lower it further.
  double limit = maxParticles.read(dict);
  if (particleCap > 0) limit = std::min(limit, particleCap);
  // `dimension` (optional) is how the solver picks 2D or 3D; it must agree.
  if (dict.found("dimension") && dimensionKey.read(dict) != D)
    dict.error("dimension", "is " + std::to_string(dict.getInt("dimension")) + " but the particles are being built in " +
                                std::to_string(D) + "D");
  out.periodic = readPeriodic<D>(dict, d0);

  // 1. Read every region, in file order.
  const Dictionary& regionsDict = dict.subDict("regions");
  const std::string caseDir = caseDirectory(dict);
  std::vector<Region<D>> fluids, walls;
  std::vector<std::string> openNames;
  for (const auto& name : regionsDict.keys()) {
    const Dictionary& r = regionsDict.subDict(name);
    const std::string type = regionType.read(r);
    if (type == "fluid")
      fluids.push_back(readFluid<D>(r, name, d0, regionsDict, limit, caseDir));
    else if (type == "wall")
      walls.push_back(readWall<D>(r, name, d0, regionsDict, limit, caseDir));
    else if (hasKey<D>(r, "motion"))
      r.error("motion", "only wall regions move; an " + type + " stays where particlesDict puts it");
    else
      openNames.push_back(name);
  }
  if (fluids.empty()) regionsDict.error("regions", "no fluid region (a region with 'type fluid;') is defined");
  if (std::count_if(walls.begin(), walls.end(), [](const Region<D>& w) { return bool(w.motion); }) > 255)
    regionsDict.error("regions", "more than 255 wall regions have a motion");
  checkTotalCount<D>(regionsDict, fluids, walls, d0, limit);
  for (std::size_t b = 0; b < fluids.size(); ++b)
    for (std::size_t a = 0; a < b; ++a)
      if (overlap(fluids[a], fluids[b], tol)) overlapError(regionsDict, fluids[a].name, fluids[b].name);

  out.openBoundaries = readOpenBoundaries<D>(regionsDict, openNames, fluids, walls, d0);

  // 2. Wall particles; a particle closer than d0/2 to an earlier one is dropped.
  std::vector<Vec<D>> wallPoints;
  std::vector<std::uint8_t> wallGroup;
  PointGrid<D> wallGrid(0.5 * d0, wallPoints);
  fillWalls<D>(walls, d0, wallPoints, wallGrid, wallGroup);

  // 3. Fluid particles, minus those inside or next to a wall; velocities.
  std::vector<Vec<D>> fluidPoints, fluidVelocity;
  fillFluids<D>(regionsDict, fluids, walls, wallGrid, out.periodic, d0, fluidPoints, fluidVelocity);
  std::vector<Vec<D>> openPoints, openVelocity;
  std::vector<std::uint8_t> openType;
  fillOpenBoundaries<D>(regionsDict, out.openBoundaries, fluidPoints, fluidVelocity, wallGrid, d0, openPoints,
                        openVelocity, openType);
  dict.checkAllRead();
  for (const auto& w : walls) {
    out.walls.push_back({w.name, w.min, w.max, w.outerMin, w.outerMax, w.open, w.layers, d0, w.solid, w.body.shape});
    if (w.motion) {
      out.walls.back().motion = int(out.motions.size());
      out.motions.push_back(w.motion);
    }
  }

  // 4. The particle set: fluid first, then walls, then inlet and outlet buffers. (A
  // disc's count was estimated from its area; the exact count is checked here.)
  ParticleSet<D>& set = out.set;
  const std::size_t nf = fluidPoints.size(), nw = wallPoints.size(), n = nf + nw + openPoints.size();
  if (double(n) > limit)
    regionsDict.error("regions", "the regions hold " + std::to_string(n) + " particles, more than maxParticles " +
                                     countText(limit) + ": use a larger spacing, or raise maxParticles in particlesDict");
  set.resize(n);
  set.spacing = d0;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < long(n); ++i) {
    const bool fluid = std::size_t(i) < nf, wall = !fluid && std::size_t(i) < nf + nw;
    const std::size_t o = std::size_t(i) - nf - nw;
    set.position[i] = fluid ? fluidPoints[i] : wall ? wallPoints[i - nf] : openPoints[o];
    set.velocity[i] = fluid ? fluidVelocity[i] : wall ? Vec<D>::Zero() : openVelocity[o];
    set.type[i] = fluid ? std::uint8_t(ParticleType::fluid) : wall ? std::uint8_t(ParticleType::wall) : openType[o];
    set.surface[i] = std::uint8_t(SurfaceClass::interior);
    set.pressure[i] = 0;
    set.density[i] = 0;
    set.id[i] = i;
  }
  set.nextId = std::int64_t(n);
  if (!out.motions.empty()) {  // every wall particle's rest position, the moving walls' motions
    set.restPosition.assign(n, Vec<D>::Zero());
    set.motion.assign(n, 0);
    for (std::size_t i = nf; i < nf + nw; ++i) {
      set.restPosition[i] = set.position[i];
      set.motion[i] = wallGroup[i - nf];
    }
  }
  return out;
}

template GeneratedParticles<2> generateParticles<2>(const Dictionary&, double);
template GeneratedParticles<3> generateParticles<3>(const Dictionary&, double);

}  // namespace shizuku
