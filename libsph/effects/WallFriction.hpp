// The law of the wall that the wall-friction effect applies (docs/method.md 11.2): the
// friction velocity u_tau of a flow running at speed U along a wall, at distance y from the
// wall face, for kinematic viscosity nu and equivalent sand-grain roughness ks (0: smooth).
//   log layer:        U / u_tau = (1/kappa) ln( y / (nu / (9 u_tau) + ks / 30) ),  kappa = 0.41
//   viscous sublayer: U / u_tau = y u_tau / nu   (where y u_tau / nu <= 11, rough or smooth)
// The log layer's two limits are the smooth law ln(y+)/kappa + 5.4 and the fully rough one
// ln(y/ks)/kappa + 8.3 (Christensen's form of the transition between them). Where y lies
// inside the roughness (y <= nu/(9 u_tau) + ks/30, no log layer), u_tau = kappa U, the log's
// argument taken as e.
#pragma once

namespace shizuku {

constexpr double kVonKarman = 0.41;

double frictionVelocity(double U, double y, double nu, double roughness);

}  // namespace shizuku
