// Time directories: what a run writes and a restart reads (docs/design.md 1.2, 1.3).
//
//   <case>/<time>/particles.vtp   every particle field (VtpFile.hpp); or, from a run on
//                                 several ranks, particles.pvtp naming one piece per rank,
//                                 particles_<k>.vtp (VtpPieces.hpp)
//   <case>/<time>/uniform/time    time, step index, dt state (TimeFile.hpp)
//   <case>/<time>/<field>         with ascii: one text file per field (AsciiFields.hpp)
//   <case>/particles.pvd          the series, for ParaView (Pvd.cpp)
//
// Writes are atomic: everything goes to <case>/<time>.tmp-<pid>/, is fsynced,
// then swapped into place (rename, or an atomic exchange when <time> exists),
// so a crash leaves either the old or the new directory, never half of one
// (plus, after a SIGKILL, a *.tmp-<pid> leftover that is never listed and is
// removed by the next successful write).
// The pvd is rewritten through a temporary file and a rename as well.
// Dictionary keys read: none (the solver passes writeFormat as `ascii`).
#pragma once
#include "core/FluidBalance.hpp"
#include "particles/ParticleSet.hpp"
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace shizuku {

struct TimeState {
  double time = 0;     // s
  long step = 0;       // time-step index
  double deltaT = 0;   // s, the next step's dt
  double deltaT0 = 0;  // s, the previous step's dt
  std::string note;    // free text (e.g. "written after a NumericalError")
  FluidBalance balance;    // removed, released and captured fluid so far (core/FluidBalance.hpp)
};

// Throws std::runtime_error naming the path and strerror on any failure; an
// existing time directory of the same or any other name is then untouched.
// An existing <time> is replaced only when whyNotReplaceable allows it:
// anything else is an error and stays as it is.
template <int D>
void writeTimeDirectory(const std::string& caseDir, const std::string& timeName,
                        const ParticleSet<D>& p, const TimeState& s, bool ascii);

// Why <target> (a time directory's path) must not be replaced by a write, or ""
// when it may be: it may when absent, an empty folder, or a complete time
// directory (particles.vtp or particles.pvtp, and uniform/time) holding only what
// Shizuku writes there (uniform/time, the pieces, the ascii field files). A file, a folder without both
// files, or one holding a file of the user's is the user's and stays.
std::string whyNotReplaceable(const std::string& target);

// Reads <case>/<timeName> back exactly. With parts > 1 only share `part` of it: of a
// pvtp's n pieces those with n part/parts <= k < n (part+1)/parts, of a single
// particles.vtp its particles N part/parts .. N (part+1)/parts - 1 (docs/parallel.md 7).
// The whole of a pvtp (parts = 1) is its pieces joined, sorted by id and checked as one
// set (ids unique over the pieces; the pieces' constants equal). Throws InputError naming the file on
// a missing or corrupt file, one written by a run of another dimension, or
// values a run cannot start from (VtpFile.hpp, RestartChecks.hpp), and when
// the folder's name, uniform/time and the vtp's time fields disagree.
template <int D>
ParticleSet<D> readTimeDirectory(const std::string& caseDir, const std::string& timeName, TimeState& s,
                                 int part = 0, int parts = 1);

// The particle file of a time directory: <dir>/particles.vtp, else <dir>/particles.pvtp,
// else "".
std::string particleFileOf(const std::string& timeDir);

// A time directory written by several processes at once (docs/parallel.md 7), with the
// atomicity of writeTimeDirectory: the root calls beginPieceWrite (the replace check,
// <time>.tmp-<pid>/uniform made), every process writes its piece into `folder`, and the
// root calls finishPieceWrite (particles.pvtp, uniform/time, the ascii fields when given,
// sync, swap into place, pvd), or abandonPieceWrite after any process failed. Each throws
// std::runtime_error naming the path.
struct PieceWrite {
  std::string caseDir, timeName, target, folder;
};
PieceWrite beginPieceWrite(const std::string& caseDir, const std::string& timeName);
template <int D>
void writePiece(const std::string& folder, int k, const ParticleSet<D>& p, std::size_t count, const TimeState& s);
template <int D>
void finishPieceWrite(const PieceWrite& w, int pieces, const ParticleSet<D>& fieldsOf, const TimeState& s,
                      const ParticleSet<D>* ascii);
void abandonPieceWrite(const PieceWrite& w);

// Complete time directories (name parses as a number, holds particles.vtp or
// particles.pvtp, and uniform/time), sorted by time; *.tmp-* folders are ignored. A missing case
// folder has none.
std::vector<std::pair<double, std::string>> listTimeDirectories(const std::string& caseDir);

// Remove <name>.tmp-<pid> and <name>.old-<pid> entries of the case folder
// left by writers that were killed (no process <pid> exists any more); a
// running writer's entries stay. writeTimeDirectory calls it after each
// successful write, so a restarted run sweeps what a SIGKILL left. Returns
// the names removed.
std::vector<std::string> removeStaleTemporaries(const std::string& caseDir);

// Rebuild <case>/particles.pvd from listTimeDirectories (atomic replace).
void writePvd(const std::string& caseDir);

namespace detail {
// Tests only: called at each file-system stage of a write ("create folder",
// "create file", "write", "sync", "rename", "write vtp"); a non-zero return is
// an errno value to fail with there. A non-zero return for "exchange" makes
// the atomic exchange look unsupported (the two-rename fallback runs).
// nullptr clears it.
void setWriteFailureHook(std::function<int(const std::string& stage)> hook);
}  // namespace detail

}  // namespace shizuku
