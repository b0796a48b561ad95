// Collective operations across ranks: see Communicator.hpp.
#include "parallel/Communicator.hpp"
#include <unistd.h>
#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <stdexcept>

#ifdef SHIZUKU_HAVE_MPI
#include <mpi.h>
#endif

namespace shizuku {

Communicator& Communicator::world() {
  static Communicator c;
  return c;
}

bool Communicator::builtWithMpi() {
#ifdef SHIZUKU_HAVE_MPI
  return true;
#else
  return false;
#endif
}

namespace {
std::optional<int> environmentInt(const char* const* names) {
  for (const char* const* n = names; *n; ++n)
    if (const char* v = std::getenv(*n)) {
      char* end = nullptr;
      const long x = std::strtol(v, &end, 10);
      if (end != v && *end == '\0' && x >= 0) return int(x);
    }
  return std::nullopt;
}
}  // namespace

// Open MPI, MPICH/Hydra and Slurm spell the rank count differently.
std::optional<int> Communicator::launcherSize() {
  static const char* const names[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "SLURM_NTASKS", nullptr};
  return environmentInt(names);
}

std::optional<int> Communicator::launcherRank() {
  static const char* const names[] = {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK", "SLURM_PROCID", nullptr};
  return environmentInt(names);
}

#ifdef SHIZUKU_HAVE_MPI

namespace {
void finaliseMpi() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) MPI_Finalize();
}
template <class T> MPI_Datatype mpiType();
template <> MPI_Datatype mpiType<double>() { return MPI_DOUBLE; }
template <> MPI_Datatype mpiType<long>() { return MPI_LONG; }

template <class T> T reduce(T x, MPI_Op op, bool started) {
  if (!started) return x;
  T r{};
  MPI_Allreduce(&x, &r, 1, mpiType<T>(), op, MPI_COMM_WORLD);
  return r;
}
}  // namespace

// A communicator of its own for the failure barrier (everyRankFailed), so that it never
// matches a collective of the solver's on MPI_COMM_WORLD.
static MPI_Comm failureComm = MPI_COMM_NULL;

void Communicator::start(int* argc, char*** argv) {
  if (started_) return;
  int initialised = 0, provided = 0;
  MPI_Initialized(&initialised);
  if (!initialised) {
    MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
    std::atexit(finaliseMpi);
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm_dup(MPI_COMM_WORLD, &failureComm);
  started_ = true;
}

bool Communicator::everyRankFailed(double seconds) const {
  if (!started_) return true;
  MPI_Request request;
  MPI_Ibarrier(failureComm, &request);
  const double end = MPI_Wtime() + seconds;
  int done = 0;
  while (!done && MPI_Wtime() < end) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (!done) ::usleep(2000);
  }
  return done != 0;
}

double Communicator::sum(double x) const { return reduce(x, MPI_SUM, started_); }
long Communicator::sum(long x) const { return reduce(x, MPI_SUM, started_); }
double Communicator::max(double x) const { return reduce(x, MPI_MAX, started_); }
long Communicator::max(long x) const { return reduce(x, MPI_MAX, started_); }
double Communicator::min(double x) const { return reduce(x, MPI_MIN, started_); }

void Communicator::sumInPlace(std::vector<double>& v) const {
  if (started_ && !v.empty()) MPI_Allreduce(MPI_IN_PLACE, v.data(), int(v.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
}
void Communicator::sumInPlace(std::vector<long>& v) const {
  if (started_ && !v.empty()) MPI_Allreduce(MPI_IN_PLACE, v.data(), int(v.size()), MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
}

long Communicator::exclusivePrefixSum(long x) const {
  if (!started_) return 0;
  long r = 0;
  MPI_Exscan(&x, &r, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
  return rank_ == 0 ? 0 : r;  // MPI_Exscan leaves rank 0's result undefined
}

std::vector<double> Communicator::allGather(const std::vector<double>& mine) const {
  if (!started_) return mine;
  std::vector<double> all(mine.size() * std::size_t(size_));
  MPI_Allgather(mine.data(), int(mine.size()), MPI_DOUBLE, all.data(), int(mine.size()), MPI_DOUBLE, MPI_COMM_WORLD);
  return all;
}

std::vector<long> Communicator::allGather(long mine) const {
  if (!started_) return {mine};
  std::vector<long> all(static_cast<std::size_t>(size_));
  MPI_Allgather(&mine, 1, MPI_LONG, all.data(), 1, MPI_LONG, MPI_COMM_WORLD);
  return all;
}

// Every rank's length, and where each rank's piece starts in the concatenation; returns the total.
long Communicator::pieces(long mine, std::vector<int>& counts, std::vector<int>& starts) const {
  const std::vector<long> lengths = allGather(mine);
  counts.assign(static_cast<std::size_t>(size_), 0);
  starts.assign(static_cast<std::size_t>(size_), 0);
  long total = 0;
  for (int r = 0; r < size_; ++r) {
    counts[std::size_t(r)] = int(lengths[std::size_t(r)]);
    starts[std::size_t(r)] = int(total);
    total += lengths[std::size_t(r)];
  }
  return total;
}

std::vector<double> Communicator::allGatherVariable(const std::vector<double>& mine) const {
  if (!started_) return mine;
  std::vector<int> counts, starts;
  std::vector<double> all(static_cast<std::size_t>(pieces(long(mine.size()), counts, starts)));
  MPI_Allgatherv(mine.data(), int(mine.size()), MPI_DOUBLE, all.data(), counts.data(), starts.data(), MPI_DOUBLE,
                 MPI_COMM_WORLD);
  return all;
}

std::vector<char> Communicator::gatherToRoot(const std::vector<char>& mine) const {
  if (!started_) return mine;
  std::vector<int> counts, starts;
  const long total = pieces(long(mine.size()), counts, starts);
  std::vector<char> all(rank_ == 0 ? std::size_t(total) : 0);
  MPI_Gatherv(mine.data(), int(mine.size()), MPI_BYTE, all.data(), counts.data(), starts.data(), MPI_BYTE, 0,
              MPI_COMM_WORLD);
  return all;
}

std::vector<long> Communicator::exchangeCounts(const std::vector<long>& sendCounts) const {
  if (!started_) return sendCounts;
  std::vector<long> recv(static_cast<std::size_t>(size_));
  MPI_Alltoall(sendCounts.data(), 1, MPI_LONG, recv.data(), 1, MPI_LONG, MPI_COMM_WORLD);
  return recv;
}

void Communicator::exchange(const std::vector<int>& ranks, const std::vector<const char*>& send,
                            const std::vector<long>& sendBytes, const std::vector<char*>& recv,
                            const std::vector<long>& recvBytes, int tag) const {
  if (!started_ || ranks.empty()) return;
  // At most two requests per neighbour; a fixed-capacity buffer reused between calls.
  static thread_local std::vector<MPI_Request> requests;
  requests.clear();
  for (std::size_t k = 0; k < ranks.size(); ++k)
    if (recvBytes[k] > 0) {
      requests.emplace_back();
      MPI_Irecv(recv[k], int(recvBytes[k]), MPI_BYTE, ranks[k], tag, MPI_COMM_WORLD, &requests.back());
    }
  for (std::size_t k = 0; k < ranks.size(); ++k)
    if (sendBytes[k] > 0) {
      requests.emplace_back();
      MPI_Isend(send[k], int(sendBytes[k]), MPI_BYTE, ranks[k], tag, MPI_COMM_WORLD, &requests.back());
    }
  MPI_Waitall(int(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
}

void Communicator::barrier() const {
  if (started_) MPI_Barrier(MPI_COMM_WORLD);
}

std::string Communicator::firstMessage(const std::string& mine) const {
  if (!started_) return mine;
  const std::vector<long> lengths = allGather(long(mine.size()));
  int from = -1;
  for (int r = 0; r < size_ && from < 0; ++r)
    if (lengths[std::size_t(r)] > 0) from = r;
  if (from < 0) return "";
  std::string text = rank_ == from ? mine : std::string(std::size_t(lengths[std::size_t(from)]), ' ');
  MPI_Bcast(text.data(), int(text.size()), MPI_CHAR, from, MPI_COMM_WORLD);
  return text;
}

std::string Communicator::broadcast(const std::string& fromRoot) const {
  if (!started_) return fromRoot;
  long length = long(fromRoot.size());
  MPI_Bcast(&length, 1, MPI_LONG, 0, MPI_COMM_WORLD);
  std::string text = isRoot() ? fromRoot : std::string(std::size_t(length), ' ');
  MPI_Bcast(text.data(), int(text.size()), MPI_CHAR, 0, MPI_COMM_WORLD);
  return text;
}

void Communicator::abort(int status) const {
  if (started_) MPI_Abort(MPI_COMM_WORLD, status);
  std::exit(status);
}

#else  // a serial build: one rank, every operation the identity

void Communicator::start(int*, char***) {
  throw std::runtime_error("this shizuku was built without MPI (cmake -DSHIZUKU_MPI=OFF): it cannot run in parallel");
}
double Communicator::sum(double x) const { return x; }
long Communicator::sum(long x) const { return x; }
double Communicator::max(double x) const { return x; }
long Communicator::max(long x) const { return x; }
double Communicator::min(double x) const { return x; }
void Communicator::sumInPlace(std::vector<double>&) const {}
void Communicator::sumInPlace(std::vector<long>&) const {}
long Communicator::exclusivePrefixSum(long) const { return 0; }
std::vector<double> Communicator::allGather(const std::vector<double>& mine) const { return mine; }
std::vector<long> Communicator::allGather(long mine) const { return {mine}; }
std::vector<long> Communicator::exchangeCounts(const std::vector<long>& c) const { return c; }
std::vector<char> Communicator::gatherToRoot(const std::vector<char>& mine) const { return mine; }
std::vector<double> Communicator::allGatherVariable(const std::vector<double>& mine) const { return mine; }
void Communicator::exchange(const std::vector<int>&, const std::vector<const char*>&, const std::vector<long>&,
                            const std::vector<char*>&, const std::vector<long>&, int) const {}
void Communicator::barrier() const {}
std::string Communicator::firstMessage(const std::string& mine) const { return mine; }
std::string Communicator::broadcast(const std::string& fromRoot) const { return fromRoot; }
bool Communicator::everyRankFailed(double) const { return true; }
void Communicator::abort(int status) const { std::exit(status); }

#endif

void Communicator::allToAll(const char* send, const std::vector<long>& sendBytes, char* recv,
                            const std::vector<long>& recvBytes, int tag) const {
  std::vector<int> ranks;
  std::vector<const char*> sendPtr;
  std::vector<char*> recvPtr;
  std::vector<long> sendSize, recvSize;
  long out = 0, in = 0;
  for (int r = 0; r < size_; ++r) {
    const std::size_t k = std::size_t(r);
    if (r == rank_) {
      std::copy(send + out, send + out + sendBytes[k], recv + in);
    } else if (sendBytes[k] > 0 || recvBytes[k] > 0) {
      ranks.push_back(r);
      sendPtr.push_back(send + out);
      sendSize.push_back(sendBytes[k]);
      recvPtr.push_back(recv + in);
      recvSize.push_back(recvBytes[k]);
    }
    out += sendBytes[k];
    in += recvBytes[k];
  }
  exchange(ranks, sendPtr, sendSize, recvPtr, recvSize, tag);
}

}  // namespace shizuku
