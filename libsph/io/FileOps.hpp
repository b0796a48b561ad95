// File-system steps of crash-safe output (docs/design.md 1.3: a crash never leaves
// a half-written time directory): create folders, write and fsync files, fsync
// folders, rename or atomically exchange paths, remove trees. Every failure
// throws std::runtime_error naming the operation, the path and strerror.
// A test-only failure hook can make any named stage fail as if the system
// call had returned an error, to exercise the clean-up paths.
// Dictionary keys read: none.
#pragma once
#include <cstddef>
#include <functional>
#include <string>

namespace shizuku {
namespace fileops {

[[noreturn]] void throwError(const std::string& what, const std::string& path, int err);

// Calls the failure hook for `stage` (if any is set); if it returns a
// non-zero errno value, throws as a failing system call on `path` would.
void failurePoint(const std::string& stage, const std::string& path);
// Test hook: stage -> errno to fail with (0: go on). Pass nullptr to clear.
void setFailureHook(std::function<int(const std::string& stage)> hook);

void makeDirectory(const std::string& path);          // one level; EEXIST is an error
void makeDirectories(const std::string& path);        // mkdir -p
bool isDirectory(const std::string& path);
bool isRegularFile(const std::string& path);
void syncPath(const std::string& path);               // fsync a file or a folder
void renamePath(const std::string& from, const std::string& to);
// Atomically swap two existing paths (renameat2 RENAME_EXCHANGE); false if the
// file system does not support it (nothing changed then).
bool exchangePaths(const std::string& a, const std::string& b);
void removeTree(const std::string& path) noexcept;    // rm -rf, errors ignored
std::string parentOf(const std::string& path);

// A file written in pieces and made durable: open truncates, close() fsyncs.
// The destructor closes without fsync (after an error, the caller deletes it).
class SyncedFile {
 public:
  explicit SyncedFile(const std::string& path);
  ~SyncedFile();
  SyncedFile(const SyncedFile&) = delete;
  SyncedFile& operator=(const SyncedFile&) = delete;
  void write(const char* data, std::size_t n);
  void write(const std::string& s) { write(s.data(), s.size()); }
  void close();  // flush, fsync, close; throws on failure
  const std::string& path() const { return path_; }

 private:
  void flushBuffer();
  std::string path_;
  int fd_ = -1;
  std::string buffer_;
};

void writeFileSynced(const std::string& path, const std::string& content);

}  // namespace fileops
}  // namespace shizuku
