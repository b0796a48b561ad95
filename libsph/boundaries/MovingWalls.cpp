// The moving wall regions at run time: see MovingWalls.hpp.
#include "boundaries/MovingWalls.hpp"
#include "core/Log.hpp"
#include <algorithm>
#include <cmath>

namespace shizuku {

namespace {
// Corner c (0 <= c < 2^D; bit a picks hi along axis a) of the box [lo, hi].
template <int D>
Vec<D> boxCorner(const Vec<D>& lo, const Vec<D>& hi, int c) {
  Vec<D> corner;
  for (int a = 0; a < D; ++a) corner[a] = (c >> a) & 1 ? hi[a] : lo[a];
  return corner;
}
}  // namespace

template <int D>
MovingWalls<D>::MovingWalls(std::vector<std::shared_ptr<WallMotion<D>>> motions, std::vector<std::string> names,
                            std::vector<std::pair<Vec<D>, Vec<D>>> boxes)
    : motions_(std::move(motions)), names_(std::move(names)), boxes_(std::move(boxes)) {
  now_.resize(motions_.size());
  before_.resize(motions_.size());
  scratch_.resize(motions_.size());
}

template <int D>
void MovingWalls<D>::evaluate(double t) {
  for (std::size_t k = 0; k < motions_.size(); ++k) scratch_[k] = motions_[k]->pose(t);
}

template <int D>
void MovingWalls<D>::place(ParticleSet<D>& P, double t) {
  evaluate(t);
  before_ = placed_ ? now_ : scratch_;
  now_ = scratch_;
  placed_ = true;
  const bool normals = !P.restNormal.empty();
  const long n = long(P.size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    const int m = P.motion[std::size_t(i)];
    if (m == 0) continue;
    const Pose<D>& pose = now_[std::size_t(m - 1)];
    P.position[i] = pose.position(P.restPosition[i]);
    if (normals) P.wallNormal[i] = pose.R * P.restNormal[i];
  }
}

template <int D>
void MovingWalls<D>::prescribeVelocity(ParticleSet<D>& P, double t) {
  evaluate(t);
  const long n = long(P.size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    const int m = P.motion[std::size_t(i)];
    if (m != 0) P.velocity[i] = scratch_[std::size_t(m - 1)].velocity(P.restPosition[i]);
  }
}

template <int D>
void MovingWalls<D>::extremes(double t, double& speed, double& acceleration) {
  evaluate(t);
  speed = acceleration = 0;
  for (std::size_t k = 0; k < motions_.size(); ++k)
    for (int c = 0; c < (1 << D); ++c) {
      const Vec<D> corner = boxCorner<D>(boxes_[k].first, boxes_[k].second, c);
      speed = std::max(speed, scratch_[k].velocity(corner).norm());
      acceleration = std::max(acceleration, scratch_[k].acceleration(corner).norm());
    }
}

template <int D>
std::vector<std::string> MovingWalls<D>::describe() const {
  std::vector<std::string> v;
  for (std::size_t k = 0; k < motions_.size(); ++k)
    v.push_back(cat("moving wall '", names_[k], "': ", motions_[k]->describe(),
                    "; its velocity enters the wall rows (eq. 11a) and the time step"));
  return v;
}

template <int D>
void MovingWalls<D>::sweptBox(const WallBox<D>& w, WallMotion<D>& m, double t0, double t1, Vec<D>& lo, Vec<D>& hi) {
  // Samples at most 1 ms apart (at least 2001, at most 2e6), and the box padded by the
  // distance a corner can travel between two samples at the largest speed seen.
  const long samples = std::clamp(long(std::ceil((t1 - t0) / 1e-3)) + 1, 2001L, 2000001L);
  const double gap = (t1 - t0) / double(samples - 1);
  const Vec<D> outerMin = w.outerMin, outerMax = w.outerMax;  // lo, hi may be w's own
  lo = Vec<D>::Constant(INFINITY);
  hi = Vec<D>::Constant(-INFINITY);
  double speed = 0;
  for (long s = 0; s < samples; ++s) {
    const Pose<D> p = m.pose(t0 + gap * double(s));
    for (int c = 0; c < (1 << D); ++c) {
      const Vec<D> corner = boxCorner<D>(outerMin, outerMax, c);
      const Vec<D> x = p.position(corner);
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
      speed = std::max(speed, p.velocity(corner).norm());
    }
  }
  lo.array() -= 0.5 * gap * speed;
  hi.array() += 0.5 * gap * speed;
}

template class MovingWalls<2>;
template class MovingWalls<3>;

}  // namespace shizuku
