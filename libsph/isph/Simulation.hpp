// The ISPH simulation of a case: set-up from the case dictionaries, the step of
// methods.md 13 one stage per function, the time loop with writes, restart,
// function objects, health guards and the log.
//
// Step (positions r^n, velocities u^n; the analysis state of r^n is current):
//   1-4  analyse():      neighbours, <rho>, free surface and normals, operator weights
//   5    predict():      u* = u^n + dt (g + nu <lap u^n>)                       (eq. 4)
//   6    solvePressure(): <lap p> = rho/dt <div u*> [+ alpha (rho - <rho>)/dt^2] (eqs 6, 9)
//   7    correct():      u^{n+1} = u* - dt/rho <grad p>                         (eq. 5)
//   8    advect():       r' = r^n + dt (u^{n+1} + du_XSPH)                      (eq. 7)
//   9    stabilise():    ADS on free-surface and vicinity particles
//   10   shiftParticles(): OPS + volume + surface-fit shift, capped; Taylor-corrected u
// Reads: every case dictionary (design.md 1.2); the keys are listed in each stage's file.
#pragma once
#include "core/RunControl.hpp"
#include "core/StageTimers.hpp"
#include "effects/Effect.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "io/TimeDirectory.hpp"
#include "isph/CaseFiles.hpp"
#include "pressure/PressureEquation.hpp"
#include "surface/FreeSurface.hpp"
#include <memory>
#include <string>
#include <vector>

namespace shizuku {

struct SimulationOptions {
  bool functionObjects = true;
  bool postProcessing = false;   // set up for analysing saved times only (no run)
  int threads = 0;               // 0 = OpenMP default
};

struct HealthLimits {
  double maxDensityErrorRms = 20;     // % over interior particles
  Eigen::VectorXd domainMin, domainMax;  // fluid particles must stay inside
  double domainMargin = 0.5;          // times the initial extent, on each side
  double maxSpeed = 0;                // m/s; 0: automatic, 10 max(|U|_start, sqrt(2 |g| L))
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
  void analyse();
  FlowState<D>& state() { return s_; }
  const FlowState<D>& state() const { return s_; }
  const CaseFiles& files() const { return files_; }
  const RunControl& runControl() const { return rc_; }
  const StageTimers& timers() const { return timers_; }
  const std::vector<std::unique_ptr<Effect<D>>>& effects() const { return effects_; }
  std::vector<std::unique_ptr<FunctionObject<D>>>& functionObjects() { return functionObjects_; }
  // One whole time step of size dt (stages 5-10), then time += dt.
  void step(double dt);
  // Statistics of the last step, for the progress line and tests.
  struct StepReport {
    LinearSolveResult ppe;
    long ppeUnknowns = 0;
    long ppeStandardRows = 0;   // Laplacian rows that fell back to the standard weights
    double maxSpeed = 0;
    long adsCount = -1;
    std::string dtLimiter = "fixed";
  };
  const StepReport& lastStep() const { return report_; }

 private:
  void readSchemes();
  void buildEffects();
  void setupInitialState();
  void predict();
  void solvePressure();
  void correct();
  void advect();
  void stabilise();
  void shiftParticles();
  void reorderParticles();
  double chooseDeltaT(double previous, double nextWrite);
  void checkHealth(const char* where);
  std::string writeOffendingParticles();
  void writeTime(const std::string& reason);
  void saveGoodState();
  void restoreGoodState();
  void runFunctionObjects(bool isWriteTime, double wall, double particleSteps);

  CaseFiles files_;
  SimulationOptions opt_;
  RunControl rc_;
  FlowState<D> s_;
  std::unique_ptr<DerivativeOperator<D>> operator_;
  std::unique_ptr<NeighbourSearch<D>> search_;
  std::unique_ptr<FreeSurfaceDetector<D>> freeSurface_;
  std::unique_ptr<PressureEquation<D>> ppe_;
  std::vector<std::unique_ptr<Effect<D>>> effects_;
  std::vector<int> effectTimer_;   // per effect: its own timer, or -1 (timed with its stage)
  std::vector<std::unique_ptr<FunctionObject<D>>> functionObjects_;
  EffectNeeds needs_;
  double maxShift_ = 0.1;   // times h
  // Which shifted particles get u += <grad u> dr (shifting/taylorCorrection): on free-surface
  // and splash particles the one-sided gradient is unreliable and the product pumps energy.
  enum class TaylorCorrection { off, interior, belowSurface, everywhere };
  TaylorCorrection taylorCorrection_ = TaylorCorrection::belowSurface;
  bool taylorCorrected(SurfaceClass c) const {
    switch (taylorCorrection_) {
      case TaylorCorrection::off: return false;
      case TaylorCorrection::interior: return c == SurfaceClass::interior;
      case TaylorCorrection::belowSurface: return c == SurfaceClass::interior || c == SurfaceClass::vicinity;
      case TaylorCorrection::everywhere: return true;
    }
    return false;
  }
  std::string taylorCorrectionDescription() const {
    switch (taylorCorrection_) {
      case TaylorCorrection::off: return "";
      case TaylorCorrection::interior: return ", Taylor-corrected velocity on interior particles";
      case TaylorCorrection::belowSurface: return ", Taylor-corrected velocity on interior and vicinity particles";
      case TaylorCorrection::everywhere: return ", Taylor-corrected velocity on every fluid particle";
    }
    return "";
  }
  int reorderInterval_ = 20;
  HealthLimits health_;
  StageTimers timers_;
  struct StageIds { int neighbours, density, freeSurface, surfaceFit, weights, predictor, ppeAssembly, ppeSolve,
                    corrector, advection, ads, shifting, functionObjects, output; } st_{};
  StepReport report_;
  long ppeFallbacks_ = 0;
  std::vector<Index> offending_;   // particles of the last failed health check
  std::string startTimeName_;
  std::vector<std::string> written_;
  // Scratch (sized once).
  std::vector<double> source_;
  std::vector<std::uint8_t> weightRows_;
  std::vector<Vec<D>> du_, dr_;
  std::vector<Mat<D>> gradU_;
  // Last good state (start of the current step).
  std::vector<Vec<D>> goodX_, goodU_;
  std::vector<double> goodP_;
  std::vector<std::int64_t> goodId_;
  double goodTime_ = 0, goodDt_ = 0;
  long goodStep_ = 0;
  bool writtenAtCurrentTime_ = false;
};

// Run-wide signal flag (SIGINT/SIGTERM write the current state and stop).
void installStopSignalHandlers();
bool stopRequested();

}  // namespace shizuku
