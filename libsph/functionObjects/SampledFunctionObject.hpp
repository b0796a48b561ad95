// Common part of every function object: name, type, the sampling schedule
// (SampleControl.hpp) and the output files' location. A concrete object
// implements open() (files and headers) and sample() (one row per file).
// In post-processing (RunInfo::postProcessing) every call samples.
// Reads (controlDict functions/<name>): type (by the factory), writeControl, writeInterval.
#pragma once
#include "core/Log.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "functionObjects/SampleControl.hpp"
#include "io/PostProcessingFile.hpp"
#include <optional>

namespace shizuku {

template <int D>
class SampledFunctionObject : public FunctionObject<D> {
 public:
  SampledFunctionObject(const std::string& name, const std::string& type, const Dictionary& dict)
      : name_(name), type_(type), control_(SampleControl::read(dict)) {}
  std::string name() const override { return name_; }
  std::string type() const override { return type_; }
  std::string describe() const override { return type_ + " '" + name_ + "' " + control_.describe() + details(); }
  void start(const FlowState<D>& s, const RunInfo& info) override { open(s, info); }
  void execute(const FlowState<D>& s, const RunInfo& info) override {
    if (control_.due(s.time, s.dt, s.step, info.isWriteTime) || info.postProcessing) sample(s, info);
  }
  const SampleControl& control() const { return control_; }

 protected:
  virtual std::string details() const { return ""; }
  virtual void open(const FlowState<D>& s, const RunInfo& info) = 0;
  virtual void sample(const FlowState<D>& s, const RunInfo& info) = 0;
  // postProcessing/<name>/<startTime>/<fileName>
  PostProcessingFile makeFile(const RunInfo& info, const std::string& fileName) const {
    return PostProcessingFile(info.caseDir, name_, info.startTimeName, fileName);
  }
  std::optional<PostProcessingFile> file_;  // the object's time-series file, opened by open()

 private:
  std::string name_, type_;
  SampleControl control_;
};

// SI units of a few quantities in D dimensions (2D quantities are per unit depth).
namespace units {
inline std::string volume(int D) { return D == 2 ? "m^2" : "m^3"; }
inline std::string mass(int D) { return D == 2 ? "kg/m" : "kg"; }
inline std::string energy(int D) { return D == 2 ? "J/m" : "J"; }
inline std::string momentum(int D) { return D == 2 ? "kg/s" : "kg*m/s"; }
inline std::string angularMomentum(int D) { return D == 2 ? "kg*m/s" : "kg*m^2/s"; }
}  // namespace units

}  // namespace shizuku
