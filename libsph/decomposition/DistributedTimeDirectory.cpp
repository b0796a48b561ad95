// Pieces of a time directory, one per rank: see DistributedTimeDirectory.hpp.
#include "decomposition/DistributedTimeDirectory.hpp"
#include "decomposition/ParticleGather.hpp"
#include "decomposition/ParticlePacking.hpp"
#include "parallel/AgreedFailure.hpp"
#include <algorithm>
#include <limits>

namespace shizuku {

namespace {

// "" when every id of every rank's `ids` is held once; else which id is held twice.
// Each id goes to rank id mod size, which looks for repeats among what it receives.
std::string repeatedId(const std::vector<std::int64_t>& ids) {
  const auto& world = Communicator::world();
  const int nranks = world.size();
  std::vector<long> count(std::size_t(nranks), 0);
  for (std::int64_t id : ids) ++count[std::size_t(id % nranks)];
  std::vector<long> fill(std::size_t(nranks), 0);  // where each rank's ids start in `send`
  for (std::size_t r = 1; r < fill.size(); ++r) fill[r] = fill[r - 1] + count[r - 1];
  std::vector<std::int64_t> send(ids.size());
  for (std::int64_t id : ids) send[std::size_t(fill[std::size_t(id % nranks)]++)] = id;
  std::vector<long> sendBytes(count), recvBytes = world.exchangeCounts(count);
  long total = 0;
  for (std::size_t r = 0; r < sendBytes.size(); ++r) {
    total += recvBytes[r];
    sendBytes[r] *= long(sizeof(std::int64_t));
    recvBytes[r] *= long(sizeof(std::int64_t));
  }
  std::vector<std::int64_t> mine(static_cast<std::size_t>(total));
  world.allToAll(reinterpret_cast<const char*>(send.data()), sendBytes, reinterpret_cast<char*>(mine.data()),
                 recvBytes, 17);
  std::sort(mine.begin(), mine.end());
  const auto twice = std::adjacent_find(mine.begin(), mine.end());
  return world.firstMessage(twice == mine.end() ? "" : "particle id " + std::to_string(*twice) + " is held twice");
}

}  // namespace

template <int D>
void writeDistributedTime(const std::string& caseDir, const std::string& timeName, ParticleSet<D>& P,
                          std::size_t owned, const TimeState& s, bool ascii) {
  const auto& world = Communicator::world();
  ParticlePacking<D>::ensureFields(P, ParticlePacking<D>::agreedFieldMask(P));
  // Rank 0 first: the replace check and the folder, or its error on every rank.
  PieceWrite w;
  agreeOnFailure<std::runtime_error>([&] {
    if (world.isRoot()) w = beginPieceWrite(caseDir, timeName);
  });
  w.folder = world.broadcast(w.folder);
  std::string failure;
  try {
    writePiece<D>(w.folder, world.rank(), P, owned, s);
  } catch (const std::exception& e) {
    failure = e.what();
  }
  failure = world.firstMessage(failure);
  // Gathered for the ascii files only (every rank takes part while rank 0 collects).
  const ParticleSet<D> whole = failure.empty() && ascii ? gatherParticles(P, owned) : ParticleSet<D>();
  if (world.isRoot()) {
    if (!failure.empty()) {
      abandonPieceWrite(w);
    } else {
      try {
        finishPieceWrite<D>(w, world.size(), P, s, ascii ? &whole : nullptr);
      } catch (const std::exception& e) {
        failure = e.what();
      }
    }
  }
  failure = world.firstMessage(failure);
  if (!failure.empty()) throw std::runtime_error(failure);
}

template <int D>
ParticleSet<D> readDistributedShare(const std::string& caseDir, const std::string& timeName, TimeState& s) {
  const auto& world = Communicator::world();
  ParticleSet<D> P;
  agreeOnFailure<InputError>([&] { P = readTimeDirectory<D>(caseDir, timeName, s, world.rank(), world.size()); });
  // A rank that read no piece takes the constants from those that did; they must agree.
  const bool has = P.spacing > 0;
  const double inf = std::numeric_limits<double>::infinity();
  const std::string where = "time directory '" + caseDir + "/" + timeName + "'";
  for (double* c : {&P.mass, &P.rho0, &P.spacing}) {
    const double hi = world.max(has ? *c : -inf), lo = world.min(has ? *c : inf);
    if (hi != lo) throw InputError(where + ": its pieces disagree on the particle mass, rho0 or spacing");
    *c = hi;
  }
  P.nextId = world.max(long(P.nextId));
  if (const std::string twice = repeatedId(P.id); !twice.empty())
    throw InputError(where + ": " + twice + " (by two of its pieces)");
  return P;
}

template void writeDistributedTime<2>(const std::string&, const std::string&, ParticleSet<2>&, std::size_t,
                                      const TimeState&, bool);
template void writeDistributedTime<3>(const std::string&, const std::string&, ParticleSet<3>&, std::size_t,
                                      const TimeState&, bool);
template ParticleSet<2> readDistributedShare<2>(const std::string&, const std::string&, TimeState&);
template ParticleSet<3> readDistributedShare<3>(const std::string&, const std::string&, TimeState&);

}  // namespace shizuku
