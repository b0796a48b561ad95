// Printing of physical dimensions (mass, length, time exponents) for the unit
// checks of the dictionary reader (docs/design.md 1.2): "[m/s^2]", "[kg/m^3]",
// "[Pa]", "[-]", and a named form for error messages ("a velocity [m/s]").
// Reads no dictionary keys.
#include "core/Dimension.hpp"
#include <vector>

namespace shizuku {

namespace {
std::string power(const char* base, int n) {
  return n == 1 ? std::string(base) : std::string(base) + "^" + std::to_string(n);
}
}  // namespace

std::string Dimension::str() const {
  if (M == 0 && L == 0 && T == 0) return "[-]";
  if (*this == dim::pressure) return "[Pa]";
  std::vector<std::string> num, den;
  const char* base[3] = {"kg", "m", "s"};
  const int expo[3] = {M, L, T};
  for (int k = 0; k < 3; ++k) {
    if (expo[k] > 0) num.push_back(power(base[k], expo[k]));
    if (expo[k] < 0) den.push_back(power(base[k], -expo[k]));
  }
  auto join = [](const std::vector<std::string>& v) {
    std::string s;
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? " " : "") + v[i];
    return s;
  };
  std::string s = num.empty() ? "1" : join(num);
  if (den.size() == 1) s += "/" + den[0];
  if (den.size() > 1) s += "/(" + join(den) + ")";
  return "[" + s + "]";
}

std::string Dimension::describe() const {
  struct Named { Dimension d; const char* name; };
  static const Named names[] = {
      {dim::none, "a dimensionless number"},     {dim::length, "a length"},
      {dim::time, "a time"},                     {dim::velocity, "a velocity"},
      {dim::acceleration, "an acceleration"},    {dim::inverseTime, "a rate"},
      {dim::inverseLength, "an inverse length"}, {dim::density, "a density"},
      {dim::kinematicViscosity, "a kinematic viscosity"},
      {dim::pressure, "a pressure"},             {dim::mass, "a mass"},
  };
  for (const auto& n : names)
    if (n.d == *this) return std::string(n.name) + " " + str();
  return "a quantity of dimension " + str();
}

}  // namespace shizuku
