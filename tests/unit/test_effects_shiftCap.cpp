// Tests of capShift (eq. 10: |dr| <= maxShift h): no shift exceeds the cap,
// directions are kept, shorter shifts are untouched.
#define BOOST_TEST_MODULE effects_shiftCap
#include <boost/test/unit_test.hpp>
#include "effects/ShiftCap.hpp"
#include <random>

using namespace shizuku;

template <int D>
void check() {
  std::mt19937 g(5);
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> len(0.0, 0.36);  // up to 3x the cap
  const double cap = 0.12;                                 // 0.1 h with h = 1.2 d0
  std::vector<Vec<D>> dr(10000), before;
  long over = 0;
  for (auto& d : dr) {
    for (int a = 0; a < D; ++a) d[a] = n(g);
    d *= len(g) / d.norm();
    over += d.norm() > cap;
  }
  before = dr;
  const long capped = capShift(dr, cap);
  BOOST_TEST(capped == over);
  for (std::size_t i = 0; i < dr.size(); ++i) {
    BOOST_TEST(dr[i].norm() <= cap * (1 + 1e-15));
    if (before[i].norm() <= cap) {
      BOOST_TEST((dr[i] - before[i]).norm() == 0.0);
    } else {
      BOOST_TEST(dr[i].norm() == cap, boost::test_tools::tolerance(1e-14));
      BOOST_TEST(dr[i].dot(before[i]) / (dr[i].norm() * before[i].norm()) == 1.0, boost::test_tools::tolerance(1e-14));
    }
  }
}

BOOST_AUTO_TEST_CASE(cap_2d) { check<2>(); }
BOOST_AUTO_TEST_CASE(cap_3d) { check<3>(); }
