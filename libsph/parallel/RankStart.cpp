// Starting the ranks of a run: see RankStart.hpp.
#include "parallel/RankStart.hpp"
#include "core/Log.hpp"
#include "parallel/Communicator.hpp"

namespace shizuku {

std::optional<int> startRanks(bool parallel, const std::string& program, int* argc, char*** argv) {
  const int launched = Communicator::launcherSize().value_or(1);
  const bool root = Communicator::launcherRank().value_or(0) == 0;
  if (!parallel) {
    if (launched <= 1) return std::nullopt;
    if (root)
      Log::get().error(cat(program, " was started on ", launched, " ranks without -parallel: each would run the whole "
                           "case and write the same files. Add -parallel (mpirun -np ", launched, " ", program,
                           " -case DIR -parallel), or start one process."));
    return 1;
  }
  if (!Communicator::builtWithMpi()) {
    if (root)
      Log::get().error(cat("-parallel: this ", program, " was built without MPI (cmake -DSHIZUKU_MPI=OFF); rebuild "
                           "with MPI (etc/install-dependencies installs Open MPI, Zoltan and PETSc) or run without "
                           "-parallel"));
    return 1;
  }
  Communicator& world = Communicator::world();
  world.start(argc, argv);
  Log::get().silent = !world.isRoot();
  return std::nullopt;
}

}  // namespace shizuku
