// muParser velocity expressions of x y z t: see VelocityExpression.hpp.
#include "particles/VelocityExpression.hpp"
#include <cmath>
#include <muParser.h>

namespace shizuku {

namespace {
// "muParser: <message> in expression "<text>"", without muParser's trailing '.' and ' ';
// a name muParser does not know gets the names it does.
VelocityExpressionError failure(const mu::Parser::exception_type& err) {
  std::string m = err.GetMsg(), e = err.GetExpr();
  while (!m.empty() && (m.back() == '.' || m.back() == ' ')) m.pop_back();
  while (!e.empty() && e.back() == ' ') e.pop_back();
  std::string known;
  if (err.GetCode() == mu::ecUNASSIGNABLE_TOKEN)
    known = ": '" + err.GetToken() + "' is not a variable; the expressions know x, y, z (m), t (s) and pi";
  return VelocityExpressionError("muParser: " + m + " in expression \"" + e + "\"" + known);
}
}  // namespace

template <int D>
struct VelocityExpression<D>::Parsers {
  double xyzt[4] = {0, 0, 0, 0};
  std::array<mu::Parser, D> parser;
};

template <int D>
VelocityExpression<D>::VelocityExpression(const std::vector<std::string>& text) : p_(std::make_unique<Parsers>()) {
  try {
    for (int k = 0; k < D; ++k) {
      mu::Parser& q = p_->parser[k];
      q.DefineVar("x", &p_->xyzt[0]);
      q.DefineVar("y", &p_->xyzt[1]);
      q.DefineVar("z", &p_->xyzt[2]);
      q.DefineVar("t", &p_->xyzt[3]);
      q.DefineConst("pi", M_PI);
      q.SetExpr(text.at(std::size_t(k)));
    }
  } catch (const mu::Parser::exception_type& err) {
    throw failure(err);
  }
}

template <int D>
VelocityExpression<D>::~VelocityExpression() = default;

template <int D>
Vec<D> VelocityExpression<D>::operator()(const Vec<D>& x, double t) {
  for (int k = 0; k < D; ++k) p_->xyzt[k] = x[k];
  p_->xyzt[3] = t;
  Vec<D> u;
  try {
    for (int k = 0; k < D; ++k) u[k] = p_->parser[k].Eval();
  } catch (const mu::Parser::exception_type& err) {
    throw failure(err);
  }
  return u;
}

template class VelocityExpression<2>;
template class VelocityExpression<3>;

}  // namespace shizuku
