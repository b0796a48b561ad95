// The named operators of Ops.hpp (docs/method.md 3.2, 11), each one call of the
// shared neighbour-loop form sumOverNeighbours().
#include "operators/Ops.hpp"

namespace shizuku {

template <int D>
void Ops<D>::gradient(const NeighbourList<D>& nl, const PairWeights<D>& pw, double scale,
                      const std::vector<double>& f, std::vector<Vec<D>>& out, const RowMask* rows) {
  sumOverNeighbours(nl, rows, scale, false, out,
                    [&](long i, Index k) -> Vec<D> { return (f[nl.j[k]] - f[i]) * pw.gradW[k]; });
}

template <int D>
void Ops<D>::addGradient(const NeighbourList<D>& nl, const PairWeights<D>& pw, double scale,
                         const std::vector<double>& f, std::vector<Vec<D>>& out, const RowMask& rows) {
  sumOverNeighbours(nl, &rows, scale, true, out,
                    [&](long i, Index k) -> Vec<D> { return (f[nl.j[k]] - f[i]) * pw.gradW[k]; });
}

template <int D>
void Ops<D>::divergence(const NeighbourList<D>& nl, const PairWeights<D>& pw, double scale,
                        const std::vector<Vec<D>>& u, std::vector<double>& out, const RowMask* rows) {
  sumOverNeighbours(nl, rows, scale, false, out,
                    [&](long i, Index k) { return (u[nl.j[k]] - u[i]).dot(pw.gradW[k]); });
}

template <int D>
void Ops<D>::laplacian(const NeighbourList<D>& nl, const PairWeights<D>& pw, double scale,
                       const std::vector<double>& f, std::vector<double>& out, const RowMask* rows) {
  sumOverNeighbours(nl, rows, scale, false, out,
                    [&](long i, Index k) { return (f[nl.j[k]] - f[i]) * pw.lapW[k]; });
}

template <int D>
void Ops<D>::laplacian(const NeighbourList<D>& nl, const PairWeights<D>& pw, double scale,
                       const std::vector<Vec<D>>& u, std::vector<Vec<D>>& out, const RowMask* rows) {
  sumOverNeighbours(nl, rows, scale, false, out,
                    [&](long i, Index k) -> Vec<D> { return (u[nl.j[k]] - u[i]) * pw.lapW[k]; });
}

template <int D>
void Ops<D>::addVelocityLaplacian(const NeighbourList<D>& nl, const PairWeights<D>& pw, double scale,
                                  const std::vector<Vec<D>>& u, const RowMask& isFluid, WallVelocity walls,
                                  std::vector<Vec<D>>& out, const RowMask* isBuffer) {
  const bool noSlip = walls == WallVelocity::noSlip;
  sumOverNeighbours(nl, &isFluid, scale, true, out, [&](long i, Index k) -> Vec<D> {
    const Index j = nl.j[k];
    const bool asIs = isFluid[j] || (isBuffer && (*isBuffer)[j]);
    const Vec<D> uj = asIs ? u[j] : noSlip ? Vec<D>(2.0 * u[j] - u[i]) : u[i];
    return pw.lapW[k] * (uj - u[i]);
  });
}

template <int D>
void Ops<D>::velocityGradient(const NeighbourList<D>& nl, const PairWeights<D>& pw, double scale,
                              const std::vector<Vec<D>>& u, std::vector<Mat<D>>& out) {
  sumOverNeighbours(nl, nullptr, scale, false, out,
                    [&](long i, Index k) -> Mat<D> { return (u[nl.j[k]] - u[i]) * pw.gradW[k].transpose(); });
}

template struct Ops<2>;
template struct Ops<3>;

}  // namespace shizuku
