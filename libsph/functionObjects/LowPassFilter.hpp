// First-order low-pass filter of a sampled signal, for the `filter { type lowPass;
// cutoff fc; }` of a sensor (docs/postprocessing.md, "wallPressure"). It integrates
//   tau dy/dt + y = x,   tau = 1 / (2 pi fc),
// exactly for an input that is linear between samples (first-order hold), at any and
// varying sample interval dt:
//   y_n = a y_{n-1} + x_n - a x_{n-1} - tau s (1 - a),   a = exp(-dt/tau),
//   s = (x_n - x_{n-1}) / dt.
// Transfer function H(i w) = 1 / (1 + i w tau): gain 1/sqrt(1 + (w tau)^2) (1/sqrt(2),
// -3 dB, at fc), phase -atan(w tau); step response 1 - exp(-t/tau). The first sample
// starts the filter at rest on its value (y_0 = x_0), so a steady signal passes unchanged.
// A sample at the same time as the previous one leaves the output as it was.
// Reads no keys (WallPressure reads cutoff).
#pragma once
#include <cmath>

namespace shizuku {

class LowPassFilter {
 public:
  LowPassFilter() = default;
  explicit LowPassFilter(double cutoff) : tau_(1 / (2 * M_PI * cutoff)) {}
  double tau() const { return tau_; }
  double output() const { return y_; }
  double update(double t, double x) {
    if (!started_) {
      started_ = true;
      y_ = x;
    } else if (t > t_) {
      const double dt = t - t_;
      const double oneMinusA = -std::expm1(-dt / tau_), a = 1 - oneMinusA;
      y_ = a * y_ + x - a * x_ - tau_ * (x - x_) / dt * oneMinusA;
    } else {
      return y_;
    }
    t_ = t;
    x_ = x;
    return y_;
  }

 private:
  double tau_ = 0;
  bool started_ = false;
  double t_ = 0, x_ = 0, y_ = 0;
};

}  // namespace shizuku
