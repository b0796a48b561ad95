// Statistics of the density error of eq. (22): see DensityErrorMeasure.hpp.
#include "operators/DensityErrorMeasure.hpp"
#include "core/BlockReduce.hpp"
#include "parallel/Communicator.hpp"
#include <cmath>
#include <limits>

namespace shizuku {

namespace {
struct Moments {
  double nIn = 0, sumIn = 0, sum2In = 0, maxIn = 0;
  double nAll = 0, sumAll = 0, sum2All = 0, maxAll = 0;
  long worst = -1;
  Moments& operator+=(const Moments& o) {
    if (o.worst >= 0 && (worst < 0 || o.maxIn > maxIn)) worst = o.worst;  // ties keep the lower index (blocks added in order)
    nIn += o.nIn; sumIn += o.sumIn; sum2In += o.sum2In; maxIn = std::max(maxIn, o.maxIn);
    nAll += o.nAll; sumAll += o.sumAll; sum2All += o.sum2All; maxAll = std::max(maxAll, o.maxAll);
    return *this;
  }
};

DensityErrorStats finish(double n, double sum, double sum2, double maxAbs) {
  DensityErrorStats st;
  st.count = long(n);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  st.mean = n > 0 ? sum / n : nan;
  st.rms = n > 0 ? std::sqrt(sum2 / n) : nan;
  st.max = n > 0 ? maxAbs : nan;
  return st;
}
}  // namespace

template <int D>
DensityErrorSummary measureDensityError(const FlowState<D>& s) {
  const auto& p = s.particles;
  thread_local std::vector<Moments> partial;
  Moments m = blockReduce(s.numOwned(), partial, [&](Moments& a, std::size_t i) {
    if (!p.isFluid(i)) return;
    const double e = densityErrorPercent(s.rho0, p.density[i]);
    a.nAll += 1; a.sumAll += e; a.sum2All += e * e; a.maxAll = std::max(a.maxAll, std::abs(e));
    if (p.surfaceClass(i) == SurfaceClass::interior) {
      a.nIn += 1; a.sumIn += e; a.sum2In += e * e;
      if (std::abs(e) > a.maxIn || a.worst < 0) { a.maxIn = std::max(a.maxIn, std::abs(e)); a.worst = long(i); }
    }
  });
  const auto& world = Communicator::world();
  if (world.isParallel()) {
    std::vector<double> sums = {m.nIn, m.sumIn, m.sum2In, m.nAll, m.sumAll, m.sum2All};
    world.sumInPlace(sums);
    m.nIn = sums[0]; m.sumIn = sums[1]; m.sum2In = sums[2]; m.nAll = sums[3]; m.sumAll = sums[4]; m.sum2All = sums[5];
    m.maxIn = world.max(m.maxIn);
    m.maxAll = world.max(m.maxAll);
  }
  DensityErrorSummary r;
  r.interior = finish(m.nIn, m.sumIn, m.sum2In, m.maxIn);
  r.all = finish(m.nAll, m.sumAll, m.sum2All, m.maxAll);
  r.worstInterior = m.worst;
  return r;
}

template DensityErrorSummary measureDensityError<2>(const FlowState<2>&);
template DensityErrorSummary measureDensityError<3>(const FlowState<3>&);

}  // namespace shizuku
