// Requests to stop a running case cleanly (write the current state, exit 0): the signals
// SIGINT, SIGTERM and SIGHUP, and `stopAt writeNow;` edited into the running case's
// system/controlDict (docs/design.md 1.3).
// Reads (system/controlDict, re-read when its modification time changes): stopAt.
#pragma once
#include <filesystem>
#include <string>

namespace shizuku {

// Run-wide signal flag: SIGINT, SIGTERM and SIGHUP set it; SIGXFSZ is ignored so that a
// file-size limit becomes a write error (EFBIG), not a kill.
void installStopSignalHandlers();
bool stopRequested();
int stopSignal();       // the last signal received, 0 if none
int stopSignalCount();  // how many stop signals have been received

class ControlDictWatch {
 public:
  explicit ControlDictWatch(const std::string& controlDictPath);
  // True once the file has changed and now says `stopAt writeNow;` (a file that cannot be
  // read is reported and ignored). Allocates only when the file has changed.
  bool writeNowRequested();

 private:
  std::filesystem::path path_;
  std::filesystem::file_time_type stamp_;
};

}  // namespace shizuku
