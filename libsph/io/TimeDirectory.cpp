// Atomic time-directory write, exact read, listing: see TimeDirectory.hpp
// (docs/design.md 1.3).
#include "io/TimeDirectory.hpp"
#include "io/AsciiFields.hpp"
#include "io/FileOps.hpp"
#include "io/RestartChecks.hpp"
#include "io/TimeFile.hpp"
#include "io/TimeName.hpp"
#include "io/VtpFile.hpp"
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

// The entries a time directory written by Shizuku holds: particles.vtp,
// uniform/ and, with writeFormat ascii, one file per field (AsciiFields.hpp).
bool writtenByShizuku(const std::string& entry) {
  if (entry == "particles.vtp" || entry == "uniform" || entry == "position") return true;
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
  const bool vtp = fileops::isRegularFile(target + "/particles.vtp");
  if (!vtp || !fileops::isRegularFile(target + "/uniform/time"))
    return std::string("a folder of that name holds ") + (vtp ? "particles.vtp but no uniform/time" : "no particles.vtp") +
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

template <int D>
void writeTimeDirectory(const std::string& caseDir, const std::string& timeName, const ParticleSet<D>& p,
                        const TimeState& s, bool ascii) {
  if (!parseTimeName(timeName))
    throw std::runtime_error("cannot write time directory '" + caseDir + "/" + timeName +
                             "': '" + timeName + "' is not a time name");
  const std::string target = caseDir + "/" + timeName;
  checkReplaceable(target);
  const std::string tmp = target + ".tmp-" + std::to_string(::getpid());
  fileops::removeTree(tmp);  // a leftover of this same process id
  fileops::makeDirectory(tmp);
  try {
    fileops::makeDirectory(tmp + "/uniform");
    writeVtp<D>(tmp + "/particles.vtp", p, s);
    fileops::syncPath(tmp + "/particles.vtp");
    fileops::writeFileSynced(tmp + "/uniform/time", formatTimeFile(s, timeName));
    if (ascii) writeAsciiFields<D>(tmp, p, s.time);
    fileops::syncPath(tmp + "/uniform");
    fileops::syncPath(tmp);
    moveIntoPlace(tmp, target);
  } catch (...) {
    fileops::removeTree(tmp);
    throw;
  }
  fileops::syncPath(caseDir);
  removeStaleTemporaries(caseDir);
  writePvd(caseDir);
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

template <int D>
ParticleSet<D> readTimeDirectory(const std::string& caseDir, const std::string& timeName, TimeState& s) {
  const std::string dir = caseDir + "/" + timeName;
  if (!fileops::isDirectory(dir)) throw InputError("time directory '" + dir + "' does not exist");
  // The small text file first: a folder of the wrong time is refused before the particles are read.
  s = readTimeFile(dir + "/uniform/time", timeName);
  VtpTime vtpTime;
  ParticleSet<D> p = readVtp<D>(dir + "/particles.vtp", &vtpTime);
  checkTimeAgreement(dir + "/particles.vtp", vtpTime, dir + "/uniform/time", s);
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
    if (fileops::isDirectory(dir) && fileops::isRegularFile(dir + "/particles.vtp") &&
        fileops::isRegularFile(dir + "/uniform/time"))
      out.emplace_back(*t, name);
  }
  ::closedir(d);
  std::sort(out.begin(), out.end());
  return out;
}

template void writeTimeDirectory<2>(const std::string&, const std::string&, const ParticleSet<2>&, const TimeState&, bool);
template void writeTimeDirectory<3>(const std::string&, const std::string&, const ParticleSet<3>&, const TimeState&, bool);
template ParticleSet<2> readTimeDirectory<2>(const std::string&, const std::string&, TimeState&);
template ParticleSet<3> readTimeDirectory<3>(const std::string&, const std::string&, TimeState&);

}  // namespace shizuku
