// A simulation assembled from its case: see Simulation.hpp.
#include "isph/Simulation.hpp"
#include "isph/CaseSetup.hpp"
#include "isph/TimeLoop.hpp"
#include "parallel/Communicator.hpp"
#include "io/TimeDirectory.hpp"
#include "io/TimeName.hpp"
#include <algorithm>
#include <omp.h>
#include <sstream>

namespace shizuku {

template <int D>
Simulation<D>::Simulation(const std::string& caseDir, const SimulationOptions& opt)
    : files_(CaseFiles::read(caseDir)), opt_(opt) {
  if (opt_.threads > 0) omp_set_num_threads(opt_.threads);
  rc_ = RunControl::read(files_.controlDict);
  const PhysicalConstants<D> physics = CaseSetup<D>::readPhysicalConstants(files_, s_);
  NumericalScheme<D> scheme = CaseSetup<D>::readScheme(files_, s_);
  guard_ = std::make_unique<HealthGuard<D>>(files_.controlDict);
  std::vector<WallBox<D>> walls;
  std::vector<OpenBoundaryRegion<D>> openRegions;
  std::vector<std::shared_ptr<WallMotion<D>>> motions;
  startTimeName_ = CaseSetup<D>::readInitialState(files_, rc_, opt_.postProcessing, s_, walls, openRegions, motions);
  std::vector<WallBox<D>> domainWalls = walls;
  if (!motions.empty()) buildMovingWalls(std::move(motions), domainWalls);
  guard_->setLimits(s_, physics.g);
  Domain<D> domain = Domain<D>::read(files_.controlDict, domainWalls, s_.particles);
  std::unique_ptr<OpenBoundaries<D>> open;
  if (!openRegions.empty()) {
    open = std::make_unique<OpenBoundaries<D>>(std::move(openRegions), s_, domain);
    open->prescribe(s_);
  }
  outflow_ = std::make_unique<Outflow<D>>(std::move(domain), walls, std::move(open));
  outflow_->setMovingWalls(movingWalls_.get());
  EffectSet<D> effects = EffectSet<D>::build(files_.gravity ? &*files_.gravity : nullptr, files_.physicalProperties,
                                             physics.nu, files_.sphSchemes, s_);
  const DecompositionSettings decomposition =
      DecompositionSettings::read(files_.decomposeParDict ? &*files_.decomposeParDict : nullptr);
  if (Communicator::world().isParallel()) distribute(decomposition);
  step_ = std::make_unique<IsphStep<D>>(s_, std::move(scheme), std::move(effects), timers_, decomposition_.get());
  step_->setMovingWalls(movingWalls_.get());
  if (opt_.functionObjects && !opt_.postProcessing)
    functionObjects_ = createFunctionObjects<D>(files_.controlDict.subDictPtr("functions"), walls,
                                                physics.g);
  else if (const Dictionary* f = files_.controlDict.subDictPtr("functions"))
    f->markAllRead();
  files_.checkAllRead();
}

template <int D>
Simulation<D>::~Simulation() = default;

// The moving walls, placed at the start time (a restart recomputes the positions it read,
// to the same values); the domain's default bounds take the boxes they sweep from the
// controlDict's startTime to endTime (the same interval for a run and its restart).
template <int D>
void Simulation<D>::buildMovingWalls(std::vector<std::shared_ptr<WallMotion<D>>> motions,
                                     std::vector<WallBox<D>>& domainWalls) {
  std::vector<std::string> names(motions.size());
  std::vector<std::pair<Vec<D>, Vec<D>>> boxes(motions.size());
  for (auto& w : domainWalls) {
    if (w.motion < 0) continue;
    names[std::size_t(w.motion)] = w.name;
    boxes[std::size_t(w.motion)] = {w.outerMin, w.outerMax};
    const double from = std::min(rc_.startTime, s_.time), to = std::max(s_.time, rc_.endTime);
    MovingWalls<D>::sweptBox(w, *motions[std::size_t(w.motion)], from, to, w.outerMin, w.outerMax);
  }
  movingWalls_ = std::make_unique<MovingWalls<D>>(std::move(motions), std::move(names), std::move(boxes));
  movingWalls_->place(s_.particles, s_.time);
  movingWalls_->prescribeVelocity(s_.particles, s_.time);
  s_.wallPoses = &movingWalls_->poses();
}

// Every rank has read or generated the whole set: each keeps its own particles and the
// halo (docs/parallel.md 3).
template <int D>
void Simulation<D>::distribute(const DecompositionSettings& settings) {
  decomposition_ = std::make_unique<DomainDecomposition<D>>(settings, s_.kernel.support(), s_.periodic);
  decomposition_->start(s_.particles, s_.step);
  s_.halo = &decomposition_->halo();
  // Each rank counts the fluid it removes from here on; rank 0 carries what was read.
  const auto& world = Communicator::world();
  if (!world.isRoot()) s_.balance = FluidBalance{};
  long fluid = 0;
  for (std::size_t i = 0; i < s_.numOwned(); ++i) fluid += s_.particles.isFluid(i);
  const std::vector<long> owned = world.allGather(long(s_.numOwned())), fluids = world.allGather(fluid);
  const std::vector<long> ghosts = world.allGather(long(decomposition_->halo().numGhosts()));
  std::string perRank;
  for (int r = 0; r < world.size(); ++r)
    perRank += cat(r ? ", " : "", owned[std::size_t(r)], " (", fluids[std::size_t(r)], " fluid, ",
                   ghosts[std::size_t(r)], " ghosts)");
  info(cat("Decomposition: ", settings.method, " (Zoltan) on ", world.size(), " ranks, halo 2h = ",
           s_.kernel.support(), " m; particles per rank: ", perRank));
  s_.refreshTypeMasks();
}

template <int D>
std::string Simulation<D>::pipeline() const {
  std::ostringstream os;
  const auto& T = s_.particles.type;
  const auto count = [&](ParticleType t) {  // every rank's own particles
    return Communicator::world().sum(long(std::count(T.begin(), T.begin() + long(s_.numOwned()), std::uint8_t(t))));
  };
  os << "Pipeline (" << D << "D, " << count(ParticleType::fluid) << " fluid + " << count(ParticleType::wall)
     << " wall particles"
     << (s_.hasOpenBoundaries ? cat(" + ", count(ParticleType::inlet), " inlet + ", count(ParticleType::outlet), " outlet")
                              : std::string())
     << ", d0 = " << s_.d0 << " m, h = " << s_.h
     << " m, rho = " << s_.rho0 << " kg/m^3)\n";
  int k = 1;
  auto line = [&](const std::string& what) { os << "  " << k++ << ". " << what << "\n"; };
  for (const auto& l : step_->describe()) line(l);
  for (const auto& l : outflow_->describe(guard_->limits())) line(l);
  for (const auto& f : functionObjects_) line(cat("function object ", f->name(), ": ", f->type(), " (", f->describe(), ")"));
  line(cat("time: ", rc_.adjustTimeStep ? cat("adjustable dt, maxCo ", rc_.maxCo) : cat("fixed dt ", rc_.deltaT, " s"),
           ", end ", rc_.endTime, " s"));
  return os.str();
}

template <int D>
int Simulation<D>::run() {
  TimeLoop<D> loop(files_, rc_, s_, *step_, *guard_, *outflow_, functionObjects_, timers_, startTimeName_);
  const int status = loop.run(pipeline());
  if (decomposition_) info(decomposition_->summary());
  return status;
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
void Simulation<D>::loadTime(const std::string& name) {
  TimeState ts;
  ParticleSet<D> p = readTimeDirectory<D>(files_.dir, name, ts);
  s_.particles = std::move(p);
  s_.time = ts.time;
  s_.step = ts.step;
  s_.dt = ts.deltaT;
  s_.balance = ts.balance;
  const std::size_t n = s_.particles.size();
  s_.refreshTypeMasks();
  s_.particles.surface.resize(n);
  s_.particles.density.resize(n);
  analyse();
}

template class Simulation<2>;
template class Simulation<3>;

}  // namespace shizuku
