// Kernel names and the declarations and reading of system/sphSchemes
// kernel { type; smoothingLengthRatio; }.
// The ratio is bounded to (0.5, 3): below 0.5 the support 2h holds too few
// neighbours for any operator, above 3 the neighbour lists grow by 36x or more.
#include "kernels/KernelParameters.hpp"
#include "core/Parameter.hpp"

namespace shizuku {

namespace {

namespace key {

const ParameterGroup kernel("system/sphSchemes: kernel", "Smoothing kernel; support 2h with h = smoothingLengthRatio x spacing.");
const OptionParameter type = kernel.option("type", {"cubicSpline", "WendlandC2"}, "kernel function").def("cubicSpline");
const ScalarParameter smoothingLengthRatio = kernel.scalar("smoothingLengthRatio", dim::none,
    "h / d0; masses are calibrated so the initial lattice has `<rho> = rho`").def(1.2).above(0.5).below(3);


}  // namespace key
}  // namespace

KernelType kernelTypeFromName(const std::string& name) {
  if (name == "cubicSpline") return KernelType::cubicSpline;
  if (name == "WendlandC2") return KernelType::WendlandC2;
  throw InputError("unknown kernel type '" + name + "': valid types are cubicSpline, WendlandC2");
}

std::string toString(KernelType t) {
  return t == KernelType::cubicSpline ? "cubicSpline" : "WendlandC2";
}

KernelParameters KernelParameters::read(const Dictionary* d) {
  KernelParameters p;
  p.type = kernelTypeFromName(key::type.read(d));
  p.smoothingLengthRatio = key::smoothingLengthRatio.read(d);
  return p;
}

}  // namespace shizuku
