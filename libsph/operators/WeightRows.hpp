// Per-particle ("row") building blocks of the derivative weights, shared by the
// SPH2, corrected and standard operators (methods.md 3.2, 3.4, 3.5). Internal
// header of libsph/operators.
//
// Notation (methods.md 0): r_ij = r_i - r_j, r_ji = -r_ij, gradW_ij = w'(r) r_ij / r
// = c r_ji with c = -w'(r)/r >= 0.
// FI (3.2), scaled by h: s = r_ji / h, rho = r / h,
//   P(s)   = (s_a ; s_a^2/2 ; s_a s_b)            Taylor basis, X = (h f_a ; h^2 f_aa ; h^2 f_ab)
//   Phi    = kappa (s_a ; s_a^2/rho^2 ; s_a s_b/rho^2), kappa = c h^2
//          = (h gradW ; h^2 T) with T = |w'| r_ji (x) r_ji / r^3 (Voigt order diag, off-diag)
//   S_i    = sum_j Phi P^T, M_i = V S_i,  tilde gradW = (first D rows of S^-1) Phi / (h V),
//   tilde lapW = (sum of the diagonal second-derivative rows of S^-1) . Phi / (h^2 V).
// First order (3.4 step 2): A = V sum_j gradW (x) r_ji, tilde gradW = A^-1 gradW;
//   Laplacian: renormalised (Basic et al. 2018, 3.5) with the kernel value as the
//   weight, written consistently so that it is exact for linear fields:
//   B = sum w r_ji r_ji^T, o = sum w r_ji, chi = 1 - r_ji . B^-1 o,
//   tilde lapW = 2 D w chi / (V sum_k w_k r_k^2 chi_k).
// Standard: tilde gradW = gradW, tilde lapW = 2 (r_ji . gradW)/r^2 = 2c (Morris/Brookshaw).
// Reads no dictionary keys.
#pragma once
#include "operators/DerivativeOperator.hpp"
#include <Eigen/LU>
#include <cmath>

namespace shizuku {
namespace weights {

// Fallback thresholds of methods.md 3.4.
template <int D> struct Thresholds {
  static constexpr int minNeighboursFI = D == 2 ? 6 : 12;
  static constexpr double minRcondFI = 1e-4;
  static constexpr int minNeighboursFirstOrder = D == 2 ? 3 : 4;
  static constexpr double minRcondFirstOrder = 1e-3;
};

enum Order : std::uint8_t { orderStandard = 0, orderFirst = 1, orderFI = 2, orderNone = 255 };

// Quadratic Taylor basis layout: [0,D) first derivatives, [D,2D) diagonal
// second derivatives, [2D,NB) mixed ones, pairs offA/offB.
template <int D> struct Taylor {
  static constexpr int NB = D + D * (D + 1) / 2;
  static constexpr int numOff = NB - 2 * D;
  static constexpr int offA[3] = {0, 1, 0};
  static constexpr int offB[3] = {1, 2, 2};
  using VecB = Eigen::Matrix<double, NB, 1>;
  using MatB = Eigen::Matrix<double, NB, NB>;
  // P(s) and phi(s) = Phi / kappa.
  static void fill(const Vec<D>& s, double invRho2, VecB& P, VecB& phi) {
    for (int a = 0; a < D; ++a) {
      P[a] = s[a];
      phi[a] = s[a];
      const double q = s[a] * s[a];
      P[D + a] = 0.5 * q;
      phi[D + a] = q * invRho2;
    }
    for (int k = 0; k < numOff; ++k) {
      const double q = s[offA[k]] * s[offB[k]];
      P[2 * D + k] = q;
      phi[2 * D + k] = q * invRho2;
    }
  }
};

// 1-norm reciprocal condition number from a matrix and its inverse; 0 or NaN
// when the inverse is not finite (a failed test `rcond > tol` either way).
template <class M>
inline double rcond1(const M& a, const M& inv) {
  const double na = a.cwiseAbs().colwise().sum().maxCoeff();
  const double ni = inv.cwiseAbs().colwise().sum().maxCoeff();
  return 1.0 / (na * ni);
}

// w and the plain gradient for every pair of row i; stores kappa = c h^2 in lapW
// (scratch for the FI pass). Returns nothing: rows are [b, e).
template <int D>
inline void kernelRow(const Kernel<D>& k, const NeighbourList<D>& nl, Index b, Index e, PairWeights<D>& out) {
  const double h2 = k.h() * k.h();
  for (Index p = b; p < e; ++p) {
    const double r = nl.r[p];
    double w, dw;
    k.eval(r, w, dw);
    const double c = -dw / r;
    out.w[p] = w;
    out.gradW[p] = -c * nl.rij[p];
    out.lapW[p] = c * h2;
  }
}

// FI row (after kernelRow). Returns false (weights untouched) if the stencil
// fails the FI criteria.
template <int D>
inline bool fiRow(double h, double V, const NeighbourList<D>& nl, Index b, Index e, PairWeights<D>& out) {
  using T = Taylor<D>;
  if (e - b < Thresholds<D>::minNeighboursFI) return false;
  const double invH = 1.0 / h;
  typename T::MatB S = T::MatB::Zero();
  typename T::VecB P, phi;
  for (Index p = b; p < e; ++p) {
    const Vec<D> s = -invH * nl.rij[p];
    const double rho = nl.r[p] * invH;
    T::fill(s, 1.0 / (rho * rho), P, phi);
    S.noalias() += (out.lapW[p] * phi) * P.transpose();
  }
  const typename T::MatB Sinv = Eigen::PartialPivLU<typename T::MatB>(S).inverse();
  if (!(rcond1(S, Sinv) > Thresholds<D>::minRcondFI)) return false;
  const double gScale = invH / V, lScale = invH * invH / V;
  Eigen::Matrix<double, D, T::NB> G = gScale * Sinv.template topRows<D>();
  typename T::VecB ell = lScale * Sinv.template middleRows<D>(D).colwise().sum().transpose();
  for (Index p = b; p < e; ++p) {
    const Vec<D> s = -invH * nl.rij[p];
    const double rho = nl.r[p] * invH;
    T::fill(s, 1.0 / (rho * rho), P, phi);
    const double kappa = out.lapW[p];
    out.gradW[p] = kappa * (G * phi);
    out.lapW[p] = kappa * ell.dot(phi);
  }
  return true;
}

// Standard row (after kernelRow): plain gradient, Morris/Brookshaw Laplacian 2c.
template <int D>
inline void standardRow(double h, const NeighbourList<D>& nl, Index b, Index e, PairWeights<D>& out) {
  const double invH2 = 1.0 / (h * h);
  for (Index p = b; p < e; ++p) out.lapW[p] = 2.0 * out.lapW[p] * invH2;  // kappa = c h^2
}

// First-order row (after kernelRow): KGC gradient and renormalised Laplacian.
// Returns false (weights untouched) if the 2x2/3x3 correction is singular.
template <int D>
inline bool firstOrderRow(double h, double V, const NeighbourList<D>& nl, Index b, Index e,
                          PairWeights<D>& out) {
  if (e - b < Thresholds<D>::minNeighboursFirstOrder) return false;
  const double invH = 1.0 / h;
  Mat<D> A = Mat<D>::Zero(), B = Mat<D>::Zero();
  Vec<D> o = Vec<D>::Zero();
  for (Index p = b; p < e; ++p) {
    const Vec<D> s = -invH * nl.rij[p];  // r_ji / h
    A.noalias() += out.gradW[p] * s.transpose();
    B.noalias() += out.w[p] * s * s.transpose();
    o += out.w[p] * s;
  }
  A *= V * h;  // = V sum gradW (x) r_ji
  const Mat<D> L = A.inverse();
  if (!(rcond1(A, L) > Thresholds<D>::minRcondFirstOrder)) return false;
  // renormalised Laplacian (scaled units: s = r_ji/h)
  const Vec<D> Bo = B.inverse() * o;
  double den = 0;
  bool ok = Bo.allFinite();
  if (ok) {
    for (Index p = b; p < e; ++p) {
      const Vec<D> s = -invH * nl.rij[p];
      den += out.w[p] * s.squaredNorm() * (1.0 - s.dot(Bo));
    }
    ok = den > 0 && std::isfinite(den);
  }
  const double lScale = ok ? 2.0 * D / (V * den * h * h) : 0.0;
  const double invH2 = invH * invH;
  for (Index p = b; p < e; ++p) {
    if (ok) {
      const Vec<D> s = -invH * nl.rij[p];
      out.lapW[p] = lScale * out.w[p] * (1.0 - s.dot(Bo));
    } else {
      out.lapW[p] = 2.0 * out.lapW[p] * invH2;  // Morris/Brookshaw
    }
    out.gradW[p] = L * out.gradW[p];
  }
  return true;
}

// Resize the outputs and run `row(i, b, e)` -> order for every particle with
// computeFor[i] != 0 (all particles if computeFor is empty); other rows get
// zero weights and order 255. OpenMP over particles.
template <int D, class Row>
void computeRows(const NeighbourList<D>& nl, const std::vector<std::uint8_t>& computeFor,
                 PairWeights<D>& out, Row&& row) {
  const std::size_t n = nl.numParticles(), np = nl.numPairs();
  if (!computeFor.empty() && computeFor.size() != n)
    throw std::invalid_argument("computeWeights: computeFor has the wrong size");
  out.w.resize(np);
  out.gradW.resize(np);
  out.lapW.resize(np);
  out.order.resize(n);
  const bool all = computeFor.empty();
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    const Index b = nl.offset[i], e = nl.offset[i + 1];
    if (all || computeFor[i]) {
      out.order[i] = row(i, b, e);
    } else {
      out.order[i] = orderNone;
      for (Index p = b; p < e; ++p) {
        out.w[p] = 0;
        out.gradW[p].setZero();
        out.lapW[p] = 0;
      }
    }
  }
}

}  // namespace weights
}  // namespace shizuku
