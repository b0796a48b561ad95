// One ISPH time step as docs/method.md 13 lists it, each stage a named function that calls
// the named operators (operators/Ops.hpp) and the effects of its stage:
//   1-4  analyse():        neighbours, <rho> (eq. 18), free surface and normals, operator weights
//   5    predict():        u* = u^n + dt (forces: g, nu <lap u^n>)                   (eq. 4)
//   6    solvePressure():  <lap p> = rho/dt <div u*> [+ pressure sources, eq. 9]     (eqs. 6, 9)
//   7    correct():        u^{n+1} = u* - dt/rho <grad p>                            (eq. 5)
//   8    advect():         r' = r^n + dt (u^{n+1} + advection velocities, XSPH)      (eq. 7,
//                          or the implicit midpoint rule of eq. 7b: isph/PositionUpdate.hpp)
//   9    correctPositions(): position corrections after advection (ADS)
//   10   shift():          particle shifting, capped, Taylor-corrected u (eq. 10)
// The step owns the numerical scheme (derivative operator, neighbour search, free-surface
// detector, pressure equation), the effects and its scratch arrays (sized once). In a
// distributed run (docs/parallel.md 5) the analysis starts by moving particles to their
// owners and building the halo; the stages refresh the ghosts' fields where a later pass
// reads them at neighbours; the step ends by dropping the ghosts.
// Reads no dictionary keys (CaseSetup builds its parts).
#pragma once
#include "core/StageTimers.hpp"
#include "boundaries/MovingWalls.hpp"
#include "decomposition/DomainDecomposition.hpp"
#include "effects/EffectSet.hpp"
#include "isph/PositionUpdate.hpp"
#include "pressure/PressureEquation.hpp"
#include "surface/FreeSurface.hpp"
#include <memory>
#include <string>
#include <vector>

namespace shizuku {

// The numerical scheme of a case, as CaseSetup reads it from system/sphSchemes and sphSolution.
template <int D>
struct NumericalScheme {
  std::unique_ptr<DerivativeOperator<D>> derivatives;
  std::unique_ptr<FreeSurfaceDetector<D>> freeSurface;
  std::unique_ptr<PressureEquation<D>> ppe;
  int reorderInterval = 20;  // steps between cell reorderings of the particles (0: never)
  typename PositionUpdate<D>::Rule positionUpdate = PositionUpdate<D>::Rule::euler;  // eq. 7 or 7b
};

// Statistics of the last step, for the progress line and tests.
struct StepReport {
  LinearSolveResult ppe;
  long ppeUnknowns = 0;
  long ppeStandardRows = 0;   // Laplacian rows that fell back to the standard weights
  double maxSpeed = 0;        // largest fluid |u| over all ranks, of the state after the step (the
                              // time loop's health check): the next step's CFL limit and shift passes
  long adsCount = -1;
  int shiftPasses = 1;        // the shift's passes (docs/method.md 6, eq. 10b)
  std::string dtLimiter = "fixed";
};

template <int D>
class IsphStep {
 public:
  // Registers the step's timed stages in `timers`, in execution order.
  // `decomposition`: a distributed run's (nullptr in serial), kept by the caller.
  IsphStep(FlowState<D>& s, NumericalScheme<D> scheme, EffectSet<D> effects, StageTimers& timers,
           DomainDecomposition<D>* decomposition = nullptr);

  // Steps 1-4 at the current positions.
  void analyse();
  // Steps 5-10 with time step dt, then time += dt and step += 1.
  void advance(double dt);
  // Sorts the particles along the neighbour cells (memory locality); the analysis must follow.
  void reorderParticles();
  // Resizes the per-particle arrays after particles were removed (or restored); no
  // allocation when the count shrank. The analysis must follow.
  void particleCountChanged();
  // A distributed run: the partition rebuilt from scratch from the particles as they are,
  // as a restart from a time written now rebuilds it (docs/parallel.md 7). The analysis
  // must follow.
  void repartitionAsAtRestart();
  // The particles were replaced by this rank's own ones alone (the last good state).
  void particlesRestored() {
    if (decomposition_) decomposition_->ghostsDropped();
    particleCountChanged();
  }

  // The moving walls (kept by the caller; nullptr: none): their velocities are set to the
  // step's end at its start, their positions with the fluid's advection.
  void setMovingWalls(MovingWalls<D>* m) { movingWalls_ = m; }
  MovingWalls<D>* movingWalls() const { return movingWalls_; }
  const EffectSet<D>& effects() const { return effects_; }
  const NumericalScheme<D>& scheme() const { return scheme_; }
  StepReport& report() { return report_; }
  const StepReport& report() const { return report_; }
  long ppeFallbacks() const { return ppeFallbacks_; }
  // Whether the next step uses no solver state built in earlier steps (a lagged AMG
  // hierarchy), so that a run stopped now restarts bit for bit; and a request that it
  // uses none (docs/reliability.md, "Restart is exact").
  bool nextStepStartsAfresh() const {
    return scheme_.ppe->nextSolveStartsAfresh(s_) || reorderDue();
  }
  // The particles are reordered by cells before the next step (every reorderInterval steps).
  bool reorderDue() const {
    const int reorder = scheme_.reorderInterval;
    return reorder > 0 && s_.step > 0 && s_.step % reorder == 0;
  }
  // A fresh start is reordered too: the generator's order (region by region) leaves the
  // first interval's threads unequal shares of the fluid and of the pressure matrix.
  bool reorders() const { return scheme_.reorderInterval > 0; }
  void startAfreshAtNextStep() { scheme_.ppe->startAfreshAtNextSolve(); }
  // The stages in execution order with their parameters and units, one per line.
  std::vector<std::string> describe() const;

 private:
  void predict();
  // effectTerms false: eq. 6 alone, without the effects' source and diagonal terms.
  void solvePressure(bool effectTerms = true);
  bool compressible() const;  // an effect adds a diagonal term (eq. 6c)
  void initialPressure();
  void correct();
  void advect();
  void correctPositions();
  void shift();
  void distribute();
  void dropGhosts();

  FlowState<D>& s_;
  NumericalScheme<D> scheme_;
  EffectSet<D> effects_;
  EffectNeeds needs_;
  std::unique_ptr<NeighbourSearch<D>> search_;
  DomainDecomposition<D>* decomposition_;
  MovingWalls<D>* movingWalls_ = nullptr;
  StageTimers& timers_;
  struct StageIds { int decomposition, neighbours, density, freeSurface, surfaceFit, weights, predictor, ppeAssembly, ppeSolve,
                    corrector, advection, positionCorrections; } st_{};
  std::vector<int> advectionTimer_;  // per advection-velocity effect
  StepReport report_;
  long ppeFallbacks_ = 0;
  // Scratch (sized once).
  std::vector<double> source_;
  std::vector<std::uint8_t> weightRows_;
  std::vector<Vec<D>> du_;
  PositionUpdate<D> positions_;
};

}  // namespace shizuku
