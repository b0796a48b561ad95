// Function object `wallPressure`: see WallPressure.hpp (docs/postprocessing.md).
#include "functionObjects/WallPressure.hpp"
#include "parallel/Communicator.hpp"
#include "core/Parameter.hpp"
#include "particles/WallLattice.hpp"
#include "particles/WallMotion.hpp"
#include <algorithm>
#include <cmath>

namespace shizuku {

namespace key {
namespace {
const ParameterGroup sensor("system/controlDict: functions/<name> (type wallPressure)",
                            "A pressure sensor on a face of a wall box: mean pressure, force and impulse.");
const OptionParameter wall =
    sensor.option("wall", {}, "the wall region (system/particlesDict) whose face holds the sensor").required();
const VectorParameter centre =
    sensor.vector("centre", dim::length, "the sensor's centre, on a closed face of the wall's surface (within d0/2)")
        .required();
const ScalarParameter size =
    sensor.scalar("size", dim::length, "length of the segment (2D); side of the square or diameter of the disc (3D)")
        .required().above(0);
const OptionParameter shape = sensor.option("shape", {"square", "disc"}, "the sensor's shape in 3D (2D: a segment)")
                                  .def("square");
const OptionParameter faceValue =
    sensor.option("faceValue", {"fluid", "wallLayers", "auto"},
                  "the face pressure: from the fluid next to the face (its pressure carried hydrostatically to the "
                  "face: the pressure the water feels) or from the first two wall layers (3/2 p_1 - 1/2 p_2); "
                  "auto: the same as fluid")
        .def("fluid");
const ParameterGroup filter("system/controlDict: functions/<name>/filter (type wallPressure)",
                            "Optional low-pass filter of the sensor's pressure, written as an extra column.");
const OptionParameter filterType =
    filter.option("type", {"lowPass"}, "first order: tau dy/dt + y = p, exact for p linear between steps").required();
const ScalarParameter cutoff =
    filter.scalar("cutoff", dim::inverseTime, "cut-off frequency fc = 1/(2 pi tau): gain 1/sqrt(2) (-3 dB)")
        .required().above(0);
}  // namespace
}  // namespace key

namespace {
const char kAxis[] = "xyz";
constexpr int kDiscRings = 32, kDiscRays = 64;  // polar quadrature of the disc
}  // namespace

template <int D>
WallPressure<D>::WallPressure(const std::string& name, const Dictionary& dict, const std::vector<WallBox<D>>& walls,
                              const Vec<D>& gravity)
    : SampledFunctionObject<D>(name, "wallPressure", dict), gravity_(gravity) {
  const std::string wallName = dict.getWord(key::wall.keyword());
  recordParameter(key::wall.info(), &dict, wallName, false);
  std::vector<std::string> names;
  for (const auto& w : walls) names.push_back(w.name);
  const auto it = std::find(names.begin(), names.end(), wallName);
  if (it == names.end()) {
    const std::string near = closestMatch(wallName, names);
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    dict.error("wall", cat("'", wallName, "' is not a wall region of system/particlesDict (",
                           names.empty() ? std::string("none known: the case has none, or, in shizukuPostProcess, the walls "
                                                         "are not read; sample the sensor during the run")
                                         : "they are: " + list,
                           ")",
                           near.empty() ? std::string() : cat("; did you mean '", near, "'?")));
  }
  wall_ = walls[std::size_t(it - names.begin())];
  if (wall_.body)
    dict.error("wall", cat("wall '", wallName, "' is a ", wall_.body->kind(), "; a sensor sits on a face of a wall box"));
  if (wall_.layers < 2)
    dict.error("wall", cat("wall '", wallName, "' has ", wall_.layers, " layer(s); the sensor extrapolates from the "
                           "first two layers to the face: give it layers 2 or more"));
  // The fluid's reading is the pressure the water feels (docs/postprocessing.md).
  fromFluid_ = key::faceValue.read(dict) != "wallLayers";
  size_ = key::size.read(dict);
  if (D == 3) disc_ = key::shape.read(dict) == "disc";
  else if (dict.found("shape")) dict.error("shape", "in 2D the sensor is a segment of length `size`; shape is for 3D");
  chooseFace(dict, key::centre.read<D>(dict));
  area_ = D == 2 ? size_ : (disc_ ? M_PI / 4 * size_ * size_ : size_ * size_);
  buildTerms(dict);
  if (const Dictionary* f = dict.subDictPtr("filter")) {
    key::filterType.read(*f);
    cutoff_ = key::cutoff.read(*f);
    filter_.emplace(cutoff_);
  }
}

// The closed face nearest to `c` within d0/2 whose extent holds c; the sensor must fit on it.
template <int D>
void WallPressure<D>::chooseFace(const Dictionary& dict, const Vec<D>& c) {
  const double d0 = wall_.d0, tol = 1e-9 * d0;
  double best = INFINITY;
  std::string faces;
  for (int a = 0; a < D; ++a)
    for (int side = 0; side < 2; ++side) {
      if (wall_.open[2 * a + side]) continue;
      const double f = side ? wall_.max[a] : wall_.min[a];
      faces += cat(faces.empty() ? "" : ", ", kAxis[a], " = ", formatNumber(f));
      bool inside = true;
      for (int t = 0; t < D; ++t)
        if (t != a) inside = inside && c[t] >= wall_.min[t] - tol && c[t] <= wall_.max[t] + tol;
      const double dist = std::abs(c[a] - f);
      if (inside && dist <= 0.5 * d0 + tol && dist < best) {
        best = dist;
        axis_ = a;
        side_ = side;
      }
    }
  if (!(best < INFINITY))
    dict.error("centre", cat(formatNumber<D>(c), " is not on a face of wall '", wall_.name,
                             "': it must lie within d0/2 = ", formatNumber(0.5 * d0), " m of one of its closed faces (",
                             faces.empty() ? std::string("none") : faces, ") inside the surface ",
                             formatNumber<D>(wall_.min), "-", formatNumber<D>(wall_.max)));
  centre_ = c;
  centre_[axis_] = side_ ? wall_.max[axis_] : wall_.min[axis_];
  for (int t = 0; t < D; ++t) {
    if (t == axis_) continue;
    if (centre_[t] - 0.5 * size_ < wall_.min[t] - tol || centre_[t] + 0.5 * size_ > wall_.max[t] + tol)
      dict.error("size", cat(formatNumber(size_), " m: the sensor centred at ", kAxis[t], " = ", formatNumber(centre_[t]),
                             " reaches beyond the face ", faceName(), " of wall '", wall_.name, "', which spans ",
                             kAxis[t], " = ", formatNumber(wall_.min[t]), " .. ", formatNumber(wall_.max[t])));
  }
}

template <int D>
std::vector<std::pair<long, double>> WallPressure<D>::segmentWeights(const std::vector<double>& x, double a, double b,
                                                                      bool linearEnds) {
  const long n = long(x.size());
  std::vector<std::pair<long, double>> out;
  if (n == 1) return {{0, 1.0}};
  // The interpolant's weights at y on the interval [x_k, x_k+1] (t outside [0, 1] beyond
  // an end node: the end interval's line continued).
  auto at = [&](long k, double y) {
    const double t = (y - x[k]) / (x[k + 1] - x[k]);
    return std::array<double, 2>{1 - t, t};
  };
  if (!(b > a)) {  // a point: the interpolant's value
    const long k = a <= x[0] ? 0 : a >= x[n - 1] ? n - 2 : long(std::upper_bound(x.begin(), x.end(), a) - x.begin()) - 1;
    if (!linearEnds && a <= x[0]) return {{0, 1.0}};
    if (!linearEnds && a >= x[n - 1]) return {{n - 1, 1.0}};
    const auto w = at(k, a);
    return {{k, w[0]}, {k + 1, w[1]}};
  }
  std::vector<double> w(x.size(), 0.0);
  // Below the first node and above the last: constant, or the end interval's line.
  const double below = std::max(0.0, std::min(b, x[0]) - a), above = std::max(0.0, b - std::max(a, x[n - 1]));
  if (!linearEnds) {
    w[0] += below;
    w[n - 1] += above;
  } else {
    const auto lo = at(0, a + 0.5 * below), hi = at(n - 2, b - 0.5 * above);
    w[0] += below * lo[0];
    w[1] += below * lo[1];
    w[n - 2] += above * hi[0];
    w[n - 1] += above * hi[1];
  }
  for (long k = 0; k + 1 < n; ++k) {
    const double l = std::max(a, x[k]), r = std::min(b, x[k + 1]);
    if (!(r > l)) continue;
    const auto m = at(k, 0.5 * (l + r));
    w[k] += (r - l) * m[0];
    w[k + 1] += (r - l) * m[1];
  }
  for (long k = 0; k < n; ++k)
    if (w[k] != 0) out.emplace_back(k, w[k] / (b - a));
  return out;
}

// The wall particles behind the sensor and their weights: the face value of each column
// (3/2 p_1 - 1/2 p_2) times the column's share of the sensor's mean.
template <int D>
void WallPressure<D>::buildTerms(const Dictionary& dict) {
  std::array<WallAxis, D> axes;
  for (int k = 0; k < D; ++k) {
    axes[k] = wall_.solid ? wallAxis(wall_.min[k], wall_.max[k], wall_.d0, 0, true, true)
                          : wallAxis(wall_.min[k], wall_.max[k], wall_.d0, wall_.layers, wall_.open[2 * k],
                                     wall_.open[2 * k + 1]);
    axisNodes_.push_back(axes[k].x);
  }
  // The first two layers behind the face: outside a container's surface, inside a solid.
  const WallAxis& n = axes[axis_];
  if (wall_.solid && n.x.size() < 2)
    dict.error("centre", cat("solid wall '", wall_.name, "' is one particle thick across the face ", faceName(),
                             ": the sensor extrapolates from two layers behind the face"));
  const int out = wall_.solid ? -1 : 1;
  const long first = side_ ? (wall_.solid ? n.innerEnd - 1 : n.innerEnd) : (wall_.solid ? n.innerBegin : n.innerBegin - 1);
  const long layer1 = first, layer2 = first + (side_ ? out : -out);
  std::map<std::array<long, D>, double> columns;  // column (normal index 0) -> share
  if (D == 2) {
    const int t = 1 - axis_;
    for (const auto& [i, w] : segmentWeights(axisNodes_[t], centre_[t] - 0.5 * size_, centre_[t] + 0.5 * size_, wall_.solid)) {
      std::array<long, D> c{};
      c[t] = i;
      columns[c] += w;
    }
  } else {
    const int t1 = (axis_ + 1) % D, t2 = (axis_ + 2) % D;
    const auto& x1 = axisNodes_[t1];
    const auto& x2 = axisNodes_[t2];
    auto add = [&](const std::vector<std::pair<long, double>>& w1, const std::vector<std::pair<long, double>>& w2,
                   double scale) {
      for (const auto& [i, a] : w1)
        for (const auto& [j, b] : w2) {
          std::array<long, D> c{};
          c[t1] = i;
          c[t2] = j;
          columns[c] += scale * a * b;
        }
    };
    if (!disc_) {
      add(segmentWeights(x1, centre_[t1] - 0.5 * size_, centre_[t1] + 0.5 * size_, wall_.solid),
          segmentWeights(x2, centre_[t2] - 0.5 * size_, centre_[t2] + 0.5 * size_, wall_.solid), 1.0);
    } else {
      // Midpoint rule in r (weight r dr) and theta: exact for a linear field by symmetry.
      double total = 0;
      for (int ir = 0; ir < kDiscRings; ++ir) total += (ir + 0.5) * kDiscRays;
      for (int ir = 0; ir < kDiscRings; ++ir) {
        const double r = 0.5 * size_ * (ir + 0.5) / kDiscRings;
        for (int it = 0; it < kDiscRays; ++it) {
          const double th = 2 * M_PI * (it + 0.5) / kDiscRays;
          const double u = centre_[t1] + r * std::cos(th), v = centre_[t2] + r * std::sin(th);
          add(segmentWeights(x1, u, u, wall_.solid), segmentWeights(x2, v, v, wall_.solid), (ir + 0.5) / total);
        }
      }
    }
  }
  for (const auto& [c, w] : columns) {
    if (w == 0) continue;
    for (int layer = 0; layer < 2; ++layer) {
      std::array<long, D> idx = c;
      idx[axis_] = layer == 0 ? layer1 : layer2;
      Term term;
      for (int k = 0; k < D; ++k) term.position[k] = axisNodes_[k][std::size_t(idx[k])];
      term.weight = layer == 0 ? 1.5 * w : -0.5 * w;
      term.share = layer == 0 ? w : 0.0;
      term.face = term.position;
      term.face[axis_] = side_ ? wall_.max[axis_] : wall_.min[axis_];
      termOf_[idx] = terms_.size();
      terms_.push_back(term);
    }
  }
  if (terms_.empty()) dict.error("centre", "the sensor covers no wall particle");
}

// Finds each term's particle by its lattice position among this rank's own particles (a
// moving wall's by its rest position: the sensor moves with the wall); in a distributed run
// the terms are spread over the ranks (id -1: elsewhere).
template <int D>
void WallPressure<D>::locate(const FlowState<D>& s) {
  if (fromFluid_ && wall_.motion >= 0 && !s.wallPoses)
    throw std::logic_error(cat("wallPressure '", this->name(), "': the moving wall '", wall_.name,
                               "' has no pose in this state (FlowState::wallPoses)"));
  const auto& P = s.particles;
  const double tol = 1e-6 * wall_.d0;
  const auto& X = P.restPosition.empty() ? P.position : P.restPosition;  // rest: every wall particle's
  std::size_t found = 0;
  for (auto& t : terms_) t.id = -1;
  for (std::size_t i = 0; i < s.numOwned(); ++i) {
    if (!P.isWall(i)) continue;
    std::array<long, D> idx{};
    bool ok = true;
    for (int k = 0; k < D && ok; ++k) {
      const auto& x = axisNodes_[k];
      const auto it = std::lower_bound(x.begin(), x.end(), X[i][k] - tol);
      ok = it != x.end() && std::abs(*it - X[i][k]) < tol;
      if (ok) idx[k] = long(it - x.begin());
    }
    if (!ok) continue;
    const auto term = termOf_.find(idx);
    if (term == termOf_.end() || terms_[term->second].id >= 0) continue;
    terms_[term->second].index = i;
    terms_[term->second].id = P.id[i];
    ++found;
  }
  found = std::size_t(Communicator::world().sum(long(found)));
  if (found != terms_.size())
    throw InputError(cat("wallPressure '", this->name(), "': ", terms_.size() - found, " of the ", terms_.size(),
                         " wall particles behind the sensor on face ", faceName(), " of wall '", wall_.name,
                         "' are missing from the particles (they do not match system/particlesDict)"));
}

template <int D>
double WallPressure<D>::pressure(const FlowState<D>& s) {
  const auto& P = s.particles;
  const auto& world = Communicator::world();
  bool current = located_;
  for (const auto& t : terms_)
    current = current && (t.id < 0 ? world.isParallel() : t.index < s.numOwned() && P.id[t.index] == t.id);
  // First call, or the particles were reordered (or, on several ranks, moved to another rank).
  if (world.any(!current)) locate(s);
  located_ = true;
  double p = 0;
  for (std::size_t k = 0; k < terms_.size(); ++k) {
    const Term& t = terms_[k];
    if (t.id < 0) continue;
    if (!fromFluid_) p += t.weight * P.pressure[t.index];
    else if (t.share > 0) p += t.share * fluidFaceValue(s, t, faceOf(s, t));
  }
  return world.sum(p);
}

// The face point of term t's column now: its rest face point, moved on a moving wall by the
// wall's current pose (the same on every rank, so no other particle is needed).
template <int D>
Vec<D> WallPressure<D>::faceOf(const FlowState<D>& s, const Term& t) const {
  if (wall_.motion < 0) return t.face;
  return (*s.wallPoses)[std::size_t(wall_.motion)].position(t.face);
}

// sum_f W_wf (p_f + rho0 g . (x_c - r_f)) / sum_f W_wf over the fluid neighbours of the
// column's first-layer particle w (0 without any: the wall row's p_w = 0).
template <int D>
double WallPressure<D>::fluidFaceValue(const FlowState<D>& s, const Term& t, const Vec<D>& face) const {
  const auto& nl = s.neighbours;
  const auto& P = s.particles;
  double sum = 0, weights = 0;
  for (Index k = nl.begin(t.index); k < nl.end(t.index); ++k) {
    const Index f = nl.j[k];
    if (!s.isFluid(std::size_t(f))) continue;
    const double wk = s.w(t.index, k);
    sum += wk * (P.pressure[f] + s.rho0 * gravity_.dot(face - P.position[f]));
    weights += wk;
  }
  return weights > 0 ? sum / weights : 0.0;
}

template <int D>
void WallPressure<D>::execute(const FlowState<D>& s, const RunInfo& info) {
  const double previousForce = force_;
  pressure_ = pressure(s);
  force_ = pressure_ * area_;
  if (!started_) {
    started_ = true;
    impulse_ = 0;
  } else if (s.time > lastTime_) {
    impulse_ += 0.5 * (previousForce + force_) * (s.time - lastTime_);
  }
  lastTime_ = s.time;
  if (filter_) filter_->update(s.time, pressure_);
  SampledFunctionObject<D>::execute(s, info);
}

template <int D>
std::string WallPressure<D>::faceName() const {
  return cat(kAxis[axis_], " = ", formatNumber(side_ ? wall_.max[axis_] : wall_.min[axis_]));
}

template <int D>
std::string WallPressure<D>::details() const {
  const std::string shape = D == 2 ? "segment" : (disc_ ? "disc" : "square");
  return cat(", wall '", wall_.name, "' face ", faceName(), ", ", shape, " ", formatNumber(size_), " m at ",
             formatNumber<D>(centre_), ", ", terms_.size(), " wall particles",
             fromFluid_ ? std::string(", face value from the fluid") : std::string(),
             filter_ ? cat(", low-pass ", formatNumber(cutoff_), " Hz") : std::string());
}

template <int D>
void WallPressure<D>::open(const FlowState<D>& s, const RunInfo& info) {
  locate(s);
  this->file_.emplace(this->makeFile(info, "wallPressure.dat"));
  const std::string shape = D == 2 ? "segment" : (disc_ ? "disc" : "square");
  this->file_->comment(cat("mean pressure on a ", shape, " of size ", formatNumber(size_), " m at ",
                           formatNumber<D>(centre_), " on face ", faceName(), " of wall '", wall_.name,
                           fromFluid_ ? "' (face value from the fluid: sum W (p_f + rho0 g . (x_face - r_f)) / sum W "
                                        "over the first wall layer's fluid neighbours"
                                      : "' (face value 3/2 p_1 - 1/2 p_2 of the first two wall layers",
                           ", interpolated along the face); force = p x area ", formatNumber(area_),
                           D == 2 ? " m (per unit depth)" : " m^2",
                           "; impulse since the start time",
                           filter_ ? cat("; p_lowPass: first-order low-pass, cut-off ", formatNumber(cutoff_), " Hz")
                                   : std::string()));
  const std::string forceUnit = D == 2 ? "N/m" : "N", impulseUnit = D == 2 ? "N*s/m" : "N*s";
  if (filter_)
    this->file_->columns({"time", "p", "p_lowPass", "force", "impulse"}, {"s", "Pa", "Pa", forceUnit, impulseUnit});
  else
    this->file_->columns({"time", "p", "force", "impulse"}, {"s", "Pa", forceUnit, impulseUnit});
}

template <int D>
void WallPressure<D>::sample(const FlowState<D>& s, const RunInfo&) {
  using F = PostProcessingFile;
  std::string row = F::number(s.time) + " " + F::number(pressure_);
  if (filter_) row += " " + F::number(filter_->output());
  this->file_->row(row + " " + F::number(force_) + " " + F::number(impulse_));
}

template class WallPressure<2>;
template class WallPressure<3>;

}  // namespace shizuku
