// Function object `fluidExtent` (docs/design.md 1.3): the bounding box of the fluid
// particle positions at time t (walls excluded; periodic positions as stored).
// File extent.dat: time, min (x y[ z]), max (x y[ z]) in m. With no fluid
// particle both are nan. connectedOnly yes: only fluid particles with another fluid
// particle within the kernel support 2h (the body of water; lone particles thrown ahead
// of a front, which an experiment's leading edge does not count, are left out);
// minNeighbours n (with connectedOnly, default 1): at least n others within 2h. In a
// periodic slab of a 2D flow a particle has copies of itself along z within 2h (4 with
// h = 1.2 d0 and 5 or more layers), so 5 there counts what 1 counts in 2D.
// Reads (controlDict functions/<name>): type fluidExtent; connectedOnly; minNeighbours;
// writeControl; writeInterval.
#pragma once
#include "functionObjects/SampledFunctionObject.hpp"
#include <optional>

namespace shizuku {

template <int D>
class FluidExtent : public SampledFunctionObject<D> {
 public:
  FluidExtent(const std::string& name, const Dictionary& dict);
  // Fluid bounding box (nan if there is no fluid particle) of the fluid particles with at
  // least minNeighbours other fluid particles within 2h (0: of every fluid particle).
  static void compute(const FlowState<D>& s, Vec<D>& lo, Vec<D>& hi, int minNeighbours = 0);

 protected:
  void open(const FlowState<D>& s, const RunInfo& info) override;
  void sample(const FlowState<D>& s, const RunInfo& info) override;

 private:
  int minNeighbours_ = 0;  // 0: every fluid particle (connectedOnly no)
};

}  // namespace shizuku
