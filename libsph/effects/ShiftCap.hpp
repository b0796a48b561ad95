// The shift cap of eq. (10): |dr_i| <= maxLength (the solver passes maxShift * h,
// `shifting { maxShift 0.1; }`), each shift scaled down along its own direction.
// Returns the number of capped shifts. Reads no dictionary keys.
#pragma once
#include "core/types.hpp"
#include <cmath>

namespace shizuku {

template <int D>
long capShift(std::vector<Vec<D>>& dr, double maxLength) {
  const long n = long(dr.size());
  const double max2 = maxLength * maxLength;
  long capped = 0;
#pragma omp parallel for schedule(static) reduction(+ : capped)
  for (long i = 0; i < n; ++i) {
    const double len2 = dr[i].squaredNorm();
    if (len2 > max2) {
      dr[i] *= maxLength / std::sqrt(len2);
      ++capped;
    }
  }
  return capped;
}

}  // namespace shizuku
