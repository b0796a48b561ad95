// The health checks after each step and the last good state: see HealthGuard.hpp.
#include "isph/HealthGuard.hpp"
#include "core/Log.hpp"
#include "core/Parameter.hpp"
#include "io/TimeName.hpp"
#include "io/VtpFile.hpp"
#include "operators/DensityErrorMeasure.hpp"
#include "parallel/AgreedFailure.hpp"
#include <cmath>
#include <filesystem>

namespace shizuku {

namespace fs = std::filesystem;

namespace {
namespace key {
const ParameterGroup health("system/controlDict: healthChecks",
    "Guards checked after every step: a failure stops the run (exit 2) with the last good state written.");
const ScalarParameter maxDensityErrorRms = health.scalar("maxDensityErrorRms", dim::none,
    "largest interior density error rms, % (eq. 22)").def(20).above(0).max(100);
const ScalarParameter maxSpeed = health.scalar("maxSpeed", dim::velocity, "largest fluid speed")
    .def(0).shownDefault("0 (10 x max(initial speed, sqrt(2 g L)))").min(0);
const ScalarParameter maxLostFraction = health.scalar("maxLostFraction", dim::none,
    "largest mass removed through the domain's bounds, over the initial fluid mass").def(0.01).min(0).max(1);
const IntParameter maxLeaks = health.integer("maxLeaks", "largest number of fluid particles found in or through a wall")
    .def(0).min(0);
const ScalarParameter domainMargin = health.scalar("domainMargin", dim::none,
    "retired: read and ignored with a warning (the domain is controlDict `domain`, removal is limited by "
    "maxLostFraction)").def(0.5).min(0).max(1e6);
}  // namespace key
}  // namespace

template <int D>
HealthGuard<D>::HealthGuard(const Dictionary& controlDict) {
  const Dictionary* hc = controlDict.subDictPtr("healthChecks");
  limits_.maxDensityErrorRms = key::maxDensityErrorRms.read(hc);
  limits_.maxSpeed = key::maxSpeed.read(hc);
  limits_.maxLostFraction = key::maxLostFraction.read(hc);
  limits_.maxLeaks = key::maxLeaks.read(hc);
  if (hc && hc->found("domainMargin")) {
    key::domainMargin.read(*hc);
    Log::get().warning(cat(hc->location("domainMargin").str(), ": healthChecks/domainMargin is retired and ignored: "
                           "a fluid particle that leaves the domain (controlDict `domain { min (..); max (..); }`, "
                           "default: the walls' box extended beyond each open face) is removed, and the run stops "
                           "only when the removed mass passes healthChecks/maxLostFraction"));
  }
}

template <int D>
void HealthGuard<D>::setLimits(const FlowState<D>& s, const Vec<D>& g) {
  const auto& P = s.particles;
  const auto& world = Communicator::world();  // every rank's particles
  Vec<D> lo = Vec<D>::Constant(INFINITY), hi = Vec<D>::Constant(-INFINITY);
  for (const auto& x : P.position) { lo = lo.cwiseMin(x); hi = hi.cwiseMax(x); }
  for (int k = 0; k < D; ++k) {
    lo[k] = world.min(lo[k]);
    hi[k] = world.max(hi[k]);
  }
  const Vec<D> ext = (hi - lo).cwiseMax(Vec<D>::Constant(s.d0));
  // No flow of this case can exceed ten times the larger of its starting speed and the
  // free-fall speed over the largest extent of the domain.
  if (limits_.maxSpeed == 0) {
    double u0 = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.isFluid(i)) u0 = std::max(u0, P.velocity[i].norm());
    u0 = world.max(u0);
    const double fall = std::sqrt(2 * g.norm() * ext.maxCoeff());
    limits_.maxSpeed = std::max(u0, fall) > 0 ? 10 * std::max(u0, fall) : INFINITY;
  }
}

template <int D>
double HealthGuard<D>::check(const FlowState<D>& s, const char* where, const std::string& caseDir) {
  const auto& world = Communicator::world();
  density_ = measureDensityError(s);  // collective: before any rank can fail
  // A failure found on one rank stops every rank, with its message.
  double maxU = 0;
  agreeOnFailure<NumericalError, NumericalError>([&] { maxU = checkOwn(s, where, caseDir); });
  return world.max(maxU);
}

// The checks on this rank's own particles.
template <int D>
double HealthGuard<D>::checkOwn(const FlowState<D>& s, const char* where, const std::string& caseDir) {
  const auto& P = s.particles;
  const long n = long(s.numOwned());
  // Offending particles: every non-finite one.
  offending_.clear();
  double maxU = 0;
  long fastest = -1;
  for (long i = 0; i < n; ++i) {
    if (!s.isFluid(i)) continue;
    if (!(P.position[i].allFinite() && P.velocity[i].allFinite() && std::isfinite(P.pressure[i]))) {
      offending_.push_back(Index(i));
      continue;
    }
    const double speed = P.velocity[i].norm();
    if (speed > maxU) { maxU = speed; fastest = i; }
  }
  auto at = [&] { return cat(" at step ", s.step, ", time ", s.time); };  // built only on failure
  auto id = [&](long i) { return P.id[std::size_t(i)]; };
  if (!offending_.empty())
    fail(s, cat("non-finite position, velocity or pressure ", where, ": particle id ", id(offending_[0]), at()), caseDir);
  if (maxU > limits_.maxSpeed) {
    offending_.push_back(Index(fastest));
    fail(s, cat("particle id ", id(fastest), " moves at ", maxU, " m/s ", where, at(), " (position ",
                P.position[fastest].transpose(), ", ", surfaceClassName(P.surfaceClass(fastest)),
                "), above healthChecks/maxSpeed ", limits_.maxSpeed, " m/s"), caseDir);
  }
  const auto& e = density_.interior;
  // (global statistics; the rank holding the worst interior particle of its own reports it)
  if (e.count > 0 && e.rms > limits_.maxDensityErrorRms && density_.worstInterior >= 0) {
    const long worst = density_.worstInterior;
    offending_.push_back(Index(worst));
    fail(s, cat("interior density error rms ", e.rms, " % exceeds healthChecks/maxDensityErrorRms ",
                limits_.maxDensityErrorRms, " %", at(), "; worst particle id ", id(worst), " (",
                std::abs(densityErrorPercent(s.rho0, P.density[worst])), " %)"), caseDir);
  }
  return maxU;
}

template <int D>
void HealthGuard<D>::failWith(const FlowState<D>& s, const std::string& message, const std::vector<Index>& offending,
                              const std::string& caseDir) {
  offending_ = offending;
  fail(s, message, caseDir);
}

template <int D>
void HealthGuard<D>::fail(const FlowState<D>& s, const std::string& message, const std::string& caseDir) const {
  const auto& P = s.particles;
  std::string ids;
  for (std::size_t k = 0; k < offending_.size() && k < 10; ++k) ids += cat(k ? " " : "", P.id[offending_[k]]);
  if (offending_.size() > 10) ids += cat(" and ", offending_.size() - 10, " more");
  const std::string file = writeOffendingParticles(s, caseDir);
  throw NumericalError(cat(message, "; ", offending_.size(), " offending particle(s): id ", ids,
                           file.empty() ? "" : cat(", written to ", file)));
}

// The offending particles of a failed health check, for ParaView:
// postProcessing/healthChecks/<time>/offending.vtp. Returns the path ("" if it could not be written).
template <int D>
std::string HealthGuard<D>::writeOffendingParticles(const FlowState<D>& s, const std::string& caseDir) const {
  try {
    const auto& P = s.particles;
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
    ts.time = s.time;
    ts.step = s.step;
    ts.deltaT = s.dt;
    ts.note = "offending particles of a failed health check";
    const std::string dir = caseDir + "/postProcessing/healthChecks/" + timeName(s.time);
    fs::create_directories(dir);
    const auto& world = Communicator::world();
    const std::string file = dir + (world.isParallel() ? cat("/offending.rank", world.rank(), ".vtp") : "/offending.vtp");
    writeVtp<D>(file, sub, ts);
    return file;
  } catch (const std::exception& e) {
    Log::get().warning(cat("could not write the offending particles: ", e.what()));
    return "";
  }
}

template <int D>
void HealthGuard<D>::saveGoodState(const FlowState<D>& s) {
  const auto& P = s.particles;
  // This rank's own particles (a distributed run's ghosts are rebuilt from them); the
  // capacity is kept, so no reallocation once the count has peaked.
  const std::size_t n = s.numOwned();
  goodX_.assign(P.position.begin(), P.position.begin() + n);
  goodU_.assign(P.velocity.begin(), P.velocity.begin() + n);
  goodP_.assign(P.pressure.begin(), P.pressure.begin() + n);
  goodId_.assign(P.id.begin(), P.id.begin() + n);
  goodType_.assign(P.type.begin(), P.type.begin() + n);
  if (!P.restPosition.empty()) {  // a case with moving walls: their rest positions travel with them
    goodRest_.assign(P.restPosition.begin(), P.restPosition.begin() + n);
    goodMotion_.assign(P.motion.begin(), P.motion.begin() + n);
  }
  // The wall normals travel with their particles too (WallNormals.hpp).
  if (!P.wallNormal.empty()) goodWallNormal_.assign(P.wallNormal.begin(), P.wallNormal.begin() + n);
  if (!P.restNormal.empty()) goodRestNormal_.assign(P.restNormal.begin(), P.restNormal.begin() + n);
  goodBalance_ = s.balance;
  goodTime_ = s.time;
  goodStep_ = s.step;
  goodDt_ = s.dt;
}

template <int D>
void HealthGuard<D>::restoreGoodState(FlowState<D>& s) const {
  auto& P = s.particles;
  P.resize(goodX_.size());  // particles removed during the step come back
  P.position = goodX_;
  P.velocity = goodU_;
  P.pressure = goodP_;
  P.id = goodId_;
  P.type = goodType_;
  if (!P.restPosition.empty()) {
    P.restPosition = goodRest_;
    P.motion = goodMotion_;
  }
  if (!P.wallNormal.empty()) P.wallNormal = goodWallNormal_;
  if (!P.restNormal.empty()) P.restNormal = goodRestNormal_;
  s.refreshTypeMasks();
  s.balance = goodBalance_;
  s.time = goodTime_;
  s.step = goodStep_;
  s.dt = goodDt_;
}

template class HealthGuard<2>;
template class HealthGuard<3>;

}  // namespace shizuku
