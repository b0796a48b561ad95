// Prescribed wall motions (particles/WallMotion, particles/MotionSignal; docs/boundaries.md,
// "Moving walls"): every motion type's position, velocity and acceleration against its
// analytic value, table interpolation (linear exact on its segments, the spline against
// the function it samples), the composition of steps, and the input errors.
#define BOOST_TEST_MODULE particles_motion
#include <boost/test/unit_test.hpp>
#include "../support/TempCase.hpp"
#include "particles/WallMotion.hpp"
#include <cmath>

using namespace shizuku;

namespace {

template <int D>
std::shared_ptr<WallMotion<D>> motion(const std::string& text, const std::string& caseDir = "case") {
  static std::vector<std::unique_ptr<Dictionary>> keep;  // the motion keeps no reference, but errors name the file
  keep.push_back(std::make_unique<Dictionary>(Dictionary::fromString(text, caseDir + "/system/particlesDict")));
  return WallMotion<D>::read(*keep.back(), caseDir);
}

template <int D>
double maxDiff(const Vec<D>& a, const Vec<D>& b) { return (a - b).cwiseAbs().maxCoeff(); }

// The message of the InputError that reading `text` throws ("" if none).
template <int D>
std::string errorOf(const std::string& text, const std::string& caseDir = "case") {
  try {
    motion<D>(text, caseDir);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

BOOST_AUTO_TEST_CASE(oscillating_with_ramp_is_exact) {
  // d = r(t) A sin(w t + phase), r = (1 - cos(pi t / Tr))/2 up to Tr.
  auto m = motion<2>("type oscillating; amplitude (0.05 0.01); period 0.8; phase 30; rampTime 1.6;");
  const Vec<2> A(0.05, 0.01), X(0.3, 0.2);
  const double w = 2 * M_PI / 0.8, ph = M_PI / 6, Tr = 1.6, c = M_PI / Tr;
  for (double t : {0.0, 0.37, 1.2, 1.6, 2.9}) {
    const double r = t < Tr ? 0.5 * (1 - std::cos(c * t)) : 1, dr = t < Tr ? 0.5 * c * std::sin(c * t) : 0,
                 ddr = t < Tr ? 0.5 * c * c * std::cos(c * t) : 0;
    const double g = std::sin(w * t + ph), dg = w * std::cos(w * t + ph), ddg = -w * w * g;
    const Pose<2> p = m->pose(t);
    BOOST_TEST(maxDiff<2>(p.position(X), X + r * g * A) < 1e-15);
    BOOST_TEST(maxDiff<2>(p.velocity(X), (dr * g + r * dg) * A) < 1e-14);
    BOOST_TEST(maxDiff<2>(p.acceleration(X), (ddr * g + 2 * dr * dg + r * ddg) * A) < 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(expression_translation_derivatives_converge) {
  // The derivatives of an expression are central differences of fourth order with a step
  // of 1e-4 s: against the exact derivatives of 0.1 sin(2 pi t / T) for T = 0.8 s and
  // T = 0.05 s (a wall shaken at 20 Hz), within 1e-9 of the amplitude's scale.
  for (double T : {0.8, 0.05}) {
    const std::string e = "0.1*sin(2*pi*t/" + std::to_string(T) + ")";
    auto m = motion<2>("type translation; displacement (\"" + e + "\" \"0\");");
    const double w = 2 * M_PI / T;
    for (double t : {0.0, 0.013, 0.41}) {
      const Pose<2> p = m->pose(t);
      BOOST_TEST(std::abs(p.b.x() - 0.1 * std::sin(w * t)) < 1e-15);
      BOOST_TEST(std::abs(p.db.x() - 0.1 * w * std::cos(w * t)) < 1e-9 * 0.1 * w);
      BOOST_TEST(std::abs(p.ddb.x() + 0.1 * w * w * std::sin(w * t)) < 1e-7 * 0.1 * w * w);
      BOOST_TEST(p.db.y() == 0.0);
    }
  }
}

BOOST_AUTO_TEST_CASE(rotation_2d_is_a_rigid_rotation_about_the_centre) {
  // 30 deg/s counter-clockwise about c: x = c + R (X - c), u = w e_z x (x - c),
  // a = -w^2 (x - c).
  auto m = motion<2>("type rotation; centre (0.45 0.1); angle \"30*t\";");
  const Vec<2> c(0.45, 0.1), X(0.9, 0.3);
  const double w = 30 * M_PI / 180;
  for (double t : {0.0, 0.5, 3.0}) {
    const double th = w * t;
    const Pose<2> p = m->pose(t);
    const Vec<2> r = X - c;
    const Vec<2> rr(std::cos(th) * r.x() - std::sin(th) * r.y(), std::sin(th) * r.x() + std::cos(th) * r.y());
    BOOST_TEST(maxDiff<2>(p.position(X), c + rr) < 1e-15);
    BOOST_TEST(maxDiff<2>(p.velocity(X), w * Vec<2>(-rr.y(), rr.x())) < 1e-10);
    BOOST_TEST(maxDiff<2>(p.acceleration(X), -w * w * rr) < 1e-8);
    BOOST_TEST(maxDiff<2>(p.restPosition(p.position(X)), X) < 1e-15);
  }
}

BOOST_AUTO_TEST_CASE(rotation_3d_about_an_axis_with_angular_acceleration) {
  // theta = 20 t^2 deg about (1 1 0)/sqrt 2 through c: u = Omega x r, a = Omega' x r +
  // Omega x (Omega x r), r = x - c.
  auto m = motion<3>("type rotation; centre (0.1 0.2 0.3); axis (1 1 0); angle \"20*t^2\";");
  const Vec<3> c(0.1, 0.2, 0.3), X(0.5, -0.2, 0.9), e = Vec<3>(1, 1, 0).normalized();
  for (double t : {0.0, 0.7, 2.0}) {
    const double k = 20 * M_PI / 180, th = k * t * t, w = 2 * k * t, dw = 2 * k;
    const Pose<3> p = m->pose(t);
    const Vec<3> r = Eigen::AngleAxisd(th, e) * (X - c);
    const Vec<3> Om = w * e, dOm = dw * e;
    BOOST_TEST(maxDiff<3>(p.position(X), c + r) < 1e-15);
    BOOST_TEST(maxDiff<3>(p.velocity(X), Vec<3>(Om.cross(r))) < 1e-9);
    BOOST_TEST(maxDiff<3>(p.acceleration(X), Vec<3>(dOm.cross(r) + Om.cross(Om.cross(r)))) < 1e-6);
  }
}

BOOST_AUTO_TEST_CASE(steps_compose_in_file_order) {
  // Roll about c, then sway d(t) = (0.02 sin(2 pi t), 0): x = c + R (X - c) + d,
  // u = w e_z x (x - d - c) + d'.
  auto m = motion<2>("roll { type rotation; centre (0 0); angle \"10*t\"; }\n"
                     "sway { type oscillating; amplitude (0.02 0); period 1; }\n");
  const Vec<2> X(0.2, 0.1);
  const double w = 10 * M_PI / 180;
  for (double t : {0.3, 1.1}) {
    const Pose<2> p = m->pose(t);
    const double th = w * t;
    const Vec<2> r(std::cos(th) * X.x() - std::sin(th) * X.y(), std::sin(th) * X.x() + std::cos(th) * X.y());
    const Vec<2> d(0.02 * std::sin(2 * M_PI * t), 0), dd(0.02 * 2 * M_PI * std::cos(2 * M_PI * t), 0);
    BOOST_TEST(maxDiff<2>(p.position(X), r + d) < 1e-15);
    BOOST_TEST(maxDiff<2>(p.velocity(X), Vec<2>(w * Vec<2>(-r.y(), r.x()) + dd)) < 1e-10);
  }
  BOOST_TEST(m->describe().find(" then oscillating") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(tables_interpolate_linearly_and_by_spline) {
  test::TempCase c("motionTables");
  c.file("constant/line.dat", "# t dx dy\n0 0 0\n1 1 0\n\n2 0 0.5\n");
  auto lin = motion<2>("type translation; table \"constant/line.dat\";", c.dir());
  BOOST_TEST(maxDiff<2>(lin->pose(0.5).b, Vec<2>(0.5, 0)) < 1e-15);
  BOOST_TEST(maxDiff<2>(lin->pose(0.5).db, Vec<2>(1, 0)) < 1e-15);
  BOOST_TEST(maxDiff<2>(lin->pose(1.5).b, Vec<2>(0.5, 0.25)) < 1e-15);
  BOOST_TEST(maxDiff<2>(lin->pose(1.5).db, Vec<2>(-1, 0.5)) < 1e-15);
  BOOST_TEST(maxDiff<2>(lin->pose(7).b, Vec<2>(0, 0.5)) < 1e-15);  // the last row holds
  BOOST_TEST(lin->pose(7).db.norm() == 0.0);
  // A natural spline through sin(t) sampled every 0.05 s, six decimals: in the interior
  // measured 5.0e-7 in the value (the rounding of the table), 2.3e-5 in the slope and
  // 1.3e-3 in the curvature (the rounding divided by h and h^2 dominates the spline's own
  // h^3 and h^2 errors); bounds at about twice those.
  std::string rows;
  for (int i = 0; i <= 126; ++i) rows += std::to_string(0.05 * i) + " " + std::to_string(std::sin(0.05 * i)) + " 0\n";
  c.file("constant/sine.dat", rows);
  auto sp = motion<2>("type translation; table \"constant/sine.dat\"; interpolation spline;", c.dir());
  double ef = 0, edf = 0, eddf = 0;
  for (double t = 1.0; t < 5.0; t += 0.0137) {
    const Pose<2> p = sp->pose(t);
    ef = std::max(ef, std::abs(p.b.x() - std::sin(t)));
    edf = std::max(edf, std::abs(p.db.x() - std::cos(t)));
    eddf = std::max(eddf, std::abs(p.ddb.x() + std::sin(t)));
  }
  BOOST_TEST_MESSAGE("spline errors: value " << ef << ", slope " << edf << ", curvature " << eddf);
  BOOST_TEST(ef < 1e-6);
  BOOST_TEST(edf < 5e-5);
  BOOST_TEST(eddf < 3e-3);
}

BOOST_AUTO_TEST_CASE(bad_motions_name_file_line_and_keyword) {
  test::TempCase c("motionErrors");
  c.file("constant/back.dat", "0 0 0\n1 0.1 0\n0.5 0.2 0\n");
  const std::string back = errorOf<2>("type translation; table \"constant/back.dat\";", c.dir());
  BOOST_TEST_MESSAGE(back);
  BOOST_TEST(back.find("back.dat', line 3") != std::string::npos);
  BOOST_TEST(back.find("does not increase") != std::string::npos);
  BOOST_TEST(back.find("particlesDict:1") != std::string::npos);
  const std::string noCentre = errorOf<2>("type rotation;\nangle \"5*t\";");
  BOOST_TEST(noCentre.find("centre") != std::string::npos);
  const std::string noAxis = errorOf<3>("type rotation; centre (0 0 0); angle \"5*t\";");
  BOOST_TEST(noAxis.find("axis") != std::string::npos);
  const std::string inf = errorOf<2>("type translation;\ndisplacement (\"1/t\" \"0\");");
  BOOST_TEST_MESSAGE(inf);
  BOOST_TEST(inf.find("particlesDict:2") != std::string::npos);
  BOOST_TEST(inf.find("not finite") != std::string::npos);
  const std::string typo = errorOf<2>("type rotaton; centre (0 0); angle \"t\";");
  BOOST_TEST(typo.find("did you mean 'rotation'") != std::string::npos);
  const std::string unknown = errorOf<2>("type translation; displacement (\"x\" \"0\");");
  BOOST_TEST(unknown.find("'x' is not a variable") != std::string::npos);
  BOOST_TEST(!errorOf<2>("type translation; displacement (\"t\");").empty());  // one expression of two
  BOOST_TEST(!errorOf<2>("type oscillating; amplitude (0.1 0); period 0;").empty());
  BOOST_TEST(!errorOf<2>("type oscillating; amplitude (0.1 0); period 1; colour red;").empty());
  BOOST_TEST(!errorOf<2>("").empty());  // an empty motion
}
