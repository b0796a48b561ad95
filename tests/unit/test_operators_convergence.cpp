// Convergence orders of the derivative operators (docs/method.md 3.3): f = sin(2x+0.5) cos(1.5y) + x^2 y on
// [0,1]^2, errors (rms over particles in (0.3,0.7)^2) at d0 = 1/20, 1/40, 1/80,
// h = 1.2 d0, regular and +-0.2 d0 disordered; orders fitted by least squares
// over the sequence. Plus a 3D check of the SPH2 gradient order.
#define BOOST_TEST_MODULE operators_convergence
#include <boost/test/unit_test.hpp>

#include "test_operators_helpers.hpp"
#include <iomanip>
#include <map>

using namespace shizuku;
using namespace shizuku::testing;

namespace {

struct Field2 {
  static double f(const Vec<2>& p) {
    const double x = p[0], y = p[1];
    return std::sin(2 * x + 0.5) * std::cos(1.5 * y) + x * x * y;
  }
  static Vec<2> grad(const Vec<2>& p) {
    const double x = p[0], y = p[1];
    return Vec<2>(2 * std::cos(2 * x + 0.5) * std::cos(1.5 * y) + 2 * x * y,
                  -1.5 * std::sin(2 * x + 0.5) * std::sin(1.5 * y) + x * x);
  }
  static double lap(const Vec<2>& p) {
    const double x = p[0], y = p[1];
    return -6.25 * std::sin(2 * x + 0.5) * std::cos(1.5 * y) + 2 * y;
  }
};

struct Result {
  std::vector<double> d0, grad, lap;
};

// Errors of one scheme on the resolution sequence.
Result run2d(DerivativeScheme scheme, double eps, KernelType kt) {
  Result res;
  for (int n : {20, 40, 80}) {
    const double d0 = 1.0 / n;
    auto x = lattice<2>(n, 1.0, eps, 1234 + n);
    Setup<2> s(x, d0, scheme, inside<2>(x, 0.3, 0.7), kt);
    std::vector<double> f(x.size()), l, eg(x.size()), el(x.size());
    std::vector<Vec<2>> g;
    for (std::size_t i = 0; i < x.size(); ++i) f[i] = Field2::f(x[i]);
    Ops<2>::gradient(s.nl, s.pw, s.V, f, g);
    Ops<2>::laplacian(s.nl, s.pw, s.V, f, l);
    for (std::size_t i = 0; i < x.size(); ++i) {
      eg[i] = (g[i] - Field2::grad(x[i])).norm();
      el[i] = l[i] - Field2::lap(x[i]);
    }
    res.d0.push_back(d0);
    res.grad.push_back(rms(eg, s.mask));
    res.lap.push_back(rms(el, s.mask));
  }
  return res;
}

void report(const std::string& name, const Result& r) {
  std::ostringstream os;
  os << std::setw(28) << std::left << name << std::scientific << std::setprecision(3);
  for (std::size_t k = 0; k < r.d0.size(); ++k) os << "  grad " << r.grad[k] << " lap " << r.lap[k];
  os << std::fixed << std::setprecision(2) << "  | order grad " << fittedOrder(r.d0, r.grad) << " lap "
     << fittedOrder(r.d0, r.lap);
  BOOST_TEST_MESSAGE(os.str());
}

// SPH2 with kernel kt on a regular and a disordered (0.2 d0) 2D lattice, reported under
// `label`: the gradient second order on both, the Laplacian second order on the
// regular lattice and first order on the disordered one. Returns (regular, disordered).
std::pair<Result, Result> sph2Orders(KernelType kt, const std::string& label) {
  const Result reg = run2d(DerivativeScheme::SPH2, 0.0, kt);
  const Result dis = run2d(DerivativeScheme::SPH2, 0.2, kt);
  report(label + "SPH2 regular", reg);
  report(label + "SPH2 disordered", dis);
  BOOST_TEST(fittedOrder(reg.d0, reg.grad) >= 1.8);
  BOOST_TEST(fittedOrder(dis.d0, dis.grad) >= 1.8);
  BOOST_TEST(fittedOrder(reg.d0, reg.lap) >= 1.8);
  BOOST_TEST(fittedOrder(dis.d0, dis.lap) >= 0.9);
  return {reg, dis};
}

}  // namespace

// Measured (cubic spline; sph2_check.out in brackets), rms errors d0 = 1/20, 1/40, 1/80:
//  regular    SPH2 grad 4.527e-3 1.146e-3 2.882e-4 [same], lap 7.855e-3 1.939e-3 4.815e-4 [same]
//  disordered SPH2 grad 4.836e-3 1.216e-3 3.036e-4 (order 2.00) [4.846e-3 1.210e-3 3.027e-4],
//             SPH2 lap  2.122e-2 9.050e-3 4.458e-3 (order 1.13) [1.935e-2 8.504e-3 4.598e-3],
//             corrected grad order 1.05 [KGC 1.07, 0.98]; standard grad order 0.02, 0.24 regular
// The asserted bounds are those of docs/method.md 3.3 with a margin for the
// random disorder (other seeds move the disordered orders by ~0.1).
BOOST_AUTO_TEST_CASE(orders_2d_cubic_spline) {
  const KernelType kt = KernelType::cubicSpline;
  const auto [sph2Reg, sph2Dis] = sph2Orders(kt, "");
  const Result corrReg = run2d(DerivativeScheme::corrected, 0.0, kt);
  const Result corrDis = run2d(DerivativeScheme::corrected, 0.2, kt);
  const Result stdReg = run2d(DerivativeScheme::standard, 0.0, kt);
  const Result stdDis = run2d(DerivativeScheme::standard, 0.2, kt);
  report("corrected regular", corrReg);
  report("corrected disordered", corrDis);
  report("standard regular", stdReg);
  report("standard disordered", stdDis);

  BOOST_TEST(fittedOrder(corrReg.d0, corrReg.grad) >= 1.8);
  BOOST_TEST(fittedOrder(corrDis.d0, corrDis.grad) >= 0.85);
  BOOST_TEST(fittedOrder(corrDis.d0, corrDis.grad) < 1.5);  // first order only
  BOOST_TEST(fittedOrder(stdReg.d0, stdReg.grad) < 0.5);
  BOOST_TEST(fittedOrder(stdDis.d0, stdDis.grad) < 0.5);
  // regular lattice, cubic spline: same stencils as sph2_check.py, so the
  // errors agree with sph2_check.out to its 4 printed digits (allow 0.5 %)
  const double refGrad[3] = {4.527e-3, 1.146e-3, 2.882e-4}, refLap[3] = {7.855e-3, 1.939e-3, 4.815e-4};
  for (int k = 0; k < 3; ++k) {
    BOOST_TEST(std::abs(sph2Reg.grad[k] / refGrad[k] - 1) < 5e-3);
    BOOST_TEST(std::abs(sph2Reg.lap[k] / refLap[k] - 1) < 5e-3);
    BOOST_TEST(std::abs(corrReg.grad[k] / refGrad[k] - 1) < 5e-3);  // KGC = FI gradient on a lattice
  }
  // disordered errors: same magnitude as sph2_check.out (another random draw)
  BOOST_TEST(sph2Dis.grad[2] < 2 * 3.027e-4);
  BOOST_TEST(sph2Dis.lap[2] < 2 * 4.598e-3);
}

BOOST_AUTO_TEST_CASE(orders_2d_wendland) {
  const Result sph2Reg = sph2Orders(KernelType::WendlandC2, "Wendland ").first;
  const double refGrad[3] = {4.114e-3, 1.041e-3, 2.620e-4};  // sph2_check.out, Wendland regular
  for (int k = 0; k < 3; ++k) BOOST_TEST(std::abs(sph2Reg.grad[k] / refGrad[k] - 1) < 5e-3);
}

BOOST_AUTO_TEST_CASE(sph2_gradient_order_3d) {
  auto f = [](const Vec<3>& p) { return std::sin(2 * p[0] + 0.5) * std::cos(1.5 * p[1]) * std::cos(p[2]) + p[0] * p[0] * p[1] * p[2]; };
  auto grad = [](const Vec<3>& p) {
    const double x = p[0], y = p[1], z = p[2];
    return Vec<3>(2 * std::cos(2 * x + 0.5) * std::cos(1.5 * y) * std::cos(z) + 2 * x * y * z,
                  -1.5 * std::sin(2 * x + 0.5) * std::sin(1.5 * y) * std::cos(z) + x * x * z,
                  -std::sin(2 * x + 0.5) * std::cos(1.5 * y) * std::sin(z) + x * x * y);
  };
  for (double eps : {0.0, 0.2}) {
    std::vector<double> d0s, errs;
    for (int n : {10, 20, 40}) {
      const double d0 = 1.0 / n;
      auto x = lattice<3>(n, 1.0, eps, 77 + n);
      Setup<3> s(x, d0, DerivativeScheme::SPH2, inside<3>(x, 0.3, 0.7));
      std::vector<double> fv(x.size()), e(x.size());
      std::vector<Vec<3>> g;
      for (std::size_t i = 0; i < x.size(); ++i) fv[i] = f(x[i]);
      Ops<3>::gradient(s.nl, s.pw, s.V, fv, g);
      for (std::size_t i = 0; i < x.size(); ++i) e[i] = (g[i] - grad(x[i])).norm();
      d0s.push_back(d0);
      errs.push_back(rms(e, s.mask));
    }
    const double order = fittedOrder(d0s, errs);
    BOOST_TEST_MESSAGE("3D SPH2 gradient eps=" << eps << ": " << errs[0] << " " << errs[1] << " " << errs[2]
                                               << " order " << order);
    BOOST_TEST(order >= 1.8);
  }
}
