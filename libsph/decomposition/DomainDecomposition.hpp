// The domain decomposition of a distributed run (docs/parallel.md 3-4): which rank owns
// which particle, moving particles to their owners, and the halo.
//   start():       every rank holds a share of the particles (a slice of the generated
//                  set, or the pieces of a time directory it read); Zoltan partitions them
//                  from scratch, and the particles move to their owners
//   distribute():  before each step's analysis: ghosts dropped; every migrationInterval
//                  steps, particles that left the rank's region sent to the rank whose region
//                  holds them (Zoltan's point assignment on the kept cuts), and a repartition
//                  when the particle counts differ by more than rebalanceThreshold (max /
//                  mean - 1); the halo built. Between migrations a rank keeps the particles
//                  that drifted out of its region: the halo follows the ranks' bounding boxes,
//                  so the answer does not change, and the pressure equation's rows stay the
//                  same particles, so its preconditioner can be kept (docs/parallel.md 3).
// Keys (system/decomposeParDict, optional): method RCB|HSFC; rebalanceThreshold 0.1;
// migrationInterval 10.
#pragma once
#include "core/Dictionary.hpp"
#include "decomposition/Halo.hpp"
#include "parallel/ZoltanPartitioner.hpp"
#include <memory>
#include <string>

namespace shizuku {

struct DecompositionSettings {
  std::string method = "RCB";
  double rebalanceThreshold = 0.1;
  int migrationInterval = 10;
  // From system/decomposeParDict (nullptr: the defaults); read in serial runs too, so a
  // misspelt key is reported wherever the case runs.
  static DecompositionSettings read(const Dictionary* dict);
};

// Statistics for the log and docs/parallel.md.
struct DecompositionStats {
  long owned = 0, ghosts = 0, migrated = 0, repartitions = 0;
  int neighbourRanks = 0;
  double imbalance = 0;  // max owned / mean owned - 1, over the ranks
  // Sums over the distributions since the start (this rank): for the per-step means.
  long distributions = 0;
  double ghostSum = 0, ownedSum = 0, neighbourSum = 0, migratedSum = 0;
};

template <int D>
class DomainDecomposition {
 public:
  DomainDecomposition(const DecompositionSettings& settings, double haloWidth, const PeriodicBox<D>& box);
  // P holds this rank's share (any share); afterwards this rank's own particles. Collective.
  void start(ParticleSet<D>& P, long step);
  // Drop the ghosts, move particles to their owners when due (repartition if unbalanced),
  // build the halo. Collective.
  void distribute(ParticleSet<D>& P, long step);
  // Remove the ghosts if P holds them (after the step's last stage, before a reordering).
  void stripGhosts(ParticleSet<D>& P) {
    if (ghostsPresent_) halo_.strip(P);
    ghostsPresent_ = false;
  }
  // P was replaced by this rank's own particles alone (the last good state restored).
  void ghostsDropped() { ghostsPresent_ = false; }
  const Halo<D>& halo() const { return halo_; }
  const DecompositionStats& stats() const { return stats_; }
  const DecompositionSettings& settings() const { return settings_; }
  // One line for the log: each rank's mean ghosts, neighbour ranks, messages and bytes per
  // step, as the mean and the largest over the ranks (docs/parallel.md 9). Collective.
  std::string summary() const;

 private:
  void partition(const ParticleSet<D>& P, bool fromScratch);
  void migrate(ParticleSet<D>& P);

  DecompositionSettings settings_;
  ZoltanPartitioner zoltan_;
  Halo<D> halo_;
  DecompositionStats stats_;
  bool ghostsPresent_ = false;
  long lastMigration_ = -1;
  std::vector<int> owner_;
  std::vector<double> coords_;
  std::vector<std::uint8_t> leaving_;
  std::vector<char> sendBuf_, recvBuf_;
};

}  // namespace shizuku
