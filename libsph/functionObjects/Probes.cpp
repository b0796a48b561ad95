// Function object `probes`: Shepard-normalised SPH interpolation at points; see Probes.hpp.
// Reads fields, points, minKernelSum through the declarations below.
#include "functionObjects/Probes.hpp"
#include "parallel/Communicator.hpp"
#include "core/Log.hpp"
#include "core/Parameter.hpp"
#include <algorithm>
#include <limits>

namespace shizuku {

static_assert(sizeof(Vec<2>) == 2 * sizeof(double) && sizeof(Vec<3>) == 3 * sizeof(double),
              "vectors are read as contiguous doubles");

namespace {
const ParameterGroup probes("system/controlDict: functions/<name> (type probes)",
    "Shepard-normalised SPH interpolation of fields at fixed points.");
const WordListParameter fieldsParameter = probes.wordList("fields", "fields to sample: p rhoN U normal shift").required();
const VectorListParameter pointsParameter = probes.vectorList("points", dim::length, "probe points ((x y) ...)").required();
const ScalarParameter minKernelSum = probes.scalar("minKernelSum", dim::none,
    "smallest Shepard sum of a valid sample (below: NaN, e.g. a point in air)").def(0.5).above(0).max(1e6);
}  // namespace

template <int D>
std::string Probes<D>::fieldUnit(const std::string& field) {
  if (field == "p") return "Pa";
  if (field == "rhoN") return "kg/m^3";
  if (field == "U") return "m/s";
  if (field == "shift") return "m";
  return "-";
}

template <int D>
Probes<D>::Probes(const std::string& name, const Dictionary& dict) : SampledFunctionObject<D>(name, "probes", dict) {
  fields_ = fieldsParameter.read(dict);
  if (fields_.empty()) dict.error("fields", "needs at least one field, e.g. (p U)");
  const auto known = knownFields();
  for (const auto& f : fields_) {
    if (std::find(known.begin(), known.end(), f) == known.end()) {
      const std::string m = closestMatch(f, known);
      dict.error("fields", "unknown field '" + f + "'" + (m.empty() ? "" : " (did you mean '" + m + "'?)") +
                               "; probes can sample p rhoN U normal shift");
    }
    if (std::count(fields_.begin(), fields_.end(), f) > 1) dict.error("fields", "field '" + f + "' is listed twice");
    comps_.push_back(f == "p" || f == "rhoN" ? 1 : D);
  }
  points_ = pointsParameter.read<D>(dict);
  if (points_.empty()) dict.error("points", "needs at least one point, e.g. ((0 0))");
  minKernelSum_ = minKernelSum.read(dict);
  kernelSum_.assign(points_.size(), 0);
  for (std::size_t f = 0; f < fields_.size(); ++f) values_.emplace_back(points_.size() * comps_[f], 0.0);
}

template <int D>
std::string Probes<D>::details() const {
  std::string f;
  for (const auto& n : fields_) f += (f.empty() ? "" : " ") + n;
  return cat(", fields (", f, ") at ", points_.size(), " point", points_.size() == 1 ? "" : "s");
}

template <int D>
const double* Probes<D>::fieldData(const FlowState<D>& s, std::size_t f) const {
  const double* data = nullptr;
  bool present = false;
  s.particles.forEachField([&](const char* n, const auto& v) {
    if (fields_[f] != n) return;
    using T = typename std::decay_t<decltype(v)>::value_type;
    if constexpr (std::is_same_v<T, double> || std::is_same_v<T, Vec<D>>) {
      present = v.size() == s.size();
      data = reinterpret_cast<const double*>(v.data());
    }
  });
  if (!present)
    throw InputError("probes '" + this->name() + "': field '" + fields_[f] +
                     "' is not computed in this run (no active effect needs it)");
  return data;
}

template <int D>
const std::vector<std::vector<double>>& Probes<D>::evaluate(const FlowState<D>& s) {
  const auto& p = s.particles;
  const std::size_t n = s.numOwned(), np = points_.size(), nf = fields_.size();
  const double support = s.kernel.support(), V = s.V();
  auto& data = fieldPtr_;
  data.resize(nf);
  int width = 1;
  for (std::size_t f = 0; f < nf; ++f) {
    data[f] = fieldData(s, f);
    width += comps_[f];
  }
  // Box of the points widened by the support: particles outside it touch no point.
  Vec<D> lo = points_[0], hi = points_[0];
  for (const auto& x : points_) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  lo.array() -= support;
  hi.array() += support;
  const bool periodic = s.periodic.any();

  constexpr std::size_t block = 4096;
  const long nb = long((n + block - 1) / block);
  const std::size_t stride = np * std::size_t(width);
  blockSums_.assign(std::size_t(nb) * stride, 0.0);
#pragma omp parallel for schedule(static)
  for (long b = 0; b < nb; ++b) {
    double* acc = blockSums_.data() + std::size_t(b) * stride;
    const std::size_t end = std::min(n, std::size_t(b + 1) * block);
    for (std::size_t j = std::size_t(b) * block; j < end; ++j) {
      if (!p.isFluid(j)) continue;
      const Vec<D>& xj = p.position[j];
      if (!periodic && ((xj - lo).minCoeff() < 0 || (hi - xj).minCoeff() < 0)) continue;
      for (std::size_t k = 0; k < np; ++k) {
        const Vec<D> d = periodic ? s.periodic.difference(points_[k], xj) : Vec<D>(points_[k] - xj);
        const double r = d.norm();
        if (r >= support) continue;
        const double vw = V * s.kernel.w(r);
        double* a = acc + k * std::size_t(width);
        a[0] += vw;
        int c0 = 1;
        for (std::size_t f = 0; f < nf; ++f) {
          for (int c = 0; c < comps_[f]; ++c) a[c0 + c] += vw * data[f][j * comps_[f] + c];
          c0 += comps_[f];
        }
      }
    }
  }
  // The blocks' sums in block order, then over the ranks (each sums its own particles).
  sums_.assign(stride, 0.0);
  for (std::size_t q = 0; q < stride; ++q)
    for (long b = 0; b < nb; ++b) sums_[q] += blockSums_[std::size_t(b) * stride + q];
  Communicator::world().sumInPlace(sums_);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < np; ++k) {
    const std::size_t base = k * std::size_t(width);
    const double S = sums_[base];
    kernelSum_[k] = S;
    int c0 = 1;
    for (std::size_t f = 0; f < nf; ++f) {
      for (int c = 0; c < comps_[f]; ++c)
        values_[f][k * comps_[f] + c] = S >= minKernelSum_ ? sums_[base + std::size_t(c0 + c)] / S : nan;
      c0 += comps_[f];
    }
  }
  return values_;
}

template <int D>
void Probes<D>::open(const FlowState<D>& s, const RunInfo& info) {
  for (std::size_t f = 0; f < fields_.size(); ++f) fieldData(s, f);  // an absent field fails now, not mid-run
  files_.clear();
  for (std::size_t f = 0; f < fields_.size(); ++f) {
    files_.push_back(this->makeFile(info, fields_[f]));
    auto& file = files_.back();
    std::string text = cat("probes of ", fields_[f], " [", fieldUnit(fields_[f]),
                           "]: Shepard-normalised SPH interpolation over fluid particles;\n",
                           "nan where the kernel sum sum_j V W < ", PostProcessingFile::number(minKernelSum_),
                           " (outside the fluid)");
    for (std::size_t k = 0; k < points_.size(); ++k)
      text += cat("\npoint", k, " ", PostProcessingFile::vector<D>(points_[k]), " m");
    file.comment(text);
    std::vector<std::string> names{"time"}, units{"s"};
    for (std::size_t k = 0; k < points_.size(); ++k) {
      names.push_back(cat("point", k));
      units.push_back(fieldUnit(fields_[f]));
    }
    file.columns(names, units);
  }
}

template <int D>
void Probes<D>::sample(const FlowState<D>& s, const RunInfo&) {
  const auto& v = evaluate(s);
  for (std::size_t f = 0; f < fields_.size(); ++f) {
    std::string row = PostProcessingFile::number(s.time);
    for (std::size_t k = 0; k < points_.size(); ++k) {
      if (comps_[f] == 1) {
        row += " " + PostProcessingFile::number(v[f][k]);
      } else {
        row += " (";
        for (int c = 0; c < comps_[f]; ++c) row += (c ? " " : "") + PostProcessingFile::number(v[f][k * comps_[f] + c]);
        row += ")";
      }
    }
    files_[f].row(row);
  }
}

template class Probes<2>;
template class Probes<3>;

}  // namespace shizuku
