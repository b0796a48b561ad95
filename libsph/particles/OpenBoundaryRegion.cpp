// Inlet and outlet regions of particlesDict: see OpenBoundaryRegion.hpp.
#include "particles/OpenBoundaryRegion.hpp"
#include "core/Parameter.hpp"
#include <cmath>

namespace shizuku {

namespace key {
namespace {
const ParameterGroup openRegion("system/particlesDict: regions/<name> (type inlet or outlet)",
                                "A buffer of particles at an open end of the domain (docs/boundaries.md).");
const VectorParameter direction = openRegion.vector("direction", dim::none,
    "flow direction, an axis: into the domain for an inlet, out of it for an outlet").required();
const ScalarParameter pressure = openRegion.scalar("pressure", dim::pressure,
    "outlet: the prescribed pressure of its particles, Pa").def(0).sane(1e12);
const ParameterGroup inletVelocity("system/particlesDict: regions/<name>/velocity (type inlet)",
                                   "The velocity of an inlet's particles, released as fluid at their face.");
const OptionParameter velocityType = inletVelocity.option("type", {"uniform", "expression"},
    "uniform value (..), or expression: muParser expressions of x y z t, one per component").required();
}  // namespace
}  // namespace key

namespace {
std::string fmt(double x) { return formatNumber(x); }
template <int D> std::string fmt(const Vec<D>& v) { return formatNumber<D>(v); }
const char* axisWord(int k, int sign) {
  static const char* words[] = {"-x", "+x", "-y", "+y", "-z", "+z"};
  return words[2 * k + (sign > 0)];
}

// The direction as (axis, sign); a zero or oblique vector is an error.
template <int D>
void readDirection(const Dictionary& r, OpenBoundaryRegion<D>& b) {
  const Vec<D> d = key::direction.read<D>(r);
  int axis = -1, nonZero = 0;
  for (int k = 0; k < D; ++k)
    if (d[k] != 0) { ++nonZero; axis = k; }
  if (nonZero == 0) r.error("direction", "direction " + fmt<D>(d) + " is zero: give the flow direction, an axis such as (1 0)");
  if (nonZero > 1) {
    int big = 0;
    for (int k = 1; k < D; ++k)
      if (std::abs(d[k]) > std::abs(d[big])) big = k;
    Vec<D> nearest = Vec<D>::Zero();
    nearest[big] = d[big] > 0 ? 1 : -1;
    r.error("direction", "direction " + fmt<D>(d) + " is oblique: inlets and outlets are boxes whose direction is an axis (+-x, +-y" +
                             std::string(D == 3 ? ", +-z)" : ")") + "; did you mean direction " + fmt<D>(nearest) + "?");
  }
  b.axis = axis;
  b.sign = d[axis] > 0 ? 1 : -1;
}

// A box beside the domain lies on one side of its centre along its direction; one that
// spans the centre along it (an inlet at the left end given direction (0 1)) would
// release into, or capture from, a side wall. The suggestion: the axis along which the
// box lies furthest from the centre, pointing into the domain (an inlet) or out of it.
template <int D>
void checkNotSideways(const Dictionary& r, const OpenBoundaryRegion<D>& b, const Vec<D>& wallsCentre) {
  const int k = b.axis;
  if (wallsCentre[k] < b.min[k] || wallsCentre[k] > b.max[k]) return;
  int best = -1;
  double furthest = 0;
  for (int j = 0; j < D; ++j) {
    const double out = std::max(b.min[j] - wallsCentre[j], wallsCentre[j] - b.max[j]);
    if (out > furthest) { furthest = out; best = j; }
  }
  const char* kind = b.inlet ? "inlet" : "outlet";
  std::string fix;
  if (best >= 0) {
    Vec<D> d = Vec<D>::Zero();
    d[best] = ((wallsCentre[best] > b.max[best]) == b.inlet) ? 1 : -1;
    fix = ": did you mean direction " + fmt<D>(d) + "?";
  }
  r.error("direction", std::string(kind) + " '" + b.name + "': direction " + fmt<D>(b.direction()) +
                           " runs along the domain's side, not " + (b.inlet ? "into" : "out of") +
                           " it: the box spans the domain's centre (" + fmt(wallsCentre[k]) + " m) along " +
                           std::string(1, "xyz"[k]) + ", so its face would meet a wall, not the fluid" + fix);
}

// The inlet's velocity keys, checked by evaluating them on the box's lattice at t = 0.
template <int D>
void readInletVelocity(const Dictionary& r, OpenBoundaryRegion<D>& b, double d0) {
  if (!r.found("velocity")) r.error("velocity", "an inlet needs velocity { type uniform; value (..); } or { type expression; value (\"..\" ..); }");
  const Dictionary& v = r.subDict("velocity");
  b.expression = key::velocityType.read(v) == "expression";
  if (!b.expression) {
    b.value = v.getVector<D>("value", dim::velocity);
    return;
  }
  b.expressionText = v.getWordList("value");
  if (int(b.expressionText.size()) != D)
    v.error("value", "expected " + std::to_string(D) + " expressions, one per velocity component, found " +
                         std::to_string(b.expressionText.size()));
  std::unique_ptr<InletVelocity<D>> u;
  try {
    u = std::make_unique<InletVelocity<D>>(b);
  } catch (const VelocityExpressionError& e) {
    v.error("value", e.what());
  }
  std::array<long, D> lo{}, n{};
  for (int k = 0; k < D; ++k) n[k] = std::max(1L, long(std::floor((b.max[k] - b.min[k]) / d0 + 1e-9)));
  forEachIndex<D>(lo, n, [&](const std::array<long, D>& i) {
    Vec<D> x;
    for (int k = 0; k < D; ++k) x[k] = b.min[k] + (double(i[k]) + 0.5) * d0;
    Vec<D> ux;
    try {
      ux = (*u)(x, 0.0);
    } catch (const VelocityExpressionError& e) {
      v.error("value", e.what());
    }
    if (!(ux.allFinite() && ux.norm() <= 1e12))
      v.error("value", "the expressions give " + fmt<D>(ux) + " m/s at " + fmt<D>(x) + " m and t = 0");
  });
}
}  // namespace

template <int D>
InletVelocity<D>::InletVelocity(const OpenBoundaryRegion<D>& b) : value_(b.value) {
  if (b.expression) expression_ = std::make_unique<VelocityExpression<D>>(b.expressionText);
}

template <int D>
std::string OpenBoundaryRegion<D>::describe() const {
  std::string s = std::string(inlet ? "inlet '" : "outlet '") + name + "': box " + fmt<D>(min) + "-" + fmt<D>(max) +
                  ", direction " + axisWord(axis, sign);
  if (!inlet) return s + ", pressure " + fmt(pressure) + " Pa";
  if (!expression) return s + ", velocity " + fmt<D>(value) + " m/s";
  s += ", velocity (";
  for (std::size_t k = 0; k < expressionText.size(); ++k) s += (k ? " \"" : "\"") + expressionText[k] + "\"";
  return s + ")";
}

template <int D>
OpenBoundaryRegion<D> readOpenBoundaryRegion(const Dictionary& r, const std::string& name, bool inlet,
                                             const Vec<D>& min, const Vec<D>& max, double d0, const Vec<D>& wallsCentre) {
  OpenBoundaryRegion<D> b;
  b.name = name;
  b.dict = &r;
  b.inlet = inlet;
  b.min = min;
  b.max = max;
  for (const char* k : {"layers", "open"})
    if (r.found(k)) r.error(k, std::string("only wall regions take '") + k + "'");
  if (inlet && r.found("pressure"))
    r.error("pressure", "an inlet's pressure follows the fluid (the wall rule); 'pressure' is for outlets");
  if (!inlet && r.found("velocity"))
    r.error("velocity", "an outlet's velocity follows the fluid; 'velocity' is for inlets");
  readDirection<D>(r, b);
  const int k = b.axis;
  // An inlet's face is its downstream end, an outlet's its upstream end.
  const bool faceAtMax = (b.sign > 0) == inlet;
  b.face = faceAtMax ? max[k] : min[k];
  b.farFace = faceAtMax ? min[k] : max[k];
  checkNotSideways<D>(r, b, wallsCentre);
  const double centre = 0.5 * (min[k] + max[k]);
  const double towardWalls = b.sign * (wallsCentre[k] - centre);
  if (inlet ? towardWalls < 0 : towardWalls > 0) {
    Vec<D> flipped = Vec<D>::Zero();  // (no -0 in the suggestion)
    flipped[k] = -b.sign;
    r.error("direction", std::string(inlet ? "inlet" : "outlet") + " '" + name + "': direction " + fmt<D>(b.direction()) +
                             " points " + (inlet ? "away from" : "into") + " the domain (its centre lies at " +
                             fmt(wallsCentre[k]) + " m along " + std::string(1, "xyz"[k]) + "); an " +
                             (inlet ? "inlet's direction points into the domain" : "outlet's direction points out of it") +
                             ": did you mean direction " + fmt<D>(flipped) + "?");
  }
  const double spacings = b.length() / d0;
  if (std::abs(spacings - std::round(spacings)) > 1e-6 || std::round(spacings) < 1) {
    const double whole = std::max(1.0, std::round(spacings));
    Vec<D> suggestion = faceAtMax ? min : max;
    suggestion[k] = b.face - (faceAtMax ? 1 : -1) * whole * d0;
    r.error(faceAtMax ? "min" : "max",
            "the length of " + std::string(inlet ? "inlet" : "outlet") + " '" + name + "' along its direction is " +
                fmt(b.length()) + " m = " + fmt(spacings) + " spacings (d0 = " + fmt(d0) +
                " m): it must be a whole number of spacings; did you mean " + (faceAtMax ? "min " : "max ") +
                fmt<D>(suggestion) + "?");
  }
  if (inlet) readInletVelocity<D>(r, b, d0);
  else b.pressure = key::pressure.read(r);
  return b;
}

#define SHIZUKU_OPEN_REGION(D)                                                                                        \
  template struct OpenBoundaryRegion<D>;                                                                               \
  template class InletVelocity<D>;                                                                                     \
  template OpenBoundaryRegion<D> readOpenBoundaryRegion<D>(const Dictionary&, const std::string&, bool, const Vec<D>&, \
                                                           const Vec<D>&, double, const Vec<D>&);
SHIZUKU_OPEN_REGION(2)
SHIZUKU_OPEN_REGION(3)

}  // namespace shizuku
