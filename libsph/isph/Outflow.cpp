// What leaves the fluid after each step: see Outflow.hpp.
#include "isph/Outflow.hpp"
#include "parallel/AgreedFailure.hpp"
#include "core/Log.hpp"
#include <algorithm>

namespace shizuku {

namespace {
// "id 12 at (0.1 1.3)" for the first few of `list`, "and N more".
template <int D, class Item, class Text>
std::string listed(const std::vector<Item>& list, Text text) {
  std::string s;
  for (std::size_t k = 0; k < list.size() && k < 5; ++k) s += cat(k ? "; " : "", text(list[k]));
  if (list.size() > 5) s += cat("; and ", list.size() - 5, " more");
  return s;
}
}  // namespace

template <int D>
Outflow<D>::Outflow(Domain<D> domain, std::vector<WallBox<D>> walls, std::unique_ptr<OpenBoundaries<D>> open)
    : domain_(std::move(domain)), leaks_(std::move(walls)), open_(std::move(open)) {}

template <int D>
Outflow<D>::~Outflow() = default;

template <int D>
void Outflow<D>::start(const FlowState<D>& s, const std::string& caseDir, const std::string& startTimeName) {
  caseDir_ = caseDir;
  startTimeName_ = startTimeName;
  const FluidBalance& b = s.balance;  // on several ranks: rank 0 carries what was read, the others 0
  long fluid = 0;
  for (std::size_t i = 0; i < s.numOwned(); ++i) fluid += s.particles.isFluid(i);
  initialMass_ = Communicator::world().sum(double(fluid - b.released + b.captured) * s.particles.mass + b.removedMass);
}

template <int D>
std::vector<std::string> Outflow<D>::describe(const HealthLimits& limits) const {
  std::vector<std::string> v;
  v.push_back(cat("domain: ", domain_.describe(), domain_.bounded() ? cat("; fluid leaving it is removed (healthChecks/"
             "maxLostFraction ", limits.maxLostFraction, ")") : "",
             leaks_.active() ? cat("; leak check on ", leaks_.walls().size(), " wall(s) (healthChecks/maxLeaks ",
                                   limits.maxLeaks, ")") : ""));
  if (open_)
    for (const auto& l : open_->describe()) v.push_back(l);
  return v;
}

template <int D>
bool Outflow<D>::afterStep(FlowState<D>& s, const std::vector<Vec<D>>& previous, HealthGuard<D>& guard) {
  // A leak one rank finds stops every rank.
  if (leaks_.active()) agreeOnFailure<NumericalError, NumericalError>([&] { checkLeaks(s, previous, guard); });
  const bool removed = removeOutside(s, guard);
  return (open_ && open_->afterStep(s)) || removed;
}

template <int D>
bool Outflow<D>::removeOutside(FlowState<D>& s, HealthGuard<D>& guard) {
  if (!domain_.bounded()) return false;
  auto& P = s.particles;
  outside_.clear();
  for (std::size_t i = 0; i < P.size(); ++i)
    if (s.isFluid(i) && P.position[i].allFinite() && !domain_.contains(P.position[i])) outside_.push_back(Index(i));
  const double mass = double(outside_.size()) * P.mass;
  const double limit = guard.limits().maxLostFraction * initialMass_;
  // Every rank's removals (each rank's balance counts its own; the ranks decide together).
  const auto& world = Communicator::world();
  const double lost = world.isParallel() ? world.sum(s.balance.removedMass + mass) : s.balance.removedMass + mass;
  if (outside_.empty() && !(lost > limit)) return false;
  if (lost > limit)
    guard.failWith(s, cat("fluid removed through the domain's bounds would reach ", lost,
                          " kg, more than healthChecks/maxLostFraction ", guard.limits().maxLostFraction,
                          " of the initial fluid mass ", initialMass_, " kg, at step ", s.step, ", time ", s.time,
                          "; leaving now: ", listed<D>(outside_, [&](Index i) {
                            return cat("id ", P.id[i], " through the ", domain_.side(P.position[i]), " side at (",
                                       P.position[i].transpose(), ")");
                          }), "; domain ", domain_.describe()),
                   outside_, caseDir_);
  logRemoved(s);
  remove_.assign(P.size(), 0);
  for (Index i : outside_) remove_[std::size_t(i)] = 1;
  P.removeMarked(remove_);
  s.balance.removedMass += mass;
  s.balance.removedCount += long(outside_.size());
  return true;
}

template <int D>
void Outflow<D>::logRemoved(const FlowState<D>& s) {
  using F = PostProcessingFile;
  const auto& P = s.particles;
  if (!removedFile_) {
    removedFile_.emplace(caseDir_, "outflow", startTimeName_, "removed.dat");
    removedFile_->comment(cat("fluid particles removed after leaving the domain, ", D, "D\n",
                              "domain ", domain_.describe(), "\n",
                              "position and velocity at the end of the step that took them out; side: the face "
                              "they crossed"));
    removedFile_->columns({"time", "id", "position", "velocity", "mass", "side"},
                          {"s", "-", "m", "m/s", D == 2 ? "kg/m" : "kg", "-"});
  }
  for (Index i : outside_) {
    std::string side = domain_.side(P.position[i]);
    side = side.substr(0, side.find(' '));
    removedFile_->row(cat(F::number(s.time), " ", P.id[i], " ", F::vector<D>(P.position[i]), " ",
                          F::vector<D>(P.velocity[i]), " ", F::number(P.mass), " ", side));
  }
}

template <int D>
void Outflow<D>::checkLeaks(const FlowState<D>& s, const std::vector<Vec<D>>& previous, HealthGuard<D>& guard) {
  if (moving_) leaks_.find(s.particles, previous, s.periodic, found_, moving_->poses(), moving_->previousPoses());
  else leaks_.find(s.particles, previous, s.periodic, found_);
  if (found_.empty()) return;
  using F = PostProcessingFile;
  const auto& P = s.particles;
  if (!leakFile_) {
    leakFile_.emplace(caseDir_, "leaks", startTimeName_, "leaks.dat");
    leakFile_->comment("fluid particles found inside a wall's layers (deeper than d0/2 past its surface) or "
                       "through a closed wall face since the previous step");
    leakFile_->columns({"time", "id", "position", "velocity", "wall", "face", "how"},
                       {"s", "-", "m", "m/s", "-", "-", "-"});
  }
  for (const Leak& l : found_) {
    std::string face = faceLabel(l.face);
    leakFile_->row(cat(F::number(s.time), " ", P.id[l.particle], " ", F::vector<D>(P.position[l.particle]), " ",
                       F::vector<D>(P.velocity[l.particle]), " ", leaks_.walls()[std::size_t(l.wall)].name, " ",
                       face.substr(0, face.find(' ')), " ", l.crossed ? "crossed" : "inside"));
  }
  leakCount_ += long(found_.size());
  const std::string which = listed<D>(found_, [&](const Leak& l) {
    return cat("id ", P.id[l.particle], (l.crossed ? " crossed " : " inside "), leaks_.describe(l), " at (",
               P.position[l.particle].transpose(), ")");
  });
  if (leakCount_ > guard.limits().maxLeaks) {
    std::vector<Index> offending;
    for (const Leak& l : found_) offending.push_back(l.particle);
    guard.failWith(s, cat(found_.size(), " fluid particle(s) leaked through a wall at step ", s.step, ", time ",
                          s.time, " (", leakCount_, " in all, more than healthChecks/maxLeaks ",
                          guard.limits().maxLeaks, "): ", which), offending, caseDir_);
  }
  Log::get().warning(cat("wall leak at step ", s.step, ", time ", s.time, ": ", which, " (", leakCount_,
                         " in all, healthChecks/maxLeaks ", guard.limits().maxLeaks, ")"));
}

template class Outflow<2>;
template class Outflow<3>;

}  // namespace shizuku
