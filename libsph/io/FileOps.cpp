// Crash-safe file-system steps: see FileOps.hpp (docs/design.md 1.3).
#include "io/FileOps.hpp"
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <stdexcept>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace shizuku {
namespace fileops {

namespace {
std::function<int(const std::string&)>& hook() {
  static std::function<int(const std::string&)> h;
  return h;
}
constexpr std::size_t kBufferSize = 1 << 20;
}  // namespace

void throwError(const std::string& what, const std::string& path, int err) {
  throw std::runtime_error(what + " '" + path + "': " + std::strerror(err));
}

void setFailureHook(std::function<int(const std::string&)> h) { hook() = std::move(h); }

void failurePoint(const std::string& stage, const std::string& path) {
  if (!hook()) return;
  int err = hook()(stage);
  if (err != 0) throwError("cannot " + stage, path, err);
}

void makeDirectory(const std::string& path) {
  failurePoint("create folder", path);
  if (::mkdir(path.c_str(), 0777) != 0) throwError("cannot create folder", path, errno);
}

void makeDirectories(const std::string& path) {
  if (path.empty() || isDirectory(path)) return;
  std::string parent = parentOf(path);
  if (!parent.empty() && parent != path) makeDirectories(parent);
  failurePoint("create folder", path);
  if (::mkdir(path.c_str(), 0777) != 0 && !(errno == EEXIST && isDirectory(path)))
    throwError("cannot create folder", path, errno);
}

bool isDirectory(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

bool isRegularFile(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

void syncPath(const std::string& path) {
  failurePoint("sync", path);
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throwError("cannot open for sync", path, errno);
  if (::fsync(fd) != 0) {
    int err = errno;
    // Some file systems refuse fsync on a folder; that is not a write failure.
    if (!(err == EINVAL && isDirectory(path))) {
      ::close(fd);
      throwError("cannot sync", path, err);
    }
  }
  ::close(fd);
}

void renamePath(const std::string& from, const std::string& to) {
  failurePoint("rename", to);
  if (std::rename(from.c_str(), to.c_str()) != 0)
    throwError("cannot rename '" + from + "' to", to, errno);
}

bool exchangePaths(const std::string& a, const std::string& b) {
  if (hook() && hook()("exchange") != 0) return false;  // tests: as if unsupported
  failurePoint("rename", b);
#if defined(SYS_renameat2)
  constexpr unsigned kExchange = 2;  // RENAME_EXCHANGE
  if (::syscall(SYS_renameat2, AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), kExchange) == 0) return true;
  int err = errno;
  if (err == EINVAL || err == ENOSYS || err == ENOTSUP || err == EPERM) return false;
  throwError("cannot exchange '" + a + "' with", b, err);
#else
  return false;
#endif
}

void removeTree(const std::string& path) noexcept {
  std::error_code ec;
  std::filesystem::remove_all(path, ec);
}

std::string parentOf(const std::string& path) {
  std::string p = path;
  while (p.size() > 1 && p.back() == '/') p.pop_back();
  auto slash = p.find_last_of('/');
  if (slash == std::string::npos) return "";
  if (slash == 0) return "/";
  return p.substr(0, slash);
}

SyncedFile::SyncedFile(const std::string& path) : path_(path) {
  failurePoint("create file", path);
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd_ < 0) throwError("cannot create file", path, errno);
  buffer_.reserve(kBufferSize);
}

SyncedFile::~SyncedFile() {
  if (fd_ >= 0) ::close(fd_);
}

void SyncedFile::write(const char* data, std::size_t n) {
  buffer_.append(data, n);
  if (buffer_.size() >= kBufferSize) flushBuffer();
}

void SyncedFile::flushBuffer() {
  failurePoint("write", path_);
  const char* p = buffer_.data();
  std::size_t left = buffer_.size();
  while (left > 0) {
    ssize_t w = ::write(fd_, p, left);
    if (w < 0) {
      if (errno == EINTR) continue;
      throwError("cannot write", path_, errno);
    }
    p += w;
    left -= std::size_t(w);
  }
  buffer_.clear();
}

void SyncedFile::close() {
  if (fd_ < 0) return;
  flushBuffer();
  failurePoint("sync", path_);
  if (::fsync(fd_) != 0) throwError("cannot sync", path_, errno);
  int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) throwError("cannot close", path_, errno);
}

void writeFileSynced(const std::string& path, const std::string& content) {
  SyncedFile f(path);
  f.write(content);
  f.close();
}

}  // namespace fileops
}  // namespace shizuku
