// Preconditioned BiCGSTAB, OpenMP parallel (see Krylov.hpp). Per iteration:
//   p = r + beta (p - omega v);  y = M^-1 p;  v = A y;        alpha = rho / (r0, v)
//   s = r - alpha v;  (stop with x += alpha y if ||s|| is small)
//   z = M^-1 s;  t = A z;  omega = (t, s) / (t, t)
//   x += alpha y + omega z;  r = s - omega t;  rho' = (r0, r)
// A vanishing rho (r orthogonal to the shadow residual) restarts with r0 = r. s is kept in
// r's storage (seven vectors of n).
#include "linearSolvers/Krylov.hpp"
#include <cmath>
#include <vector>

namespace shizuku {

void KrylovWorkspace::resize(int n) {
  for (auto* v : {&r, &r0, &p, &v, &t, &y, &z}) v->resize(n);
}

namespace {
// The one row loop of the products below: f(i, (A x)_i - b_i) for every row (b null: zero),
// OpenMP over rows; Reduce carries the reductions (a struct with operator+=, value-initialised
// to zero).
template <class Reduce, class F>
Reduce overRows(const SparseMatrixR& A, const double* x, const double* b, F&& f) {
  const int n = int(A.rows());
  const int* outer = A.outerIndexPtr();
  const int* col = A.innerIndexPtr();
  const double* val = A.valuePtr();
  Reduce total{};
#pragma omp declare reduction(sum : Reduce : omp_out += omp_in) initializer(omp_priv = Reduce{})
#pragma omp parallel for schedule(static) reduction(sum : total)
  for (int i = 0; i < n; ++i) {
    double s = b ? -b[i] : 0.0;
    for (int p = outer[i]; p < outer[i + 1]; ++p) s += val[p] * x[col[p]];
    f(i, s, total);
  }
  return total;
}

struct NoSum {
  NoSum& operator+=(const NoSum&) { return *this; }
};
struct TwoSums {
  double a = 0, b = 0;
  TwoSums& operator+=(const TwoSums& o) { a += o.a; b += o.b; return *this; }
};

// y = A x; returns (a, y) in ay and, when WithNorm, (y, y) in yy (one pass over the matrix).
template <bool WithNorm>
void multiplyDots(const SparseMatrixR& A, const double* x, double* y, const double* a, double& ay, double& yy) {
  const TwoSums t = overRows<TwoSums>(A, x, nullptr, [&](int i, double s, TwoSums& r) {
    y[i] = s;
    r.a += s * a[i];
    if (WithNorm) r.b += s * s;
  });
  ay = t.a;
  yy = t.b;
}
}  // namespace

void multiply(const SparseMatrixR& A, const double* x, double* y) {
  overRows<NoSum>(A, x, nullptr, [&](int i, double s, NoSum&) { y[i] = s; });
}

double relativeResidual(const SparseMatrixR& A, const double* b, const double* x) {
  const TwoSums t = overRows<TwoSums>(A, x, b, [&](int i, double s, TwoSums& r) {
    r.a += s * s;
    r.b += b[i] * b[i];
  });
  return t.b > 0 ? std::sqrt(t.a / t.b) : std::sqrt(t.a);
}

KrylovResult bicgstab(const SparseMatrixR& A, const double* b, double* x, const Preconditioner& M,
                      double tolerance, int maxIterations, KrylovWorkspace& w) {
  KrylovResult res;
  const int n = int(A.rows());
  w.resize(n);
  double* r = w.r.data();
  double* r0 = w.r0.data();
  double* p = w.p.data();
  double* v = w.v.data();
  double* s = r;  // s = r - alpha v overwrites r, which is not read again before r = s - omega t
  double* t = w.t.data();
  double* y = w.y.data();
  double* z = w.z.data();

  // r = b - A x, r0 = r, p = v = 0.
  multiply(A, x, v);
  double bb = 0, rr = 0;
#pragma omp parallel for schedule(static) reduction(+ : bb, rr)
  for (int i = 0; i < n; ++i) {
    r[i] = b[i] - v[i];
    r0[i] = r[i];
    p[i] = 0;
    v[i] = 0;
    bb += b[i] * b[i];
    rr += r[i] * r[i];
  }
  if (bb == 0) {
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; ++i) x[i] = 0;
    res.converged = true;
    return res;
  }
  const double target2 = tolerance * tolerance * bb;
  res.residual = std::sqrt(rr / bb);
  if (rr <= target2) { res.converged = true; return res; }
  double rho = 1, alpha = 1, omega = 1, rhoNew = rr, r0norm2 = rr;
  int restarts = 0;
  for (int it = 0; it < maxIterations; ++it) {
    res.iterations = it + 1;
    // Restart when r has become (nearly) orthogonal to the shadow residual.
    if (std::abs(rhoNew) < 1e-30 * r0norm2) {
      if (++restarts > 10) { res.breakdown = true; return res; }
      rr = 0;
#pragma omp parallel for schedule(static) reduction(+ : rr)
      for (int i = 0; i < n; ++i) { r0[i] = r[i]; p[i] = 0; v[i] = 0; rr += r[i] * r[i]; }
      rhoNew = r0norm2 = rr;
      rho = alpha = omega = 1;
    }
    const double beta = (rhoNew / rho) * (alpha / omega);
    rho = rhoNew;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; ++i) p[i] = r[i] + beta * (p[i] - omega * v[i]);
    M.apply(p, y);
    double r0v = 0, unused = 0;
    multiplyDots<false>(A, y, v, r0, r0v, unused);
    if (r0v == 0 || !std::isfinite(r0v)) { res.breakdown = true; return res; }
    alpha = rho / r0v;
    double ss = 0;
#pragma omp parallel for schedule(static) reduction(+ : ss)
    for (int i = 0; i < n; ++i) {
      s[i] = r[i] - alpha * v[i];
      ss += s[i] * s[i];
    }
    if (ss <= target2) {
#pragma omp parallel for schedule(static)
      for (int i = 0; i < n; ++i) x[i] += alpha * y[i];
      res.residual = std::sqrt(ss / bb);
      res.converged = true;
      return res;
    }
    M.apply(s, z);
    double ts = 0, tt = 0;
    multiplyDots<true>(A, z, t, s, ts, tt);
    if (tt == 0 || !std::isfinite(tt)) { res.breakdown = true; return res; }
    omega = ts / tt;
    if (omega == 0) { res.breakdown = true; return res; }
    rr = 0;
    rhoNew = 0;
#pragma omp parallel for schedule(static) reduction(+ : rr, rhoNew)
    for (int i = 0; i < n; ++i) {
      x[i] += alpha * y[i] + omega * z[i];
      r[i] = s[i] - omega * t[i];
      rr += r[i] * r[i];
      rhoNew += r0[i] * r[i];
    }
    res.residual = std::sqrt(rr / bb);
    if (!std::isfinite(rr)) { res.breakdown = true; return res; }
    if (rr <= target2) { res.converged = true; return res; }
  }
  return res;
}

}  // namespace shizuku
