// Kernel tests (docs/method.md section 2): normalisation, derivative, gradient
// antisymmetry, compact support, lattice sums against the table of docs/method.md 2, kernel names, the declared kernel { } settings;
// the two-lane evaluation (eval on a DoublePair) gives the scalar one's bits.
#define BOOST_TEST_MODULE kernels
#include <boost/test/unit_test.hpp>

#include "kernels/Kernel.hpp"
#include "../support/ErrorOf.hpp"
#include "kernels/KernelParameters.hpp"
#include <cmath>
#include <vector>

using namespace shizuku;

namespace {

// Integral of W over the support: integral_0^2h W(r) S_D(r) dr with the
// sphere measure S_2 = 2 pi r, S_3 = 4 pi r^2, by composite Simpson on [0,h]
// and [h,2h] separately (the integrand is a polynomial on each piece for the
// cubic spline and smooth for Wendland, so 2000 panels give ~1e-13).
template <int D>
double integral(const Kernel<D>& k) {
  auto f = [&](double r) { return k.w(r) * (D == 2 ? 2 * M_PI * r : 4 * M_PI * r * r); };
  double total = 0;
  const int n = 2000;
  for (int piece = 0; piece < 2; ++piece) {
    const double a = piece * k.h(), b = (piece + 1) * k.h(), dr = (b - a) / n;
    double s = f(a) + f(b);
    for (int m = 1; m < n; ++m) s += f(a + m * dr) * (m % 2 ? 4 : 2);
    total += s * dr / 3;
  }
  return total;
}

template <int D>
void checkKernel(KernelType type, double h) {
  Kernel<D> k(type, h);
  BOOST_TEST_CONTEXT("D=" << D << " kernel=" << toString(type) << " h=" << h) {
    BOOST_TEST(std::abs(integral(k) - 1.0) < 1e-6);
    // compact support, non-negative, non-increasing
    // q = r * (1/h) may round to just below 2 at r = 2h: W there is ~1e-50
    BOOST_TEST(k.w(2 * h) < 1e-12 * k.w(0));
    BOOST_TEST(k.w(2 * h * (1 + 1e-14)) == 0.0);
    BOOST_TEST(k.w(2.5 * h) == 0.0);
    BOOST_TEST(k.dwdr(2 * h * (1 + 1e-14)) == 0.0);
    BOOST_TEST(k.w(1.999 * h) > 0.0);
    for (double q = 0.05; q < 2; q += 0.05) {
      const double r = q * h;
      BOOST_TEST(k.dwdr(r) <= 0.0);
      // central difference, step 1e-6 h: truncation ~ w''' dr^2 ~ 1e-12
      // relative, round-off ~ 1e-16 w / 1e-6 ~ 1e-10 relative to w/h.
      const double dr = 1e-6 * h;
      const double fd = (k.w(r + dr) - k.w(r - dr)) / (2 * dr);
      BOOST_TEST(std::abs(fd - k.dwdr(r)) < 1e-7 * k.w(0) / h);
    }
    BOOST_TEST(k.dwdr(0.0) == 0.0);
    // gradient antisymmetry grad W(r_ij) = -grad W(-r_ij), and direction toward j
    Vec<D> rij = Vec<D>::Zero();
    for (int a = 0; a < D; ++a) rij[a] = 0.3 * h * (a + 1);
    const double r = rij.norm();
    const Vec<D> g1 = k.gradW(rij, r), g2 = k.gradW(Vec<D>(-rij), r);
    BOOST_TEST((g1 + g2).norm() == 0.0);
    BOOST_TEST(g1.dot(rij) < 0.0);  // points from i toward j, i.e. along -r_ij
    BOOST_TEST(std::abs(g1.norm() - std::abs(k.dwdr(r))) < 1e-14 * g1.norm());
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(normalisation_derivative_support) {
  for (KernelType t : {KernelType::cubicSpline, KernelType::WendlandC2})
    for (double h : {1.0, 0.012, 3.7}) {
      checkKernel<2>(t, h);
      checkKernel<3>(t, h);
    }
}

// docs/method.md 2 table, h = 1.2 d0, units 1/d0^2 in 2D.
BOOST_AUTO_TEST_CASE(values_and_lattice_sums_2d) {
  const double d0 = 0.01;
  Kernel<2> cs(KernelType::cubicSpline, 1.2 * d0), wc(KernelType::WendlandC2, 1.2 * d0);
  const double u = d0 * d0;
  // table values are printed with 5 significant digits: tolerance half a unit of the last digit
  BOOST_TEST(std::abs(cs.w(0) * u - 0.31578) < 5e-6);
  BOOST_TEST(std::abs(cs.w(d0) * u - 0.12390) < 5e-6);
  BOOST_TEST(std::abs(wc.w(0) * u - 0.38683) < 5e-6);
  BOOST_TEST(std::abs(wc.w(d0) * u - 0.11944) < 5e-6);
  // Shepard sums printed with 4 decimals
  BOOST_TEST(std::abs(cs.latticeSum(d0) * u - 0.9998) < 5e-5);
  BOOST_TEST(std::abs(wc.latticeSum(d0) * u - 1.0180) < 5e-5);
}

// The lattice sum is a Riemann sum of the normalised kernel: d0^D * sum -> 1
// as h/d0 grows (measured: h=3 d0 within 1.6e-4 in 2D and 3D for both kernels; 3D h=1.2 d0:
// cubic 1.0008, Wendland 1.0175).
BOOST_AUTO_TEST_CASE(lattice_sums_converge_to_one) {
  for (KernelType t : {KernelType::cubicSpline, KernelType::WendlandC2}) {
    Kernel<2> k2(t, 3.0);
    Kernel<3> k3(t, 3.0);
    BOOST_TEST_MESSAGE(toString(t) << ": 2D h=3d0 " << k2.latticeSum(1.0) << ", 3D h=3d0 "
                                   << k3.latticeSum(1.0) << ", 3D h=1.2d0 "
                                   << Kernel<3>(t, 1.2).latticeSum(1.0));
    BOOST_TEST(std::abs(k2.latticeSum(1.0) - 1.0) < 2e-3);
    BOOST_TEST(std::abs(k3.latticeSum(1.0) - 1.0) < 2e-3);
    BOOST_TEST(std::abs(Kernel<3>(t, 1.2).latticeSum(1.0) - 1.0) < 0.05);
  }
}

// Every branch and boundary (q = 0, 1, 2, beyond 2) and 4000 distances between: the packed
// evaluation the weights' kernel pass uses must be the scalar one bit for bit, so that
// vectorising that pass changes no result.
template <int D>
void packedEqualsScalar(KernelType type) {
  const Kernel<D> k(type, 0.012);
  const double h = k.h();
  std::vector<double> r = {0.0, h, 2 * h, 2.5 * h, std::nextafter(h, 0.0), std::nextafter(2 * h, 0.0)};
  for (int m = 0; m < 4000; ++m) r.push_back(2.2 * h * m / 3999.0 + 1e-7 * h * (m % 7));
  for (std::size_t m = 0; m + 1 < r.size(); ++m) {
    DoublePair w2, dw2;
    k.eval(DoublePair{r[m], r[m + 1]}, w2, dw2);
    for (int lane = 0; lane < 2; ++lane) {
      double w, dw;
      k.eval(r[m + lane], w, dw);
      BOOST_TEST(w2[lane] == w, "W at r = " << r[m + lane]);
      BOOST_TEST(dw2[lane] == dw, "dW/dr at r = " << r[m + lane]);
      BOOST_TEST(k.dwdr(DoublePair{r[m], r[m + 1]})[lane] == dw);
    }
  }
}

BOOST_AUTO_TEST_CASE(packed_evaluation_gives_the_scalar_bits) {
  for (KernelType t : {KernelType::cubicSpline, KernelType::WendlandC2}) {
    packedEqualsScalar<2>(t);
    packedEqualsScalar<3>(t);
  }
}

BOOST_AUTO_TEST_CASE(names) {
  BOOST_TEST((kernelTypeFromName("cubicSpline") == KernelType::cubicSpline));
  BOOST_TEST((Kernel<2>::kernelTypeFromName("WendlandC2") == KernelType::WendlandC2));
  BOOST_TEST(toString(KernelType::WendlandC2) == "WendlandC2");
  {
    const std::string msg = test::errorOf([] { kernelTypeFromName("gaussian"); });
    BOOST_TEST(msg.find("gaussian") != std::string::npos);
    BOOST_TEST(msg.find("cubicSpline") != std::string::npos);
    BOOST_TEST(msg.find("WendlandC2") != std::string::npos);
  }
  BOOST_CHECK_THROW(Kernel<2>(KernelType::cubicSpline, 0.0), InputError);
  BOOST_CHECK_THROW(Kernel<2>(KernelType::cubicSpline, 1.0).latticeSum(-1.0), InputError);
}

BOOST_AUTO_TEST_CASE(kernel_settings_from_declarations) {
  const KernelParameters absent = KernelParameters::read(nullptr);
  BOOST_TEST(int(absent.type) == int(KernelType::cubicSpline));
  BOOST_TEST(absent.smoothingLengthRatio == 1.2);
  const Dictionary d = Dictionary::fromString("type WendlandC2; smoothingLengthRatio 1.5;\n", "sphSchemes/kernel");
  const KernelParameters p = KernelParameters::read(&d);
  BOOST_TEST(int(p.type) == int(KernelType::WendlandC2));
  BOOST_TEST(p.smoothingLengthRatio == 1.5);
  const Dictionary bad = Dictionary::fromString("smoothingLengthRatio 3;\n", "sphSchemes/kernel");
  std::string m;
  try { KernelParameters::read(&bad); } catch (const InputError& e) { m = e.what(); }
  BOOST_TEST(m.find("sphSchemes/kernel:1:1: keyword 'smoothingLengthRatio': 3 must be less than 3") != std::string::npos, m);
  const Dictionary typo = Dictionary::fromString("type Wendland;\n", "sphSchemes/kernel");
  m.clear();
  try { KernelParameters::read(&typo); } catch (const InputError& e) { m = e.what(); }
  BOOST_TEST(m.find("did you mean 'WendlandC2'?") != std::string::npos, m);
}
