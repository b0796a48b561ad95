// Per-particle ("row") building blocks of the derivative weights, shared by the
// SPH2, corrected and standard operators (docs/method.md 3.2, 3.4, 3.5). Internal
// header of libsph/operators.
//
// Notation (docs/method.md 0): r_ij = r_i - r_j, r_ji = -r_ij, gradW_ij = w'(r) r_ij / r
// = c r_ji with c = -w'(r)/r >= 0.
// FI (3.2), scaled by h: s = r_ji / h, rho = r / h,
//   P(s)   = (s_a ; s_a^2/2 ; s_a s_b)            Taylor basis, X = (h f_a ; h^2 f_aa ; h^2 f_ab)
//   Phi    = (kappa s_a ; beta s_a^2 ; beta s_a s_b), kappa = c h^2, beta = kappa / rho^2
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
#include "core/OverwriteBuffer.hpp"
#include "operators/DerivativeOperator.hpp"
#include <algorithm>
#include <cmath>

namespace shizuku {
namespace weights {

// Fallback thresholds of docs/method.md 3.4 with the dimension defaults filled in.
template <int D> struct Limits {
  int minNeighboursFI, minNeighboursFirstOrder;
  double minRcondFI, minRcondFirstOrder, minLaplacianRenormalisation, maxGradientAmplification;
  explicit Limits(const FallbackThresholds& t)
      : minNeighboursFI(t.minNeighboursFI > 0 ? t.minNeighboursFI : (D == 2 ? 6 : 12)),
        minNeighboursFirstOrder(t.minNeighboursFirstOrder > 0 ? t.minNeighboursFirstOrder : (D == 2 ? 3 : 4)),
        minRcondFI(t.minRcondFI),
        minRcondFirstOrder(t.minRcondFirstOrder),
        minLaplacianRenormalisation(t.minLaplacianRenormalisation),
        maxGradientAmplification(t.maxGradientAmplification) {}
};

using Pair = DoublePair;  // core/types.hpp

enum Order : std::uint8_t { orderStandard = 0, orderFirst = 1, orderFI = 2, orderNone = 255 };

// Quadratic Taylor basis layout: [0,D) first derivatives, [D,2D) diagonal
// second derivatives, [2D,NB) mixed ones, pairs offA/offB.
template <int D> struct Taylor {
  static constexpr int NB = D + D * (D + 1) / 2;
  static constexpr int numOff = NB - 2 * D;
  static constexpr int offA[3] = {0, 1, 0};
  static constexpr int offB[3] = {1, 2, 2};
  // P(s) and the test-function vector Phi for given kappa and beta.
  static void fill(const Vec<D>& s, double kappa, double beta, double* P, double* phi) {
    for (int a = 0; a < D; ++a) {
      P[a] = s[a];
      phi[a] = kappa * s[a];
      const double q = s[a] * s[a];
      P[D + a] = 0.5 * q;
      phi[D + a] = beta * q;
    }
    for (int k = 0; k < numOff; ++k) {
      const double q = s[offA[k]] * s[offB[k]];
      P[2 * D + k] = q;
      phi[2 * D + k] = beta * q;
    }
  }
};

// Moments of the FI matrix. Every entry of S = sum_j Phi P^T is a kernel-
// weighted moment of s: S[a][b] = sum kappa s_a s_b, S[a][2nd l] = c_l sum kappa s_a q_l,
// S[2nd k][b] = sum beta q_k s_b, S[2nd k][2nd l] = c_l sum beta q_k q_l, with q the
// quadratic monomials in Taylor order and c_l = 1/2 (diagonal) or 1 (mixed). So
// per pair only the distinct monomials of degree 2..4 are accumulated: 16 (2D) /
// 41 (3D) multiply-adds instead of 25 / 81. Tables built at compile time.
template <int D> struct Monomials {
  static constexpr int n2 = D * (D + 1) / 2, n3 = D == 2 ? 4 : 10, n4 = D == 2 ? 5 : 15;
  int e2[n2][3] = {}, e3[n3][3] = {}, e4[n4][3] = {};  // exponents
  int par3[n3] = {}, var3[n3] = {}, par4[n4] = {}, var4[n4] = {};  // m3 = m2[par3] s[var3], ...
  int sq[D][D] = {};       // s_a s_b -> degree-2 index
  int mul13[D][n2] = {};   // s_a q_m -> degree-3 index
  int mul22[n2][n2] = {};  // q_k q_m -> degree-4 index

  static constexpr bool same(const int* a, const int* b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }
  template <int N> static constexpr int find(const int (&list)[N][3], const int* e) {
    for (int m = 0; m < N; ++m)
      if (same(list[m], e)) return m;
    return -1;
  }
  template <int N> static constexpr void enumerate(int (&list)[N][3], int degree) {
    int m = 0;
    for (int a = degree; a >= 0; --a)
      for (int b = degree - a; b >= 0; --b) {
        const int c = degree - a - b;
        if (D == 2 && c != 0) continue;
        list[m][0] = a;
        list[m][1] = b;
        list[m][2] = c;
        ++m;
      }
  }
  // Each monomial of `list` as a monomial of `lower` (one degree less) times one
  // variable: the first variable it contains.
  template <int N, int M>
  static constexpr void parents(const int (&list)[N][3], const int (&lower)[M][3], int (&par)[N], int (&var)[N]) {
    for (int m = 0; m < N; ++m) {
      int a = 0;
      while (list[m][a] == 0) ++a;
      int e[3] = {list[m][0], list[m][1], list[m][2]};
      e[a] -= 1;
      par[m] = find(lower, e);
      var[m] = a;
    }
  }
  constexpr Monomials() {
    for (int a = 0; a < D; ++a) e2[a][a] = 2;
    for (int k = 0; k < n2 - D; ++k) {
      e2[D + k][Taylor<D>::offA[k]] += 1;
      e2[D + k][Taylor<D>::offB[k]] += 1;
    }
    enumerate(e3, 3);
    enumerate(e4, 4);
    parents(e3, e2, par3, var3);
    parents(e4, e3, par4, var4);
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) {
        int e[3] = {0, 0, 0};
        e[a] += 1;
        e[b] += 1;
        sq[a][b] = find(e2, e);
      }
    for (int a = 0; a < D; ++a)
      for (int m = 0; m < n2; ++m) {
        int e[3] = {e2[m][0], e2[m][1], e2[m][2]};
        e[a] += 1;
        mul13[a][m] = find(e3, e);
      }
    for (int k = 0; k < n2; ++k)
      for (int m = 0; m < n2; ++m) {
        int e[3] = {e2[k][0] + e2[m][0], e2[k][1] + e2[m][1], e2[k][2] + e2[m][2]};
        mul22[k][m] = find(e4, e);
      }
  }
};

// Inverse of a small fixed-size matrix by Gauss-Jordan elimination with
// partial pivoting (for N = 2..9 several times faster than Eigen's blocked
// PartialPivLU::inverse). Returns false on a zero or non-finite pivot.
template <int N>
inline bool invertSmall(const double (&m)[N][N], double (&b)[N][N]) {
  double a[N][N];
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      a[i][j] = m[i][j];
      b[i][j] = i == j ? 1.0 : 0.0;
    }
  for (int k = 0; k < N; ++k) {
    int piv = k;
    double best = std::abs(a[k][k]);
    for (int i = k + 1; i < N; ++i)
      if (std::abs(a[i][k]) > best) {
        best = std::abs(a[i][k]);
        piv = i;
      }
    if (!(best > 0) || !std::isfinite(best)) return false;
    if (piv != k)
      for (int j = 0; j < N; ++j) {
        std::swap(a[k][j], a[piv][j]);
        std::swap(b[k][j], b[piv][j]);
      }
    const double d = 1.0 / a[k][k];
    for (int j = 0; j < N; ++j) {
      a[k][j] *= d;
      b[k][j] *= d;
    }
    for (int i = 0; i < N; ++i) {
      if (i == k) continue;
      const double f = a[i][k];
      for (int j = 0; j < N; ++j) {
        a[i][j] -= f * a[k][j];
        b[i][j] -= f * b[k][j];
      }
    }
  }
  return true;
}

// 1-norm reciprocal condition number from a matrix and its inverse.
template <int N>
inline double rcond1(const double (&m)[N][N], const double (&inv)[N][N]) {
  double na = 0, ni = 0;
  for (int j = 0; j < N; ++j) {
    double ca = 0, ci = 0;
    for (int i = 0; i < N; ++i) {
      ca += std::abs(m[i][j]);
      ci += std::abs(inv[i][j]);
    }
    na = std::max(na, ca);
    ni = std::max(ni, ci);
  }
  return 1.0 / (na * ni);
}

// Eigen D x D front end: inverse and its 1-norm rcond (0 if singular).
template <int D>
inline double invertWithRcond(const Mat<D>& m, Mat<D>& inv) {
  double a[D][D], b[D][D];
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) a[i][j] = m(i, j);
  if (!invertSmall<D>(a, b)) return 0.0;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) inv(i, j) = b[i][j];
  return rcond1<D>(a, b);
}

// Kernel pass of row [b, e): kappa = c h^2 into out.lapW and
// beta = kappa h^2 / r^2 into out.gradW[p][0] (scratch, overwritten by the row
// functions below, one of which must follow). Returns the row's largest kernel
// gradient |dW/dr| (the reference of gradientBounded).
template <int D>
inline double kernelRow(const Kernel<D>& k, const NeighbourList<D>& nl, std::size_t i, Index b, Index e, PairWeights<D>& out) {
  const double h2 = k.h() * k.h();
  double largest = 0;
  // Two pairs at a time: their square roots, divisions and kernel derivatives share one
  // packed instruction each (the same operations as the scalar loop below, lane by lane).
  Index p = b;
  Pair largest2 = {0, 0};
  for (; p + 1 < e; p += 2) {
    const Pair r = nl.r2(i, p);
    const auto positive = r > 0.0;
    const Pair invR = positive ? 1.0 / r : Pair{0, 0};
    const Pair dw = k.dwdr(r);
    const Pair kappa = -dw * invR * h2;
    const Pair beta = kappa * h2 * invR * invR;
    out.lapW[p] = kappa[0];
    out.lapW[p + 1] = kappa[1];
    out.gradW[p][0] = beta[0];
    out.gradW[p + 1][0] = beta[1];
    const Pair absDw = positive ? (dw < 0.0 ? -dw : dw) : Pair{0, 0};
    largest2 = largest2 > absDw ? largest2 : absDw;
  }
  largest = std::max(largest2[0], largest2[1]);
  for (; p < e; ++p) {
    const double r = nl.r(i, p), invR = r > 0 ? 1.0 / r : 0.0;  // coincident particles: no weight
    double w, dw;
    k.eval(r, w, dw);
    const double kappa = -dw * invR * h2;
    out.lapW[p] = kappa;
    out.gradW[p][0] = kappa * h2 * invR * invR;
    if (r > 0) largest = std::max(largest, std::abs(dw));
  }
  return largest;
}

// The FI matrix S of row [b, e) (after kernelRow): its moments summed over the pairs, then
// placed by the tables of Monomials. The moments are summed in pairs of doubles (one SSE2
// register each), so that the 16 sums of 2D stay in registers instead of spilling to the
// stack and waiting on their own stores: (kappa m3, beta m3) side by side, and kappa m2
// followed by beta m4 two at a time. Each lane adds the same products in the same order as
// a scalar sum would.
template <int D>
inline void fiMatrix(double invH, const NeighbourList<D>& nl, std::size_t i, Index b, Index e, const PairWeights<D>& out,
                     double (&S)[Taylor<D>::NB][Taylor<D>::NB]) {
  using T = Taylor<D>;
  using Mo = Monomials<D>;
  static constexpr Mo mo{};
  constexpr int n2 = Mo::n2, n3 = Mo::n3, n4 = Mo::n4;
  constexpr int nKB = n2 + n4, nPairs = (nKB + 1) / 2;
  Pair K3B3[n3] = {}, K2B4[nPairs] = {};
  for (Index p = b; p < e; ++p) {
    const Vec<D> s = -invH * nl.rij(i, p);
    const double kappa = out.lapW[p], beta = out.gradW[p][0];
    double m2[n2], m3[n3], mono[2 * nPairs];  // mono: m2 then m4 (then a zero pad)
    for (int a = 0; a < D; ++a) m2[a] = s[a] * s[a];
    for (int k = 0; k < T::numOff; ++k) m2[D + k] = s[T::offA[k]] * s[T::offB[k]];
    for (int m = 0; m < n3; ++m) m3[m] = m2[mo.par3[m]] * s[mo.var3[m]];
    for (int m = 0; m < n2; ++m) mono[m] = m2[m];
    for (int m = 0; m < n4; ++m) mono[n2 + m] = m3[mo.par4[m]] * s[mo.var4[m]];
    if (nKB % 2) mono[nKB] = 0;
    const Pair kb = {kappa, beta};
    for (int m = 0; m < n3; ++m) K3B3[m] += kb * m3[m];
    for (int k = 0; k < nPairs; ++k) {
      const Pair c = {2 * k < n2 ? kappa : beta, 2 * k + 1 < n2 ? kappa : beta};
      const Pair q = {mono[2 * k], mono[2 * k + 1]};
      K2B4[k] += c * q;
    }
  }
  double K2[n2], K3[n3], B3[n3], B4[n4];
  for (int m = 0; m < n3; ++m) {
    K3[m] = K3B3[m][0];
    B3[m] = K3B3[m][1];
  }
  for (int m = 0; m < nKB; ++m) (m < n2 ? K2[m] : B4[m - n2]) = K2B4[m / 2][m % 2];
  for (int a = 0; a < D; ++a) {
    for (int b = 0; b < D; ++b) {
      S[a][b] = K2[mo.sq[a][b]];
    }
    for (int m = 0; m < n2; ++m) {
      const double c = m < D ? 0.5 : 1.0;  // P = s_a^2 / 2 on the diagonal
      S[a][D + m] = c * K3[mo.mul13[a][m]];
      S[D + m][a] = B3[mo.mul13[a][m]];
    }
  }
  for (int k = 0; k < n2; ++k)
    for (int m = 0; m < n2; ++m) S[D + k][D + m] = (m < D ? 0.5 : 1.0) * B4[mo.mul22[k][m]];
}

// FI row (after kernelRow). Returns false (kernelRow scratch untouched) if the
// stencil fails the FI criteria.
template <int D>
inline bool fiRow(const Limits<D>& lim, double h, double V, const NeighbourList<D>& nl, std::size_t i, Index b, Index e,
                  PairWeights<D>& out) {
  using T = Taylor<D>;
  constexpr int NB = T::NB;
  constexpr int n2 = Monomials<D>::n2;
  if (e - b < lim.minNeighboursFI) return false;
  const double invH = 1.0 / h;
  double S[NB][NB];
  fiMatrix<D>(invH, nl, i, b, e, out, S);
  double Sinv[NB][NB];
  if (!invertSmall<NB>(S, Sinv) || !(rcond1<NB>(S, Sinv) > lim.minRcondFI)) return false;
  // tilde gradW = G Phi, tilde lapW = ell . Phi with Phi = (kappa s ; beta q)
  const double gScale = invH / V, lScale = invH * invH / V;
  double G[D][NB], ell[NB];
  for (int l = 0; l < NB; ++l) {
    for (int a = 0; a < D; ++a) G[a][l] = gScale * Sinv[a][l];
    double sum = 0;
    for (int a = 0; a < D; ++a) sum += Sinv[D + a][l];
    ell[l] = lScale * sum;
  }
  // The gradient's components two at a time (columns of G as pairs, a zero lane in 3D).
  constexpr int nG = (D + 1) / 2;
  Pair Gp[nG][NB];
  for (int k = 0; k < nG; ++k)
    for (int l = 0; l < NB; ++l) Gp[k][l] = Pair{G[2 * k][l], 2 * k + 1 < D ? G[2 * k + 1][l] : 0.0};
  for (Index p = b; p < e; ++p) {
    const Vec<D> s = -invH * nl.rij(i, p);
    const double kappa = out.lapW[p], beta = out.gradW[p][0];
    double q[n2];
    for (int a = 0; a < D; ++a) q[a] = s[a] * s[a];
    for (int k = 0; k < T::numOff; ++k) q[D + k] = s[T::offA[k]] * s[T::offB[k]];
    // Written component by component: a Vec<D> assembled in scalars and stored whole made
    // the compiler spill it and reload it as a vector, a store-forwarding stall per pair.
    double* g = out.gradW[p].data();
    for (int k = 0; k < nG; ++k) {
      Pair gs = {0, 0}, gq = {0, 0};
      for (int c = 0; c < D; ++c) gs += Gp[k][c] * s[c];
      for (int m = 0; m < n2; ++m) gq += Gp[k][D + m] * q[m];
      const Pair gk = kappa * gs + beta * gq;
      g[2 * k] = gk[0];
      if (2 * k + 1 < D) g[2 * k + 1] = gk[1];
    }
    double ls = 0, lq = 0;
    for (int a = 0; a < D; ++a) ls += ell[a] * s[a];
    for (int m = 0; m < n2; ++m) lq += ell[D + m] * q[m];
    out.lapW[p] = kappa * ls + beta * lq;
  }
  return true;
}

// Standard row (after kernelRow): plain gradient, Morris/Brookshaw Laplacian 2c.
template <int D>
inline void standardRow(double h, const NeighbourList<D>& nl, std::size_t i, Index b, Index e, PairWeights<D>& out) {
  const double invH2 = 1.0 / (h * h);
  for (Index p = b; p < e; ++p) {
    const double c = out.lapW[p] * invH2;  // kappa = c h^2
    out.gradW[p] = -c * nl.rij(i, p);  // c r_ji
    out.lapW[p] = 2.0 * c;
  }
}

// Whether a row's corrected gradient weights stay within lim.maxGradientAmplification
// times `kernelGradient` (docs/method.md 3.4): on one-sided stencils the correction
// matrices can pass their rcond test and still multiply the kernel gradient a hundredfold.
template <int D>
inline bool gradientBounded(const Limits<D>& lim, double kernelGradient, Index b, Index e, const PairWeights<D>& out) {
  const double bound = lim.maxGradientAmplification * kernelGradient;
  for (Index p = b; p < e; ++p)
    if (!(out.gradW[p].squaredNorm() <= bound * bound)) return false;
  return true;
}

// First-order row (after kernelRow): KGC gradient and renormalised Laplacian.
// Returns false (weights untouched) if the 2x2/3x3 correction is singular.
template <int D>
inline bool firstOrderRow(const Limits<D>& lim, const Kernel<D>& k, double V, const NeighbourList<D>& nl, std::size_t i,
                          Index b, Index e, PairWeights<D>& out) {
  const double h = k.h();
  if (e - b < lim.minNeighboursFirstOrder) return false;
  const double invH = 1.0 / h;
  Mat<D> A = Mat<D>::Zero(), B = Mat<D>::Zero();
  Vec<D> o = Vec<D>::Zero();
  for (Index p = b; p < e; ++p) {
    const Vec<D> rij = nl.rij(i, p), s = -invH * rij;  // r_ji / h
    const double w = k.w(rij.norm());
    A.noalias() += out.lapW[p] * s * s.transpose();  // kappa s s^T = h gradW (x) s
    B.noalias() += w * s * s.transpose();
    o += w * s;
  }
  A *= V;  // = V sum gradW (x) r_ji
  Mat<D> L;
  if (!(invertWithRcond<D>(A, L) > lim.minRcondFirstOrder)) return false;
  // renormalised Laplacian (scaled units: s = r_ji/h)
  Mat<D> Binv;
  bool ok = invertWithRcond<D>(B, Binv) > 0;
  const Vec<D> Bo = ok ? Vec<D>(Binv * o) : Vec<D>::Zero();
  // den -> 0 on one-sided stencils (a convex corner with a far neighbour beyond it):
  // the weights grow as 1/den, so the row takes Morris's Laplacian below a tenth of
  // the unrenormalised sum (FallbackThresholds::minLaplacianRenormalisation).
  double den = 0, plain = 0;
  ok = ok && Bo.allFinite();
  if (ok) {
    for (Index p = b; p < e; ++p) {
      const Vec<D> rij = nl.rij(i, p), s = -invH * rij;
      const double w = k.w(rij.norm());
      den += w * s.squaredNorm() * (1.0 - s.dot(Bo));
      plain += w * s.squaredNorm();
    }
    ok = den > lim.minLaplacianRenormalisation * plain && std::isfinite(den);
  }
  const double lScale = ok ? 2.0 * D / (V * den * h * h) : 0.0;
  const double invH2 = invH * invH;
  for (Index p = b; p < e; ++p) {
    const Vec<D> rij = nl.rij(i, p), s = -invH * rij;
    const double kappa = out.lapW[p];
    out.gradW[p] = (kappa * invH) * (L * s);  // L gradW, gradW = c r_ji = kappa s / h
    out.lapW[p] = ok ? lScale * k.w(rij.norm()) * (1.0 - s.dot(Bo)) : 2.0 * kappa * invH2;  // else Morris
  }
  return true;
}

// Resize the outputs and run `row(i, b, e)` -> order for every particle with
// computeFor[i] != 0 (all particles if computeFor is empty); other rows get
// zero gradient and Laplacian weights and order 255. OpenMP over particles.
template <int D, class Row>
void computeRows(const NeighbourList<D>& nl, const std::vector<std::uint8_t>& computeFor,
                 PairWeights<D>& out, Row&& row) {
  const std::size_t n = nl.numParticles(), np = nl.numPairs();
  if (!computeFor.empty() && computeFor.size() != n)
    throw std::invalid_argument("computeWeights: computeFor has the wrong size");
  resizeForOverwrite(out.gradW, np);  // every pair's weights are written below
  resizeForOverwrite(out.lapW, np);
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
        out.gradW[p].setZero();
        out.lapW[p] = 0;
      }
    }
  }
}

}  // namespace weights
}  // namespace shizuku
