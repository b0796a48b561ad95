// The prescribed rigid motion of a wall region: see WallMotion.hpp.
#include "particles/WallMotion.hpp"
#include "core/Log.hpp"
#include "core/Parameter.hpp"
#include "particles/ShapeRegion.hpp"
#include <cmath>

namespace shizuku {

namespace {
namespace key {
const ParameterGroup motion("system/particlesDict: regions/<name>/motion",
    "Prescribed motion of a wall region (docs/boundaries.md, \"Moving walls\"); several steps as named "
    "sub-dictionaries, applied in file order.");
const OptionParameter type = motion.option("type", {"translation", "oscillating", "rotation"},
    "translation d(t), oscillating A sin(2 pi t/T + phase), or rotation about centre by angle(t)").required();
const WordListParameter displacement = motion.wordList("displacement",
    "translation: muParser expressions of t (s), one per component, in m").def("none (or table)");
const OptionParameter table = motion.option("table", {},
    "translation, rotation: file of rows `t d_x d_y [d_z]` or `t angle`, relative to the case directory")
    .def("").shownDefault("none (or displacement, angle)");
const OptionParameter interpolation = motion.option("interpolation", {"linear", "spline"},
    "table: linear, or a natural cubic spline (continuous velocity and acceleration)").def("linear");
const VectorParameter amplitude = motion.vector("amplitude", dim::length, "oscillating: amplitude vector A").required();
const ScalarParameter period = motion.scalar("period", dim::time, "oscillating: period T").required().above(0);
const ScalarParameter phase = motion.scalar("phase", dim::none, "oscillating: phase, degrees").def(0);
const ScalarParameter rampTime = motion.scalar("rampTime", dim::time,
    "oscillating: the amplitude rises as (1 - cos(pi t/T_r))/2 over T_r (0: no ramp)").def(0).min(0);
const VectorParameter centre = motion.vector("centre", dim::length, "rotation: the fixed point").required();
const VectorParameter axis = motion.vector("axis", dim::none, "rotation (3D): the axis, right hand").required();
const OptionParameter angle = motion.option("angle", {},
    "rotation: the angle in degrees, counter-clockwise, a muParser expression of t (s)")
    .def("").shownDefault("none (or table)");
}  // namespace key

// The skew matrix K of the rotation generator (2D: about +z; 3D: axis x), with
// R(theta) = I + sin(theta) K + (1 - cos(theta)) K^2.
template <int D>
Mat<D> generator(const Vec<3>& a) {
  Mat<D> K = Mat<D>::Zero();
  if constexpr (D == 2) {
    K(0, 1) = -1;
    K(1, 0) = 1;
  } else {
    K << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  }
  return K;
}

// The signal named by `table` or by `textKey` (expressions), `components` wide.
std::unique_ptr<MotionSignal> readSignal(const Dictionary& d, const char* textKey, int components,
                                         const std::string& caseDir) {
  const bool hasTable = d.found(key::table.keyword()), hasText = d.found(textKey);
  if (hasTable == hasText)
    d.error(hasTable ? key::table.keyword() : d.found("type") ? "type" : key::table.keyword(),
            std::string("give either '") + textKey + "' (expressions of t) or 'table' (a file), " +
                (hasTable ? "not both" : "neither is given"));
  try {
    if (hasTable) {
      const std::string file = d.getWord(key::table.keyword());
      recordParameter(key::table.info(), &d, file, false);
      const bool spline = key::interpolation.read(d) == "spline";
      return MotionSignal::table(resolveCasePath(caseDir, file), components, spline);
    }
    std::vector<std::string> text = d.getWordList(textKey);
    if (int(text.size()) != components)
      d.error(textKey, cat("expected ", components, components == 1 ? " expression" : " expressions, one per component",
                           ", found ", text.size()));
    return MotionSignal::expression(text);
  } catch (const MotionSignalError& e) {
    d.error(hasTable ? key::table.keyword() : textKey, e.what());
  }
}

}  // namespace

template <int D>
Pose<D> Pose<D>::then(const Pose& n) const {
  Pose p;
  p.R = n.R * R;
  p.dR = n.dR * R + n.R * dR;
  p.ddR = n.ddR * R + 2 * n.dR * dR + n.R * ddR;
  p.b = n.R * b + n.b;
  p.db = n.dR * b + n.R * db + n.db;
  p.ddb = n.ddR * b + 2 * n.dR * db + n.R * ddb + n.ddb;
  return p;
}

template <int D>
typename WallMotion<D>::Step WallMotion<D>::readStep(const Dictionary& d, const std::string& caseDir) {
  Step s;
  const std::string type = key::type.read(d);
  if (type == "translation") {
    s.signal = readSignal(d, key::displacement.keyword().c_str(), D, caseDir);
    s.text = "translation by " + s.signal->describe() + " m";
  } else if (type == "oscillating") {
    const Vec<D> a = key::amplitude.read<D>(d);
    std::array<double, 3> amp{};
    for (int k = 0; k < D; ++k) amp[k] = a[k];
    const double T = key::period.read(d), ph = key::phase.read(d) * M_PI / 180, ramp = key::rampTime.read(d);
    s.signal = MotionSignal::sinusoid(amp, D, T, ph, ramp);
    s.text = "oscillating, " + s.signal->describe();
  } else {
    s.kind = Step::Kind::rotation;
    s.centre = key::centre.read<D>(d);
    if constexpr (D == 3) {
      s.axis = key::axis.read<3>(d);
      if (!(s.axis.norm() > 0)) d.error("axis", "(0 0 0) has no direction: give the rotation axis, e.g. (0 0 1)");
      s.axis.normalize();
    } else if (d.found("axis")) {
      d.error("axis", "a 2D rotation is about +z (counter-clockwise); it takes no axis");
    }
    s.signal = readSignal(d, key::angle.keyword().c_str(), 1, caseDir);
    s.text = cat("rotation about ", formatNumber<D>(s.centre), D == 3 ? cat(" axis ", formatNumber<3>(s.axis)) : "",
                 " by ", s.signal->describe(), " deg");
  }
  return s;
}

template <int D>
std::shared_ptr<WallMotion<D>> WallMotion<D>::read(const Dictionary& dict, const std::string& caseDir) {
  auto m = std::make_shared<WallMotion<D>>();
  if (dict.found("type")) {
    m->steps_.push_back(readStep(dict, caseDir));
  } else {
    for (const auto& name : dict.keys()) {
      if (!dict.isDict(name))
        dict.error(name, "a motion has a 'type', or holds its steps as named sub-dictionaries (each with a 'type')");
      m->steps_.push_back(readStep(dict.subDict(name), caseDir));
      dict.subDict(name).checkAllRead();
    }
    if (m->steps_.empty()) dict.error("type", "the motion is empty: give its 'type' (translation, oscillating, rotation)");
  }
  dict.checkAllRead();
  return m;
}

template <int D>
Pose<D> WallMotion<D>::stepPose(Step& s, double t) {
  const SignalValue v = s.signal->at(t);
  Pose<D> p;
  if (s.kind == Step::Kind::translation) {
    for (int k = 0; k < D; ++k) {
      p.b[k] = v.f[k];
      p.db[k] = v.df[k];
      p.ddb[k] = v.ddf[k];
    }
    return p;
  }
  constexpr double rad = M_PI / 180;
  const double th = v.f[0] * rad, w = v.df[0] * rad, dw = v.ddf[0] * rad;
  const Mat<D> K = generator<D>(s.axis), K2 = K * K, I = Mat<D>::Identity();
  const double sn = std::sin(th), cs = std::cos(th);
  const Mat<D> dRdth = cs * K + sn * K2, d2Rdth2 = -sn * K + cs * K2;
  p.R = I + sn * K + (1 - cs) * K2;
  p.dR = w * dRdth;
  p.ddR = dw * dRdth + w * w * d2Rdth2;
  p.b = s.centre - p.R * s.centre;
  p.db = -p.dR * s.centre;
  p.ddb = -p.ddR * s.centre;
  return p;
}

template <int D>
Pose<D> WallMotion<D>::pose(double t) {
  Pose<D> p;
  for (auto& s : steps_) p = p.then(stepPose(s, t));
  return p;
}

template <int D>
std::string WallMotion<D>::describe() const {
  std::string d;
  for (const auto& s : steps_) d += (d.empty() ? "" : " then ") + s.text;
  return d;
}

template struct Pose<2>;
template struct Pose<3>;
template class WallMotion<2>;
template class WallMotion<3>;

}  // namespace shizuku
