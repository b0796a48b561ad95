// Function object `waveGauge` (docs/postprocessing.md, "waveGauge"): the free-surface
// elevation eta = y_s - stillWaterLevel at fixed horizontal positions, x in 2D and (x z)
// in 3D, as a resistance wave gauge in a flume reads it. y_s is found as `waterLevel`
// finds it (WaterLevel.hpp): along the vertical line up from (x, bottom[, z]) the highest
// y where the fluid's kernel sum S(y) = sum_j V W(|x_g + y e_y - x_j|) crosses
// minKernelSum (0.5: the nominal surface, half a spacing above a flat lattice's top row),
// linearly interpolated between samples d0/4 apart; eta = bottom - stillWaterLevel where no
// water covers the line. Measured on lattice blocks (test_functionObjects_values): a flat
// surface within 0.004 d0, a surface tilted by 1:10 within 0.002 d0.
// File elevation.dat: time, then eta at each gauge (gauge0, gauge1, ...) in m.
// Reads (controlDict functions/<name>): type waveGauge; positions (x ...) in 2D or
//   ((x z) ...) in 3D [m]; bottom [m] (default 0: the lines start there; put it at or
//   below the bed); stillWaterLevel [m] (default 0); minKernelSum 0.5; writeControl;
//   writeInterval.
#pragma once
#include "functionObjects/WaterLevel.hpp"

namespace shizuku {

template <int D>
class WaveGauge final : public WaterLevel<D> {
 public:
  WaveGauge(const std::string& name, const Dictionary& dict);
  // The elevation at each gauge (m).
  const std::vector<double>& elevation(const FlowState<D>& s);

 protected:
  std::string details() const override;
  std::string fileComment() const override;

 private:
  double still_ = 0;
  std::vector<double> eta_;
};

}  // namespace shizuku
