// A velocity given as muParser expressions, one per component, of the position x y z (m)
// and the time t (s), with the constant pi: the `expression` velocity of fluid regions
// (initial velocity, t = 0) and of inlets (docs/boundaries.md). Not thread-safe: one
// object per thread. Errors (syntax, unknown variable, evaluation) are thrown as
// VelocityExpressionError, whose text names the expression; the caller adds the file,
// line and keyword.
// Reads no dictionary keys (the caller hands the expressions' text).
#pragma once
#include "core/types.hpp"
#include <array>
#include <memory>
#include <string>
#include <vector>

namespace shizuku {

struct VelocityExpressionError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

template <int D>
class VelocityExpression {
 public:
  // Parses the D expressions (throws on a syntax error or an unknown variable).
  explicit VelocityExpression(const std::vector<std::string>& text);
  ~VelocityExpression();
  VelocityExpression(const VelocityExpression&) = delete;
  VelocityExpression& operator=(const VelocityExpression&) = delete;
  Vec<D> operator()(const Vec<D>& x, double t = 0);

 private:
  struct Parsers;
  std::unique_ptr<Parsers> p_;
};

}  // namespace shizuku
