// Domain decomposition and halo (decomposition/DomainDecomposition.hpp, Halo.hpp), on
// whatever number of ranks mpirun starts (ctest runs 1, 2 and 3; label mpi):
//   - from any share of the particles on each rank (every size-th, rank 0 also the last
//     five), every particle is owned by exactly one rank after the first partition, after
//     particles moved (point assignment) and after a repartition (counts and id sums);
//   - the halo is complete: for every owned particle, the particles within the halo width
//     among owned + ghosts are exactly those of the whole set (by id, brute force, the
//     minimum image in periodic directions), in 2D and 3D, with and without a periodic
//     direction;
//   - update() gives every ghost its owner's value, for double, Vec<D> and byte fields;
//   - RCB and HSFC both; the partition is balanced within Zoltan's tolerance;
//   - with migration only at the start (migrationInterval larger than the run), the halo
//     stays complete while particles drift out of their ranks' regions.
#define BOOST_TEST_MODULE mpi_decomposition
#include <boost/test/unit_test.hpp>

#include "decomposition/DomainDecomposition.hpp"
#include "parallel/Communicator.hpp"
#include <algorithm>
#include <map>
#include <random>
#include <set>

using namespace shizuku;

struct StartMpi {
  StartMpi() {
    int argc = 0;
    char** argv = nullptr;
    Communicator::world().start(&argc, &argv);
  }
};
BOOST_TEST_GLOBAL_FIXTURE(StartMpi);

namespace {

// The whole set, identical on every rank: a jittered lattice nx x ny (x nz) of spacing 1.
template <int D>
ParticleSet<D> wholeSet(int n, unsigned seed) {
  ParticleSet<D> P;
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  const int nz = D == 3 ? n / 2 : 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n + 7; ++i) {
        Vec<D> x;
        x[0] = i + 0.5 + jitter(gen);
        x[1] = j + 0.5 + jitter(gen);
        if constexpr (D == 3) x[2] = k + 0.5 + jitter(gen);
        P.position.push_back(x);
      }
  const std::size_t N = P.position.size();
  P.resize(N);
  for (std::size_t i = 0; i < N; ++i) {
    P.id[i] = std::int64_t(i);
    P.pressure[i] = 3.0 * double(i);
    P.velocity[i] = Vec<D>::Constant(double(i));
    P.type[i] = std::uint8_t(i % 3);
  }
  return P;
}

template <int D>
PeriodicBox<D> box(int n, bool periodicX) {
  PeriodicBox<D> b;
  b.periodic[0] = periodicX;
  b.lo.setZero();
  b.hi = Vec<D>::Constant(double(n));
  b.hi[0] = n + 7;
  return b;
}

// Every id of the whole set owned exactly once across the ranks.
template <int D>
void checkOwnership(const ParticleSet<D>& P, std::size_t owned, std::size_t N) {
  const auto& world = Communicator::world();
  std::vector<double> count(N, 0.0);
  for (std::size_t i = 0; i < owned; ++i) count[std::size_t(P.id[i])] += 1;
  world.sumInPlace(count);
  BOOST_TEST(std::all_of(count.begin(), count.end(), [](double c) { return c == 1; }));
}

// The ids within `width` of each owned particle: here (owned + ghosts) and in the whole set.
template <int D>
void checkHalo(const ParticleSet<D>& P, std::size_t owned, const ParticleSet<D>& whole, double width,
               const PeriodicBox<D>& b) {
  std::map<std::int64_t, Vec<D>> where;
  for (std::size_t i = 0; i < whole.size(); ++i) where[whole.id[i]] = whole.position[i];
  long missing = 0, extra = 0;
  for (std::size_t i = 0; i < owned; ++i) {
    std::set<std::int64_t> local, all;
    for (std::size_t j = 0; j < P.size(); ++j)
      if (j != i && b.difference(P.position[i], P.position[j]).norm() < width) local.insert(P.id[j]);
    for (const auto& [id, x] : where)
      if (id != P.id[i] && b.difference(P.position[i], x).norm() < width) all.insert(id);
    for (auto id : all) missing += !local.count(id);
    for (auto id : local) extra += !all.count(id);
  }
  BOOST_TEST(missing == 0);
  BOOST_TEST(extra == 0);
}

// Ghost values after update() are the owners' values (a function of the id here).
template <int D>
void checkUpdate(ParticleSet<D>& P, const Halo<D>& halo) {
  std::vector<double> f(P.size(), -1.0);
  std::vector<Vec<D>> v(P.size(), Vec<D>::Constant(-1.0));
  std::vector<std::uint8_t> c(P.size(), 255);
  for (std::size_t i = 0; i < halo.numOwned(); ++i) {
    f[i] = 0.5 * double(P.id[i]);
    v[i] = Vec<D>::Constant(2.0 * double(P.id[i]));
    c[i] = std::uint8_t(P.id[i] % 7);
  }
  halo.update(f);
  halo.update(v);
  halo.update(c);
  long wrong = 0;
  for (std::size_t g = halo.numOwned(); g < P.size(); ++g)
    wrong += f[g] != 0.5 * double(P.id[g]) || v[g] != Vec<D>::Constant(2.0 * double(P.id[g])) || c[g] != P.id[g] % 7;
  BOOST_TEST(wrong == 0);
}

template <int D>
void runCase(const std::string& method, bool periodicX, int migrationInterval = 1) {
  const int n = D == 2 ? 24 : 10;
  const double width = 2.4;
  const PeriodicBox<D> b = box<D>(n, periodicX);
  ParticleSet<D> whole = wholeSet<D>(n, 7);
  const std::size_t N = whole.size();
  // Each rank starts from any share: here every size-th particle (as a restart reading
  // another rank count's pieces may give it), rank 0 also the last ones.
  ParticleSet<D> P = whole;
  const auto& ranks = Communicator::world();
  std::vector<std::uint8_t> other(N);
  for (std::size_t i = 0; i < N; ++i)
    other[i] = i + 5 >= N ? ranks.rank() != 0 : int(i % std::size_t(ranks.size())) != ranks.rank();
  P.removeMarked(other);
  DecompositionSettings set;
  set.method = method;
  set.migrationInterval = migrationInterval;
  DomainDecomposition<D> dd(set, width, b);
  dd.start(P, 0);
  const auto& world = Communicator::world();
  BOOST_TEST(world.sum(long(dd.halo().numOwned())) == long(N));
  BOOST_TEST(dd.stats().imbalance < 0.1);
  checkOwnership(P, dd.halo().numOwned(), N);
  checkHalo(P, dd.halo().numOwned(), whole, width, b);
  // Ghosts arrive with every field of their owner.
  long wrongFields = 0;
  for (std::size_t g = dd.halo().numOwned(); g < P.size(); ++g)
    wrongFields += P.pressure[g] != 3.0 * double(P.id[g]) || P.type[g] != P.id[g] % 3;
  BOOST_TEST(wrongFields == 0);
  checkUpdate(P, dd.halo());

  // Move every particle (a shear, wrapped in x when periodic), then redistribute.
  for (int round = 0; round < 3; ++round) {
    auto move = [&](ParticleSet<D>& Q, std::size_t count) {
      for (std::size_t i = 0; i < count; ++i) {
        Q.position[i][0] += 1.5 * (Q.position[i][1] / n - 0.5);
        if (periodicX) b.wrap(Q.position[i]);
      }
    };
    move(whole, whole.size());
    dd.stripGhosts(P);
    move(P, P.size());
    dd.distribute(P, round + 1);
    checkOwnership(P, dd.halo().numOwned(), N);
    checkHalo(P, dd.halo().numOwned(), whole, width, b);
    checkUpdate(P, dd.halo());
  }
  if (world.size() > 1) BOOST_TEST(dd.stats().neighbourRanks >= 1);
}

}  // namespace

BOOST_AUTO_TEST_CASE(rcb_2d) { runCase<2>("RCB", false); }
BOOST_AUTO_TEST_CASE(rcb_2d_periodic) { runCase<2>("RCB", true); }
BOOST_AUTO_TEST_CASE(hsfc_2d) { runCase<2>("HSFC", false); }
BOOST_AUTO_TEST_CASE(rcb_3d) { runCase<3>("RCB", false); }
BOOST_AUTO_TEST_CASE(hsfc_3d_periodic) { runCase<3>("HSFC", true); }
// No migration after the start: particles drift out of their ranks' regions, and the halo,
// which follows the ranks' bounding boxes, is still complete.
BOOST_AUTO_TEST_CASE(rcb_2d_periodic_without_migration) { runCase<2>("RCB", true, 1000); }
