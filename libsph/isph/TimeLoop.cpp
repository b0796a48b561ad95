// The time loop of a run: see TimeLoop.hpp.
#include "isph/TimeLoop.hpp"
#include "io/FileOps.hpp"
#include "io/TimeDirectory.hpp"
#include "io/TimeName.hpp"
#include "isph/RunLog.hpp"
#include "isph/StopRequests.hpp"
#include "isph/TimeStepFloor.hpp"
#include "decomposition/DistributedTimeDirectory.hpp"
#include "parallel/Communicator.hpp"
#include <chrono>
#include <cmath>
#include <exception>
#include <filesystem>
#include <iostream>

namespace shizuku {

namespace fs = std::filesystem;

namespace {
double clockSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

template <int D>
TimeLoop<D>::TimeLoop(const CaseFiles& files, const RunControl& rc, FlowState<D>& s, IsphStep<D>& step,
                      HealthGuard<D>& guard, Outflow<D>& outflow, std::vector<std::unique_ptr<FunctionObject<D>>>& functionObjects,
                      StageTimers& timers, const std::string& startTimeName)
    : files_(files), rc_(rc), s_(s), step_(step), guard_(guard), outflow_(outflow), functionObjects_(functionObjects), timers_(timers),
      startTimeName_(startTimeName) {
  functionObjectTimer_ = timers_.stage("functionObjects");
  outputTimer_ = timers_.stage("output");
}

template <int D>
double TimeLoop<D>::chooseDeltaT(double previous, double nextWrite) {
  StepReport& report = step_.report();
  double dt = rc_.deltaT;
  report.dtLimiter = "fixed";
  choice_.clear();
  choice_.add({dt, "fixed"});
  if (rc_.adjustTimeStep) {
    // Every rank takes the same step: the limits over all ranks' particles (the fluid's
    // largest speed is the health check's, over all ranks, of the state the step starts from).
    const auto& world = Communicator::world();
    const double umax = report.maxSpeed;
    TimeStepLimit effects = step_.effects().timeStepLimit(s_);
    effects.dt = world.min(effects.dt);
    // Moving walls: their Courant number as the fluid's, their acceleration as a force's
    // (at the step's start and one previous step later; the same on every rank).
    double wallSpeed = 0, wallAcceleration = 0;
    if (auto* walls = step_.movingWalls())
      for (double t : {s_.time, s_.time + previous}) {
        double u = 0, a = 0;
        walls->extremes(t, u, a);
        wallSpeed = std::max(wallSpeed, u);
        wallAcceleration = std::max(wallAcceleration, a);
      }
    const TimeStepLimit lim[] = {
        {umax > 0 ? rc_.maxCo * s_.h / umax : INFINITY, "CFL"},
        {wallSpeed > 0 ? rc_.maxCo * s_.h / wallSpeed : INFINITY, "wallSpeed"},
        {wallAcceleration > 0 ? 0.25 * std::sqrt(s_.h / wallAcceleration) : INFINITY, "wallAcceleration"},
        effects,
        {rc_.maxDeltaT, "maxDeltaT"},
        {previous > 0 ? 1.2 * previous : rc_.deltaT, "growth"},
    };
    dt = INFINITY;
    choice_.clear();
    for (const auto& l : lim) choice_.add(l);
    for (const auto& l : lim)
      if (l.dt < dt) { dt = l.dt; report.dtLimiter = l.name; }
    if (!std::isfinite(dt)) { dt = rc_.deltaT; report.dtLimiter = "deltaT"; }
    // Land exactly on the next write time in equal steps (docs/method.md 4.3).
    if (rc_.writeControl == RunControl::WriteControl::adjustableRunTime) {
      const double remaining = nextWrite - s_.time;
      if (remaining > rc_.timeTolerance()) {
        // The last two steps before a write are named after it (the time-step floor lets a
        // landing step be short); earlier ones keep the limit they are a rounding of.
        if (remaining < 2 * dt) report.dtLimiter = "write";
        dt = RunControl::evenStepTo(dt, remaining, previous);
      }
    }
  }
  const double toEnd = rc_.endTime - s_.time;
  if (RunControl::landsOn(dt, toEnd)) { dt = toEnd; report.dtLimiter = "endTime"; }
  return dt;
}

// The fluid removed, released and captured on every rank (each counts its own).
static FluidBalance globalBalance(const FluidBalance& mine) {
  const auto& world = Communicator::world();
  FluidBalance b;
  b.removedMass = world.sum(mine.removedMass);
  b.removedCount = world.sum(mine.removedCount);
  b.released = world.sum(mine.released);
  b.captured = world.sum(mine.captured);
  return b;
}

// Fluid particles of every rank (this rank's own, summed).
template <int D>
double TimeLoop<D>::fluidCount() const {
  long n = 0;
  for (std::size_t i = 0; i < s_.numOwned(); ++i) n += s_.particles.isFluid(i);
  return double(Communicator::world().sum(n));
}

template <int D>
void TimeLoop<D>::writeTime(const std::string& reason) {
  StageTimers::Scope t(timers_, outputTimer_);
  TimeState ts;
  ts.time = s_.time;
  ts.step = s_.step;
  ts.deltaT = s_.dt;
  ts.deltaT0 = s_.dt;
  ts.note = reason;
  ts.balance = s_.balance;
  const std::string name = timeName(s_.time);
  const auto& world = Communicator::world();
  if (world.isParallel()) {
    // Each rank writes its own particles as a piece; a failure on any stops all ranks.
    ts.balance = globalBalance(s_.balance);
    writeDistributedTime<D>(files_.dir, name, s_.particles, s_.numOwned(), ts, rc_.ascii);
  } else {
    writeTimeDirectory<D>(files_.dir, name, s_.particles, ts, rc_.ascii);
  }
  written_.push_back(name);
  writtenAtCurrentTime_ = true;
}

template <int D>
void TimeLoop<D>::runFunctionObjects(bool isWriteTime, double wall, double particleSteps) {
  if (functionObjects_.empty()) return;
  StageTimers::Scope t(timers_, functionObjectTimer_);
  RunInfo info;
  info.caseDir = files_.dir;
  info.startTimeName = startTimeName_;
  info.timers = &timers_;
  info.wallSeconds = wall;
  info.particleSteps = particleSteps;
  info.isWriteTime = isWriteTime;
  if (const auto* open = outflow_.openBoundaries()) info.crossings = &open->crossings();
  for (auto& f : functionObjects_) f->execute(s_, info);
}

// The initial state: analysed, handed to the function objects, written on a fresh start, checked.
template <int D>
void TimeLoop<D>::start() {
  const bool freshStart = listTimeDirectories(files_.dir).empty() ||
                          particleFileOf(files_.dir + "/" + startTimeName_).empty();
  info(cat("Starting at time ", s_.time, " (", startTimeName_, "), step ", s_.step, freshStart ? ", from particlesDict" : ""));
  RunInfo startInfo;
  startInfo.caseDir = files_.dir;
  startInfo.startTimeName = startTimeName_;
  startInfo.timers = &timers_;
  if (const auto* open = outflow_.openBoundaries()) startInfo.crossings = &open->crossings();
  // A restart keeps the order it was written in, so that it continues bit for bit.
  if (freshStart && step_.reorders()) step_.reorderParticles();
  step_.analyse();
  // The initial write comes first: if it fails, no function-object file has been opened (truncated).
  if (freshStart) writeTime("initial particles");
  outflow_.start(s_, files_.dir, startTimeName_);
  for (auto& f : functionObjects_) f->start(s_, startInfo);
  step_.report().maxSpeed = guard_.check(s_, "in the initial state", files_.dir);
  runFunctionObjects(freshStart, 0, 0);
}

template <int D>
bool TimeLoop<D>::advanceOneStep(double& previousDt, double& particleSteps, double wallStart, ControlDictWatch& watch) {
  writtenAtCurrentTime_ = false;
  if (step_.reorderDue()) {
    step_.reorderParticles();
    step_.analyse();
  }
  guard_.saveGoodState(s_);
  const double dt = chooseDeltaT(previousDt, rc_.nextWriteTime(s_.time));
  checkTimeStepFloor(s_.time, s_.step, dt, rc_.minDeltaT, step_.report().dtLimiter.c_str(), choice_);
  step_.advance(dt);
  previousDt = dt;
  particleSteps += fluidCount_;
  const bool changed = outflow_.afterStep(s_, guard_.goodPositions(), guard_);
  if (changed) step_.particleCountChanged();
  if (Communicator::world().any(changed)) fluidCount_ = fluidCount();  // a sum over the ranks: all take part
  step_.analyse();
  step_.report().maxSpeed = guard_.check(s_, "after the step", files_.dir);
  const bool scheduled = rc_.isWriteStep(s_.time, s_.step);
  const bool writeNow = scheduled || atEnd();
  // Every rank stops at the same step: a signal or `stopAt writeNow` seen by any rank.
  const bool stopNow = Communicator::world().any(stopDue(watch));
  if (writeNow || stopNow) writeTime(stopNow ? "stop requested" : "write interval");
  // A restart from a scheduled write then rebuilds what the uninterrupted run rebuilds.
  if (scheduled) step_.startAfreshAtNextStep();
  const double wall = clockSeconds() - wallStart;
  runFunctionObjects(writtenAtCurrentTime_, wall, particleSteps);
  // On several ranks, the partition a restart from this time rebuilds, so that the run
  // goes on as a restarted one would (docs/parallel.md 7).
  if (scheduled && !stopNow && !atEnd() && Communicator::world().isParallel()) {
    step_.repartitionAsAtRestart();
    step_.analyse();
  }
  if (s_.step % rc_.progressInterval == 0 || stopNow || atEnd()) {
    ProgressInfo p;
    p.step = s_.step;
    p.time = s_.time;
    p.dt = s_.dt;
    p.densityErrorRms = guard_.densityError().interior.count > 0 ? guard_.densityError().interior.rms : 0.0;
    p.fractionDone = (s_.time - startTime_) / span_;
    p.wallSeconds = clockSeconds() - wallStart;
    const FluidBalance b = globalBalance(s_.balance);  // every rank's (the same step on all: collective)
    p.removed = b.removedCount;
    p.removedFraction = b.removedMass / std::max(b.removedMass + fluidCount_ * s_.particles.mass, 1e-300);
    p.leaks = Communicator::world().sum(long(outflow_.leakCount()));
    p.released = b.released;
    p.captured = b.captured;
    StepReport r = step_.report();  // counts of this rank's own particles, summed over the ranks
    const auto& world = Communicator::world();
    if (world.isParallel()) {
      r.ppeStandardRows = world.sum(r.ppeStandardRows);
      if (r.adsCount >= 0) r.adsCount = world.sum(r.adsCount);
    }
    info(progressLine(p, r));
  }
  return stopNow;
}

// A stop request (a signal, `stopAt writeNow`) is honoured at the end of the first step
// after which the pressure solver keeps nothing from earlier steps (at most amgReuse - 1
// steps later), so that the state written restarts bit for bit; a further signal, or
// the end time, stops at once.
template <int D>
bool TimeLoop<D>::stopDue(ControlDictWatch& watch) {
  if (stopRequest_.empty()) {
    if (watch.writeNowRequested()) stopRequest_ = "stopAt writeNow read from system/controlDict";
    else if (stopRequested()) stopRequest_ = cat("signal ", stopSignal(), " received");
    else return false;
    signalsAtRequest_ = stopSignalCount();
  }
  const bool insisted = stopSignalCount() > signalsAtRequest_;
  if (insisted || atEnd() || step_.nextStepStartsAfresh()) {
    info(cat(stopRequest_, insisted ? cat(", then signal ", stopSignal(), " (stopping at once)") : "",
             ": writing time ", s_.time, " and stopping"));
    return true;
  }
  if (!stopDeferralLogged_)
    info(cat(stopRequest_, " at time ", s_.time, ": going on to the end of the pressure preconditioner's reuse "
             "cycle (at most amgReuse - 1 steps), so that a restart continues exactly; a second signal stops at once"));
  stopDeferralLogged_ = true;
  return false;
}

template <int D>
void TimeLoop<D>::writeLastGoodState(const NumericalError& e) {
  Log::get().error(cat("numerical failure: ", e.what()));
  guard_.restoreGoodState(s_);
  step_.particlesRestored();
  info(cat("Writing the last good state (time ", s_.time, ", step ", s_.step, ")"));
  try {
    step_.analyse();
    writeTime("last good state before a numerical failure");
  } catch (const std::exception& w) {
    Log::get().error(cat("could not write the last good state: ", w.what()));
  }
}

template <int D>
int TimeLoop<D>::run(const std::string& pipeline) {
  installStopSignalHandlers();
  if (Communicator::world().isRoot())
    for (const auto& left : removeStaleTemporaries(files_.dir))
      info("removed the leftover of an interrupted write: " + left);
  const double wallStart = clockSeconds();
  info(pipeline);
  for (const auto& d : Dictionary::defaultsUsed()) info("default: " + d);
  start();
  double previousDt = s_.dt, particleSteps = 0;
  const long firstStep = s_.step;
  startTime_ = s_.time;
  fluidCount_ = fluidCount();
  span_ = std::max(rc_.endTime - s_.time, 1e-300);
  int exitCode = 0;
  ControlDictWatch watch(files_.path("system/controlDict"));
  try {
    bool stopNow = false;
    while (!atEnd() && !stopNow) stopNow = advanceOneStep(previousDt, particleSteps, wallStart, watch);
  } catch (const NumericalError& e) {
    writeLastGoodState(e);
    exitCode = 2;
  } catch (...) {
    // A write error (full disk, unwritable case): close the function-object files,
    // then let the caller report it (exit 1); nothing written before is touched.
    // On several ranks an error of this rank's alone (its file) stops the whole run
    // (solver/shizuku.cpp: the ranks that did not meet it wait elsewhere).
    for (auto& f : functionObjects_) f->end();
    throw;
  }
  for (auto& f : functionObjects_) f->end();
  RunSummary sum;
  sum.steps = s_.step - firstStep;
  sum.simulated = s_.time - startTime_;
  sum.wallSeconds = clockSeconds() - wallStart;
  sum.particleSteps = particleSteps;
  sum.ppeFallbacks = step_.ppeFallbacks();
  sum.caseDir = files_.dir;
  sum.written = written_;
  sum.functionObjects = !functionObjects_.empty();
  for (const auto& line : summaryLines(sum, timers_)) info(line);
  return exitCode;
}

template class TimeLoop<2>;
template class TimeLoop<3>;

}  // namespace shizuku
