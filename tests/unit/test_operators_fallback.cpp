// Fallback chain of the SPH2 weights near free surfaces (docs/method.md 3.4): a flat free surface and a convex corner keep FI
// (order 2), a 2-particle-thick jet falls back to first order (order 1), a
// single row to standard SPH (order 0); an isolated particle gets standard
// (zero) weights. Weights stay finite, the order flag is what the operator
// used, and each fallback keeps its own exactness (linear fields for order 1).
// Also: rows marked 2 in computeFor (free-surface rows) start at first order, rows
// marked 3 (splash) get standard weights,
// and FallbackThresholds move the switch points.
#define BOOST_TEST_MODULE operators_fallback
#include <boost/test/unit_test.hpp>

#include "test_operators_helpers.hpp"

using namespace shizuku;
using namespace shizuku::testing;

namespace {

template <int D>
std::vector<Vec<D>> select(const std::vector<Vec<D>>& x, bool (*keep)(const Vec<D>&)) {
  std::vector<Vec<D>> y;
  for (const auto& p : x)
    if (keep(p)) y.push_back(p);
  return y;
}

template <int D>
std::size_t closest(const std::vector<Vec<D>>& x, const Vec<D>& target) {
  std::size_t best = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    if ((x[i] - target).norm() < (x[best] - target).norm()) best = i;
  return best;
}

struct Stencil {
  int order = -1;
  int neighbours = 0;
  double gradErr = 0;   // |grad f - exact| for the smooth test field
  double linearErr = 0; // |grad f - exact| for a linear field
};

// Weights at the particle nearest `target` with the given scheme.
template <int D>
Stencil at(const std::vector<Vec<D>>& x, double d0, const Vec<D>& target, DerivativeScheme scheme) {
  const std::size_t i = closest(x, target);
  std::vector<std::uint8_t> mask(x.size(), 0);
  mask[i] = 1;
  Setup<D> s(x, d0, scheme, mask);
  for (std::size_t p = 0; p < s.nl.numPairs(); ++p) {
    BOOST_TEST_REQUIRE(s.pw.gradW[p].allFinite());
    BOOST_TEST_REQUIRE(std::isfinite(s.pw.lapW[p]));
  }
  Stencil st;
  st.order = s.pw.order[i];
  st.neighbours = s.nl.end(i) - s.nl.begin(i);
  std::vector<double> f(x.size()), lin(x.size());
  std::vector<Vec<D>> g, gl;
  Vec<D> ge, c;
  for (int a = 0; a < D; ++a) c[a] = 0.3 + 0.4 * a;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const Vec<D>& p = x[k];
    f[k] = std::sin(2 * p[0] + 0.5) * std::cos(1.5 * p[1]) + p[0] * p[0] * p[1];
    lin[k] = 1 + c.dot(p);
  }
  ge.setZero();
  const Vec<D>& p = x[i];
  ge[0] = 2 * std::cos(2 * p[0] + 0.5) * std::cos(1.5 * p[1]) + 2 * p[0] * p[1];
  ge[1] = -1.5 * std::sin(2 * p[0] + 0.5) * std::sin(1.5 * p[1]) + p[0] * p[0];
  Ops<D>::gradient(s.nl, s.pw, s.V, f, g);
  Ops<D>::gradient(s.nl, s.pw, s.V, lin, gl);
  st.gradErr = (g[i] - ge).norm();
  st.linearErr = (gl[i] - c).norm();
  return st;
}

bool flat(const Vec<2>& p) { return p[1] <= 0.5 + 1e-9; }
bool corner(const Vec<2>& p) { return p[0] <= 0.5 + 1e-9 && p[1] <= 0.5 + 1e-9; }
bool jet(const Vec<2>& p) { return p[1] >= 0.48 - 1e-9 && p[1] <= 0.5 + 1e-9; }
bool row(const Vec<2>& p) { return std::abs(p[1] - 0.5) < 1e-9; }

}  // namespace

// d0 = 0.02, h = 1.2 d0 (the cases of sph2_surface.py, cubic spline).
BOOST_AUTO_TEST_CASE(fallback_chain_2d) {
  const double d0 = 0.02;
  const auto base = lattice<2>(50, 1.0, 0.0);
  const Vec<2> c(0.5, 0.5);
  const Stencil sFlat = at(select(base, flat), d0, c, DerivativeScheme::SPH2);
  const Stencil kFlat = at(select(base, flat), d0, c, DerivativeScheme::corrected);
  const Stencil sCorner = at(select(base, corner), d0, c, DerivativeScheme::SPH2);
  const Stencil kCorner = at(select(base, corner), d0, c, DerivativeScheme::corrected);
  const Stencil sJet = at(select(base, jet), d0, c, DerivativeScheme::SPH2);
  const Stencil sRow = at(select(base, row), d0, c, DerivativeScheme::SPH2);
  BOOST_TEST_MESSAGE("flat:   n=" << sFlat.neighbours << " order " << sFlat.order << " grad err FI " << sFlat.gradErr
                                  << " KGC " << kFlat.gradErr);
  BOOST_TEST_MESSAGE("corner: n=" << sCorner.neighbours << " order " << sCorner.order << " grad err FI "
                                  << sCorner.gradErr << " KGC " << kCorner.gradErr);
  BOOST_TEST_MESSAGE("jet:    n=" << sJet.neighbours << " order " << sJet.order << " grad err " << sJet.gradErr);
  BOOST_TEST_MESSAGE("row:    n=" << sRow.neighbours << " order " << sRow.order);
  BOOST_TEST(sFlat.neighbours == 12);
  BOOST_TEST(sFlat.order == 2);
  BOOST_TEST(sCorner.neighbours == 7);
  BOOST_TEST(sCorner.order == 2);
  BOOST_TEST(sJet.neighbours == 9);
  BOOST_TEST(sJet.order == 1);
  BOOST_TEST(sRow.neighbours == 4);
  BOOST_TEST(sRow.order == 0);
  // FI stays more accurate than KGC at the surface (sph2_surface.out: 3.6x flat, 68x corner, Wendland)
  BOOST_TEST(sFlat.gradErr < 0.5 * kFlat.gradErr);
  BOOST_TEST(sCorner.gradErr < 0.1 * kCorner.gradErr);
  // exactness of what was used: FI and KGC reproduce linear fields
  BOOST_TEST(sFlat.linearErr < 1e-9);
  BOOST_TEST(sCorner.linearErr < 1e-9);
  BOOST_TEST(sJet.linearErr < 1e-9);
}

BOOST_AUTO_TEST_CASE(isolated_particle_and_sparse_rows) {
  // an isolated particle and a pair: standard weights, no NaN
  std::vector<Vec<2>> x = {Vec<2>(0, 0), Vec<2>(5, 5), Vec<2>(5.01, 5)};
  Setup<2> s(x, 0.01, DerivativeScheme::SPH2, {});
  for (int i = 0; i < 3; ++i) BOOST_TEST(int(s.pw.order[i]) == 0);
  BOOST_TEST(s.nl.numPairs() == 2u);
  for (std::size_t p = 0; p < 2; ++p) BOOST_TEST(s.pw.gradW[p].allFinite());
  Setup<2> k(x, 0.01, DerivativeScheme::corrected, {});
  for (int i = 0; i < 3; ++i) BOOST_TEST(int(k.pw.order[i]) == 0);
  // two coincident particles inside a lattice: the r = 0 pair gets zero
  // weights, the rows stay FI and finite
  auto y = lattice<2>(10, 1.0, 0.0);
  y.push_back(y[60]);
  for (auto scheme : {DerivativeScheme::SPH2, DerivativeScheme::corrected, DerivativeScheme::standard}) {
    Setup<2> c(y, 0.1, scheme, {});
    for (std::size_t p = 0; p < c.nl.numPairs(); ++p) {
      BOOST_TEST_REQUIRE(c.pw.gradW[p].allFinite());
      BOOST_TEST_REQUIRE(std::isfinite(c.pw.lapW[p]));
    }
    if (scheme == DerivativeScheme::SPH2) BOOST_TEST(int(c.pw.order[60]) == 2);
  }
}

namespace {
bool half3(const Vec<3>& p) { return p[2] <= 0.5 + 1e-9; }
bool sheet3(const Vec<3>& p) { return p[2] >= 0.48 - 1e-9 && p[2] <= 0.5 + 1e-9; }
bool plane3(const Vec<3>& p) { return std::abs(p[2] - 0.5) < 1e-9; }
}  // namespace

BOOST_AUTO_TEST_CASE(fallback_chain_3d) {
  const double d0 = 0.02;
  auto base = lattice<3>(50, 1.0, 0.0);
  // keep a block around the centre only (speed)
  std::vector<Vec<3>> block;
  for (const auto& p : base)
    if ((p.array() - 0.5).abs().maxCoeff() < 0.1) block.push_back(p);
  const Vec<3> c(0.5, 0.5, 0.5);
  const Stencil sHalf = at(select(block, half3), d0, c, DerivativeScheme::SPH2);
  const Stencil sSheet = at(select(block, sheet3), d0, c, DerivativeScheme::SPH2);
  const Stencil sPlane = at(select(block, plane3), d0, c, DerivativeScheme::SPH2);
  BOOST_TEST_MESSAGE("3D half-space n=" << sHalf.neighbours << " order " << sHalf.order << "; sheet n="
                                        << sSheet.neighbours << " order " << sSheet.order << "; plane n="
                                        << sPlane.neighbours << " order " << sPlane.order);
  BOOST_TEST(sHalf.order == 2);
  BOOST_TEST(sSheet.order == 1);
  BOOST_TEST(sPlane.order == 0);
  BOOST_TEST(sHalf.linearErr < 1e-9);
  BOOST_TEST(sSheet.linearErr < 1e-9);
}

BOOST_AUTO_TEST_CASE(surface_rows_and_thresholds) {
  const double d0 = 0.02;
  const auto flatSet = select(lattice<2>(50, 1.0, 0.0), flat);
  const std::size_t i = closest(flatSet, Vec<2>(0.5, 0.5));    // on the surface, rcond(M) = 5.1e-3
  const std::size_t k = closest(flatSet, Vec<2>(0.5, 0.3));    // interior, rcond(M) = 0.2
  std::vector<std::uint8_t> mask(flatSet.size(), 0);
  mask[i] = 1;
  mask[k] = 2;  // a free-surface row: SPH2 starts at first order
  Setup<2> s(flatSet, d0, DerivativeScheme::SPH2, mask);
  BOOST_TEST(int(s.pw.order[i]) == 2);
  BOOST_TEST(int(s.pw.order[k]) == 1);
  // a stricter FI threshold sends the surface particle to first order
  FallbackThresholds t;
  t.minRcondFI = 1e-2;
  auto op = DerivativeOperator<2>::create(DerivativeScheme::SPH2, t);
  BOOST_TEST(op->thresholds().minRcondFI == 1e-2);
  std::fill(mask.begin(), mask.end(), 1);
  op->computeWeights(s.kernel, s.V, s.nl, mask, s.pw);
  BOOST_TEST(int(s.pw.order[i]) == 1);
  BOOST_TEST(int(s.pw.order[k]) == 2);
  // a higher neighbour minimum does the same
  FallbackThresholds n;
  n.minNeighboursFI = 13;  // the surface particle has 12
  DerivativeOperator<2>::create(DerivativeScheme::SPH2, n)->computeWeights(s.kernel, s.V, s.nl, mask, s.pw);
  BOOST_TEST(int(s.pw.order[i]) == 1);
  BOOST_TEST(int(s.pw.order[k]) == 2);
}

BOOST_AUTO_TEST_CASE(splash_rows_use_standard_weights) {
  // A row marked 3 (a splash particle) gets standard weights with SPH2 and corrected
  // operators even where its neighbourhood would allow a corrected gradient: built from
  // the few neighbours of a droplet, a correction matrix amplifies their pressure noise.
  const double d0 = 0.02;
  const auto flatSet = select(lattice<2>(50, 1.0, 0.0), flat);
  const std::size_t k = closest(flatSet, Vec<2>(0.5, 0.3));  // interior: FI otherwise
  for (auto scheme : {DerivativeScheme::SPH2, DerivativeScheme::corrected}) {
    std::vector<std::uint8_t> mask(flatSet.size(), 0);
    mask[k] = 3;
    Setup<2> s(flatSet, d0, scheme, mask);
    BOOST_TEST_CONTEXT(toString(scheme)) { BOOST_TEST(int(s.pw.order[k]) == 0); }
    mask[k] = 1;
    Setup<2> full(flatSet, d0, scheme, mask);
    BOOST_TEST_CONTEXT(toString(scheme)) { BOOST_TEST(int(full.pw.order[k]) == (scheme == DerivativeScheme::SPH2 ? 2 : 1)); }
  }
}
