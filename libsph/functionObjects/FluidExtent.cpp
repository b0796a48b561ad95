// Function object `fluidExtent`: see FluidExtent.hpp (docs/design.md 1.3).
#include "functionObjects/FluidExtent.hpp"
#include "core/BlockReduce.hpp"
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
}  // namespace

template <int D>
FluidExtent<D>::FluidExtent(const std::string& name, const Dictionary& dict)
    : SampledFunctionObject<D>(name, "fluidExtent", dict) {}

template <int D>
void FluidExtent<D>::compute(const FlowState<D>& s, Vec<D>& lo, Vec<D>& hi) {
  const auto& p = s.particles;
  thread_local std::vector<Box<D>> partial;
  const Box<D> b = blockReduce(p.size(), partial, [&](Box<D>& a, std::size_t i) {
    if (!p.isFluid(i)) return;
    a.lo = a.lo.cwiseMin(p.position[i]);
    a.hi = a.hi.cwiseMax(p.position[i]);
  });
  if (b.lo[0] > b.hi[0]) {  // no fluid particle
    lo = hi = Vec<D>::Constant(std::numeric_limits<double>::quiet_NaN());
  } else {
    lo = b.lo;
    hi = b.hi;
  }
}

template <int D>
void FluidExtent<D>::open(const FlowState<D>&, const RunInfo& info) {
  this->file_.emplace(this->makeFile(info, "extent.dat"));
  this->file_->comment("bounding box of the fluid particle positions (walls excluded)");
  this->file_->columns({"time", "min", "max"}, {"s", "m", "m"});
}

template <int D>
void FluidExtent<D>::sample(const FlowState<D>& s, const RunInfo&) {
  Vec<D> lo, hi;
  compute(s, lo, hi);
  using F = PostProcessingFile;
  this->file_->row(F::number(s.time) + " " + F::vector<D>(lo) + " " + F::vector<D>(hi));
}

template class FluidExtent<2>;
template class FluidExtent<3>;

}  // namespace shizuku
