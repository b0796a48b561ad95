// Time directory names and exact number text: see TimeName.hpp (docs/design.md 1.3).
#include "io/TimeName.hpp"
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace shizuku {

std::string timeName(double t, int precision) {
  if (!std::isfinite(t)) throw std::runtime_error("timeName: time is not finite");
  if (precision < 1 || precision > 17)
    throw std::runtime_error("timeName: precision must be 1..17, got " + std::to_string(precision));
  if (t == 0) t = 0;  // -0 -> 0
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, t, std::chars_format::general, precision);
  std::string s(buf, r.ptr);
  if (s == "-0") s = "0";
  return s;
}

std::optional<double> parseNumber(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const char* first = text.data();
  const char* last = first + text.size();
  if (*first == '+') ++first;  // from_chars does not take a leading '+'
  double v = 0;
  auto r = std::from_chars(first, last, v, std::chars_format::general);
  if (r.ec != std::errc() || r.ptr != last) return std::nullopt;
  return v;
}

std::optional<double> parseTimeName(const std::string& name) {
  if (name.empty()) return std::nullopt;
  for (char c : name) {
    bool ok = (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-';
    if (!ok) return std::nullopt;
  }
  auto v = parseNumber(name);
  if (!v || !std::isfinite(*v)) return std::nullopt;
  return v;
}

std::string exactNumber(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, v);  // shortest round-trip form
  return std::string(buf, r.ptr);
}

}  // namespace shizuku
