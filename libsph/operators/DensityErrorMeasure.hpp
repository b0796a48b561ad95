// The density error of eq. (22) (docs/method.md 0, 13):
//   e_i = (rho0 - <rho>_i) / rho0 x 100 %,   <rho>_i the summation density (eq. 18),
// and its statistics over the interior fluid particles (free-surface class `interior`)
// and over all fluid particles (walls never count). Used by the `densityError` function
// object, the density health check and the progress line: one definition for all three.
// The sums are deterministic block sums (core/BlockReduce.hpp): the same bits on any
// number of threads. Reads no dictionary keys.
#pragma once
#include "operators/FlowState.hpp"

namespace shizuku {

inline double densityErrorPercent(double rho0, double rho) { return (rho0 - rho) / rho0 * 100.0; }

struct DensityErrorStats {
  long count = 0;
  double mean = 0, rms = 0, max = 0, mode = 0;  // % (nan when count == 0; mode set by histograms)
};

struct DensityErrorSummary {
  DensityErrorStats interior, all;
  long worstInterior = -1;  // index of the interior particle with the largest |e| (-1: none)
};

template <int D>
DensityErrorSummary measureDensityError(const FlowState<D>& s);

}  // namespace shizuku
