// Function object `fluidExtent`: see FluidExtent.hpp (docs/design.md 1.3).
#include "functionObjects/FluidExtent.hpp"
#include "parallel/Communicator.hpp"
#include "core/BlockReduce.hpp"
#include "core/Parameter.hpp"
#include <limits>

namespace shizuku {

namespace {
template <int D>
struct Box {
  Vec<D> lo = Vec<D>::Constant(std::numeric_limits<double>::infinity());
  Vec<D> hi = Vec<D>::Constant(-std::numeric_limits<double>::infinity());
  Box& operator+=(const Box& o) {
    lo = lo.cwiseMin(o.lo);
    hi = hi.cwiseMax(o.hi);
    return *this;
  }
};

namespace key {
const ParameterGroup extent("system/controlDict: functions/<name> (type fluidExtent)",
    "Bounding box of the fluid written by fluidExtent.");
const SwitchParameter connectedOnly = extent.onOff("connectedOnly",
    "only fluid particles with another fluid particle within 2h (lone particles left out)").def(false);
const IntParameter minNeighbours = extent.integer("minNeighbours",
    "with connectedOnly: fewest other fluid particles within 2h of a counted particle").def(1).min(1).max(1000);
}  // namespace key

// Whether fluid particle i has at least `least` other fluid particles within the support at
// its current position (the neighbour list of the step's start, minimum-image distances
// taken now).
template <int D>
bool connected(const FlowState<D>& s, std::size_t i, int least) {
  const auto& nl = s.neighbours;
  const auto& x = s.particles.position;
  const double support2 = 4 * s.h * s.h;
  int found = 0;
  for (Index k = nl.begin(i); k < nl.end(i); ++k) {
    const auto j = std::size_t(nl.j[k]);
    if (j != i && s.particles.isFluid(j) && s.periodic.difference(x[i], x[j]).squaredNorm() < support2 &&
        ++found >= least)
      return true;
  }
  return false;
}
}  // namespace

template <int D>
FluidExtent<D>::FluidExtent(const std::string& name, const Dictionary& dict)
    : SampledFunctionObject<D>(name, "fluidExtent", dict),
      minNeighbours_(key::connectedOnly.read(dict) ? key::minNeighbours.read(&dict) : 0) {
  if (minNeighbours_ == 0 && dict.found("minNeighbours"))
    dict.error("minNeighbours", "counts only with connectedOnly yes");
}

template <int D>
void FluidExtent<D>::compute(const FlowState<D>& s, Vec<D>& lo, Vec<D>& hi, int minNeighbours) {
  const auto& p = s.particles;
  const bool lists = minNeighbours > 0 && s.neighbours.numParticles() == s.size();
  thread_local std::vector<Box<D>> partial;
  Box<D> b = blockReduce(s.numOwned(), partial, [&](Box<D>& a, std::size_t i) {
    if (!p.isFluid(i) || (lists && !connected(s, i, minNeighbours))) return;
    a.lo = a.lo.cwiseMin(p.position[i]);
    a.hi = a.hi.cwiseMax(p.position[i]);
  });
  const auto& world = Communicator::world();  // the box of every rank's own particles
  for (int a = 0; a < D; ++a) {
    b.lo[a] = world.min(b.lo[a]);
    b.hi[a] = world.max(b.hi[a]);
  }
  if (b.lo[0] > b.hi[0]) {  // no fluid particle
    lo = hi = Vec<D>::Constant(std::numeric_limits<double>::quiet_NaN());
  } else {
    lo = b.lo;
    hi = b.hi;
  }
}

template <int D>
void FluidExtent<D>::open(const FlowState<D>&, const RunInfo& info) {
  if (minNeighbours_ > 0 && info.postProcessing)
    throw InputError(cat("function object '", this->name(), "': connectedOnly needs the solver's neighbour lists; "
                         "shizukuPostProcess has none: sample it during the run"));
  this->file_.emplace(this->makeFile(info, "extent.dat"));
  this->file_->comment(minNeighbours_ == 0 ? "bounding box of the fluid particle positions (walls excluded)"
                       : minNeighbours_ == 1
                           ? "bounding box of the fluid particle positions with another fluid particle within 2h "
                             "(walls and lone particles excluded)"
                           : cat("bounding box of the fluid particle positions with at least ", minNeighbours_,
                                 " other fluid particles within 2h (walls and smaller groups excluded)"));
  this->file_->columns({"time", "min", "max"}, {"s", "m", "m"});
}

template <int D>
void FluidExtent<D>::sample(const FlowState<D>& s, const RunInfo&) {
  Vec<D> lo, hi;
  compute(s, lo, hi, minNeighbours_);
  using F = PostProcessingFile;
  this->file_->row(F::number(s.time) + " " + F::vector<D>(lo) + " " + F::vector<D>(hi));
}

template class FluidExtent<2>;
template class FluidExtent<3>;

}  // namespace shizuku
