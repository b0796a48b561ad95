// The stages of one ISPH time step (docs/method.md 13): see IsphStep.hpp.
#include "isph/IsphStep.hpp"
#include "boundaries/WallParticles.hpp"
#include "surface/SurfaceFit.hpp"
#include "parallel/Communicator.hpp"

namespace shizuku {

template <int D>
IsphStep<D>::IsphStep(FlowState<D>& s, NumericalScheme<D> scheme, EffectSet<D> effects, StageTimers& timers,
                      DomainDecomposition<D>* decomposition)
    : s_(s), scheme_(std::move(scheme)), effects_(std::move(effects)), decomposition_(decomposition), timers_(timers) {
  needs_ = effects_.needs();
  // The free-surface pressure condition (eq. 6b) reads the fit's normal and distance.
  needs_.surfaceFit |= scheme_.ppe->zeroPressureOnSurface() && scheme_.freeSurface->parameters().enabled;
  effects_.allocate(s_);
  if (needs_.surfaceFit) {
    s_.fitDistance.assign(s_.size(), NAN);
    s_.fitNormal.assign(s_.size(), Vec<D>::Zero());
    s_.curvature.assign(s_.size(), NAN);
  }
  if (!effects_.advectionVelocities.empty()) du_.resize(s_.size());
  positions_ = PositionUpdate<D>(scheme_.positionUpdate);
  positions_.allocate(s_.size());
  search_ = std::make_unique<NeighbourSearch<D>>(s_.kernel.support(), s_.periodic);
  source_.resize(s_.size());
  // Timed stages in execution order (the timing columns follow it); optional stages
  // exist only when an active effect runs them.
  st_.decomposition = decomposition_ ? timers_.stage("decomposition") : -1;
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
  for (const auto& e : effects_.advectionVelocities) advectionTimer_.push_back(timers_.stage(e->name()));
  st_.positionCorrections = effects_.positionCorrections.empty() ? -1 : timers_.stage("ads");
  if (effects_.shifting) effects_.shifting->registerTimers(timers_);
}

// Particles to their owners, and the halo (a distributed run).
template <int D>
void IsphStep<D>::distribute() {
  if (!decomposition_) return;
  StageTimers::Scope t(timers_, st_.decomposition);
  // A non-finite position stops every rank together (the neighbour search would stop only
  // the rank that holds it, and the others would wait for it).
  long bad = -1;
  for (std::size_t i = 0; i < s_.particles.size() && bad < 0; ++i)
    if (!s_.particles.position[i].allFinite()) bad = long(i);
  const std::string failure = Communicator::world().firstMessage(
      bad < 0 ? std::string() : cat("particle id ", s_.particles.id[std::size_t(bad)], " has a non-finite position at step ",
                                    s_.step, ", time ", s_.time));
  if (!failure.empty()) throw NumericalError(failure);
  decomposition_->distribute(s_.particles, s_.step);
  s_.halo = &decomposition_->halo();
  particleCountChanged();
}

template <int D>
void IsphStep<D>::dropGhosts() {
  if (!decomposition_) return;
  decomposition_->stripGhosts(s_.particles);
  particleCountChanged();
}

template <int D>
void IsphStep<D>::repartitionAsAtRestart() {
  if (!decomposition_) return;
  StageTimers::Scope t(timers_, st_.decomposition);
  decomposition_->stripGhosts(s_.particles);
  decomposition_->start(s_.particles, s_.step);
  s_.halo = &decomposition_->halo();
  particleCountChanged();
}

template <int D>
void IsphStep<D>::analyse() {
  auto& P = s_.particles;
  distribute();
  { StageTimers::Scope t(timers_, st_.neighbours); search_->build(P.position, s_.neighbours); }
  {
    StageTimers::Scope t(timers_, st_.density);
    s_.computeDensity();
  }
  { StageTimers::Scope t(timers_, st_.freeSurface); scheme_.freeSurface->detect(s_); }
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
    scheme_.derivatives->computeWeights(s_.kernel, s_.V(), s_.neighbours, weightRows_, s_.weights);
  }
  if (needs_.surfaceFit) { StageTimers::Scope t(timers_, st_.surfaceFit); computeSurfaceFit(s_); }
}

template <int D>
void IsphStep<D>::predict() {
  StageTimers::Scope t(timers_, st_.predictor);
  // The forces' acceleration is summed in u*'s storage, then u* = u + dt a in place (a
  // force reads the velocity, never u*).
  auto& acc = s_.uStar;
  const long n = long(s_.size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) acc[i].setZero();
  for (auto& e : effects_.forces) e->addAcceleration(s_, acc);
  const auto& u = s_.particles.velocity;
  const double dt = s_.dt;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) s_.uStar[i] = s_.isFluid(i) ? Vec<D>(u[i] + dt * acc[i]) : u[i];
  s_.exchange(s_.uStar);  // the walls' Shepard sum reads the fluid neighbours' u*
  shepardFluidVelocity(s_, s_.uStar);
}

template <int D>
bool IsphStep<D>::compressible() const {
  for (const auto& e : effects_.pressureSources)
    if (e->rowDiagonal(s_) > 0) return true;
  return false;
}

// The compressibility term (eq. 6c) needs a last pressure p^n; at a fresh start it is the
// pressure that holds the water against its body forces: the incompressible solve with every
// velocity set to zero (docs/method.md 4.1). From p^n = 0 a column at rest would ring as a
// quarter-wave resonator; a moving initial state keeps its own velocities for the first step,
// so water that starts against a wall meets it at the sound speed.
template <int D>
void IsphStep<D>::initialPressure() {
  auto& u = s_.particles.velocity;
  std::vector<Vec<D>> kept = u;  // once, before the first step
  for (auto& v : u) v.setZero();
  predict();
  solvePressure(false);
  u = std::move(kept);
}

template <int D>
void IsphStep<D>::solvePressure(bool effectTerms) {
  {
    StageTimers::Scope t(timers_, st_.ppeAssembly);
    Ops<D>::divergence(s_.neighbours, s_.weights, s_.rho0 / s_.dt * s_.V(), s_.uStar, source_, &s_.isFluidMask);
    double diagonal = 0;
    if (effectTerms)
      for (auto& e : effects_.pressureSources) {
        e->addPressureSource(s_, source_);
        diagonal += e->rowDiagonal(s_);
      }
    scheme_.ppe->assemble(s_, source_, diagonal);
  }
  StageTimers::Scope t(timers_, st_.ppeSolve);
  report_.ppe = scheme_.ppe->solve(s_);
  // Eq. 11b decided with the pressure just solved (docs/method.md 11): where a wall row's
  // bound changed, the rewritten wall rows are solved again, at most twice.
  for (int pass = 0; pass < 2 && report_.ppe.ok && scheme_.ppe->redecideWallRows(s_); ++pass) {
    const int iterations = report_.ppe.iterations;
    report_.ppe = scheme_.ppe->solve(s_, true);
    report_.ppe.iterations += iterations;
  }
  report_.ppeUnknowns = scheme_.ppe->numUnknowns();
  report_.ppeStandardRows = scheme_.ppe->standardRows();
  if (report_.ppe.usedFallback && ++ppeFallbacks_ <= 10)
    Log::get().warning(cat("step ", s_.step + 1, ": ", report_.ppe.message,
                           ppeFallbacks_ == 10 ? " (further fallbacks are counted, not shown)" : ""));
  if (!report_.ppe.ok)
    throw NumericalError(cat("pressure Poisson equation failed at step ", s_.step + 1, ", time ", s_.time, ": ",
                             report_.ppe.message));
}

template <int D>
void IsphStep<D>::correct() {
  StageTimers::Scope t(timers_, st_.corrector);
  auto& P = s_.particles;
  const long n = long(s_.size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i)
    if (s_.isFluid(i)) P.velocity[i] = s_.uStar[i];
  // u + (-c) <grad p> is u - c <grad p> to the last bit (negation is exact).
  Ops<D>::addGradient(s_.neighbours, s_.weights, -(s_.dt / s_.rho0 * s_.V()), P.pressure, P.velocity, s_.isFluidMask);
  // Outlet particles carry the fluid's velocity on (zero normal gradient, docs/boundaries.md).
  if (s_.hasOpenBoundaries) shepardFluidVelocity(s_, P.velocity, true);
  else s_.exchange(P.velocity);
}

template <int D>
void IsphStep<D>::advect() {
  auto& P = s_.particles;
  const long n = long(s_.size());
  const bool extra = !du_.empty();
  if (extra) {
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) du_[i].setZero();
    for (std::size_t k = 0; k < effects_.advectionVelocities.size(); ++k) {
      StageTimers::Scope t(timers_, advectionTimer_[k]);
      effects_.advectionVelocities[k]->addAdvectionVelocity(s_, P.velocity, du_);
    }
  }
  StageTimers::Scope t(timers_, st_.advection);
  positions_.move(s_, du_);
  if (movingWalls_) movingWalls_->place(P, s_.time + s_.dt);
  s_.exchange(P.position);
}

template <int D>
void IsphStep<D>::correctPositions() {
  if (effects_.positionCorrections.empty()) return;
  StageTimers::Scope t(timers_, st_.positionCorrections);
  for (auto& e : effects_.positionCorrections) {
    e->correctPositions(s_);
    report_.adsCount = e->lastActionCount();
  }
  if (s_.periodic.any())
    for (std::size_t i = 0; i < s_.size(); ++i)
      if (s_.isFluid(i)) s_.periodic.wrap(s_.particles.position[i]);
  s_.exchange(s_.particles.position);
}

template <int D>
void IsphStep<D>::shift() {
  if (!effects_.shifting) return;
  effects_.shifting->apply(s_, timers_);
  report_.shiftPasses = effects_.shifting->stepPasses();
}

template <int D>
void IsphStep<D>::advance(double dt) {
  s_.dt = dt;
  if (effects_.shifting) effects_.shifting->beginStep(dt * report_.maxSpeed / s_.h);
  // A moving wall shows the fluid its velocity at the step's end (docs/method.md 11.1).
  if (movingWalls_) movingWalls_->prescribeVelocity(s_.particles, s_.time + dt);
  if (s_.step == 0 && compressible()) initialPressure();
  predict();
  solvePressure();
  correct();
  advect();
  if (effects_.shifting) effects_.shifting->velocityGradient(s_, timers_);
  correctPositions();
  shift();
  dropGhosts();
  s_.time += dt;
  ++s_.step;
}

template <int D>
void IsphStep<D>::reorderParticles() {
  auto& P = s_.particles;
  dropGhosts();
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
  s_.refreshTypeMasks();
}

template <int D>
void IsphStep<D>::particleCountChanged() {
  const std::size_t n = s_.size();
  s_.refreshTypeMasks();
  s_.uStar.resize(n);
  if (needs_.surfaceFit) {
    s_.fitDistance.resize(n, NAN);
    s_.fitNormal.resize(n, Vec<D>::Zero());
    s_.curvature.resize(n, NAN);
  }
  if (!du_.empty()) du_.resize(n);
  positions_.allocate(n);
  source_.resize(n);
  effects_.allocate(s_);  // the effects' scratch (re-zeroed; refilled every step)
}

template <int D>
std::vector<std::string> IsphStep<D>::describe() const {
  std::vector<std::string> v;
  auto line = [&](const std::string& what) { v.push_back(what); };
  const int reorder = scheme_.reorderInterval;
  line(cat("neighbours: cell-linked list, radius 2h = ", s_.kernel.support(), " m", s_.periodic.any() ? ", periodic" : "",
           reorder > 0 ? cat(", reorder every ", reorder, " steps") : ""));
  line(cat("density: summation <rho> (eq. 18), ",
           s_.kernel.type() == KernelType::cubicSpline ? "cubic spline" : "Wendland C2", " kernel, mass ",
           s_.particles.mass));
  const auto& fp = scheme_.freeSurface->parameters();
  line(fp.enabled ? cat("free surface: indicator < ", fp.candidateThreshold, fp.scanRegion ? " + scan region" : "",
                        ", splash < ", fp.splashThreshold, ", vicinity ", fp.vicinityRadius, " h",
                        fp.zeroPressureOnSurface ? ", p = 0 on the surface (eq. 6b)" : ", p = 0 on the particles")
                  : std::string("free surface: off (closed domain, pressure level pinned)"));
  if (needs_.surfaceFit) line("surface fit: leave-one-out line fit, curvature (eqs 19-21)");
  line(cat("derivatives: ", toString(scheme_.derivatives->scheme())));
  for (const auto& e : effects_.forces) line(cat("predictor force: ", e->name(), " (", e->describe(), ")"));
  line(cat("pressure Poisson equation: source rho/dt <div u*> (eq. 6), ", scheme_.ppe->solver().describe()));
  for (const auto& e : effects_.pressureSources) line(cat("  + ", e->name(), " (", e->describe(), ")"));
  line("corrector: u = u* - dt/rho <grad p> (eq. 5)");
  line(positions_.describe() + (movingWalls_ ? "; moving walls to their pose at t + dt" : ""));
  if (movingWalls_)
    for (const auto& l : movingWalls_->describe()) line(l);
  for (const auto& e : effects_.advectionVelocities) line(cat(e->name(), " (", e->describe(), ")"));
  for (const auto& e : effects_.positionCorrections) line(cat(e->name(), " (", e->describe(), ")"));
  if (effects_.shifting) {
    for (const auto& e : effects_.shifting->terms()) line(cat(e->name(), " (", e->describe(), ")"));
    line(effects_.shifting->describe());
  } else {
    line("shifting: off");
  }
  return v;
}

template class IsphStep<2>;
template class IsphStep<3>;

}  // namespace shizuku
