// Function object `wallPressure` (docs/postprocessing.md, "wallPressure"): the mean
// pressure on a sensor face of a named wall box, its force and impulse.
//   The sensor lies on the face of wall `wall` on which `centre` lies (within d0/2 of a
//   closed face of its surface): in 2D a segment of length `size` along the face, in 3D
//   a square of side `size` (or `shape disc;`, a disc of diameter `size`).
//   The face pressure at each wall column (`faceValue`: fluid, the default, or
//   wallLayers; auto is the same as fluid):
//   - wallLayers: extrapolated from the PPE's pressure of the first two wall
//     layers (docs/method.md 11: the Adami rows carry the fluid pressure into the wall),
//     which sit d0/2 and 3d0/2 behind the surface (s/2 and 3s/2 inside a solid box, s <= d0
//     its lattice spacing normal to the face):
//       p_face = p_1 + (p_1 - p_2)/2 = 3/2 p_1 - 1/2 p_2,
//     exact for a pressure linear across the wall (hydrostatic, or any uniform
//     acceleration);
//   - fluid: the fluid's pressure carried to the face point x_c of the column, from the
//     fluid neighbours f of the column's first-layer wall particle w:
//       p_face = sum_f W_wf (p_f + rho0 g . (x_c - r_f)) / sum_f W_wf,
//     the Adami row's hydrostatic extrapolation evaluated at the face, without the wall
//     row's velocity term (which is a Neumann condition's penalty inside the wall, not a
//     pressure the water feels: docs/validation.md, "Which pressure the water feels");
//     exact on any hydrostatic field. On a moving wall x_c is the rest face point moved by
//     the wall's current pose (FlowState::wallPoses).
//   Along the face the column values are interpolated linearly (2D) or
//   bilinearly (3D) between the columns, constant beyond the last column of an open
//   edge (linear, the last interval continued, on a solid box's face, whose columns end
//   s/2 before its edges), and the interpolant is averaged over the sensor exactly (segment, square: the
//   hat functions' integrals) or by a polar quadrature (disc, 32 x 64 points). The
//   reading is a fixed weighted sum of wall particles' pressures, so it is smooth in
//   the sensor's position and size (a sensor narrower than d0 reads the interpolant's
//   mean, not the nearest particle) and exact (to the solver's tolerance) on any linear
//   pressure field, e.g. rho g (H - y_c) on a hydrostatic wall.
//   Force F = p A (A = size in 2D, per unit depth: N/m; size^2 or pi size^2/4 in 3D: N),
//   impulse = time integral of F since the start time (trapezoidal rule over every
//   step, whatever writeControl), optional first-order low-pass filter of p
//   (LowPassFilter.hpp) updated every step.
// File wallPressure.dat: time, p, [p_lowPass], force, impulse.
// Reads (controlDict functions/<name>): type wallPressure; wall; centre; size; shape;
// faceValue; filter { type lowPass; cutoff; }; writeControl; writeInterval.
#pragma once
#include "functionObjects/LowPassFilter.hpp"
#include "functionObjects/SampledFunctionObject.hpp"
#include "particles/WallBox.hpp"
#include <array>
#include <map>
#include <optional>

namespace shizuku {

template <int D>
class WallPressure : public SampledFunctionObject<D> {
 public:
  // gravity: the case's g (the fluid-side face value's hydrostatic part).
  WallPressure(const std::string& name, const Dictionary& dict, const std::vector<WallBox<D>>& walls,
               const Vec<D>& gravity = Vec<D>::Zero());
  void execute(const FlowState<D>& s, const RunInfo& info) override;

  // Mean of the linear interpolant of `values` at `nodes` (increasing; constant beyond
  // the ends) over [a, b], as weights per node: (node index, weight), weights sum to 1.
  // The weights of the nodes in the mean of the piecewise linear interpolant over [a, b]
  // (its value at a if b <= a): constant beyond the end nodes, or, with linearEnds, the
  // end interval's line continued (a solid's face beyond its last column).
  static std::vector<std::pair<long, double>> segmentWeights(const std::vector<double>& nodes, double a, double b,
                                                             bool linearEnds = false);
  // The sensor's pressure in state `s` (Pa); finds the wall particles first if needed.
  double pressure(const FlowState<D>& s);
  double area() const { return area_; }
  double force() const { return force_; }
  double impulse() const { return impulse_; }
  double filtered() const { return filter_ ? filter_->output() : pressure_; }

 protected:
  std::string details() const override;
  void open(const FlowState<D>& s, const RunInfo& info) override;
  void sample(const FlowState<D>& s, const RunInfo& info) override;

 private:
  struct Term {
    Vec<D> position;      // the wall particle's lattice position
    double weight = 0;    // its share of the reading (wallLayers)
    double share = 0;     // its column's share of the sensor's mean; 0 on the second layer
    Vec<D> face;          // the face point of its column (at rest on a moving wall)
    std::size_t index = 0;
    std::int64_t id = -1;
  };
  void chooseFace(const Dictionary& dict, const Vec<D>& centre);
  void buildTerms(const Dictionary& dict);
  void locate(const FlowState<D>& s);
  Vec<D> faceOf(const FlowState<D>& s, const Term& t) const;
  double fluidFaceValue(const FlowState<D>& s, const Term& t, const Vec<D>& face) const;
  std::string faceName() const;

  WallBox<D> wall_;
  int axis_ = 0, side_ = 0;          // the face: normal axis, 0 low (min) or 1 high (max)
  Vec<D> centre_ = Vec<D>::Zero();   // on the face
  double size_ = 0, area_ = 0;
  bool disc_ = false;
  bool fromFluid_ = false;           // faceValue fluid (or auto)
  Vec<D> gravity_ = Vec<D>::Zero();
  std::vector<Term> terms_;
  bool located_ = false;                              // the terms were looked up once
  std::map<std::array<long, D>, std::size_t> termOf_;  // lattice indices (x, y[, z]) -> term
  std::vector<std::vector<double>> axisNodes_;        // per axis: the wall lattice coordinates
  std::optional<LowPassFilter> filter_;
  double cutoff_ = 0;
  double pressure_ = 0, force_ = 0, impulse_ = 0, lastTime_ = 0;
  bool started_ = false;
};

}  // namespace shizuku
