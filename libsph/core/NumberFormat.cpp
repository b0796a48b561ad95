// Numbers as messages, the log and the keyword tables print them (formatNumber,
// declared in Dictionary.hpp): 10 significant digits, the exponent as a user writes it
// (1e-8, not 1e-08), round numbers far from 1 as powers of ten (1e7, 1e-4).
#include "core/Dictionary.hpp"
#include <cmath>
#include <sstream>

namespace shizuku {

namespace {

// 1e-08 -> 1e-8, 1e+300 -> 1e300: the exponent as a user writes it.
std::string tidyExponent(std::string t) {
  const auto e = t.find('e');
  if (e == std::string::npos) return t;
  std::string mant = t.substr(0, e), exp = t.substr(e + 1), sign;
  if (!exp.empty() && (exp[0] == '+' || exp[0] == '-')) {
    if (exp[0] == '-') sign = "-";
    exp.erase(0, 1);
  }
  while (exp.size() > 1 && exp[0] == '0') exp.erase(0, 1);
  return mant + "e" + sign + exp;
}

}  // namespace

std::string formatNumber(double x) {
  std::ostringstream s;
  s.precision(10);
  s << x;
  if (!std::isfinite(x)) return s.str();
  std::string t = tidyExponent(s.str());
  // Round numbers far from 1 read better as 1e7 and 1e-4 than 10000000 and 0.0001.
  if ((std::abs(x) >= 1e5 || (x != 0 && std::abs(x) < 1e-3)) && t.find('e') == std::string::npos) {
    for (int digits = 1; digits <= 10; ++digits) {
      std::ostringstream e;
      e.precision(digits - 1);
      e << std::scientific << x;
      if (std::stod(e.str()) == x) {
        std::string sci = e.str();
        const auto k = sci.find('e');
        std::string mant = sci.substr(0, k);
        if (mant.find('.') != std::string::npos) {
          while (mant.back() == '0') mant.pop_back();
          if (mant.back() == '.') mant.pop_back();
        }
        sci = tidyExponent(mant + sci.substr(k));
        if (sci.size() < t.size()) t = sci;
        break;
      }
    }
  }
  return t;
}

}  // namespace shizuku
