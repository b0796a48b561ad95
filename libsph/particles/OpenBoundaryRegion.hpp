// Inlet and outlet regions of system/particlesDict (docs/boundaries.md, "Inlets and
// outlets"): a box of buffer particles on the lattice of the fluid beside an open end.
//
//   inflow  { type inlet;  shape box; min (..); max (..); direction (1 0);
//             velocity { type uniform; value (0.1 0); } }        // or
//             velocity { type expression; value ("0.15*(1-((y-0.05)/0.05)^2)" "0"); }
//   outflow { type outlet; shape box; min (..); max (..); direction (1 0); pressure 0; }
//
// `direction` is an axis direction (+-x, +-y, +-z), the flow direction through the
// region: an inlet's points into the domain, an outlet's out of it. The region's
// `face` is the box face the fluid side meets: an inlet's downstream face, an
// outlet's upstream face; `farFace` is the opposite one. The box's length along
// `direction` must be a whole number of spacings (a released particle's replacement
// goes exactly one buffer length back, keeping the lattice); the solver also requires
// it to cover the kernel support 2h (checked with the kernel, in OpenBoundaries).
// Velocity (inlets): uniform, or muParser expressions of x y z t with pi (t in s).
// Pressure (outlets): the prescribed pressure of the outlet particles, Pa (default 0).
//
// Filling at the start from particlesDict: the lattice points min + (i + 1/2) d0 of
// the box, dropped where closer than d0/2 to a wall particle. An inlet is filled
// whole, at its velocity at t = 0. An outlet is filled where fluid meets its face (a
// point is kept when some fluid particle lies within d0 of the point's image in the
// first fluid row, at `face` - d0/2 along `direction`), at that fluid particle's
// velocity: a channel full of fluid starts with a full outlet, a dry outlet (the
// downstream end of a weir) with an empty one.
//
// Errors (InputError naming file, line and keyword): shape other than box, a zero or
// oblique direction, a direction along which the box spans the walls' centre (sideways:
// its face would meet a side wall), an inlet whose direction points away from the
// walls' interior (or an outlet's into it), a length along the direction that is not a whole number
// of spacings, fluid inside the box, a velocity type other than uniform or
// expression, an expression that does not parse or is not finite at t = 0, keys of
// the other kind (velocity on an outlet, pressure on an inlet).
// Keys read: direction, velocity { type; value; }, pressure (min, max, shape, type are
// read by ParticleGenerator).
#pragma once
#include "core/Dictionary.hpp"
#include "particles/PointGrid.hpp"
#include "particles/VelocityExpression.hpp"
#include <memory>
#include <string>
#include <vector>

namespace shizuku {

template <int D>
struct OpenBoundaryRegion {
  std::string name;
  const Dictionary* dict = nullptr;  // the region's sub-dictionary (for errors)
  bool inlet = true;                 // inlet, or outlet
  Vec<D> min = Vec<D>::Zero(), max = Vec<D>::Zero();
  int axis = 0;                      // direction = sign e_axis
  int sign = 1;
  double face = 0, farFace = 0;      // coordinates along axis
  // inlet velocity: uniform `value`, or one expression per component
  bool expression = false;
  Vec<D> value = Vec<D>::Zero();
  std::vector<std::string> expressionText;
  double pressure = 0;               // outlet, Pa

  Vec<D> direction() const { Vec<D> d = Vec<D>::Zero(); d[axis] = sign; return d; }
  double length() const { return max[axis] - min[axis]; }
  // Distance of x past the face along the direction (> 0: on the fluid side of an
  // inlet's face, beyond an outlet's face).
  double pastFace(const Vec<D>& x) const { return sign * (x[axis] - face); }
  double pastFarFace(const Vec<D>& x) const { return sign * (x[axis] - farFace); }
  // Within the box's extent across the direction.
  bool acrossInside(const Vec<D>& x, double tol) const {
    for (int k = 0; k < D; ++k)
      if (k != axis && (x[k] < min[k] - tol || x[k] > max[k] + tol)) return false;
    return true;
  }
  std::string describe() const;  // "inlet 'inflow': box (..)-(..), direction (1 0), velocity ..."
};

// An inlet's velocity u(x, t): uniform, or its expressions (one evaluator; not thread-safe).
template <int D>
class InletVelocity {
 public:
  explicit InletVelocity(const OpenBoundaryRegion<D>& b);
  // Throws VelocityExpressionError when an expression fails to evaluate.
  Vec<D> operator()(const Vec<D>& x, double t) const { return expression_ ? (*expression_)(x, t) : value_; }

 private:
  Vec<D> value_;
  std::unique_ptr<VelocityExpression<D>> expression_;
};

// The keys of an inlet or outlet region `r` whose box (min, max) the generator has read.
// wallsCentre: the centre of the walls' bounding box (or of the fluid without walls),
// to tell an inward from an outward direction.
template <int D>
OpenBoundaryRegion<D> readOpenBoundaryRegion(const Dictionary& r, const std::string& name, bool inlet,
                                             const Vec<D>& min, const Vec<D>& max, double d0, const Vec<D>& wallsCentre);

// The buffer particles of region b (see above): points appended to `points`, their
// velocities to `velocity`. fluid/fluidVelocity: the initial fluid; nearWall(x): a wall
// particle lies closer than d0/2.
template <int D, class NearWall>
void fillOpenBoundaryRegion(const OpenBoundaryRegion<D>& b, double d0, const std::vector<Vec<D>>& fluid,
                            const std::vector<Vec<D>>& fluidVelocity, NearWall nearWall,
                            std::vector<Vec<D>>& points, std::vector<Vec<D>>& velocity) {
  std::unique_ptr<InletVelocity<D>> u;
  if (b.inlet) u = std::make_unique<InletVelocity<D>>(b);
  PointGrid<D> fluidGrid(d0, fluid);
  for (std::size_t i = 0; i < fluid.size(); ++i)
    if (b.acrossInside(fluid[i], 2 * d0) && std::abs(b.pastFace(fluid[i])) < 2 * d0) fluidGrid.insert(Index(i));
  std::array<long, D> lo{}, n{};
  for (int k = 0; k < D; ++k) n[k] = long(std::floor((b.max[k] - b.min[k]) / d0 + 1e-9));
  forEachIndex<D>(lo, n, [&](const std::array<long, D>& i) {
    Vec<D> x;
    for (int k = 0; k < D; ++k) x[k] = b.min[k] + (double(i[k]) + 0.5) * d0;
    if (nearWall(x)) return;
    if (b.inlet) {
      points.push_back(x);
      velocity.push_back((*u)(x, 0.0));
      return;
    }
    Vec<D> image = x;
    image[b.axis] = b.face - b.sign * 0.5 * d0;
    const Index f = fluidGrid.closest(image, d0);
    if (f < 0) return;
    points.push_back(x);
    velocity.push_back(fluidVelocity[std::size_t(f)]);
  });
}

}  // namespace shizuku
