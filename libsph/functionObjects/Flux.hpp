// Function object `flux` (docs/boundaries.md, "Flux"): the volume flow rate of the
// fluid (m^2/s per unit depth in 2D, m^3/s in 3D) through
//   - a named inlet or outlet, `boundary inflow;`: the particles it released (inlet) or
//     captured (outlet) since the previous sample times the particle volume V = m/rho0,
//     over the time since that sample. Its time mean over any window is exactly the
//     volume that crossed, and its cumulative column the volume since the run began;
//     the rate of one sample is as noisy as one particle per interval. Needs the run:
//     in post-processing (no crossing counts) it is an error.
//   - a plane, `plane { point (..); normal (..); thickness 0.005; }`: the slab estimate
//     Q = (1/delta) sum_i V u_i . n over the fluid particles within delta/2 of the plane
//     (delta = thickness, default d0), optionally only those inside `min`/`max` (a box
//     that limits the plane to one opening). It is the rate at which the particles'
//     volume crosses the plane, averaged over the slab; it fluctuates as particles enter
//     and leave the slab (about 1/N_slab relative).
// File flux.dat: time, flux, and for a boundary the volume crossed since the run began.
// Reads (controlDict functions/<name>): type flux; boundary <name> | plane { point; normal;
// thickness; min; max; }; writeControl; writeInterval. Exactly one of boundary and plane.
#pragma once
#include "functionObjects/SampledFunctionObject.hpp"

namespace shizuku {

template <int D>
class Flux : public SampledFunctionObject<D> {
 public:
  Flux(const std::string& name, const Dictionary& dict);
  // The slab estimate through the plane (point, unit normal), slab thickness delta,
  // particles inside [lo, hi] only.
  static double planeFlux(const FlowState<D>& s, const Vec<D>& point, const Vec<D>& normal, double delta,
                          const Vec<D>& lo, const Vec<D>& hi);

 protected:
  std::string details() const override;
  void open(const FlowState<D>& s, const RunInfo& info) override;
  void sample(const FlowState<D>& s, const RunInfo& info) override;

 private:
  long crossedNow(const RunInfo& info) const;
  const Dictionary* dict_;
  std::string boundary_;          // empty: a plane
  Vec<D> point_ = Vec<D>::Zero(), normal_ = Vec<D>::Zero(), lo_, hi_;
  double thickness_ = 0;          // 0: d0
  long startCount_ = 0, lastCount_ = 0;
  double lastTime_ = 0;
  std::size_t index_ = 0;         // the boundary's place in RunInfo::crossings
};

}  // namespace shizuku
