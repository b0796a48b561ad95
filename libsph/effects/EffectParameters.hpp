// Range-checked reading of an effect's dimensionless parameters: the value of `key`
// (or `def` when absent), an InputError naming file, line and keyword when out of range.
#pragma once
#include "core/Dictionary.hpp"

namespace shizuku {

inline double nonNegative(const Dictionary& d, const std::string& key, double def) {
  const double v = d.getScalarOr(key, def, dim::none);
  if (!(v >= 0)) d.error(key, "must be >= 0");
  return v;
}

inline double positive(const Dictionary& d, const std::string& key, double def) {
  const double v = d.getScalarOr(key, def, dim::none);
  if (!(v > 0)) d.error(key, "must be > 0");
  return v;
}

}  // namespace shizuku
