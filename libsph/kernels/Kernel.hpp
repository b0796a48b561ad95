// Smoothing kernels with support 2h (docs/method.md section 2): cubic B-spline
// (default) and Wendland C2, in D = 2 or 3 dimensions, with q = r/h:
//   cubic spline: w = s [1 - 1.5q^2 + 0.75q^3] (q<1), s 0.25 (2-q)^3 (1<=q<2), 0 else;
//                 s = 10/(7 pi h^2) (2D), 1/(pi h^3) (3D)
//   Wendland C2:  w = s (1-q/2)^4 (2q+1) (q<2);  s = 7/(4 pi h^2) (2D), 21/(16 pi h^3) (3D)
// latticeSum(d0) is the Shepard sum over an infinite square/cubic lattice
// including the self term, used to calibrate the particle mass
// m = rho0 / latticeSum(d0) (docs/method.md 2, option (b)).
// Reads (system/sphSchemes): kernel { type cubicSpline|WendlandC2; smoothingLengthRatio 1.2; }
// (the dictionary itself is read by the solver; kernelTypeFromName maps `type`).
#pragma once
#include "core/types.hpp"
#include <cmath>
#include <string>

namespace shizuku {

enum class KernelType { cubicSpline, WendlandC2 };

// "cubicSpline" | "WendlandC2"; throws InputError listing the valid names.
KernelType kernelTypeFromName(const std::string& name);
std::string toString(KernelType t);

template <int D>
class Kernel {
 public:
  Kernel() : Kernel(KernelType::cubicSpline, 1.0) {}
  Kernel(KernelType type, double h);  // throws InputError if h <= 0
  static KernelType kernelTypeFromName(const std::string& name) { return shizuku::kernelTypeFromName(name); }

  KernelType type() const { return type_; }
  double h() const { return h_; }
  double support() const { return 2.0 * h_; }
  double sigma() const { return sigma_; }  // normalisation constant (1/m^D)

  double w(double r) const {  // kernel value
    double wv, dw;
    eval(r, wv, dw);
    return wv;
  }
  double dwdr(double r) const {  // dW/dr (<= 0)
    double wv, dw;
    eval(r, wv, dw);
    return dw;
  }
  // Both at once (the hot loops use this).
  void eval(double r, double& wv, double& dw) const {
    const double q = r * invH_;
    if (type_ == KernelType::cubicSpline) {
      if (q < 1.0) {
        wv = sigma_ * (1.0 - q * q * (1.5 - 0.75 * q));
        dw = sigma_ * invH_ * q * (-3.0 + 2.25 * q);
      } else if (q < 2.0) {
        const double t = 2.0 - q;
        wv = sigma_ * 0.25 * t * t * t;
        dw = -sigma_ * invH_ * 0.75 * t * t;
      } else {
        wv = dw = 0.0;
      }
    } else {
      if (q < 2.0) {
        const double t = 1.0 - 0.5 * q, t3 = t * t * t;
        wv = sigma_ * t3 * t * (2.0 * q + 1.0);
        dw = -5.0 * sigma_ * invH_ * q * t3;
      } else {
        wv = dw = 0.0;
      }
    }
  }
  // W and dW/dr at two distances at once: eval's arithmetic lane by lane (the same bits).
  void eval(DoublePair r, DoublePair& wv, DoublePair& dw) const {
    const DoublePair q = r * invH_;
    const DoublePair zero = {0, 0};
    if (type_ == KernelType::cubicSpline) {
      const DoublePair t = 2.0 - q;
      const auto inner = q < 1.0, inside = q < 2.0;
      wv = inner ? sigma_ * (1.0 - q * q * (1.5 - 0.75 * q)) : inside ? sigma_ * 0.25 * t * t * t : zero;
      dw = inner ? sigma_ * invH_ * q * (-3.0 + 2.25 * q) : inside ? -sigma_ * invH_ * 0.75 * t * t : zero;
    } else {
      const DoublePair t = 1.0 - 0.5 * q, t3 = t * t * t;
      const auto inside = q < 2.0;
      wv = inside ? sigma_ * t3 * t * (2.0 * q + 1.0) : zero;
      dw = inside ? -5.0 * sigma_ * invH_ * q * t3 : zero;
    }
  }
  DoublePair dwdr(DoublePair r) const {
    DoublePair wv, dw;
    eval(r, wv, dw);
    return dw;
  }
  // grad_i W_ij = dW/dr * r_ij / r with r_ij = r_i - r_j; since dW/dr <= 0 it
  // points from i toward j (docs/method.md 0).
  Vec<D> gradW(const Vec<D>& rij, double r) const {
    return r > 0 ? Vec<D>(dwdr(r) / r * rij) : Vec<D>::Zero();
  }
  // Sum of W(|r|) over the infinite square (2D) / cubic (3D) lattice of
  // spacing d0, self term included (units 1/m^D).
  double latticeSum(double d0) const;

 private:
  KernelType type_ = KernelType::cubicSpline;
  double h_ = 1, invH_ = 1, sigma_ = 1;
};

extern template class Kernel<2>;
extern template class Kernel<3>;

}  // namespace shizuku
