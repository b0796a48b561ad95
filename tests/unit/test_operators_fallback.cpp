// Fallback chain of the SPH2 weights near free surfaces (docs/method.md 3.4): a flat free surface (without the amplification bound) and a convex corner keep FI
// (order 2), a 2-particle-thick jet falls back to first order (order 1), a
// single row to standard SPH (order 0); an isolated particle gets standard
// (zero) weights. Weights stay finite, the order flag is what the operator
// used, and each fallback keeps its own exactness (linear fields for order 1).
// Also: rows marked 2 in computeFor (free-surface rows) start at first order, rows
// marked 3 (splash) get standard weights,
// and FallbackThresholds move the switch points. A first-order row whose renormalised
// Laplacian would divide by nearly zero takes Morris's weights (2D and 3D), and a row
// whose corrected gradient weights exceed ten times its kernel gradient takes the next
// link of the chain (a flat surface's FI row: 19 times in 2D, 59 in 3D).
#define BOOST_TEST_MODULE operators_fallback
#include <boost/test/unit_test.hpp>

#include "test_operators_helpers.hpp"
#include <limits>

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

// FI and first order without the bound on gradient amplification (docs/method.md 3.4): what
// the correction itself does on a surface stencil, where the solver's chain would not use it.
FallbackThresholds unbounded() {
  FallbackThresholds t;
  t.maxGradientAmplification = std::numeric_limits<double>::infinity();
  return t;
}

// Weights at the particle nearest `target` with the given scheme and thresholds.
template <int D>
Stencil at(const std::vector<Vec<D>>& x, double d0, const Vec<D>& target, DerivativeScheme scheme,
           const FallbackThresholds& limits = unbounded()) {
  const std::size_t i = closest(x, target);
  std::vector<std::uint8_t> mask(x.size(), 0);
  mask[i] = 1;
  Setup<D> s(x, d0, scheme, mask);
  DerivativeOperator<D>::create(scheme, limits)->computeWeights(s.kernel, s.V, s.nl, mask, s.pw);
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
  // With the solver's bound (weights at most 10 times the largest kernel gradient) the flat
  // surface's FI weights (19 times) are refused and the row takes first order, as a
  // free-surface row does anyway; the corner's (7.6 times) are kept.
  BOOST_TEST(at(select(base, flat), d0, c, DerivativeScheme::SPH2, FallbackThresholds()).order == 1);
  BOOST_TEST(at(select(base, corner), d0, c, DerivativeScheme::SPH2, FallbackThresholds()).order == 2);
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
  // The 3D half-space's FI weights are 59 times its largest kernel gradient: refused.
  BOOST_TEST(at(select(block, half3), d0, c, DerivativeScheme::SPH2, FallbackThresholds()).order == 1);
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
  DerivativeOperator<2>::create(DerivativeScheme::SPH2, unbounded())->computeWeights(s.kernel, s.V, s.nl, mask, s.pw);
  BOOST_TEST(int(s.pw.order[i]) == 2);
  BOOST_TEST(int(s.pw.order[k]) == 1);
  // a stricter FI threshold sends the surface particle to first order
  FallbackThresholds t = unbounded();
  t.minRcondFI = 1e-2;
  auto op = DerivativeOperator<2>::create(DerivativeScheme::SPH2, t);
  BOOST_TEST(op->thresholds().minRcondFI == 1e-2);
  std::fill(mask.begin(), mask.end(), 1);
  op->computeWeights(s.kernel, s.V, s.nl, mask, s.pw);
  BOOST_TEST(int(s.pw.order[i]) == 1);
  BOOST_TEST(int(s.pw.order[k]) == 2);
  // a higher neighbour minimum does the same
  FallbackThresholds n = unbounded();
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

namespace {
// The Laplacian weights of particle i (first-order row, computeFor = 2) with the given
// threshold; returns the largest |lapW_ij| over the largest Morris weight -2 w'(r)/r of
// the row, and the Laplacian of f = x^2 (exact 2) at i.
template <int D>
std::pair<double, double> renormalisedLaplacian(const std::vector<Vec<D>>& x, double d0, std::size_t i,
                                                double minRenormalisation) {
  std::vector<std::uint8_t> mask(x.size(), 0);
  mask[i] = 2;
  Setup<D> s(x, d0, DerivativeScheme::SPH2, mask);
  FallbackThresholds t;
  t.minLaplacianRenormalisation = minRenormalisation;
  DerivativeOperator<D>::create(DerivativeScheme::SPH2, t)->computeWeights(s.kernel, s.V, s.nl, mask, s.pw);
  BOOST_TEST_REQUIRE(int(s.pw.order[i]) == 1);
  double largest = 0, morris = 0, lap = 0;
  for (Index k = s.nl.begin(i); k < s.nl.end(i); ++k) {
    const double r = s.nl.r(i, k);
    largest = std::max(largest, std::abs(s.pw.lapW[k]));
    morris = std::max(morris, -2 * s.kernel.dwdr(r) / r);
    const Vec<D>& xj = x[s.nl.j[k]];
    lap += s.V * s.pw.lapW[k] * (xj[0] * xj[0] - x[i][0] * x[i][0]);
  }
  return {largest / morris, lap};
}

// A convex corner of the lattice (the particle at the origin, neighbours at i, j <= 0)
// with one more neighbour beyond it at `extra` (in d0): a splash particle passing a
// corner of the surface. Found by a scan of such stencils: their renormalisation
// denominator is 2e-4 (2D) and 5e-4 (3D) of the plain sum.
template <int D>
std::vector<Vec<D>> cornerWithStray(double d0, const Vec<D>& extra) {
  std::vector<Vec<D>> x;
  const int n = 3;
  for (int a = -n; a <= 0; ++a)
    for (int b = -n; b <= 0; ++b)
      for (int c = (D == 3 ? -n : 0); c <= 0; ++c) {
        Vec<D> p;
        p[0] = a * d0;
        p[1] = b * d0;
        if constexpr (D == 3) p[2] = c * d0;
        x.push_back(p);
      }
  x.push_back(extra * d0);
  return x;
}
}  // namespace

// The renormalised Laplacian of a first-order row (docs/method.md 3.5) divides by
// sum_j w s^2 chi, which passes through zero as a stencil turns one-sided. Near zero its
// weights were a thousand times Morris's: in the wave flume (d0 = 1 cm) a free particle
// at a crest got lapW ~ 1e15, nu <lap u> of 4.6e5 m/s^2 in the predictor and 473 m/s in
// one step. Such rows now take Morris's Laplacian; a flat surface keeps the renormalised
// one (its denominator is 0.46 of the plain sum; disordered by 0.15 d0, at least 0.10 of
// it in 2000 samples).
BOOST_AUTO_TEST_CASE(renormalised_laplacian_guard) {
  const double d0 = 0.01;
  {
    const auto x = cornerWithStray<2>(d0, Vec<2>(2.1, -0.55));
    const std::size_t i = closest(x, Vec<2>(0, 0));
    const auto unguarded = renormalisedLaplacian<2>(x, d0, i, 0.0);
    const auto guarded = renormalisedLaplacian<2>(x, d0, i, FallbackThresholds().minLaplacianRenormalisation);
    BOOST_TEST_MESSAGE("2D corner + stray: largest |lapW| / Morris " << unguarded.first << " -> " << guarded.first
                       << ", lap x^2 " << unguarded.second << " -> " << guarded.second << " (exact 2)");
    BOOST_TEST(unguarded.first > 100);             // what the guard catches
    BOOST_TEST(guarded.first == 1.0, boost::test_tools::tolerance(1e-12));  // Morris's weights
    BOOST_TEST(std::abs(guarded.second - 2) < 3);  // a one-sided Morris Laplacian: O(1) error
  }
  {
    const auto x = cornerWithStray<3>(d0, Vec<3>(1.2, -1.0, -1.0));
    const std::size_t i = closest(x, Vec<3>(0, 0, 0));
    const auto unguarded = renormalisedLaplacian<3>(x, d0, i, 0.0);
    const auto guarded = renormalisedLaplacian<3>(x, d0, i, FallbackThresholds().minLaplacianRenormalisation);
    BOOST_TEST_MESSAGE("3D corner + stray: largest |lapW| / Morris " << unguarded.first << " -> " << guarded.first
                       << ", lap x^2 " << unguarded.second << " -> " << guarded.second << " (exact 2)");
    BOOST_TEST(unguarded.first > 100);
    BOOST_TEST(guarded.first == 1.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(std::abs(guarded.second - 2) < 3);
  }
  // A flat surface keeps the renormalised Laplacian: exact for linear fields, and its
  // weights are not Morris's.
  const auto flatSet = select(lattice<2>(50, 1.0, 0.0), flat);
  const std::size_t k = closest(flatSet, Vec<2>(0.5, 0.5));
  std::vector<std::uint8_t> mask(flatSet.size(), 0);
  mask[k] = 2;
  Setup<2> s(flatSet, 0.02, DerivativeScheme::SPH2, mask);
  double linear = 0;
  for (Index p = s.nl.begin(k); p < s.nl.end(k); ++p) {
    const Vec<2>& xj = flatSet[s.nl.j[p]];
    linear += s.V * s.pw.lapW[p] * (0.3 * (xj[0] - flatSet[k][0]) - 0.7 * (xj[1] - flatSet[k][1]));
  }
  BOOST_TEST(std::abs(linear) < 1e-9);
  BOOST_TEST(renormalisedLaplacian<2>(flatSet, 0.02, k, FallbackThresholds().minLaplacianRenormalisation).first != 1.0);
}

// FI and first-order weights are kept only while no corrected gradient weight exceeds ten
// times the row's largest kernel gradient (docs/method.md 3.4). The stencil is the one a
// vicinity particle had in a thin film behind the weir (tutorials/weir, d0 = 1 cm, two
// threads, t = 1.4275 s; offsets in d0, its 13 neighbours): its FI matrix passed the rcond
// test, its weights were 112 times the kernel gradient, and the step's pressure gradient
// threw it up at 165 m/s. Healthy rows measured in the same run stay below 5.6 (FI) and 10
// (first order); a lattice interior 1.0, the row below a flat surface 1.25.
BOOST_AUTO_TEST_CASE(gradient_amplification_bound) {
  const double d0 = 0.01;
  const double offsets[][2] = {{-0.953, -1.504}, {-0.275, -0.903}, {-2.003, -1.297}, {-0.008, -1.811}, {0.806, -1.537},
                               {0.497, -0.809},  {1.300, -0.679},  {-1.094, -0.649}, {-1.863, -0.202}, {-0.862, 0.243},
                               {-2.087, 0.702},  {0.838, 0.138},   {1.968, 0.158}};
  std::vector<Vec<2>> x = {Vec<2>(0, 0)};
  for (const auto& o : offsets) x.push_back(Vec<2>(o[0] * d0, o[1] * d0));
  std::vector<std::uint8_t> mask(x.size(), 0);
  mask[0] = 1;
  Setup<2> s(x, d0, DerivativeScheme::SPH2, mask);
  auto amplification = [&] {
    double g = 0, k = 0;
    for (Index p = s.nl.begin(0); p < s.nl.end(0); ++p) {
      g = std::max(g, s.pw.gradW[p].norm());
      k = std::max(k, std::abs(s.kernel.dwdr(s.nl.r(0, p))));
    }
    return g / k;
  };
  BOOST_TEST_REQUIRE(s.nl.end(0) - s.nl.begin(0) == 13);
  const double bounded = amplification();
  const int boundedOrder = s.pw.order[0];
  DerivativeOperator<2>::create(DerivativeScheme::SPH2, unbounded())->computeWeights(s.kernel, s.V, s.nl, mask, s.pw);
  const double free = amplification();
  BOOST_TEST_MESSAGE("thin-film stencil: FI unbounded amplification " << free << " (order " << int(s.pw.order[0])
                     << "); bounded " << bounded << " (order " << boundedOrder << ")");
  BOOST_TEST(int(s.pw.order[0]) == 2);
  BOOST_TEST(free > 50);
  BOOST_TEST(boundedOrder < 2);
  BOOST_TEST(bounded <= FallbackThresholds().maxGradientAmplification);
}
