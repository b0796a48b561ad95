// Full Hessian of a scalar field at one particle by the FI system of
// docs/method.md 3.2: X = M_i^-1 sum_j V (f_j - f_i) Phi_ij with the scaled basis of
// WeightRows.hpp; H_aa = X[D+a]/h^2, H_ab = X[mixed]/h^2. For tests and
// diagnostics (not per step); entries are NaN/inf if M_i is singular.
// Reads no dictionary keys.
#include "operators/Ops.hpp"
#include "operators/WeightRows.hpp"
#include <Eigen/LU>

namespace shizuku {

template <int D>
Mat<D> Ops<D>::hessian(const Kernel<D>& kernel, double V, const NeighbourList<D>& nl,
                       const std::vector<double>& f, std::size_t i) {
  using T = weights::Taylor<D>;
  constexpr int NB = T::NB;
  const double h = kernel.h(), invH = 1.0 / h;
  Eigen::Matrix<double, NB, NB> S = Eigen::Matrix<double, NB, NB>::Zero();
  Eigen::Matrix<double, NB, 1> rhs = Eigen::Matrix<double, NB, 1>::Zero(), P, phi;
  for (Index p = nl.offset[i]; p < nl.offset[i + 1]; ++p) {
    const Vec<D> rij = nl.rij(i, p);
    const double r = rij.norm();
    if (!(r > 0)) continue;  // coincident particles carry no information
    double w, dw;
    kernel.eval(r, w, dw);
    const double kappa = -dw / r * h * h, beta = kappa * h * h / (r * r);
    T::fill(Vec<D>(-invH * rij), kappa, beta, P.data(), phi.data());
    S.noalias() += phi * P.transpose();
    rhs += (f[nl.j[p]] - f[i]) * phi;
  }
  // M = V S and the right-hand side carries V too: V cancels.
  (void)V;
  const Eigen::Matrix<double, NB, 1> X = Eigen::FullPivLU<Eigen::Matrix<double, NB, NB>>(S).solve(rhs);
  Mat<D> H;
  const double invH2 = invH * invH;
  for (int a = 0; a < D; ++a) H(a, a) = X[D + a] * invH2;
  for (int k = 0; k < T::numOff; ++k) {
    H(T::offA[k], T::offB[k]) = H(T::offB[k], T::offA[k]) = X[2 * D + k] * invH2;
  }
  return H;
}

template Mat<2> Ops<2>::hessian(const Kernel<2>&, double, const NeighbourList<2>&, const std::vector<double>&,
                                std::size_t);
template Mat<3> Ops<3>::hessian(const Kernel<3>&, double, const NeighbourList<3>&, const std::vector<double>&,
                                std::size_t);

}  // namespace shizuku
