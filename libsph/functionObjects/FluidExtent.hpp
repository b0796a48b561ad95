// Function object `fluidExtent` (docs/design.md 1.3): the bounding box of the fluid
// particle positions at time t (walls excluded; periodic positions as stored).
// File extent.dat: time, min (x y[ z]), max (x y[ z]) in m. With no fluid
// particle both are nan. connectedOnly yes: only fluid particles with another fluid
// particle within the kernel support 2h (the body of water; lone particles thrown ahead
// of a front, which an experiment's leading edge does not count, are left out).
// Reads (controlDict functions/<name>): type fluidExtent; connectedOnly; writeControl;
// writeInterval.
#pragma once
#include "functionObjects/SampledFunctionObject.hpp"
#include <optional>

namespace shizuku {

template <int D>
class FluidExtent : public SampledFunctionObject<D> {
 public:
  FluidExtent(const std::string& name, const Dictionary& dict);
  // Fluid bounding box (nan if there is no fluid particle); connectedOnly: see above.
  static void compute(const FlowState<D>& s, Vec<D>& lo, Vec<D>& hi, bool connectedOnly = false);

 protected:
  void open(const FlowState<D>& s, const RunInfo& info) override;
  void sample(const FlowState<D>& s, const RunInfo& info) override;

 private:
  bool connectedOnly_ = false;
};

}  // namespace shizuku
