// Signals and `stopAt writeNow`: see StopRequests.hpp.
#include "isph/StopRequests.hpp"
#include "core/Dictionary.hpp"
#include "core/Log.hpp"
#include <atomic>
#include <csignal>

namespace shizuku {

namespace {
std::atomic<int> receivedSignal{0};
std::atomic<int> signalCount{0};
extern "C" void onStopSignal(int sig) {
  receivedSignal = sig;
  ++signalCount;
}
}  // namespace

void installStopSignalHandlers() {
  std::signal(SIGINT, onStopSignal);
  std::signal(SIGTERM, onStopSignal);
  std::signal(SIGHUP, onStopSignal);
  std::signal(SIGXFSZ, SIG_IGN);
}
bool stopRequested() { return receivedSignal != 0; }
int stopSignal() { return receivedSignal; }
int stopSignalCount() { return signalCount; }

ControlDictWatch::ControlDictWatch(const std::string& controlDictPath)
    : path_(controlDictPath), stamp_(std::filesystem::last_write_time(path_)) {}

bool ControlDictWatch::writeNowRequested() {
  std::error_code ec;
  const auto stamp = std::filesystem::last_write_time(path_, ec);
  if (ec || stamp == stamp_) return false;
  stamp_ = stamp;
  try {
    const Dictionary d = Dictionary::fromFile(path_.string());
    return d.getWordOr("stopAt", "endTime") == "writeNow";
  } catch (const InputError& e) {
    Log::get().warning(cat("system/controlDict changed but could not be read (ignored): ", e.what()));
    return false;
  }
}

}  // namespace shizuku
