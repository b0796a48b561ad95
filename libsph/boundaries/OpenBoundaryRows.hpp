// How inlet and outlet particles enter the pressure equation (docs/boundaries.md,
// "Inlets and outlets"): an outlet particle's pressure is prescribed (its region's
// `pressure`, set by OpenBoundaries), a Dirichlet value that fluid rows move to their
// right-hand side; an inlet particle takes the wall row (WallParticles.hpp, AdamiRow)
// with its prescribed velocity. Reads no dictionary keys.
#pragma once
#include "operators/FlowState.hpp"

namespace shizuku {

template <int D>
inline bool hasPrescribedPressure(const FlowState<D>& s, long i) {
  return s.hasOpenBoundaries && s.particles.isOutlet(std::size_t(i));
}

}  // namespace shizuku
