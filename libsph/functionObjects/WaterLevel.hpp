// Function object `waterLevel` (docs/postprocessing.md, "waterLevel"): the height of the
// water above gauge points, as a wave gauge reads it. Along the vertical line up from
// each gauge point x_g (the +y axis; gravity points along -y) the kernel sum of the fluid
//   S(y) = sum_j V W(|x_g + y e_y - x_j|),   V = m / rho0,  j over fluid particles,
// is sampled every d0/4 from the gauge point up to 2h above the highest fluid particle
// near the line; the level is the highest y where S crosses `minKernelSum` (default 0.5)
// from above, placed by linear interpolation between the two samples around the
// crossing, and the file holds the height y_level - y_g (0 when S is below the threshold
// everywhere). S = 0.499 half a spacing outside a flat lattice face (Probes.hpp), so 0.5
// cuts at the nominal free surface: a still layer of depth H reads H (within 0.03 d0,
// test_functionObjects_values.cpp). Spray above the body of water counts where it raises
// S to the threshold, as a drop on a capacitance wire would.
// Cost per sample: one pass over the particles per gauge (the ones within 2h of the line
// are kept, minimum image in periodic directions), then a sum over those per level
// sample; no allocation after the first sample.
// File height.dat: time, then the height at each gauge (point0, point1, ...) in m.
// Reads (controlDict functions/<name>): type waterLevel; points ((x y [z]) ...) [m];
//   minKernelSum 0.5; writeControl; writeInterval.
#pragma once
#include "functionObjects/SampledFunctionObject.hpp"

namespace shizuku {

template <int D>
class WaterLevel : public SampledFunctionObject<D> {
 public:
  WaterLevel(const std::string& name, const Dictionary& dict);
  // A gauge of another type (waveGauge) whose keys the caller reads.
  WaterLevel(const std::string& name, const std::string& type, const Dictionary& dict, std::vector<Vec<D>> points,
             double minKernelSum);
  const std::vector<Vec<D>>& points() const { return points_; }
  // Height of the water above each gauge point (m).
  const std::vector<double>& evaluate(const FlowState<D>& s);

 protected:
  std::string details() const override;
  void open(const FlowState<D>& s, const RunInfo& info) override;
  void sample(const FlowState<D>& s, const RunInfo& info) override;
  virtual std::string fileComment() const;
  double threshold() const { return minKernelSum_; }
  std::vector<Vec<D>> points_;
  // The file, its columns' prefix, and what is added to each height before it is written.
  std::string fileName_ = "height.dat", columnPrefix_ = "point";
  double offset_ = 0;

 private:
  double height(const FlowState<D>& s, const Vec<D>& foot);
  double minKernelSum_ = 0.5;
  std::vector<double> heights_;
  std::vector<Vec<D>> near_;  // offsets x_j - x_g of the fluid particles within 2h of a line
};

}  // namespace shizuku
