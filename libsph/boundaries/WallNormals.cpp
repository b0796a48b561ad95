// Wall particles' surface normals from their regions' geometry (WallNormals.hpp).
#include "boundaries/WallNormals.hpp"

#include <algorithm>
#include <cmath>

namespace shizuku {

template <int D>
void assignWallNormals(ParticleSet<D>& P, const std::vector<WallBox<D>>& walls) {
  const long n = long(P.size());
  long wallParticles = 0;
  for (long i = 0; i < n; ++i) wallParticles += P.isWall(std::size_t(i));
  if (wallParticles == 0) {
    P.wallNormal.clear();
    P.restNormal.clear();
    return;
  }
  P.wallNormal.assign(std::size_t(n), Vec<D>::Zero());
  const bool moving = !P.motion.empty() && !P.restPosition.empty();
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    if (!P.isWall(std::size_t(i))) continue;
    const int group = moving ? int(P.motion[std::size_t(i)]) - 1 : -1;
    const Vec<D>& x = group >= 0 ? P.restPosition[std::size_t(i)] : P.position[std::size_t(i)];
    // The region x lies least deep in; where several tie (boxes that meet at an edge of
    // the wall, as a weir's face and crest built as two boxes), their normals summed: the
    // diagonal of that edge.
    double depth = INFINITY;
    for (const auto& w : walls)
      if (w.motion == group) depth = std::min(depth, w.layerDepth(x));
    if (!std::isfinite(depth)) continue;
    const double tie = 1e-6 * P.spacing;
    Vec<D> n = Vec<D>::Zero();
    for (const auto& w : walls)
      if (w.motion == group && w.layerDepth(x) <= depth + tie) n += w.outwardNormal(x);
    const double len = n.norm();
    if (len > 0) P.wallNormal[std::size_t(i)] = n / len;
  }
  if (moving) P.restNormal = P.wallNormal;
  else P.restNormal.clear();
}

template void assignWallNormals<2>(ParticleSet<2>&, const std::vector<WallBox<2>>&);
template void assignWallNormals<3>(ParticleSet<3>&, const std::vector<WallBox<3>>&);

}  // namespace shizuku
