// The physical constants of a case, declared once and read by everything that needs them:
// the set-up (rho, nu, g), the viscosity effect (nu, wallCondition), the wall friction (nu) and
// the gravity effect (g). With wallFriction { } the walls show the viscous term free slip.
// Reads: constant/physicalProperties rho (kg/m^3, required), nu (m^2/s, 0: no viscous term),
//        wallCondition noSlip|slip, soundSpeed (m/s, read by the compressibility effect); constant/g value (m/s^2, required when the file exists).
#pragma once
#include "core/Dictionary.hpp"
#include "operators/Ops.hpp"

namespace shizuku {

struct PhysicalProperties {
  double rho = 0;                            // kg/m^3
  double nu = 0;                             // m^2/s
  WallVelocity walls = WallVelocity::noSlip; // what a wall shows the viscous term
};

PhysicalProperties readPhysicalProperties(const Dictionary& physicalProperties);
// soundSpeed (m/s), when the case names it (the compressibility effect, eq. 6c).
double readSoundSpeed(const Dictionary& physicalProperties);
template <int D> Vec<D> readGravity(const Dictionary& g);

}  // namespace shizuku
