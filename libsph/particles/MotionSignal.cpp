// Prescribed functions of time for wall motions: see MotionSignal.hpp.
#include "particles/MotionSignal.hpp"
#include "core/Dictionary.hpp"
#include "core/Log.hpp"
#include <algorithm>
#include <cmath>
#include <fstream>
#include <muParser.h>
#include <sstream>

namespace shizuku {

namespace {

// The step of the central differences (s).
constexpr double kStep = 1e-4;

std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == '.' || s.back() == ' ')) s.pop_back();
  return s;
}

class ExpressionSignal final : public MotionSignal {
 public:
  explicit ExpressionSignal(const std::vector<std::string>& text) : text_(text), parser_(text.size()) {
    try {
      for (auto& p : parser_) {
        p.DefineVar("t", &t_);
        p.DefineConst("pi", M_PI);
      }
      for (std::size_t k = 0; k < text.size(); ++k) parser_[k].SetExpr(text[k]);
      t_ = 0;
      for (std::size_t k = 0; k < text.size(); ++k) {
        const double v = parser_[k].Eval();
        if (!std::isfinite(v))
          throw MotionSignalError("expression \"" + text[k] + "\" is " + formatNumber(v) + " at t = 0, not finite");
      }
    } catch (const mu::Parser::exception_type& err) {
      std::string known;
      if (err.GetCode() == mu::ecUNASSIGNABLE_TOKEN)
        known = ": '" + err.GetToken() + "' is not a variable; a motion's expressions know t (s) and pi";
      throw MotionSignalError("muParser: " + trimmed(err.GetMsg()) + " in expression \"" + trimmed(err.GetExpr()) +
                              "\"" + known);
    }
  }
  int components() const override { return int(text_.size()); }
  SignalValue at(double t) override {
    SignalValue s;
    for (std::size_t k = 0; k < text_.size(); ++k) {
      const double m2 = eval(k, t - 2 * kStep), m1 = eval(k, t - kStep), f = eval(k, t);
      const double p1 = eval(k, t + kStep), p2 = eval(k, t + 2 * kStep);
      s.f[k] = f;
      s.df[k] = (-p2 + 8 * p1 - 8 * m1 + m2) / (12 * kStep);
      s.ddf[k] = (-p2 + 16 * p1 - 30 * f + 16 * m1 - m2) / (12 * kStep * kStep);
    }
    return s;
  }
  std::string describe() const override {
    std::string d = "expression (";
    for (std::size_t k = 0; k < text_.size(); ++k) d += (k ? " \"" : "\"") + text_[k] + "\"";
    return d + ")";
  }

 private:
  double eval(std::size_t k, double t) {
    t_ = t;
    try {
      return parser_[k].Eval();
    } catch (const mu::Parser::exception_type& err) {
      throw MotionSignalError("muParser: " + trimmed(err.GetMsg()) + " in expression \"" + text_[k] + "\" at t = " +
                              formatNumber(t));
    }
  }
  std::vector<std::string> text_;
  std::vector<mu::Parser> parser_;
  double t_ = 0;
};

class TableSignal final : public MotionSignal {
 public:
  TableSignal(const std::string& path, int components, bool spline) : path_(path), n_(components), spline_(spline) {
    read();
    if (spline_) fitSplines();
  }
  int components() const override { return n_; }
  SignalValue at(double t) override {
    SignalValue s;
    const std::size_t m = time_.size();
    if (t <= time_.front() || t >= time_.back()) {
      const std::size_t end = t <= time_.front() ? 0 : m - 1;
      for (int k = 0; k < n_; ++k) s.f[k] = value_[k][end];
      return s;
    }
    const std::size_t i = std::size_t(std::upper_bound(time_.begin(), time_.end(), t) - time_.begin()) - 1;
    const double h = time_[i + 1] - time_[i], b = (t - time_[i]) / h, a = 1 - b;
    for (int k = 0; k < n_; ++k) {
      const auto& y = value_[k];
      s.f[k] = a * y[i] + b * y[i + 1];
      s.df[k] = (y[i + 1] - y[i]) / h;
      if (!spline_) continue;
      const auto& M = curvature_[k];
      s.f[k] += ((a * a * a - a) * M[i] + (b * b * b - b) * M[i + 1]) * h * h / 6;
      s.df[k] += (-(3 * a * a - 1) * M[i] + (3 * b * b - 1) * M[i + 1]) * h / 6;
      s.ddf[k] = a * M[i] + b * M[i + 1];
    }
    return s;
  }
  std::string describe() const override {
    return cat("table '", path_, "' (", time_.size(), " rows, ", formatNumber(time_.front()), " to ",
               formatNumber(time_.back()), " s, ", spline_ ? "cubic spline" : "linear", ")");
  }

 private:
  [[noreturn]] void fail(long line, const std::string& what) const {
    throw MotionSignalError("table '" + path_ + "'" + (line > 0 ? cat(", line ", line) : std::string()) + ": " + what);
  }
  void read() {
    std::ifstream in(path_);
    if (!in) fail(0, "cannot be read");
    std::string text;
    long line = 0;
    value_.assign(std::size_t(n_), {});
    while (std::getline(in, text)) {
      ++line;
      const auto first = text.find_first_not_of(" \t\r");
      if (first == std::string::npos || text[first] == '#') continue;
      std::istringstream row(text);
      std::vector<double> v;
      std::string word;
      while (row >> word) {
        char* end = nullptr;
        const double x = std::strtod(word.c_str(), &end);
        if (*end != '\0' || !std::isfinite(x)) fail(line, "'" + word + "' is not a finite number");
        v.push_back(x);
      }
      if (int(v.size()) != n_ + 1)
        fail(line, cat("expected ", n_ + 1, " columns (t and ", n_, n_ == 1 ? " value" : " values", "), found ", v.size()));
      if (!time_.empty() && !(v[0] > time_.back()))
        fail(line, cat("time ", formatNumber(v[0]), " s does not increase (the row before has ",
                       formatNumber(time_.back()), " s); times must increase strictly"));
      time_.push_back(v[0]);
      for (int k = 0; k < n_; ++k) value_[k].push_back(v[std::size_t(k) + 1]);
    }
    if (time_.size() < 2) fail(0, cat("holds ", time_.size(), " rows; a table needs at least two"));
  }
  // Natural cubic spline: second derivatives M_i, zero at both ends.
  void fitSplines() {
    const std::size_t m = time_.size();
    curvature_.assign(std::size_t(n_), std::vector<double>(m, 0.0));
    if (m < 3) return;
    std::vector<double> c(m, 0.0), r(m, 0.0);
    for (int k = 0; k < n_; ++k) {
      const auto& y = value_[k];
      auto& M = curvature_[k];
      // Thomas algorithm on rows 1..m-2.
      for (std::size_t i = 1; i + 1 < m; ++i) {
        const double h0 = time_[i] - time_[i - 1], h1 = time_[i + 1] - time_[i];
        const double rhs = 6 * ((y[i + 1] - y[i]) / h1 - (y[i] - y[i - 1]) / h0);
        const double diag = 2 * (h0 + h1) - (i > 1 ? h0 * c[i - 1] : 0);
        c[i] = h1 / diag;
        r[i] = (rhs - (i > 1 ? h0 * r[i - 1] : 0)) / diag;
      }
      for (std::size_t i = m - 2; i >= 1; --i) M[i] = r[i] - c[i] * M[i + 1];
    }
  }
  std::string path_;
  int n_;
  bool spline_;
  std::vector<double> time_;
  std::vector<std::vector<double>> value_, curvature_;
};

class SinusoidSignal final : public MotionSignal {
 public:
  SinusoidSignal(const std::array<double, 3>& a, int n, double period, double phase, double ramp)
      : a_(a), n_(n), omega_(2 * M_PI / period), period_(period), phase_(phase), ramp_(ramp) {}
  int components() const override { return n_; }
  SignalValue at(double t) override {
    // Ramp r(t) and its derivatives.
    double r = 1, dr = 0, ddr = 0;
    if (t < 0) r = 0;
    else if (t < ramp_) {
      const double w = M_PI / ramp_;
      r = 0.5 * (1 - std::cos(w * t));
      dr = 0.5 * w * std::sin(w * t);
      ddr = 0.5 * w * w * std::cos(w * t);
    }
    const double sn = std::sin(omega_ * t + phase_), cs = std::cos(omega_ * t + phase_);
    SignalValue s;
    for (int k = 0; k < n_; ++k) {
      const double g = a_[k] * sn, dg = a_[k] * omega_ * cs, ddg = -a_[k] * omega_ * omega_ * sn;
      s.f[k] = r * g;
      s.df[k] = dr * g + r * dg;
      s.ddf[k] = ddr * g + 2 * dr * dg + r * ddg;
    }
    return s;
  }
  std::string describe() const override {
    std::string amp;
    for (int k = 0; k < n_; ++k) amp += (k ? " " : "") + formatNumber(a_[k]);
    return cat("amplitude (", amp, "), period ", formatNumber(period_), " s, phase ",
               formatNumber(phase_ * 180 / M_PI), " deg", ramp_ > 0 ? cat(", ramp ", formatNumber(ramp_), " s") : "");
  }

 private:
  std::array<double, 3> a_;
  int n_;
  double omega_, period_, phase_, ramp_;
};

}  // namespace

std::unique_ptr<MotionSignal> MotionSignal::expression(const std::vector<std::string>& text) {
  return std::make_unique<ExpressionSignal>(text);
}

std::unique_ptr<MotionSignal> MotionSignal::table(const std::string& path, int components, bool spline) {
  return std::make_unique<TableSignal>(path, components, spline);
}

std::unique_ptr<MotionSignal> MotionSignal::sinusoid(const std::array<double, 3>& amplitude, int components,
                                                     double period, double phase, double rampTime) {
  return std::make_unique<SinusoidSignal>(amplitude, components, period, phase, rampTime);
}

}  // namespace shizuku
