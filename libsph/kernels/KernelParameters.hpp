// The kernel settings of system/sphSchemes, declared once (KernelParameters.cpp):
//   kernel { type cubicSpline|WendlandC2; smoothingLengthRatio 1.2; }   (h = ratio x d0)
// read() takes the `kernel` sub-dictionary, or nullptr when it is absent (defaults).
#pragma once
#include "core/Dictionary.hpp"
#include "kernels/Kernel.hpp"

namespace shizuku {

struct KernelParameters {
  KernelType type = KernelType::cubicSpline;
  double smoothingLengthRatio = 1.2;
  static KernelParameters read(const Dictionary* kernelDict);
};

}  // namespace shizuku
