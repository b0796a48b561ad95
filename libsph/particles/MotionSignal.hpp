// A prescribed function of time with its first and second derivatives, one to three
// components: the displacement of a wall's translation or the angle of its rotation
// (docs/boundaries.md, "Moving walls"; docs/method.md 11.1).
//   expression: muParser expressions of t (s) with the constant pi, one per component.
//               Derivatives by fourth-order central differences with step 1e-4 s,
//                 f'  = (-f(t+2e) + 8 f(t+e) - 8 f(t-e) + f(t-2e)) / (12 e),
//                 f'' = (-f(t+2e) + 16 f(t+e) - 30 f(t) + 16 f(t-e) - f(t-2e)) / (12 e^2),
//               truncation error e^4 f^(5)/30 and e^4 f^(6)/90 (about 5e-7 of omega A and
//               2e-7 of omega^2 A for a period of 0.01 s, falling as the period^-4), and
//               rounding of about 1e-7 A in f'' (A the signal's size): test_particles_motion
//               holds f' to 1e-9 of omega A and f'' to 1e-7 of omega^2 A for periods of
//               0.8 and 0.05 s.
//   table:      rows "t f1 [f2 f3]" read from a file (blank lines and lines starting with
//               '#' skipped), times strictly increasing; linear interpolation (f' piecewise
//               constant, f'' zero) or a natural cubic spline (f, f', f'' continuous);
//               before the first time and after the last the end value holds (f' = f'' = 0).
//   sinusoid:   f = r(t) A sin(omega t + phase), omega = 2 pi / period, with the ramp
//               r = (1 - cos(pi t / T_r)) / 2 for 0 <= t < T_r, 1 after, 0 before 0
//               (T_r = 0: no ramp); derivatives exact.
// Evaluation allocates nothing (the time loop calls it every step). Not thread-safe.
// Reads no dictionary keys (WallMotion reads them and builds the signal).
#pragma once
#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace shizuku {

// Value and first and second time derivatives of each component (up to three).
struct SignalValue {
  std::array<double, 3> f{}, df{}, ddf{};
};

struct MotionSignalError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class MotionSignal {
 public:
  virtual ~MotionSignal() = default;
  virtual int components() const = 0;
  virtual SignalValue at(double t) = 0;
  virtual std::string describe() const = 0;

  // muParser expressions of t; throws MotionSignalError naming the expression on a
  // syntax error, an unknown variable, or a value that is not finite at t = 0.
  static std::unique_ptr<MotionSignal> expression(const std::vector<std::string>& text);
  // A table file with `components` value columns; throws MotionSignalError naming the
  // file and line (unreadable, a malformed row, times not increasing, fewer than two rows).
  static std::unique_ptr<MotionSignal> table(const std::string& path, int components, bool spline);
  static std::unique_ptr<MotionSignal> sinusoid(const std::array<double, 3>& amplitude, int components,
                                                double period, double phase, double rampTime);
};

}  // namespace shizuku
