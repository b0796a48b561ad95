// The ISPH simulation of a case: it owns the flow state and the parts that act on it,
// each built from the case by CaseSetup: the step (IsphStep: the numerical scheme and the
// effects), the health guard, the function objects and the stage timers; run() hands them
// to the TimeLoop. Programs (shizuku, shizukuParticles, shizukuPostProcess) and tests talk
// to this class only.
// Reads: every case dictionary (docs/design.md 1.2), through CaseSetup, EffectSet,
// HealthGuard, RunControl and the function objects; checkAllRead() then rejects any
// keyword nobody read.
#pragma once
#include "core/RunControl.hpp"
#include "core/StageTimers.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "isph/CaseFiles.hpp"
#include "isph/HealthGuard.hpp"
#include "isph/IsphStep.hpp"
#include "isph/Outflow.hpp"
#include "isph/StopRequests.hpp"
#include <memory>
#include <string>
#include <vector>

namespace shizuku {

struct SimulationOptions {
  bool functionObjects = true;
  bool postProcessing = false;   // set up for analysing saved times only (no run)
  int threads = 0;               // 0 = OpenMP default
};

template <int D>
class Simulation {
 public:
  Simulation(const std::string& caseDir, const SimulationOptions& opt);
  ~Simulation();

  // The pipeline in execution order with parameters and units (for -dryRun and the log).
  std::string pipeline() const;
  // Run the time loop from the start time; returns the exit status (0, or 2 after a
  // numerical failure with the last good state written).
  int run();
  // Generate the initial particles from system/particlesDict and write 0/ (shizukuParticles).
  void writeInitialParticles();

  // Post-processing: load a saved time and compute its analysis state.
  void loadTime(const std::string& timeName);
  // Steps 1-4 at the current positions.
  void analyse() { step_->analyse(); }
  // One whole time step of size dt (stages 5-10), then time += dt.
  void step(double dt) { step_->advance(dt); }

  FlowState<D>& state() { return s_; }
  const FlowState<D>& state() const { return s_; }
  const CaseFiles& files() const { return files_; }
  const RunControl& runControl() const { return rc_; }
  const StageTimers& timers() const { return timers_; }
  // Every active effect in step order.
  std::vector<const Effect<D>*> effects() const { return step_->effects().all(); }
  std::vector<std::unique_ptr<FunctionObject<D>>>& functionObjects() { return functionObjects_; }
  // Statistics of the last step, for the progress line and tests.
  const StepReport& lastStep() const { return step_->report(); }
  const Outflow<D>& outflow() const { return *outflow_; }
  // A distributed run's decomposition (nullptr in serial).
  const DomainDecomposition<D>* decomposition() const { return decomposition_.get(); }

 private:
  void distribute(const DecompositionSettings& settings);
  void buildMovingWalls(std::vector<std::shared_ptr<WallMotion<D>>> motions, std::vector<WallBox<D>>& domainWalls);
  CaseFiles files_;
  SimulationOptions opt_;
  RunControl rc_;
  FlowState<D> s_;
  StageTimers timers_;
  std::unique_ptr<DomainDecomposition<D>> decomposition_;  // a distributed run's
  std::unique_ptr<MovingWalls<D>> movingWalls_;            // the case's moving walls (null: none)
  std::unique_ptr<IsphStep<D>> step_;
  std::unique_ptr<HealthGuard<D>> guard_;
  std::unique_ptr<Outflow<D>> outflow_;
  std::vector<std::unique_ptr<FunctionObject<D>>> functionObjects_;
  std::string startTimeName_;
};

}  // namespace shizuku
