// The ranks of a distributed run and the collective operations the solver needs
// (docs/parallel.md 1): sums, extrema and prefix sums across ranks, gathers, and the
// exchange of byte buffers with a few neighbour ranks (halo updates, migration).
// A serial run (no `-parallel`) never starts MPI: world() is then one rank and every
// operation is the identity, so serial code calls the same functions at no cost.
// Reads no dictionary keys.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace shizuku {

class Communicator {
 public:
  static Communicator& world();

  // Start MPI for a `-parallel` run (MPI_Init_thread, OpenMP threads funnelled through the
  // main thread); MPI is finalised at exit. Throws std::runtime_error in a build without MPI.
  void start(int* argc, char*** argv);
  bool started() const { return started_; }
  int rank() const { return rank_; }
  int size() const { return size_; }
  bool isRoot() const { return rank_ == 0; }
  bool isParallel() const { return size_ > 1; }

  double sum(double x) const;
  long sum(long x) const;
  double max(double x) const;
  long max(long x) const;
  double min(double x) const;
  bool any(bool x) const { return max(long(x)) != 0; }
  // Element-wise sum of v over all ranks, in place (every rank gets the result).
  void sumInPlace(std::vector<double>& v) const;
  void sumInPlace(std::vector<long>& v) const;
  // sum of x over the ranks below this one.
  long exclusivePrefixSum(long x) const;
  // Every rank's `mine` (equal lengths), concatenated in rank order.
  std::vector<double> allGather(const std::vector<double>& mine) const;
  std::vector<long> allGather(long mine) const;
  // Every rank's `mine` (any lengths), concatenated in rank order.
  std::vector<double> allGatherVariable(const std::vector<double>& mine) const;
  // Every rank's bytes, concatenated in rank order on rank 0 (empty elsewhere).
  std::vector<char> gatherToRoot(const std::vector<char>& mine) const;
  // The number of bytes each rank sends to every other (one alltoall of counts).
  std::vector<long> exchangeCounts(const std::vector<long>& sendCounts) const;
  // Send send[k] (sendBytes[k] bytes) to ranks[k] and receive recvBytes[k] bytes from
  // ranks[k] into recv[k], for every k (non-blocking point to point, then wait).
  void exchange(const std::vector<int>& ranks, const std::vector<const char*>& send,
                const std::vector<long>& sendBytes, const std::vector<char*>& recv,
                const std::vector<long>& recvBytes, int tag) const;
  // Bytes to every rank at once: rank r's part of `send` is sendBytes[r] bytes, the parts
  // one after the other in rank order; recv takes recvBytes[r] from each rank likewise
  // (recvBytes from exchangeCounts). This rank's own part is copied. Collective.
  void allToAll(const char* send, const std::vector<long>& sendBytes, char* recv,
                const std::vector<long>& recvBytes, int tag) const;
  // The message of the lowest rank whose message is not empty ("" when all are): a
  // failure one rank found, made every rank's, so that all stop together. Collective.
  std::string firstMessage(const std::string& mine) const;
  // Rank 0's text on every rank. Collective.
  std::string broadcast(const std::string& fromRoot) const;
  void barrier() const;
  // Called by a rank that met an error it cannot go on from: true when every rank called
  // it within `seconds` (the error was met by all, which then exit together), false when
  // some rank did not (it waits elsewhere, and only abort() stops the run).
  bool everyRankFailed(double seconds) const;
  // Stop every rank at once (a rank that cannot go on while the others wait).
  [[noreturn]] void abort(int status) const;

  // The rank count the launcher (mpirun) started, read from its environment without
  // starting MPI; nothing when the program was started without a launcher.
  static std::optional<int> launcherSize();
  static std::optional<int> launcherRank();
  static bool builtWithMpi();

 private:
  Communicator() = default;
  long pieces(long mine, std::vector<int>& counts, std::vector<int>& starts) const;
  bool started_ = false;
  int rank_ = 0, size_ = 1;
};

}  // namespace shizuku
