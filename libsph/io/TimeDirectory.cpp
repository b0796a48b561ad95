// Atomic time-directory write, exact read, listing: see TimeDirectory.hpp
// (docs/design.md 1.3).
#include "io/TimeDirectory.hpp"
#include "io/AsciiFields.hpp"
#include "io/FileOps.hpp"
#include "io/RestartChecks.hpp"
#include "io/TimeFile.hpp"
#include "io/TimeName.hpp"
#include "io/VtpFile.hpp"
#include "io/VtpLayout.hpp"
#include "io/VtpPieces.hpp"
#include <algorithm>
#include <cstdio>
#include <cerrno>
#include <csignal>
#include <dirent.h>
#include <filesystem>
#include <unistd.h>

namespace shizuku {

namespace detail {
void setWriteFailureHook(std::function<int(const std::string&)> hook) { fileops::setFailureHook(std::move(hook)); }
}  // namespace detail

namespace {

// Put the finished folder `tmp` at `target`, replacing whatever is there.
void moveIntoPlace(const std::string& tmp, const std::string& target) {
  if (!fileops::isDirectory(target) && !fileops::isRegularFile(target)) {
    fileops::renamePath(tmp, target);
    return;
  }
  if (fileops::exchangePaths(tmp, target)) {  // atomic: tmp now holds the old one
    fileops::removeTree(tmp);
    return;
  }
  // No atomic exchange on this file system: move the old one aside first.
  const std::string old = target + ".old-" + std::to_string(::getpid());
  fileops::removeTree(old);
  fileops::renamePath(target, old);
  try {
    fileops::renamePath(tmp, target);
  } catch (...) {
    std::rename(old.c_str(), target.c_str());  // put the old one back
    throw;
  }
  fileops::removeTree(old);
}

// The entries a time directory written by Shizuku holds: particles.vtp (or
// particles.pvtp and its pieces), uniform/ and, with writeFormat ascii, one file per
// field (AsciiFields.hpp).
bool writtenByShizuku(const std::string& entry) {
  if (entry == "particles.vtp" || entry == "particles.pvtp" || isPieceFileName(entry) || entry == "uniform" ||
      entry == "position")
    return true;
  bool field = false;
  ParticleSet<2>().forEachField([&](const char* name, const auto&) { field = field || entry == name; });
  return field;
}

void checkReplaceable(const std::string& target) {
  const std::string why = whyNotReplaceable(target);
  if (!why.empty()) throw std::runtime_error("cannot write time directory '" + target + "': " + why);
}

}  // namespace

std::string whyNotReplaceable(const std::string& target) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(target, ec);
  if (ec || !fs::exists(st)) return "";
  if (!fs::is_directory(st)) return "a file that is not a folder has that name; move it away";
  if (fs::is_empty(target, ec)) return "";
  const std::string particles = particleFileOf(target);
  const bool vtp = !particles.empty();
  if (!vtp || !fileops::isRegularFile(target + "/uniform/time"))
    return std::string("a folder of that name holds ") +
           (vtp ? particles.substr(particles.rfind('/') + 1) + " but no uniform/time"
                : std::string("no particles.vtp (nor particles.pvtp)")) +
           ", so it is not a complete time directory written by Shizuku, and writing would delete what it holds; "
           "move it away (or, to start from its particles, give it the uniform/time of a Shizuku time directory)";
  std::string foreign;
  for (const auto& e : fs::directory_iterator(target, ec))
    if (!writtenByShizuku(e.path().filename().string())) foreign += (foreign.empty() ? "" : ", ") + e.path().filename().string();
  for (const auto& e : fs::directory_iterator(target + "/uniform", ec))
    if (e.path().filename() != "time") foreign += (foreign.empty() ? "uniform/" : ", uniform/") + e.path().filename().string();
  if (!foreign.empty())
    return "the time directory holds files Shizuku does not write (" + foreign +
           "), which writing it would delete; move them away";
  return "";
}

PieceWrite beginPieceWrite(const std::string& caseDir, const std::string& timeName) {
  if (!parseTimeName(timeName))
    throw std::runtime_error("cannot write time directory '" + caseDir + "/" + timeName +
                             "': '" + timeName + "' is not a time name");
  PieceWrite w;
  w.caseDir = caseDir;
  w.timeName = timeName;
  w.target = caseDir + "/" + timeName;
  checkReplaceable(w.target);
  w.folder = w.target + ".tmp-" + std::to_string(::getpid());
  fileops::removeTree(w.folder);  // a leftover of this same process id
  fileops::makeDirectory(w.folder);
  try {
    fileops::makeDirectory(w.folder + "/uniform");
  } catch (...) {
    fileops::removeTree(w.folder);
    throw;
  }
  return w;
}

void abandonPieceWrite(const PieceWrite& w) { fileops::removeTree(w.folder); }

namespace {

// uniform/time and the ascii fields into the folder, then the folder into place and the
// series updated.
template <int D>
void completeWrite(const PieceWrite& w, const TimeState& s, const ParticleSet<D>* ascii) {
  try {
    fileops::writeFileSynced(w.folder + "/uniform/time", formatTimeFile(s, w.timeName));
    if (ascii) writeAsciiFields<D>(w.folder, *ascii, s.time);
    fileops::syncPath(w.folder + "/uniform");
    fileops::syncPath(w.folder);
    moveIntoPlace(w.folder, w.target);
  } catch (...) {
    abandonPieceWrite(w);
    throw;
  }
  fileops::syncPath(w.caseDir);
  removeStaleTemporaries(w.caseDir);
  writePvd(w.caseDir);
}

}  // namespace

template <int D>
void writePiece(const std::string& folder, int k, const ParticleSet<D>& p, std::size_t count, const TimeState& s) {
  const std::string path = folder + "/" + pieceFileName(k);
  writeVtp<D>(path, p, s, count);
  fileops::syncPath(path);
}

template <int D>
void finishPieceWrite(const PieceWrite& w, int pieces, const ParticleSet<D>& fieldsOf, const TimeState& s,
                      const ParticleSet<D>* ascii) {
  try {
    writePvtp<D>(w.folder + "/particles.pvtp", fieldsOf, pieces);
  } catch (...) {
    abandonPieceWrite(w);
    throw;
  }
  completeWrite<D>(w, s, ascii);
}

template <int D>
void writeTimeDirectory(const std::string& caseDir, const std::string& timeName, const ParticleSet<D>& p,
                        const TimeState& s, bool ascii) {
  const PieceWrite w = beginPieceWrite(caseDir, timeName);
  try {
    writeVtp<D>(w.folder + "/particles.vtp", p, s);
    fileops::syncPath(w.folder + "/particles.vtp");
  } catch (...) {
    abandonPieceWrite(w);
    throw;
  }
  completeWrite<D>(w, s, ascii ? &p : nullptr);
}

std::vector<std::string> removeStaleTemporaries(const std::string& caseDir) {
  std::vector<std::string> removed;
  DIR* d = ::opendir(caseDir.c_str());
  if (!d) return removed;
  std::vector<std::string> stale;
  while (dirent* e = ::readdir(d)) {
    const std::string name = e->d_name;
    std::size_t at = name.rfind(".tmp-");
    if (at == std::string::npos) at = name.rfind(".old-");
    if (at == std::string::npos || at == 0) continue;
    const std::string digits = name.substr(at + 5);
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    const long pid = std::stol(digits);
    // Only leftovers of processes that no longer exist: another writer still
    // running (or a reused pid) keeps its folder.
    if (pid == long(::getpid()) || pid <= 0 || !(::kill(pid_t(pid), 0) != 0 && errno == ESRCH)) continue;
    stale.push_back(name);
  }
  ::closedir(d);
  for (const auto& name : stale) {
    fileops::removeTree(caseDir + "/" + name);
    removed.push_back(name);
  }
  return removed;
}

std::string particleFileOf(const std::string& timeDir) {
  for (const char* name : {"/particles.vtp", "/particles.pvtp"})
    if (fileops::isRegularFile(timeDir + name)) return timeDir + name;
  return "";
}

namespace {

// Pieces first .. last - 1 of a pvtp joined (each checked, and its time fields against
// uniform/time), sorted by id when there are several.
template <int D>
ParticleSet<D> readPieces(const std::string& dir, const std::vector<std::string>& pieces, std::size_t first,
                          std::size_t last, const TimeState& s) {
  ParticleSet<D> whole;
  for (std::size_t k = first; k < last; ++k) {
    const std::string path = dir + "/" + pieces[k];
    VtpTime vtpTime;
    const ParticleSet<D> piece = readVtp<D>(path, &vtpTime);
    checkTimeAgreement(path, vtpTime, dir + "/uniform/time", s);
    if (k == first) {
      whole.mass = piece.mass;
      whole.rho0 = piece.rho0;
      whole.spacing = piece.spacing;
    } else if (piece.mass != whole.mass || piece.rho0 != whole.rho0 || piece.spacing != whole.spacing) {
      corruptVtp(path, "its mass, rho0 or spacing differ from those of " + pieces[first]);
    }
    if (!whole.append(piece)) corruptVtp(path, "it holds other point arrays than " + pieces[first]);
    whole.nextId = std::max(whole.nextId, piece.nextId);
  }
  // One piece keeps its order (a rank reading its own piece back continues exactly);
  // pieces joined are sorted by id, whatever pieces a share holds.
  if (last - first > 1) whole.sortById();
  return whole;
}

}  // namespace

template <int D>
ParticleSet<D> readTimeDirectory(const std::string& caseDir, const std::string& timeName, TimeState& s, int part,
                                 int parts) {
  const std::string dir = caseDir + "/" + timeName;
  if (!fileops::isDirectory(dir)) throw InputError("time directory '" + dir + "' does not exist");
  // The small text file first: a folder of the wrong time is refused before the particles are read.
  s = readTimeFile(dir + "/uniform/time", timeName);
  const std::string pvtp = dir + "/particles.pvtp";
  if (fileops::isRegularFile(dir + "/particles.vtp") || !fileops::isRegularFile(pvtp)) {
    VtpTime vtpTime;
    ParticleSet<D> p = readVtp<D>(dir + "/particles.vtp", &vtpTime);
    checkTimeAgreement(dir + "/particles.vtp", vtpTime, dir + "/uniform/time", s);
    const std::size_t n = p.size();
    if (parts > 1) p.keepRange(n * std::size_t(part) / std::size_t(parts), n * std::size_t(part + 1) / std::size_t(parts));
    return p;
  }
  const std::vector<std::string> pieces = readPvtpPieces(pvtp);
  const std::size_t n = pieces.size();
  ParticleSet<D> p = readPieces<D>(dir, pieces, n * std::size_t(part) / std::size_t(parts),
                                   n * std::size_t(part + 1) / std::size_t(parts), s);
  if (parts == 1) {  // the whole set: ids unique over the pieces
    ParticleCounts stated = countParticles(p);
    checkParticleValues<D>(pvtp, p, stated);
  }
  return p;
}

std::vector<std::pair<double, std::string>> listTimeDirectories(const std::string& caseDir) {
  std::vector<std::pair<double, std::string>> out;
  DIR* d = ::opendir(caseDir.c_str());
  if (!d) return out;
  while (dirent* e = ::readdir(d)) {
    std::string name = e->d_name;
    auto t = parseTimeName(name);  // rejects "x.tmp-123", "system", ...
    if (!t) continue;
    const std::string dir = caseDir + "/" + name;
    if (fileops::isDirectory(dir) && !particleFileOf(dir).empty() && fileops::isRegularFile(dir + "/uniform/time"))
      out.emplace_back(*t, name);
  }
  ::closedir(d);
  std::sort(out.begin(), out.end());
  return out;
}

template void writeTimeDirectory<2>(const std::string&, const std::string&, const ParticleSet<2>&, const TimeState&, bool);
template void writeTimeDirectory<3>(const std::string&, const std::string&, const ParticleSet<3>&, const TimeState&, bool);
template ParticleSet<2> readTimeDirectory<2>(const std::string&, const std::string&, TimeState&, int, int);
template ParticleSet<3> readTimeDirectory<3>(const std::string&, const std::string&, TimeState&, int, int);
template void writePiece<2>(const std::string&, int, const ParticleSet<2>&, std::size_t, const TimeState&);
template void writePiece<3>(const std::string&, int, const ParticleSet<3>&, std::size_t, const TimeState&);
template void finishPieceWrite<2>(const PieceWrite&, int, const ParticleSet<2>&, const TimeState&, const ParticleSet<2>*);
template void finishPieceWrite<3>(const PieceWrite&, int, const ParticleSet<3>&, const TimeState&, const ParticleSet<3>*);

}  // namespace shizuku
