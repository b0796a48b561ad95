// Factories of the three derivative schemes (one implementation file each:
// SPH2Operator.cpp, CorrectedOperator.cpp, StandardOperator.cpp), used by
// DerivativeOperator<D>::create. Internal header of libsph/operators.
// Reads no dictionary keys.
#pragma once
#include "operators/DerivativeOperator.hpp"

namespace shizuku {

template <int D> std::unique_ptr<DerivativeOperator<D>> makeSPH2Operator();
template <int D> std::unique_ptr<DerivativeOperator<D>> makeCorrectedOperator();
template <int D> std::unique_ptr<DerivativeOperator<D>> makeStandardOperator();

}  // namespace shizuku
