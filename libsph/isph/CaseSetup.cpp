// The set-up of a simulation from its case directory: see CaseSetup.hpp.
#include "isph/CaseSetup.hpp"
#include "boundaries/WallNormals.hpp"
#include "core/Parameter.hpp"
#include "decomposition/DistributedTimeDirectory.hpp"
#include "effects/PhysicalProperties.hpp"
#include "kernels/KernelParameters.hpp"
#include "io/TimeDirectory.hpp"
#include "io/TimeName.hpp"
#include "parallel/Communicator.hpp"
#include "particles/ParticleGenerator.hpp"
#include <cmath>

namespace shizuku {

namespace {
namespace key {
const ParameterGroup schemes("system/sphSchemes", "The numerical scheme (each effect has a sub-dictionary of its own).");
const OptionParameter derivatives = schemes.option("derivatives", {"SPH2", "corrected", "standard"},
    "derivative operators: second-order SPH(2), first-order corrected, or standard (docs/method.md 3)").def("SPH2");
const IntParameter reorderInterval = schemes.integer("reorderInterval",
    "steps between cell reorderings of the particles, the first at a fresh start (0: never)").def(20).min(0);
const OptionParameter positionUpdate = schemes.option("positionUpdate", {"euler", "midpoint"},
    "advection: r + dt u (eq. 7), or the implicit midpoint rule on the velocity linearised at each particle, "
    "which keeps the volume of a strained fluid (eq. 7b; docs/method.md 4.1)").def("euler");
}  // namespace key

// The neighbour search (minimum image) needs each periodic length to be at least twice
// the kernel support 2h, or a particle would meet a neighbour and its image: the error
// names particlesDict's periodic box and the spacing and ratio that set h.
template <int D>
void checkPeriodicLength(const Dictionary& particlesDict, const FlowState<D>& s) {
  const char* axes[] = {"x", "y", "z"};
  const double support = s.kernel.support(), need = 2 * support;
  for (int k = 0; k < D; ++k) {
    const double L = s.periodic.hi[k] - s.periodic.lo[k];
    if (s.periodic.periodic[k] && !(L >= need))
      particlesDict.subDict("periodic").error("max", cat("the periodic length in ", axes[k], " (", L,
          " m) is shorter than twice the kernel support 2h = ", support, " m (h = spacing ", s.d0,
          " m x system/sphSchemes kernel/smoothingLengthRatio ", s.h / s.d0, "): make it at least ", need, " m"));
  }
}

// The moving walls of a restart: the saved particles carry each moving wall particle's
// rest position and motion (written by a run of a case with motions). A case without
// motions drops the fields (its walls stay where they are).
template <int D>
void checkMotionFields(const CaseFiles& files, const std::string& startName, ParticleSet<D>& P, std::size_t motions) {
  if (motions == 0) {
    P.restPosition.clear();
    P.motion.clear();
    return;
  }
  // Each rank checks its share; the first rank's message stops every rank.
  const std::string where = "time directory '" + files.dir + "/" + startName + "'";
  std::string why;
  if (P.size() > 0 && (P.motion.empty() || P.restPosition.empty()))
    why = where + " holds no moving-wall fields (restPosition, motion): it was written by the case without "
                  "motions; start from particlesDict (startFrom startTime with no time directory) to build the moving walls";
  for (std::size_t i = 0; i < P.size() && why.empty(); ++i)
    if (P.motion[i] > motions || (P.motion[i] > 0 && !P.isWall(i)))
      why = cat(where, ": particle id ", P.id[i], " has motion ", int(P.motion[i]), ", but the case has ", motions,
                " moving wall region(s) and only wall particles move: the saved time belongs to another case");
  why = Communicator::world().firstMessage(why);
  if (!why.empty()) files.particlesDict.error("regions", "a wall region has a motion, but " + why);
}

}  // namespace

template <int D>
PhysicalConstants<D> CaseSetup<D>::readPhysicalConstants(const CaseFiles& files, FlowState<D>& s) {
  const PhysicalProperties p = readPhysicalProperties(files.physicalProperties);
  s.rho0 = p.rho;
  PhysicalConstants<D> c;
  c.nu = p.nu;
  if (files.gravity) c.g = readGravity<D>(*files.gravity);
  return c;
}

template <int D>
NumericalScheme<D> CaseSetup<D>::readScheme(const CaseFiles& files, FlowState<D>& s) {
  const Dictionary& sch = files.sphSchemes;
  const KernelParameters kp = KernelParameters::read(sch.subDictPtr("kernel"));
  // The spacing comes from particlesDict (the generator checks it); h = ratio * d0.
  s.d0 = readSpacing(files.particlesDict);
  s.h = kp.smoothingLengthRatio * s.d0;
  s.kernel = Kernel<D>(kp.type, s.h);
  NumericalScheme<D> scheme;
  scheme.derivatives = DerivativeOperator<D>::create(derivativeSchemeFromName(key::derivatives.read(sch)));
  scheme.freeSurface = std::make_unique<FreeSurfaceDetector<D>>(
      FreeSurfaceParameters::read(sch.subDictPtr("freeSurface")));
  scheme.reorderInterval = key::reorderInterval.read(sch);
  scheme.positionUpdate = key::positionUpdate.read(sch) == "midpoint" ? PositionUpdate<D>::Rule::midpoint
                                                                      : PositionUpdate<D>::Rule::euler;
  scheme.ppe = std::make_unique<PressureEquation<D>>(LinearSolver::create(files.sphSolution.subDictPtr("pressure")));
  scheme.ppe->setZeroPressureOnSurface(scheme.freeSurface->parameters().zeroPressureOnSurface);
  return scheme;
}

template <int D>
std::string CaseSetup<D>::readInitialState(const CaseFiles& files, const RunControl& rc, bool postProcessing,
                                           FlowState<D>& s, std::vector<WallBox<D>>& walls,
                                           std::vector<OpenBoundaryRegion<D>>& openRegions,
                                           std::vector<std::shared_ptr<WallMotion<D>>>& motions) {
  // The generator always reads particlesDict (it checks it and gives the periodic box);
  // its particles are used when the start time has none.
  GeneratedParticles<D> gen = generateParticles<D>(files.particlesDict);
  s.periodic = gen.periodic;
  walls = gen.walls;
  markCoveredFaces(walls);
  openRegions = gen.openBoundaries;
  motions = gen.motions;
  s.hasOpenBoundaries = !openRegions.empty();
  checkPeriodicLength(files.particlesDict, s);
  const auto times = listTimeDirectories(files.dir);
  std::string startName;
  if (!postProcessing) {
    if (rc.startFrom == RunControl::StartFrom::latestTime && !times.empty()) startName = times.back().second;
    else
      for (const auto& t : times)
        if (std::abs(t.first - rc.startTime) <= 1e-12 * std::max(1.0, std::abs(rc.startTime))) startName = t.second;
  }
  if (!startName.empty()) {
    TimeState ts;
    // On several ranks each reads its share (the pieces of a parallel run's time).
    s.particles = Communicator::world().isParallel() ? readDistributedShare<D>(files.dir, startName, ts)
                                                     : readTimeDirectory<D>(files.dir, startName, ts);
    s.time = ts.time;
    s.step = ts.step;
    s.dt = ts.deltaT;
    s.balance = ts.balance;
  } else {
    s.particles = std::move(gen.set);
    const auto& world = Communicator::world();
    const std::size_t n = s.particles.size(), part = std::size_t(world.rank()), parts = std::size_t(world.size());
    s.particles.keepRange(n * part / parts, n * (part + 1) / parts);  // this rank's share
    s.particles.rho0 = s.rho0;
    s.particles.spacing = s.d0;
    // Mass calibrated on the initial lattice so that <rho> = rho there (docs/method.md 2).
    s.particles.mass = s.rho0 / s.kernel.latticeSum(s.d0);
    s.time = rc.startTime;
    s.step = 0;
    s.dt = 0;
    startName = timeName(s.time);
    // The run writes these particles as <startName>/ first: refused here, before
    // anything is opened or written, when that would delete something of the user's.
    if (!postProcessing)
      if (const std::string why = whyNotReplaceable(files.dir + "/" + startName); !why.empty())
        throw InputError("the run starts from particlesDict, so it must write time directory '" + files.dir + "/" +
                         startName + "' first: " + why);
  }
  if (!startName.empty()) checkMotionFields(files, startName, s.particles, motions.size());
  // From the regions' geometry, on a restart too (at rest; the moving walls turn them).
  assignWallNormals(s.particles, walls);
  if (std::abs(s.particles.spacing - s.d0) > 1e-12 * s.d0)
    files.particlesDict.error("spacing", cat("differs from the spacing of the saved particles (",
                                            s.particles.spacing, " m)"));
  auto& P = s.particles;
  const std::size_t n = P.size();
  P.density.resize(n);
  P.surface.resize(n);
  P.pressure.resize(n);
  s.refreshTypeMasks();
  if (Communicator::world().sum(long(P.countFluid())) == 0)  // every rank's share
    files.particlesDict.error("regions", "the case has no fluid particles");
  s.uStar.resize(n);
  return startName;
}

template struct CaseSetup<2>;
template struct CaseSetup<3>;

}  // namespace shizuku
