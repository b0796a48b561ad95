// The function-object factory (docs/design.md 1.3): one object per entry of the
// controlDict `functions { <name> { type <type>; ... } }`, built only when listed.
// Reads (controlDict): functions { <name> { type probes|densityError|conservation|fluidExtent|flux|wallPressure|waterLevel|waveGauge|timing; ... } }
#include "core/Parameter.hpp"
#include "functionObjects/Conservation.hpp"
#include "functionObjects/DensityError.hpp"
#include "functionObjects/FluidExtent.hpp"
#include "functionObjects/Flux.hpp"
#include "functionObjects/FunctionObjectFactory.hpp"
#include "functionObjects/Probes.hpp"
#include "functionObjects/Timing.hpp"
#include "functionObjects/WallPressure.hpp"
#include "functionObjects/WaterLevel.hpp"
#include "functionObjects/WaveGauge.hpp"
#include <set>

namespace shizuku {

std::vector<std::string> functionObjectTypes() {
  return {"probes", "densityError", "conservation", "fluidExtent", "flux", "wallPressure", "waterLevel", "waveGauge", "timing"};
}

namespace {
// The scope is shared with the sampling keys of SampleControl.cpp.
const ParameterGroup functionObject("system/controlDict: functions/<name>",
    "Keys of every function object: its type and when it samples.");
const OptionParameter typeParameter = functionObject.option("type", functionObjectTypes(), "what the object computes").required();
}  // namespace

template <int D>
std::unique_ptr<FunctionObject<D>> createFunctionObject(const std::string& name, const Dictionary& dict,
                                                        const std::vector<WallBox<D>>& walls, const Vec<D>& gravity) {
  const std::string type = typeParameter.read(dict);
  if (type == "probes") return std::make_unique<Probes<D>>(name, dict);
  if (type == "densityError") return std::make_unique<DensityError<D>>(name, dict);
  if (type == "conservation") return std::make_unique<Conservation<D>>(name, dict);
  if (type == "fluidExtent") return std::make_unique<FluidExtent<D>>(name, dict);
  if (type == "flux") return std::make_unique<Flux<D>>(name, dict);
  if (type == "wallPressure") return std::make_unique<WallPressure<D>>(name, dict, walls, gravity);
  if (type == "waterLevel") return std::make_unique<WaterLevel<D>>(name, dict);
  if (type == "waveGauge") return std::make_unique<WaveGauge<D>>(name, dict);
  return std::make_unique<Timing<D>>(name, dict);
}

template <int D>
std::vector<std::unique_ptr<FunctionObject<D>>> createFunctionObjects(const Dictionary* functions,
                                                                      const std::vector<WallBox<D>>& walls,
                                                                      const Vec<D>& gravity) {
  std::vector<std::unique_ptr<FunctionObject<D>>> list;
  if (!functions) return list;
  for (const auto& name : functions->keys()) {
    if (!functions->isDict(name))
      functions->error(name, "a function object is a dictionary { type <type>; ... } (types: probes densityError "
                             "conservation fluidExtent flux wallPressure waterLevel waveGauge timing)");
    if (name.find('/') != std::string::npos || name == "." || name == "..")
      functions->error(name, "a function-object name names a folder: no '/', '.' or '..'");
    list.push_back(createFunctionObject<D>(name, functions->subDict(name), walls, gravity));
  }
  return list;
}

template std::unique_ptr<FunctionObject<2>> createFunctionObject<2>(const std::string&, const Dictionary&,
                                                                   const std::vector<WallBox<2>>&, const Vec<2>&);
template std::unique_ptr<FunctionObject<3>> createFunctionObject<3>(const std::string&, const Dictionary&,
                                                                   const std::vector<WallBox<3>>&, const Vec<3>&);
template std::vector<std::unique_ptr<FunctionObject<2>>> createFunctionObjects<2>(const Dictionary*,
                                                                                  const std::vector<WallBox<2>>&,
                                                                                  const Vec<2>&);
template std::vector<std::unique_ptr<FunctionObject<3>>> createFunctionObjects<3>(const Dictionary*,
                                                                                  const std::vector<WallBox<3>>&,
                                                                                  const Vec<3>&);

}  // namespace shizuku
