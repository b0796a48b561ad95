// Wall-clock timers for the named stages of a time step (docs/design.md part 2:
// "each stage is timed by name"). Stages are registered once, in execution
// order, before the time loop; timing a stage inside the loop allocates nothing.
#pragma once
#include <chrono>
#include <string>
#include <vector>

namespace shizuku {

class StageTimers {
 public:
  // Index of a stage, registering it on first use (call before the time loop).
  int stage(const std::string& name) {
    for (std::size_t k = 0; k < names_.size(); ++k)
      if (names_[k] == name) return int(k);
    names_.push_back(name);
    total_.push_back(0);
    sinceWrite_.push_back(0);
    return int(names_.size() - 1);
  }
  void add(int k, double seconds) {
    if (k < 0) return;  // a stage that is not part of this run's pipeline
    total_[k] += seconds;
    sinceWrite_[k] += seconds;
  }
  const std::vector<std::string>& names() const { return names_; }
  const std::vector<double>& total() const { return total_; }
  const std::vector<double>& sinceLastSample() const { return sinceWrite_; }
  void resetSample() { for (auto& s : sinceWrite_) s = 0; }
  double sumTotal() const { double s = 0; for (double t : total_) s += t; return s; }

  // RAII scope: times the enclosing block into stage k (k < 0: not timed).
  class Scope {
   public:
    Scope(StageTimers& t, int k) : t_(t), k_(k), start_(std::chrono::steady_clock::now()) {}
    ~Scope() { t_.add(k_, std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count()); }
   private:
    StageTimers& t_;
    int k_;
    std::chrono::steady_clock::time_point start_;
  };

 private:
  std::vector<std::string> names_;
  std::vector<double> total_, sinceWrite_;
};

}  // namespace shizuku
