// What crosses the fluid's bounds after each step (docs/boundaries.md, "Domain, outflow and
// leaks", "Inlets and outlets"):
//   - wall leaks (boundaries/LeakDetector): counted, logged to
//     postProcessing/leaks/<startTime>/leaks.dat (time, id, position, velocity, wall, face,
//     how), and more than healthChecks/maxLeaks stops the run (exit 2) with the leaking
//     particles written as the offending ones;
//   - fluid outside the domain (boundaries/Domain) is removed: logged to
//     postProcessing/outflow/<startTime>/removed.dat (time, id, position, velocity, mass,
//     side), its mass added to FlowState::removedMass (the conservation function object
//     reports it), the particle arrays compacted in place (ids unchanged, never reused).
//     When the removed mass would pass healthChecks/maxLostFraction of the initial fluid
//     mass, the run stops instead (exit 2, last good state), naming the particles.
//   - inlets and outlets (boundaries/OpenBoundaries, when the case has any): buffers moved,
//     fluid released and captured; the initial fluid mass of the balance counts them.
// Files are opened at the first event, so a run where nothing leaves or leaks writes none.
// O(N) per step; no allocation once the buffers have their capacity.
// Reads no dictionary keys (the limits come from HealthGuard, the domain from Domain).
#pragma once
#include "boundaries/Domain.hpp"
#include "boundaries/LeakDetector.hpp"
#include "boundaries/MovingWalls.hpp"
#include "boundaries/OpenBoundaries.hpp"
#include "io/PostProcessingFile.hpp"
#include "isph/HealthGuard.hpp"
#include <optional>

namespace shizuku {

template <int D>
class Outflow {
 public:
  // open: the inlets and outlets (nullptr: none).
  Outflow(Domain<D> domain, std::vector<WallBox<D>> walls, std::unique_ptr<OpenBoundaries<D>> open = nullptr);
  ~Outflow();
  // The initial fluid mass (the current one plus what left before a restart).
  void start(const FlowState<D>& s, const std::string& caseDir, const std::string& startTimeName);
  // After a step: leaks, then removal. `previous`: the positions at the start of the step.
  // Returns whether particles were removed or added, or changed type (the caller
  // refreshes the step's arrays).
  bool afterStep(FlowState<D>& s, const std::vector<Vec<D>>& previous, HealthGuard<D>& guard);
  // The moving walls (their poses for the leak test; nullptr: none), kept by the caller.
  void setMovingWalls(const MovingWalls<D>* m) { moving_ = m; }
  long leakCount() const { return leakCount_; }
  const Domain<D>& domain() const { return domain_; }
  const OpenBoundaries<D>* openBoundaries() const { return open_.get(); }
  // For -dryRun and the log: the domain line, then a line per inlet and outlet.
  std::vector<std::string> describe(const HealthLimits& limits) const;

 private:
  bool removeOutside(FlowState<D>& s, HealthGuard<D>& guard);
  void checkLeaks(const FlowState<D>& s, const std::vector<Vec<D>>& previous, HealthGuard<D>& guard);
  void logRemoved(const FlowState<D>& s);
  Domain<D> domain_;
  LeakDetector<D> leaks_;
  std::unique_ptr<OpenBoundaries<D>> open_;
  const MovingWalls<D>* moving_ = nullptr;
  std::string caseDir_, startTimeName_;
  double initialMass_ = 0;
  long leakCount_ = 0;
  std::vector<Leak> found_;          // leaks of this step
  std::vector<Index> outside_;       // fluid particles outside the domain this step
  std::vector<std::uint8_t> remove_; // 1 for those, per particle
  std::optional<PostProcessingFile> removedFile_, leakFile_;
};

}  // namespace shizuku
