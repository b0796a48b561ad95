// Function object `timing`: stage wall times and throughput; see Timing.hpp.
#include "functionObjects/Timing.hpp"
#include "core/Log.hpp"
#include <limits>

namespace shizuku {

template <int D>
Timing<D>::Timing(const std::string& name, const Dictionary& dict) : SampledFunctionObject<D>(name, "timing", dict) {}

template <int D>
void Timing<D>::writeHeader() {
  std::vector<std::string> names{"time"}, units{"s"};
  for (const auto& n : names_) {
    names.push_back(n);
    units.push_back("s");
  }
  names.push_back("particleStepsPerSecond");
  units.push_back("1/s");
  this->file_->columns(names, units);
}

template <int D>
void Timing<D>::open(const FlowState<D>&, const RunInfo& info) {
  if (!info.timers) {
    shizuku::info("timing '" + this->name() + "': no stage timers in post-processing; it writes nothing");
    return;
  }
  this->file_.emplace(this->makeFile(info, "timing.dat"));
  this->file_->comment(
      "wall-clock seconds spent in each stage of the step since the previous row, and\n"
      "particleStepsPerSecond = fluid particles x steps / wall seconds over the same interval");
  names_ = info.timers->names();
  writeHeader();
}

template <int D>
void Timing<D>::sample(const FlowState<D>& s, const RunInfo& info) {
  if (!info.timers || !this->file_) return;
  const auto& total = info.timers->total();
  if (info.timers->names() != names_) {  // a stage registered late: new header, new baseline
    names_ = info.timers->names();
    this->file_->comment("stages changed: new columns below");
    writeHeader();
    lastTotal_.resize(total.size(), 0.0);
  }
  if (haveLast_ && info.particleSteps > lastParticleSteps_) {
    row_.clear();
    for (std::size_t k = 0; k < total.size(); ++k) row_.push_back(total[k] - lastTotal_[k]);
    const double wall = info.wallSeconds - lastWall_;
    row_.push_back(wall > 0 ? (info.particleSteps - lastParticleSteps_) / wall
                            : std::numeric_limits<double>::quiet_NaN());
    this->file_->row(s.time, row_);
  } else if (haveLast_) {
    return;  // no step since the previous sample: keep the baseline
  }
  lastTotal_ = total;
  lastWall_ = info.wallSeconds;
  lastParticleSteps_ = info.particleSteps;
  haveLast_ = true;
}

template class Timing<2>;
template class Timing<3>;

}  // namespace shizuku
