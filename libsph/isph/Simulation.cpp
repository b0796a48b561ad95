// Set-up of a simulation from its case and the stages of the ISPH step (methods.md 13).
#include "isph/Simulation.hpp"
#include "boundaries/WallParticles.hpp"
#include "core/Log.hpp"
#include "effects/ShiftCap.hpp"
#include "io/TimeName.hpp"
#include "particles/ParticleGenerator.hpp"
#include "surface/SurfaceFit.hpp"
#include <cmath>
#include <filesystem>
#include <omp.h>

namespace shizuku {

namespace fs = std::filesystem;

template <int D>
Simulation<D>::Simulation(const std::string& caseDir, const SimulationOptions& opt)
    : files_(CaseFiles::read(caseDir)), opt_(opt) {
  if (opt_.threads > 0) omp_set_num_threads(opt_.threads);
  rc_ = RunControl::read(files_.controlDict);
  readSchemes();
  setupInitialState();
  buildEffects();
  // Stages in execution order (the timing columns follow it); optional stages
  // exist only when an active effect runs them.
  auto hasStage = [&](EffectStage st) {
    for (auto& e : effects_) if (e->stage() == st) return true;
    return false;
  };
  st_.neighbours = timers_.stage("neighbours");
  st_.weights = timers_.stage("weights");
  st_.density = timers_.stage("density");
  st_.freeSurface = timers_.stage("freeSurface");
  st_.surfaceFit = needs_.surfaceFit ? timers_.stage("surfaceFit") : -1;
  st_.predictor = timers_.stage("predictor");
  st_.ppeAssembly = timers_.stage("ppeAssembly");
  st_.ppeSolve = timers_.stage("ppeSolve");
  st_.corrector = timers_.stage("corrector");
  st_.advection = timers_.stage("advection");
  // XSPH and each shifting term have a timer of their own (named after the effect).
  effectTimer_.assign(effects_.size(), -1);
  for (std::size_t k = 0; k < effects_.size(); ++k)
    if (effects_[k]->stage() == EffectStage::advection) effectTimer_[k] = timers_.stage(effects_[k]->name());
  st_.ads = hasStage(EffectStage::postAdvection) ? timers_.stage("ads") : -1;
  st_.shifting = hasStage(EffectStage::shift) ? timers_.stage("shifting") : -1;
  for (std::size_t k = 0; k < effects_.size(); ++k)
    if (effects_[k]->stage() == EffectStage::shift) effectTimer_[k] = timers_.stage(effects_[k]->name());
  st_.functionObjects = timers_.stage("functionObjects");
  st_.output = timers_.stage("output");
  if (opt_.functionObjects && !opt_.postProcessing)
    functionObjects_ = createFunctionObjects<D>(files_.controlDict.subDictPtr("functions"));
  else if (const Dictionary* f = files_.controlDict.subDictPtr("functions"))
    f->markAllRead();
  files_.checkAllRead();
}

template <int D>
Simulation<D>::~Simulation() = default;

// --- set-up ------------------------------------------------------------------

template <int D>
void Simulation<D>::readSchemes() {
  const Dictionary& sch = files_.sphSchemes;
  const Dictionary& props = files_.physicalProperties;
  s_.rho0 = props.getScalar("rho", dim::density);
  if (!(s_.rho0 > 0)) props.error("rho", "must be > 0");
  s_.nu = props.getScalarOr("nu", 0.0, dim::kinematicViscosity);
  if (s_.nu < 0) props.error("nu", "must be >= 0");
  if (files_.gravity) {
    s_.g = files_.gravity->getVector<D>("value", dim::acceleration);
    s_.gravity = true;
  }
  // kernel { type cubicSpline|WendlandC2; smoothingLengthRatio 1.2; }
  KernelType ktype = KernelType::cubicSpline;
  double ratio = 1.2;
  if (const Dictionary* k = sch.subDictPtr("kernel")) {
    ktype = Kernel<D>::kernelTypeFromName(k->getOptionOr("type", {"cubicSpline", "WendlandC2"}, "cubicSpline"));
    ratio = k->getScalarOr("smoothingLengthRatio", 1.2, dim::none);
    if (!(ratio > 0.5 && ratio < 3)) k->error("smoothingLengthRatio", "must be between 0.5 and 3");
  }
  // The spacing comes from particlesDict (the generator checks it); h = ratio * d0.
  s_.d0 = files_.particlesDict.getScalar("spacing", dim::length);
  if (!(s_.d0 > 0)) files_.particlesDict.error("spacing", "must be > 0");
  files_.particlesDict.markRead("dimension");
  s_.h = ratio * s_.d0;
  s_.kernel = Kernel<D>(ktype, s_.h);
  operator_ = DerivativeOperator<D>::create(
      derivativeSchemeFromName(sch.getOptionOr("derivatives", {"SPH2", "corrected", "standard"}, "SPH2")));
  freeSurface_ = std::make_unique<FreeSurfaceDetector<D>>(
      FreeSurfaceParameters::read(sch.subDictPtr("freeSurface"), D));
  reorderInterval_ = sch.getIntOr("reorderInterval", 20);
  if (reorderInterval_ < 0) sch.error("reorderInterval", "must be >= 0 (0: never)");
  ppe_ = std::make_unique<PressureEquation<D>>(LinearSolver::create(files_.sphSolution.subDictPtr("pressure")));
  if (const Dictionary* hc = files_.controlDict.subDictPtr("healthChecks")) {
    health_.maxDensityErrorRms = hc->getScalarOr("maxDensityErrorRms", 20.0, dim::none);
    health_.domainMargin = hc->getScalarOr("domainMargin", 0.5, dim::none);
    health_.maxSpeed = hc->getScalarOr("maxSpeed", 0.0, dim::velocity);
    if (!(health_.maxSpeed >= 0)) hc->error("maxSpeed", "must be >= 0 (m/s; 0 chooses it from the case)");
    if (!(health_.domainMargin >= 0)) hc->error("domainMargin", "must be >= 0 (times the initial extent)");
    if (!(health_.maxDensityErrorRms > 0)) hc->error("maxDensityErrorRms", "must be > 0 (%)");
  }
}

template <int D>
void Simulation<D>::buildEffects() {
  registerBuiltinEffects<D>();
  auto& reg = EffectRegistry<D>::instance();
  const Dictionary& sch = files_.sphSchemes;
  auto add = [&](const std::string& name, const Dictionary& d) { effects_.push_back(reg.create(name, d, s_)); };
  if (files_.gravity) add("gravity", *files_.gravity);
  if (s_.nu > 0) add("viscosity", files_.physicalProperties);
  else files_.physicalProperties.markRead("wallCondition");
  if (const Dictionary* d = sch.subDictPtr("pressureStabilization")) add("pressureStabilization", *d);
  if (const Dictionary* d = sch.subDictPtr("xsph")) add("xsph", *d);
  if (const Dictionary* d = sch.subDictPtr("ads")) add("ads", *d);
  if (const Dictionary* sh = sch.subDictPtr("shifting")) {
    for (const char* term : {"distribution", "volumeCorrection", "surfaceFitting"})
      if (const Dictionary* d = sh->subDictPtr(term)) add(std::string("shifting/") + term, *d);
    maxShift_ = sh->getScalarOr("maxShift", 0.1, dim::none);
    if (!(maxShift_ > 0)) sh->error("maxShift", "must be > 0 (times h)");
    {
      const std::string t = sh->getOptionOr("taylorCorrection",
          {"on", "yes", "true", "off", "no", "false", "everywhere", "belowSurface", "interior"}, "on");
      if (t == "off" || t == "no" || t == "false") taylorCorrection_ = TaylorCorrection::off;
      else if (t == "everywhere") taylorCorrection_ = TaylorCorrection::everywhere;
      else if (t == "interior") taylorCorrection_ = TaylorCorrection::interior;
      else taylorCorrection_ = TaylorCorrection::belowSurface;  // on: where the gradient is two-sided
    }
  }
  // Order effects by the stage they act in (stable: keeps dictionary order inside a stage).
  std::stable_sort(effects_.begin(), effects_.end(),
                   [](const auto& a, const auto& b) { return int(a->stage()) < int(b->stage()); });
  for (auto& e : effects_) {
    const EffectNeeds n = e->needs();
    needs_.normals |= n.normals;
    needs_.surfaceFit |= n.surfaceFit;
    needs_.velocityGradient |= n.velocityGradient;
    e->allocate(s_);
  }
  bool anyShift = false;
  for (auto& e : effects_) anyShift |= e->stage() == EffectStage::shift;
  if (anyShift) {
    s_.particles.shift.assign(s_.size(), Vec<D>::Zero());
    dr_.resize(s_.size());
    if (taylorCorrection_ != TaylorCorrection::off) { needs_.velocityGradient = true; gradU_.resize(s_.size()); }
  }
  if (needs_.surfaceFit) {
    s_.fitDistance.assign(s_.size(), NAN);
    s_.fitNormal.assign(s_.size(), Vec<D>::Zero());
    s_.curvature.assign(s_.size(), NAN);
  }
  bool anyAdvection = false;
  for (auto& e : effects_) anyAdvection |= e->stage() == EffectStage::advection;
  if (anyAdvection) du_.resize(s_.size());
}

template <int D>
void Simulation<D>::setupInitialState() {
  // The generator always reads particlesDict (it checks it and gives the periodic box);
  // its particles are used when the start time has none.
  GeneratedParticles<D> gen = generateParticles<D>(files_.particlesDict);
  s_.periodic = gen.periodic;
  const auto times = listTimeDirectories(files_.dir);
  std::string startName;
  if (!opt_.postProcessing) {
    if (rc_.startFrom == RunControl::StartFrom::latestTime && !times.empty()) startName = times.back().second;
    else
      for (const auto& t : times)
        if (std::abs(t.first - rc_.startTime) <= 1e-12 * std::max(1.0, std::abs(rc_.startTime))) startName = t.second;
  }
  if (!startName.empty()) {
    TimeState ts;
    s_.particles = readTimeDirectory<D>(files_.dir, startName, ts);
    s_.time = ts.time;
    s_.step = ts.step;
    s_.dt = ts.deltaT;
    startTimeName_ = startName;
  } else {
    s_.particles = std::move(gen.set);
    s_.particles.rho0 = s_.rho0;
    s_.particles.spacing = s_.d0;
    // Mass calibrated on the initial lattice so that <rho> = rho there (methods.md 2 (b)).
    s_.particles.mass = s_.rho0 / s_.kernel.latticeSum(s_.d0);
    s_.time = rc_.startTime;
    s_.step = 0;
    s_.dt = 0;
    startTimeName_ = timeName(s_.time);
  }
  if (std::abs(s_.particles.spacing - s_.d0) > 1e-12 * s_.d0)
    files_.particlesDict.error("spacing", cat("differs from the spacing of the saved particles (",
                                             s_.particles.spacing, " m)"));
  auto& P = s_.particles;
  const std::size_t n = P.size();
  P.density.resize(n);
  P.surface.resize(n);
  P.pressure.resize(n);
  s_.isFluidMask.resize(n);
  for (std::size_t i = 0; i < n; ++i) s_.isFluidMask[i] = P.isFluid(i);
  if (P.countFluid() == 0) files_.particlesDict.error("regions", "the case has no fluid particles");
  search_ = std::make_unique<NeighbourSearch<D>>(s_.kernel.support(), s_.periodic);
  s_.uStar.resize(n);
  s_.acceleration.resize(n);
  source_.resize(n);
  // Domain guard box: the initial extent of all particles, widened by domainMargin.
  Vec<D> lo = P.position[0], hi = P.position[0];
  for (const auto& x : P.position) { lo = lo.cwiseMin(x); hi = hi.cwiseMax(x); }
  const Vec<D> ext = (hi - lo).cwiseMax(Vec<D>::Constant(s_.d0));
  health_.domainMin = lo - health_.domainMargin * ext;
  health_.domainMax = hi + health_.domainMargin * ext;
  // Speed guard: no flow of this case can exceed ten times the larger of its starting
  // speed and the free-fall speed over the largest extent of the domain.
  if (health_.maxSpeed == 0) {
    double u0 = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (P.isFluid(i)) u0 = std::max(u0, P.velocity[i].norm());
    const double fall = s_.gravity ? std::sqrt(2 * s_.g.norm() * ext.maxCoeff()) : 0.0;
    health_.maxSpeed = std::max(u0, fall) > 0 ? 10 * std::max(u0, fall) : INFINITY;
  }
}

template <int D>
void Simulation<D>::writeInitialParticles() {
  TimeState ts;
  ts.time = s_.time;
  ts.step = s_.step;
  ts.deltaT = rc_.deltaT;
  ts.deltaT0 = rc_.deltaT;
  analyse();
  writeTimeDirectory<D>(files_.dir, timeName(s_.time), s_.particles, ts, rc_.ascii);
}

template <int D>
std::string Simulation<D>::pipeline() const {
  std::ostringstream os;
  os << "Pipeline (" << D << "D, " << s_.particles.countFluid() << " fluid + "
     << s_.size() - s_.particles.countFluid() << " wall particles, d0 = " << s_.d0 << " m, h = " << s_.h
     << " m, rho = " << s_.rho0 << " kg/m^3)\n";
  int k = 1;
  auto line = [&](const std::string& what) { os << "  " << k++ << ". " << what << "\n"; };
  line(cat("neighbours: cell-linked list, radius 2h = ", s_.kernel.support(), " m",
           s_.periodic.any() ? ", periodic" : "", reorderInterval_ > 0 ? cat(", reorder every ", reorderInterval_, " steps") : ""));
  line(cat("density: summation <rho> (eq. 18), ", s_.kernel.type() == KernelType::cubicSpline ? "cubic spline" : "Wendland C2",
           " kernel, mass ", s_.particles.mass));
  const auto& fp = freeSurface_->parameters();
  line(fp.enabled ? cat("free surface: divR < ", fp.candidateThreshold, " + scan region, splash < ", fp.splashThreshold,
                        ", vicinity ", fp.vicinityRadius, " h")
                  : std::string("free surface: off (closed domain, pressure level pinned)"));
  if (needs_.surfaceFit) line("surface fit: leave-one-out line fit, curvature (eqs 19-21)");
  line(cat("derivatives: ", toString(operator_->scheme())));
  for (const auto& e : effects_)
    if (e->stage() == EffectStage::force) line(cat("predictor force: ", e->name(), " (", e->describe(), ")"));
  line(cat("pressure Poisson equation: source rho/dt <div u*> (eq. 6), ", ppe_->solver().describe()));
  for (const auto& e : effects_)
    if (e->stage() == EffectStage::pressureSource) line(cat("  + ", e->name(), " (", e->describe(), ")"));
  line("corrector: u = u* - dt/rho <grad p> (eq. 5)");
  line("advection: r = r + dt u (eq. 7)");
  for (const auto& e : effects_)
    if (e->stage() == EffectStage::advection || e->stage() == EffectStage::postAdvection)
      line(cat(e->name(), " (", e->describe(), ")"));
  bool anyShift = false;
  for (const auto& e : effects_)
    if (e->stage() == EffectStage::shift) { line(cat(e->name(), " (", e->describe(), ")")); anyShift = true; }
  if (anyShift) line(cat("shift cap |dr| <= ", maxShift_, " h", taylorCorrectionDescription()));
  else line("shifting: off");
  for (const auto& f : functionObjects_) line(cat("function object ", f->name(), ": ", f->type(), " (", f->describe(), ")"));
  line(cat("time: ", rc_.adjustTimeStep ? cat("adjustable dt, maxCo ", rc_.maxCo) : cat("fixed dt ", rc_.deltaT, " s"),
           ", end ", rc_.endTime, " s"));
  return os.str();
}

// --- the stages --------------------------------------------------------------

template <int D>
void Simulation<D>::analyse() {
  auto& P = s_.particles;
  { StageTimers::Scope t(timers_, st_.neighbours); search_->build(P.position, s_.neighbours); }
  {
    StageTimers::Scope t(timers_, st_.density);
    // Kernel values of every pair (the operator below refills the fluid rows with
    // identical values): <rho>, the Shepard wall velocity and the Adami rows use them.
    const auto& nl = s_.neighbours;
    const long n = long(s_.size());
    s_.weights.w.resize(nl.numPairs());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i)
      for (Index k = nl.begin(i); k < nl.end(i); ++k) s_.weights.w[k] = s_.kernel.w(nl.r[k]);
    s_.computeDensity();
  }
  { StageTimers::Scope t(timers_, st_.freeSurface); freeSurface_->detect(s_); }
  {
    StageTimers::Scope t(timers_, st_.weights);
    // Fluid rows: 1 = the full operator, 2 = free-surface rows (first order at most),
    // 3 = splash rows (standard weights; DerivativeOperator.hpp).
    const long n = long(s_.size());
    weightRows_.resize(n);
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
      const SurfaceClass c = P.surfaceClass(i);
      weightRows_[i] = !s_.isFluid(i) ? 0 : c == SurfaceClass::splash ? 3 : c == SurfaceClass::free ? 2 : 1;
    }
    operator_->computeWeights(s_.kernel, s_.V(), s_.neighbours, weightRows_, s_.weights);
  }
  if (needs_.surfaceFit) { StageTimers::Scope t(timers_, st_.surfaceFit); computeSurfaceFit(s_); }
}

template <int D>
void Simulation<D>::predict() {
  StageTimers::Scope t(timers_, st_.predictor);
  auto& acc = s_.acceleration;
  const long n = long(s_.size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) acc[i].setZero();
  for (auto& e : effects_)
    if (e->stage() == EffectStage::force) e->addAcceleration(s_, acc);
  const auto& u = s_.particles.velocity;
  const double dt = s_.dt;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) s_.uStar[i] = s_.isFluid(i) ? Vec<D>(u[i] + dt * acc[i]) : u[i];
  shepardFluidVelocity(s_, s_.uStar);
}

template <int D>
void Simulation<D>::solvePressure() {
  {
    StageTimers::Scope t(timers_, st_.ppeAssembly);
    const auto& nl = s_.neighbours;
    const auto& us = s_.uStar;
    const double V = s_.V(), c = s_.rho0 / s_.dt;
    const long n = long(s_.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
      double div = 0;
      if (s_.isFluid(i))
        for (Index k = nl.begin(i); k < nl.end(i); ++k) div += (us[nl.j[k]] - us[i]).dot(s_.weights.gradW[k]);
      source_[i] = c * V * div;
    }
    for (auto& e : effects_)
      if (e->stage() == EffectStage::pressureSource) e->addPressureSource(s_, source_);
    ppe_->assemble(s_, source_);
  }
  StageTimers::Scope t(timers_, st_.ppeSolve);
  report_.ppe = ppe_->solve(s_);
  report_.ppeUnknowns = ppe_->numUnknowns();
  report_.ppeStandardRows = ppe_->standardRows();
  if (report_.ppe.usedFallback && ++ppeFallbacks_ <= 10)
    Log::get().warning(cat("step ", s_.step + 1, ": ", report_.ppe.message,
                           ppeFallbacks_ == 10 ? " (further fallbacks are counted, not shown)" : ""));
  if (!report_.ppe.ok)
    throw NumericalError(cat("pressure Poisson equation failed at step ", s_.step + 1, ", time ", s_.time, ": ",
                             report_.ppe.message));
}

template <int D>
void Simulation<D>::correct() {
  StageTimers::Scope t(timers_, st_.corrector);
  auto& P = s_.particles;
  const auto& nl = s_.neighbours;
  const double c = s_.dt / s_.rho0 * s_.V();
  const long n = long(s_.size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    if (!s_.isFluid(i)) continue;
    Vec<D> gp = Vec<D>::Zero();
    const double pi = P.pressure[i];
    for (Index k = nl.begin(i); k < nl.end(i); ++k) gp += (P.pressure[nl.j[k]] - pi) * s_.weights.gradW[k];
    P.velocity[i] = s_.uStar[i] - c * gp;
  }
}

template <int D>
void Simulation<D>::advect() {
  auto& P = s_.particles;
  const long n = long(s_.size());
  const bool xsph = !du_.empty();
  if (xsph) {
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) du_[i].setZero();
    for (std::size_t k = 0; k < effects_.size(); ++k)
      if (effects_[k]->stage() == EffectStage::advection) {
        StageTimers::Scope t(timers_, effectTimer_[k]);
        effects_[k]->addAdvectionVelocity(s_, P.velocity, du_);
      }
  }
  StageTimers::Scope t(timers_, st_.advection);
  const double dt = s_.dt;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    if (!s_.isFluid(i)) continue;
    P.position[i] += dt * (xsph ? Vec<D>(P.velocity[i] + du_[i]) : P.velocity[i]);
    if (s_.periodic.any()) s_.periodic.wrap(P.position[i]);
  }
}

template <int D>
void Simulation<D>::stabilise() {
  bool any = false;
  for (auto& e : effects_) any |= e->stage() == EffectStage::postAdvection;
  if (!any) return;
  StageTimers::Scope t(timers_, st_.ads);
  s_.refreshPairGeometry();
  for (auto& e : effects_)
    if (e->stage() == EffectStage::postAdvection) {
      e->correctPositions(s_);
      report_.adsCount = e->lastActionCount();
    }
  if (s_.periodic.any())
    for (std::size_t i = 0; i < s_.size(); ++i)
      if (s_.isFluid(i)) s_.periodic.wrap(s_.particles.position[i]);
}

template <int D>
void Simulation<D>::shiftParticles() {
  if (dr_.empty()) return;
  auto& P = s_.particles;
  const long n = long(s_.size());
  {
    StageTimers::Scope t(timers_, st_.shifting);
    // Velocity gradient of u^{n+1} for the Taylor correction (walls show the fluid's Shepard velocity).
    if (taylorCorrection_ != TaylorCorrection::off) {
#pragma omp parallel for schedule(static)
      for (long i = 0; i < n; ++i) s_.uStar[i] = P.velocity[i];
      shepardFluidVelocity(s_, s_.uStar);
      Ops<D>::velocityGradient(s_.neighbours, s_.weights, s_.V(), s_.uStar, gradU_);
    }
    s_.refreshPairGeometry();
    s_.computeDensity();
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) dr_[i].setZero();
  }
  for (std::size_t k = 0; k < effects_.size(); ++k)
    if (effects_[k]->stage() == EffectStage::shift) {
      StageTimers::Scope t(timers_, effectTimer_[k]);
      effects_[k]->addShift(s_, dr_);
    }
  StageTimers::Scope t(timers_, st_.shifting);
  capShift(dr_, maxShift_ * s_.h);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    if (!s_.isFluid(i)) { P.shift[i].setZero(); continue; }
    P.position[i] += dr_[i];
    if (s_.periodic.any()) s_.periodic.wrap(P.position[i]);
    if (taylorCorrected(P.surfaceClass(i))) P.velocity[i] += gradU_[i] * dr_[i];
    P.shift[i] = dr_[i];
  }
}

template <int D>
void Simulation<D>::step(double dt) {
  s_.dt = dt;
  predict();
  solvePressure();
  correct();
  advect();
  stabilise();
  shiftParticles();
  s_.time += dt;
  ++s_.step;
}

template class Simulation<2>;
template class Simulation<3>;

}  // namespace shizuku
