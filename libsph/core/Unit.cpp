// Units written in square brackets after a number or a list (docs/design.md 1.2):
// parseUnit("g/cm^3") gives the SI factor (1000) and the dimension (kg/m^3).
// Grammar: factors separated by spaces or '*' multiply, '/' divides by the one
// factor that follows it (so "m/s/s" = "m/s^2"), '^' takes an integer power,
// parentheses group: "kg/(m s^2)". "1" is a neutral factor ("1/s"); "-" or an
// empty unit is dimensionless. Known units: m cm mm s ms kg g Pa kPa rad Hz
// (rad is dimensionless, Hz is 1/s). Reads no dictionary keys.
#include "core/Dictionary.hpp"
#include <cctype>
#include <cmath>
#include <cstdlib>

namespace shizuku {

namespace {

struct BaseUnit { const char* name; double factor; Dimension dim; };
const BaseUnit kUnits[] = {
    {"m", 1.0, dim::length},      {"cm", 1e-2, dim::length},  {"mm", 1e-3, dim::length},
    {"s", 1.0, dim::time},        {"ms", 1e-3, dim::time},    {"kg", 1.0, dim::mass},
    {"g", 1e-3, dim::mass},       {"Pa", 1.0, dim::pressure}, {"kPa", 1e3, dim::pressure},
    {"rad", 1.0, dim::none},       {"Hz", 1.0, dim::inverseTime},
};

class UnitParser {
 public:
  explicit UnitParser(const std::string& text) : s_(text) {}

  Unit parse() {
    skipSpace();
    if (pos_ == s_.size() || s_.substr(pos_) == "-") return Unit{};
    Unit u = product();
    skipSpace();
    if (pos_ != s_.size()) fail("unexpected '" + std::string(1, s_[pos_]) + "'");
    return u;
  }

 private:
  const std::string& s_;
  std::size_t pos_ = 0;
  int depth_ = 0;
  // Powers stay within +-kMaxPower after every step, so no int overflows.
  static constexpr int kMaxPower = 99;

  void checkPowers(const Unit& u) const {
    if (std::abs(u.dim.M) > kMaxPower || std::abs(u.dim.L) > kMaxPower || std::abs(u.dim.T) > kMaxPower)
      fail("powers of the units add up to more than " + std::to_string(kMaxPower));
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError("unit [" + s_ + "]: " + what);
  }
  void skipSpace() { while (pos_ < s_.size() && std::isspace((unsigned char)s_[pos_])) ++pos_; }
  bool atFactorStart() {
    skipSpace();
    return pos_ < s_.size() && (std::isalnum((unsigned char)s_[pos_]) || s_[pos_] == '(');
  }

  // product := factor { ['*'] factor | '/' factor }
  Unit product() {
    Unit u = factor();
    for (;;) {
      skipSpace();
      if (pos_ < s_.size() && s_[pos_] == '/') {
        ++pos_;
        if (!atFactorStart()) fail("expected a unit after '/'");
        Unit d = factor();
        u.factor /= d.factor;
        u.dim = u.dim / d.dim;
        checkPowers(u);
      } else if (pos_ < s_.size() && s_[pos_] == '*') {
        ++pos_;
        if (!atFactorStart()) fail("expected a unit after '*'");
        Unit m = factor();
        u.factor *= m.factor;
        u.dim = u.dim * m.dim;
        checkPowers(u);
      } else if (atFactorStart()) {
        Unit m = factor();
        u.factor *= m.factor;
        u.dim = u.dim * m.dim;
        checkPowers(u);
      } else {
        return u;
      }
    }
  }

  // factor := ( name | '1' | '(' product ')' ) [ '^' ['-'] digits ]
  Unit factor() {
    skipSpace();
    Unit u;
    if (s_[pos_] == '(') {
      ++pos_;
      if (++depth_ > 16) fail("parentheses nested more than 16 deep");
      u = product();
      --depth_;
      skipSpace();
      if (pos_ >= s_.size() || s_[pos_] != ')') fail("expected ')'");
      ++pos_;
    } else if (std::isdigit((unsigned char)s_[pos_])) {
      std::size_t b = pos_;
      while (pos_ < s_.size() && std::isdigit((unsigned char)s_[pos_])) ++pos_;
      if (s_.substr(b, pos_ - b) != "1") fail("a number in a unit may only be 1 (as in [1/s])");
    } else {
      std::size_t b = pos_;
      while (pos_ < s_.size() && std::isalpha((unsigned char)s_[pos_])) ++pos_;
      const std::string name = s_.substr(b, pos_ - b);
      const BaseUnit* found = nullptr;
      for (const auto& k : kUnits)
        if (name == k.name) found = &k;
      if (!found) {
        std::vector<std::string> names;
        std::string list;
        for (const auto& k : kUnits) { names.push_back(k.name); list += std::string(" ") + k.name; }
        std::string m = "unknown unit '" + name + "'";
        const std::string near = closestMatch(name, names);
        if (!near.empty()) m += "; did you mean '" + near + "'?";
        fail(m + " (known units:" + list + ", combined with * / ^ and parentheses)");
      }
      u.factor = found->factor;
      u.dim = found->dim;
    }
    skipSpace();
    if (pos_ < s_.size() && s_[pos_] == '^') {
      ++pos_;
      skipSpace();
      bool neg = false;
      if (pos_ < s_.size() && (s_[pos_] == '-' || s_[pos_] == '+')) neg = s_[pos_++] == '-';
      std::size_t b = pos_;
      while (pos_ < s_.size() && std::isdigit((unsigned char)s_[pos_])) ++pos_;
      if (b == pos_) fail("expected an integer power after '^'");
      if (pos_ - b > 2) fail("power ^" + s_.substr(b, pos_ - b) + " is larger than " + std::to_string(kMaxPower));
      int n = std::stoi(s_.substr(b, pos_ - b));
      if (neg) n = -n;
      u.factor = std::pow(u.factor, n);
      u.dim = u.dim.pow(n);
      checkPowers(u);
    }
    return u;
  }
};

}  // namespace

Unit parseUnit(const std::string& text) { return UnitParser(text).parse(); }

}  // namespace shizuku
