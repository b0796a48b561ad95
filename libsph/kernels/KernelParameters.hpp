// The kernel settings of system/sphSchemes, declared once (KernelParameters.cpp):
//   kernel { type cubicSpline|WendlandC2; smoothingLengthRatio; }   (h = ratio x d0)
// read() takes the `kernel` sub-dictionary, or nullptr when it is absent (defaults).
#pragma once
#include "core/Dictionary.hpp"
#include "kernels/Kernel.hpp"

namespace shizuku {

struct KernelParameters {
  // Set by read(); defaults and ranges are declared once in KernelParameters.cpp.
  KernelType type{};
  double smoothingLengthRatio{};
  static KernelParameters read(const Dictionary* kernelDict);
};

}  // namespace shizuku
