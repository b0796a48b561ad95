// Function object `conservation` (docs/design.md 1.3): global balances of the fluid
// particles (walls excluded), from the flow state at time t:
//   volume         = sum_i m / <rho>_i            (eq. 18 density; m^2 per unit depth in 2D)
//   nominalVolume  = N_fluid m / rho0            (constant unless particles are lost)
//   kineticEnergy  = sum_i 0.5 m |u_i|^2
//   momentum       = sum_i m u_i                  (vector)
//   angularMomentum= sum_i m r_i x u_i about the origin (z component in 2D, vector in 3D)
//   fluidMass      = N_fluid m
//   removedMass    = the mass of the fluid particles removed through the domain's bounds
//                    since the start (FlowState::removedMass): fluidMass + removedMass is
//                    the initial fluid mass to round-off
//   fluidVolume    = sum over interior particles of m/<rho>_i, plus m/rho0 for every other
//                    fluid particle: the volume the fluid occupies, counting only real
//                    compression. A free-surface, vicinity or splash particle's kernel sum
//                    is truncated, so its <rho> is low without any expansion and `volume`
//                    grows as a surface stretches (+8-12 % in a dam break); fluidVolume is
//                    constant for a splashing incompressible fluid and falls by the interior
//                    particles' mean density error when they compress.
//   releasedMass, capturedMass (cases with inlets or outlets): the mass inlets released
//                    and outlets captured since the start (FlowState::balance);
//                    fluidMass + removedMass - releasedMass + capturedMass is the initial
//                    fluid mass to round-off
// File conservation.dat: time, volume, nominalVolume, kineticEnergy, momentum, angularMomentum,
// fluidMass, removedMass, fluidVolume[, releasedMass, capturedMass].
// Reads (controlDict functions/<name>): type conservation; writeControl; writeInterval.
#pragma once
#include "core/BlockReduce.hpp"
#include "functionObjects/SampledFunctionObject.hpp"
#include <optional>

namespace shizuku {

template <int D>
struct ConservationValues {
  using Angular = Eigen::Matrix<double, D == 2 ? 1 : 3, 1>;  // z only in 2D
  double volume = 0, nominalVolume = 0, kineticEnergy = 0, fluidMass = 0, removedMass = 0;
  double releasedMass = 0, capturedMass = 0;
  double fluidVolume = 0;
  Vec<D> momentum = Vec<D>::Zero();
  Angular angularMomentum = Angular::Zero();
};

template <int D>
class Conservation : public SampledFunctionObject<D> {
 public:
  Conservation(const std::string& name, const Dictionary& dict);
  static ConservationValues<D> compute(const FlowState<D>& s);

 protected:
  void open(const FlowState<D>& s, const RunInfo& info) override;
  void sample(const FlowState<D>& s, const RunInfo& info) override;

 private:
  bool openBoundaries_ = false;  // the released and captured columns
};

}  // namespace shizuku
