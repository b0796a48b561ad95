// The fluid's mass balance across the case's boundaries since the start from
// particlesDict (docs/boundaries.md, "Mass balance"): what the domain's bounds
// removed, what inlets released and what outlets took. Kept across restarts in
// uniform/time, restored with the last good state, reported by `conservation`:
//   fluid mass now = initial fluid mass + released m - captured m - removedMass,
// m the particle mass (every particle carries the same mass).
// Reads no dictionary keys.
#pragma once
#include <string>

namespace shizuku {

struct FluidBalance {
  double removedMass = 0;  // kg (kg/m in 2D): fluid removed through the domain's bounds
  long removedCount = 0;   // particles removed through the domain's bounds
  long released = 0;       // inlet particles that crossed their inlet's face and became fluid
  long captured = 0;       // fluid particles that crossed an outlet's face (then outlet particles)
};

// The particles one inlet released, or one outlet captured, since the run began (the
// `flux` function object differences them).
struct BoundaryCrossings {
  std::string name;
  bool inlet = true;
  long count = 0;
};

}  // namespace shizuku
