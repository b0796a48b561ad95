// The time loop of a simulation: time-step choice (methods.md 4.3), writes that
// land on the write interval, restart, stopAt writeNow, signals, health guards,
// function objects, progress lines and the final summary (design.md 1.3).
#include "core/Log.hpp"
#include "io/TimeName.hpp"
#include "io/VtpFile.hpp"
#include "isph/Simulation.hpp"
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <ctime>
#include <filesystem>
#include <iomanip>
#include <omp.h>

namespace shizuku {

namespace fs = std::filesystem;

namespace {
std::atomic<int> stopSignal{0};
extern "C" void onStopSignal(int sig) { stopSignal = sig; }

double clockSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
std::string formatSeconds(double s) {
  if (!std::isfinite(s) || s < 0) return "?";
  std::ostringstream os;
  if (s < 120) os << std::fixed << std::setprecision(1) << s << " s";
  else if (s < 7200) os << std::fixed << std::setprecision(1) << s / 60 << " min";
  else os << std::fixed << std::setprecision(2) << s / 3600 << " h";
  return os.str();
}
}  // namespace

void installStopSignalHandlers() {
  std::signal(SIGINT, onStopSignal);
  std::signal(SIGTERM, onStopSignal);
  std::signal(SIGXFSZ, SIG_IGN);  // a file-size limit becomes a write error (EFBIG), not a kill
}
bool stopRequested() { return stopSignal != 0; }

template <int D>
void Simulation<D>::loadTime(const std::string& name) {
  TimeState ts;
  ParticleSet<D> p = readTimeDirectory<D>(files_.dir, name, ts);
  s_.particles = std::move(p);
  s_.time = ts.time;
  s_.step = ts.step;
  s_.dt = ts.deltaT;
  const std::size_t n = s_.particles.size();
  s_.isFluidMask.resize(n);
  for (std::size_t i = 0; i < n; ++i) s_.isFluidMask[i] = s_.particles.isFluid(i);
  s_.particles.surface.resize(n);
  s_.particles.density.resize(n);
  analyse();
}

template <int D>
double Simulation<D>::chooseDeltaT(double previous, double nextWrite) {
  double dt = rc_.deltaT;
  report_.dtLimiter = "fixed";
  if (rc_.adjustTimeStep) {
    double umax = 0;
    for (std::size_t i = 0; i < s_.size(); ++i)
      if (s_.isFluid(i)) umax = std::max(umax, s_.particles.velocity[i].norm());
    struct Limit { double dt; const char* name; };
    Limit lim[] = {
        {umax > 0 ? rc_.maxCo * s_.h / umax : INFINITY, "CFL"},
        {s_.nu > 0 ? 0.125 * s_.h * s_.h / s_.nu : INFINITY, "viscous"},
        {s_.gravity && s_.g.norm() > 0 ? 0.25 * std::sqrt(s_.h / s_.g.norm()) : INFINITY, "force"},
        {rc_.maxDeltaT, "maxDeltaT"},
        {previous > 0 ? 1.2 * previous : rc_.deltaT, "growth"},
    };
    dt = INFINITY;
    for (const auto& l : lim)
      if (l.dt < dt) { dt = l.dt; report_.dtLimiter = l.name; }
    if (!std::isfinite(dt)) { dt = rc_.deltaT; report_.dtLimiter = "deltaT"; }
    // Land exactly on the next write time.
    if (rc_.writeControl == RunControl::WriteControl::adjustableRunTime) {
      const double remaining = nextWrite - s_.time;
      if (remaining > rc_.timeTolerance() && RunControl::landsOn(dt, remaining)) { dt = remaining; report_.dtLimiter = "write"; }
      else if (remaining > dt && remaining < 2 * dt) { dt = 0.5 * remaining; report_.dtLimiter = "write"; }
    }
  }
  const double toEnd = rc_.endTime - s_.time;
  if (RunControl::landsOn(dt, toEnd)) { dt = toEnd; report_.dtLimiter = "endTime"; }
  return dt;
}

template <int D>
void Simulation<D>::checkHealth(const char* where) {
  const auto& P = s_.particles;
  const long n = long(s_.size());
  // Offending particles: every non-finite one, every one outside the domain box,
  // and (for the density guard) the interior particle with the largest error.
  offending_.clear();
  const char* failure = nullptr;
  double maxU = 0, sumE2 = 0, worstE = 0;
  long nInterior = 0, worst = -1, fastest = -1;
  for (long i = 0; i < n; ++i) {
    if (!s_.isFluid(i)) continue;
    const bool finite = P.position[i].allFinite() && P.velocity[i].allFinite() && std::isfinite(P.pressure[i]);
    bool outside = false;
    for (int a = 0; a < D && finite; ++a)
      outside |= P.position[i][a] < health_.domainMin[a] || P.position[i][a] > health_.domainMax[a];
    if (!finite || outside) {
      if (!failure || (!finite && std::string(failure) != "non-finite"))
        failure = finite ? "outside" : "non-finite";
      offending_.push_back(Index(i));
      continue;
    }
    const double speed = P.velocity[i].norm();
    if (speed > maxU) { maxU = speed; fastest = i; }
    if (P.surfaceClass(i) == SurfaceClass::interior) {
      const double e = (s_.rho0 - P.density[i]) / s_.rho0 * 100;
      sumE2 += e * e;
      ++nInterior;
      if (std::abs(e) > worstE) { worstE = std::abs(e); worst = i; }
    }
  }
  report_.maxSpeed = maxU;
  const double rms = nInterior ? std::sqrt(sumE2 / nInterior) : 0;
  if (!failure && maxU > health_.maxSpeed) {
    failure = "speed";
    offending_.push_back(Index(fastest));
  } else if (!failure && rms > health_.maxDensityErrorRms) {
    failure = "density";
    offending_.push_back(Index(worst));
  }
  if (!failure) return;
  std::string ids;
  for (std::size_t k = 0; k < offending_.size() && k < 10; ++k) ids += cat(k ? " " : "", P.id[offending_[k]]);
  if (offending_.size() > 10) ids += cat(" and ", offending_.size() - 10, " more");
  const std::string at = cat(" at step ", s_.step, ", time ", s_.time);
  const std::string file = writeOffendingParticles();
  const std::string see = cat("; ", offending_.size(), " offending particle(s): id ", ids,
                              file.empty() ? "" : cat(", written to ", file));
  const std::string f = failure;
  const long first = P.id[offending_[0]];
  if (f == "non-finite")
    throw NumericalError(cat("non-finite position, velocity or pressure ", where, ": particle id ", first, at, see));
  if (f == "outside")
    throw NumericalError(cat("particle id ", first, " left the domain ", where, at, " (position ",
                             P.position[offending_[0]].transpose(), "; limits set by healthChecks/domainMargin)", see));
  if (f == "speed")
    throw NumericalError(cat("particle id ", first, " moves at ", maxU, " m/s ", where, at, " (position ",
                             P.position[offending_[0]].transpose(), ", ", surfaceClassName(P.surfaceClass(offending_[0])),
                             "), above healthChecks/maxSpeed ", health_.maxSpeed, " m/s", see));
  throw NumericalError(cat("interior density error rms ", rms, " % exceeds healthChecks/maxDensityErrorRms ",
                           health_.maxDensityErrorRms, " %", at, "; worst particle id ", first, " (", worstE, " %)",
                           see));
}

// The offending particles of a failed health check, for ParaView:
// postProcessing/healthChecks/<time>/offending.vtp. Returns the path ("" if it could not be written).
template <int D>
std::string Simulation<D>::writeOffendingParticles() {
  try {
    const auto& P = s_.particles;
    ParticleSet<D> sub;
    sub.mass = P.mass;
    sub.rho0 = P.rho0;
    sub.spacing = P.spacing;
    auto pick = [&](auto& dst, const auto& src) {
      if (src.empty()) return;
      dst.clear();
      for (Index i : offending_) dst.push_back(src[i]);
    };
    pick(sub.position, P.position);
    P.forEachField([&](const char* name, const auto& v) {
      sub.forEachField([&](const char* n2, auto& w) {
        if (std::string(name) == n2) {
          if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::decay_t<decltype(w)>>) pick(w, v);
        }
      });
    });
    TimeState ts;
    ts.time = s_.time;
    ts.step = s_.step;
    ts.deltaT = s_.dt;
    ts.note = "offending particles of a failed health check";
    const std::string dir = files_.dir + "/postProcessing/healthChecks/" + timeName(s_.time);
    fs::create_directories(dir);
    writeVtp<D>(dir + "/offending.vtp", sub, ts);
    return dir + "/offending.vtp";
  } catch (const std::exception& e) {
    Log::get().warning(cat("could not write the offending particles: ", e.what()));
    return "";
  }
}

template <int D>
void Simulation<D>::saveGoodState() {
  const auto& P = s_.particles;
  goodX_ = P.position;  // same size every step: no reallocation after the first
  goodU_ = P.velocity;
  goodP_ = P.pressure;
  goodId_ = P.id;
  goodTime_ = s_.time;
  goodStep_ = s_.step;
  goodDt_ = s_.dt;
}

template <int D>
void Simulation<D>::restoreGoodState() {
  auto& P = s_.particles;
  P.position = goodX_;
  P.velocity = goodU_;
  P.pressure = goodP_;
  P.id = goodId_;
  s_.time = goodTime_;
  s_.step = goodStep_;
  s_.dt = goodDt_;
}

template <int D>
void Simulation<D>::writeTime(const std::string& reason) {
  StageTimers::Scope t(timers_, st_.output);
  TimeState ts;
  ts.time = s_.time;
  ts.step = s_.step;
  ts.deltaT = s_.dt;
  ts.deltaT0 = s_.dt;
  ts.note = reason;
  const std::string name = timeName(s_.time);
  writeTimeDirectory<D>(files_.dir, name, s_.particles, ts, rc_.ascii);
  written_.push_back(name);
  writtenAtCurrentTime_ = true;
}

template <int D>
void Simulation<D>::runFunctionObjects(bool isWriteTime, double wall, double particleSteps) {
  if (functionObjects_.empty()) return;
  StageTimers::Scope t(timers_, st_.functionObjects);
  RunInfo info;
  info.caseDir = files_.dir;
  info.startTimeName = startTimeName_;
  info.timers = &timers_;
  info.wallSeconds = wall;
  info.particleSteps = particleSteps;
  info.isWriteTime = isWriteTime;
  for (auto& f : functionObjects_) f->execute(s_, info);
}

template <int D>
void Simulation<D>::reorderParticles() {
  auto& P = s_.particles;
  const std::vector<Index> perm = search_->cellOrder(P.position);
  auto apply = [&](auto& v) {
    if (v.empty()) return;
    // One scratch copy per field type, kept between reorderings (no allocation once
    // it has the capacity; reordering runs on one thread).
    static std::remove_reference_t<decltype(v)> copy;
    copy = v;
    for (std::size_t k = 0; k < perm.size(); ++k) v[k] = copy[perm[k]];
  };
  apply(P.position);
  P.forEachField([&](const char*, auto& v) { apply(v); });
  for (std::size_t i = 0; i < P.size(); ++i) s_.isFluidMask[i] = P.isFluid(i);
}

template <int D>
int Simulation<D>::run() {
  installStopSignalHandlers();
  for (const auto& left : removeStaleTemporaries(files_.dir))
    info("removed the leftover of an interrupted write: " + left);
  const double wallStart = clockSeconds();
  const std::size_t nFluid = s_.particles.countFluid();
  const bool freshStart = listTimeDirectories(files_.dir).empty() ||
                          !fs::exists(files_.dir + "/" + startTimeName_ + "/particles.vtp");
  info(pipeline());
  for (const auto& d : Dictionary::defaultsUsed()) info("default: " + d);
  info(cat("Starting at time ", s_.time, " (", startTimeName_, "), step ", s_.step, freshStart ? ", from particlesDict" : ""));

  RunInfo startInfo;
  startInfo.caseDir = files_.dir;
  startInfo.startTimeName = startTimeName_;
  startInfo.timers = &timers_;
  analyse();
  for (auto& f : functionObjects_) f->start(s_, startInfo);
  if (freshStart) writeTime("initial particles");
  checkHealth("in the initial state");
  runFunctionObjects(freshStart, 0, 0);

  double previousDt = s_.dt;
  const long firstStep = s_.step;
  double particleSteps = 0;
  int exitCode = 0;
  bool stopNow = false;
  const fs::path controlPath = files_.path("system/controlDict");  // built once: no allocation per step
  fs::file_time_type controlTime = fs::last_write_time(controlPath);
  const double span = std::max(rc_.endTime - s_.time, 1e-300);
  const double startTime = s_.time;
  try {
    while (s_.time < rc_.endTime - rc_.timeTolerance() && !stopNow) {
      writtenAtCurrentTime_ = false;
      if (reorderInterval_ > 0 && s_.step > 0 && s_.step % reorderInterval_ == 0) {
        reorderParticles();
        analyse();
      }
      saveGoodState();
      const double dt = chooseDeltaT(previousDt, rc_.nextWriteTime(s_.time));
      step(dt);
      previousDt = dt;
      particleSteps += double(nFluid);
      analyse();
      checkHealth("after the step");
      const bool writeNow = rc_.isWriteStep(s_.time, s_.step) || s_.time >= rc_.endTime - rc_.timeTolerance();
      // stopAt writeNow edited into the running case, or a signal.
      if (fs::last_write_time(controlPath) != controlTime) {
        controlTime = fs::last_write_time(controlPath);
        try {
          const Dictionary d = Dictionary::fromFile(files_.path("system/controlDict"));
          if (d.getWordOr("stopAt", "endTime") == "writeNow") {
            stopNow = true;
            info(cat("stopAt writeNow read from system/controlDict: writing time ", s_.time, " and stopping"));
          }
        } catch (const InputError& e) {
          Log::get().warning(cat("system/controlDict changed but could not be read (ignored): ", e.what()));
        }
      }
      if (stopRequested()) {
        stopNow = true;
        info(cat("signal ", int(stopSignal), " received: writing time ", s_.time, " and stopping"));
      }
      if (writeNow || stopNow) writeTime(stopNow ? "stop requested" : "write interval");
      runFunctionObjects(writtenAtCurrentTime_, clockSeconds() - wallStart, particleSteps);
      if (s_.step % rc_.progressInterval == 0 || stopNow || s_.time >= rc_.endTime - rc_.timeTolerance()) {
        const double wall = clockSeconds() - wallStart;
        const double frac = (s_.time - startTime) / span;
        double sumE2 = 0;
        long nIn = 0;
        for (std::size_t i = 0; i < s_.size(); ++i)
          if (s_.isFluid(i) && s_.particles.surfaceClass(i) == SurfaceClass::interior) {
            const double e = (s_.rho0 - s_.particles.density[i]) / s_.rho0 * 100;
            sumE2 += e * e;
            ++nIn;
          }
        info(cat("step ", s_.step, "  t = ", s_.time, "  dt = ", s_.dt, " (", report_.dtLimiter, ")  PPE ",
                 report_.ppe.iterations, " it, res ", std::setprecision(2), report_.ppe.residual, std::setprecision(6),
                 report_.ppeStandardRows ? cat(" (", report_.ppeStandardRows, " std rows)") : "",
                 "  max|U| = ", report_.maxSpeed, "  rhoErr rms = ", std::setprecision(3),
                 nIn ? std::sqrt(sumE2 / nIn) : 0.0, std::setprecision(6), " %",
                 report_.adsCount >= 0 ? cat("  ADS ", report_.adsCount) : "", "  ", std::fixed,
                 std::setprecision(1), 100 * frac, std::defaultfloat, std::setprecision(6), "% done, ETA ",
                 formatSeconds(frac > 0 ? wall * (1 - frac) / frac : NAN)));
      }
    }
  } catch (const NumericalError& e) {
    Log::get().error(cat("numerical failure: ", e.what()));
    restoreGoodState();
    info(cat("Writing the last good state (time ", s_.time, ", step ", s_.step, ")"));
    try {
      analyse();
      writeTime("last good state before a numerical failure");
    } catch (const std::exception& w) {
      Log::get().error(cat("could not write the last good state: ", w.what()));
    }
    exitCode = 2;
  } catch (...) {
    // A write error (full disk, unwritable case): close the function-object files,
    // then let the caller report it (exit 1); nothing written before is touched.
    for (auto& f : functionObjects_) f->end();
    throw;
  }
  for (auto& f : functionObjects_) f->end();

  // Summary.
  const double wall = clockSeconds() - wallStart;
  const long steps = s_.step - firstStep;
  info(cat("\nEnd: ", steps, " steps, simulated ", s_.time - startTime, " s in ", formatSeconds(wall), ", ",
           std::setprecision(3), steps > 0 ? particleSteps / wall : 0.0, " particle-steps/s (",
           particleSteps > 0 ? wall / particleSteps * 1e6 : 0.0, " us per particle-step), ",
           omp_get_max_threads(), " threads"));
  const double tsum = timers_.sumTotal();
  for (std::size_t k = 0; k < timers_.names().size(); ++k)
    info(cat("  ", std::left, std::setw(26), timers_.names()[k], std::right, std::setw(10), std::fixed,
             std::setprecision(3), timers_.total()[k], " s  ", std::setw(5), std::setprecision(1),
             tsum > 0 ? 100 * timers_.total()[k] / tsum : 0.0, " %", std::defaultfloat));
  if (ppeFallbacks_ > 0) info(cat("PPE: the iterative solver fell back to a direct LU in ", ppeFallbacks_, " steps"));
  info("Files written:");
  for (const auto& w : written_) info("  " + files_.dir + "/" + w + "/particles.vtp");
  if (!written_.empty()) info("  " + files_.dir + "/particles.pvd");
  if (!functionObjects_.empty()) info("  " + files_.dir + "/postProcessing/ (function objects)");
  return exitCode;
}

template class Simulation<2>;
template class Simulation<3>;

}  // namespace shizuku
