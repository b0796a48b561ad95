// The set-up of a simulation from its case directory: the physical constants, the kernel
// and spacing, the numerical scheme (derivative operator, free-surface detector, pressure
// equation) and the initial particles, either generated from system/particlesDict or read
// from the start time's directory.
// Reads: constant/physicalProperties rho, nu; constant/g value; system/sphSchemes kernel
// { type cubicSpline|WendlandC2; smoothingLengthRatio 1.2; }, derivatives SPH2|corrected|standard,
// freeSurface {..}, reorderInterval 20; system/sphSolution pressure {..}; system/particlesDict
// spacing (and, through the generator, every region).
#pragma once
#include "core/RunControl.hpp"
#include "isph/CaseFiles.hpp"
#include "isph/IsphStep.hpp"
#include "particles/OpenBoundaryRegion.hpp"
#include "particles/WallBox.hpp"
#include "particles/WallMotion.hpp"

namespace shizuku {

// Physical constants the effects and guards are built from (the flow state keeps rho0).
template <int D>
struct PhysicalConstants {
  double nu = 0;                     // m^2/s; 0: no viscous term is built
  Vec<D> g = Vec<D>::Zero();         // m/s^2; zero without constant/g
};

template <int D>
struct CaseSetup {
  // rho0 into the state; nu and g returned.
  static PhysicalConstants<D> readPhysicalConstants(const CaseFiles& files, FlowState<D>& s);
  // Kernel, d0 and h into the state; the scheme returned.
  static NumericalScheme<D> readScheme(const CaseFiles& files, FlowState<D>& s);
  // The initial particles and time into the state, per-particle arrays sized; returns the
  // name of the start time; the wall regions into `walls`, the inlets and outlets into
  // `openRegions` (FlowState::hasOpenBoundaries set when there are any), the moving walls'
  // motions into `motions` (indexed by WallBox::motion and the particle field `motion`).
  // postProcessing: only the particlesDict checks, no start time.
  static std::string readInitialState(const CaseFiles& files, const RunControl& rc, bool postProcessing,
                                      FlowState<D>& s, std::vector<WallBox<D>>& walls,
                                      std::vector<OpenBoundaryRegion<D>>& openRegions,
                                      std::vector<std::shared_ptr<WallMotion<D>>>& motions);
};

}  // namespace shizuku
