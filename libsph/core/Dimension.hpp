// Physical dimensions (mass, length, time exponents) used to check the unit a
// user writes after a number, e.g. `spacing 1 [cm];` (docs/design.md 1.2).
#pragma once
#include <string>

namespace shizuku {

struct Dimension {
  int M = 0, L = 0, T = 0;
  bool operator==(const Dimension& o) const { return M == o.M && L == o.L && T == o.T; }
  bool operator!=(const Dimension& o) const { return !(*this == o); }
  std::string str() const;       // e.g. "[m/s^2]", "[-]", "[Pa]"
  std::string describe() const;  // e.g. "a length [m]", "a dimensionless number [-]"
  Dimension operator*(const Dimension& o) const { return {M + o.M, L + o.L, T + o.T}; }
  Dimension operator/(const Dimension& o) const { return {M - o.M, L - o.L, T - o.T}; }
  Dimension pow(int n) const { return {M * n, L * n, T * n}; }
};

namespace dim {
constexpr Dimension none{0, 0, 0};
constexpr Dimension length{0, 1, 0};
constexpr Dimension time{0, 0, 1};
constexpr Dimension velocity{0, 1, -1};
constexpr Dimension acceleration{0, 1, -2};
constexpr Dimension inverseTime{0, 0, -1};
constexpr Dimension inverseLength{0, -1, 0};
constexpr Dimension density{1, -3, 0};
constexpr Dimension kinematicViscosity{0, 2, -1};
constexpr Dimension pressure{1, -1, -2};
constexpr Dimension mass{1, 0, 0};
}  // namespace dim

}  // namespace shizuku
