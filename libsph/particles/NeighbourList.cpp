// Neighbour search by a cell-linked list (docs/method.md 13 step 1): all pairs
// 0 < |r_ij| < radius in CSR form, O(N), minimum image in periodic directions.
//
// build(): (1) a uniform grid over the bounding box (periodic directions: over
// the periodic box, cell size L/floor(L/radius)), cell size >= radius. Where a
// few particles far from the rest (spray, a droplet in free flight) would make
// that grid hold far more cells than particles, the grid covers the bulk only
// (the 0.5 % to 99.5 % quantiles of each coordinate, widened) and a particle
// outside it goes to the nearest edge cell: clamping cell coordinates never
// moves two cells further apart, so every pair within the radius is still in
// the same or adjacent cells, and the grid's size does not grow with the
// distance of the far particles;
// (2) counting sort of particles by cell (wrapped positions copied in cell
// order for locality); (3) parallel scan over cells, each thread a run of cells
// holding an equal share of the particles: it appends the
// neighbours found to its own buffer and records the row length: as 16-bit
// offsets into the cell's list of candidates (the particles of its 3^D cells)
// when no cell holds more than 65535 / 3^D particles, which halves the buffers
// that stay allocated between builds, else as 32-bit cell-order positions;
// (4) prefix sum -> CSR offsets; (5) parallel copy pass per particle writing
// j, rows sorted by j. Every buffer lives in
// Impl and the output vectors only grow, so a rebuild allocates nothing once
// the capacity has been reached. Rows are identical for any thread count.
// Reads no dictionary keys (radius and box come from the caller).
#include "particles/NeighbourList.hpp"
#include "core/OverwriteBuffer.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <omp.h>
#include <type_traits>

namespace shizuku {

// ---------------------------------------------------------------- PeriodicBox
template <int D>
void PeriodicBox<D>::wrap(Vec<D>& x) const {
  for (int a = 0; a < D; ++a) {
    if (!periodic[a]) continue;
    const double L = hi[a] - lo[a];
    double v = x[a] - L * std::floor((x[a] - lo[a]) / L);
    if (v >= hi[a]) v -= L;  // round-off at the upper end
    if (v < lo[a]) v = lo[a];
    x[a] = v;
  }
}

// ---------------------------------------------------------------- Impl
// Cells along axis a of a grid of cell size cs over [mn, mx]; periodic: the box's
// length in whole cells, at least one.
namespace {
template <int D>
double cellsAlong(int a, const Vec<D>& mn, const Vec<D>& mx, double cs, const PeriodicBox<D>& box) {
  return box.periodic[a] ? std::max(1.0, std::floor((box.hi[a] - box.lo[a]) / cs))
                         : std::floor((mx[a] - mn[a]) / cs) + 1;
}
}  // namespace

template <int D>
struct NeighbourSearch<D>::Impl {
  // grid
  std::array<int, D> nc{};
  std::array<std::int64_t, D> stride{};
  Vec<D> lo = Vec<D>::Zero(), invCell = Vec<D>::Zero();
  Vec<D> period = Vec<D>::Zero(), halfPeriod = Vec<D>::Zero();
  std::int64_t numCells = 0;
  // per particle / per cell
  std::vector<Index> cellOf;     // linear cell of particle i
  std::vector<Index> cellStart;  // numCells + 1
  std::vector<Index> sorted;     // particle indices in cell order (stable)
  std::vector<Vec<D>> xs;        // wrapped positions in cell order
  std::vector<Index> cursor;     // per-cell fill cursor of the counting sort
  std::vector<double> coordinate;// scratch for the quantiles of the bulk box
  // scan results: per-thread lists of neighbours (cell-order positions, or offsets
  // into the cell's candidates), and where the row of particle i starts in which
  // thread's list
  std::vector<std::vector<Index>> found;
  std::vector<std::vector<std::uint16_t>> foundNarrow;
  bool narrow = false;  // the last build used foundNarrow
  std::vector<Index> rowStart;
  std::vector<std::uint8_t> rowThread;

  void setupGrid(const std::vector<Vec<D>>& x, double radius, const PeriodicBox<D>& box);
  // The box of the bulk of the particles: per direction the quantiles q and 1 - q
  // of the coordinate, widened by a tenth of their distance and the radius.
  void bulkBox(const std::vector<Vec<D>>& x, double radius, Vec<D>& mn, Vec<D>& mx);
  void sortByCell(const std::vector<Vec<D>>& x, const PeriodicBox<D>& box);
  // After the scan (row lengths summed into out.offset): the rows, sorted by j, from the
  // per-thread buffers of cell-order positions (Index) or of offsets into the cell's
  // candidates (std::uint16_t).
  template <class T>
  void copyRows(NeighbourList<D>& out, const std::vector<std::vector<T>>& buffers, const PeriodicBox<D>& box);
  // Whether 16-bit offsets into a cell's candidates cannot wrap: no cell holds more than
  // 65535 / 3^D particles.
  bool offsetsFit() const {
    Index fullest = 0;
#pragma omp parallel for schedule(static) reduction(max : fullest)
    for (std::int64_t c = 0; c < numCells; ++c) fullest = std::max(fullest, cellStart[c + 1] - cellStart[c]);
    return std::int64_t(fullest) * (D == 2 ? 9 : 27) <= 65535;
  }
  // The first cell of share k of `team` runs of cells holding equal shares of the
  // particles (cellStart counts them); share `team` ends at numCells.
  std::int64_t firstCellOfShare(int k, int team) const {
    if (k >= team) return numCells;
    const Index target = Index(std::int64_t(cellStart[numCells]) * k / team);
    return std::int64_t(std::lower_bound(cellStart.begin(), cellStart.begin() + numCells, target) - cellStart.begin());
  }
  // The particles of the distinct neighbour cells of cell c (including c), as
  // ranges [b, e) of cell-order positions; consecutive cells are merged.
  int neighbourRanges(std::int64_t c, const PeriodicBox<D>& box, Index* ranges) const;
};

template <int D>
void NeighbourSearch<D>::Impl::setupGrid(const std::vector<Vec<D>>& x, double radius,
                                         const PeriodicBox<D>& box) {
  const std::size_t n = x.size();
  Vec<D> mn = Vec<D>::Constant(std::numeric_limits<double>::infinity());
  Vec<D> mx = -mn;
  bool finite = true;
#pragma omp parallel
  {
    Vec<D> lmn = mn, lmx = mx;
    bool lfinite = true;
#pragma omp for schedule(static) nowait
    for (std::size_t i = 0; i < n; ++i) {
      lmn = lmn.cwiseMin(x[i]);
      lmx = lmx.cwiseMax(x[i]);
      lfinite &= x[i].allFinite();
    }
#pragma omp critical
    {
      mn = mn.cwiseMin(lmn);
      mx = mx.cwiseMax(lmx);
      finite &= lfinite;
    }
  }
  if (!finite) throw NumericalError("neighbour search: non-finite particle position");
  if (n == 0) mn = mx = Vec<D>::Zero();

  // Cell size >= radius. A grid with far more cells than particles (a few
  // particles far away) covers the bulk only; if even that is too fine (a
  // sparse cloud), the cells are enlarged, which keeps the search correct (any
  // cell size >= radius is) and the memory bounded.
  const double maxCells = std::min(8.0 * double(n) + 4096.0, double(1 << 30));
  double cells = 1;
  for (int a = 0; a < D; ++a) cells *= cellsAlong<D>(a, mn, mx, radius, box);
  if (cells > maxCells) bulkBox(x, radius, mn, mx);
  double cs = radius;
  for (;;) {
    double total = 1;
    for (int a = 0; a < D; ++a) {
      const double mm = cellsAlong<D>(a, mn, mx, cs, box);
      const int m = mm > 2e9 ? 2000000000 : int(mm);
      if (box.periodic[a]) {
        const double L = box.hi[a] - box.lo[a];
        lo[a] = box.lo[a];
        invCell[a] = m / L;
        period[a] = L;
        halfPeriod[a] = 0.5 * L;
      } else {
        lo[a] = mn[a];
        invCell[a] = 1.0 / cs;
        period[a] = halfPeriod[a] = 0;
      }
      nc[a] = m;
      total *= m;
    }
    if (total <= maxCells) break;
    cs *= 1.5 * std::pow(total / maxCells, 1.0 / D);
  }
  std::int64_t s = 1;
  for (int a = 0; a < D; ++a) {
    stride[a] = s;
    s *= nc[a];
  }
  numCells = s;
}

template <int D>
void NeighbourSearch<D>::Impl::bulkBox(const std::vector<Vec<D>>& x, double radius, Vec<D>& mn, Vec<D>& mx) {
  constexpr double q = 0.005;
  const std::size_t n = x.size();
  coordinate.resize(n);
  const std::size_t lo = std::size_t(q * double(n - 1)), hi = n - 1 - lo;
  for (int a = 0; a < D; ++a) {
    for (std::size_t i = 0; i < n; ++i) coordinate[i] = x[i][a];
    std::nth_element(coordinate.begin(), coordinate.begin() + lo, coordinate.end());
    const double low = coordinate[lo];
    std::nth_element(coordinate.begin(), coordinate.begin() + hi, coordinate.end());
    const double high = coordinate[hi];
    const double widen = 0.1 * (high - low) + radius;
    mn[a] = std::max(mn[a], low - widen);
    mx[a] = std::min(mx[a], high + widen);
  }
}

template <int D>
void NeighbourSearch<D>::Impl::sortByCell(const std::vector<Vec<D>>& x, const PeriodicBox<D>& box) {
  const Index n = Index(x.size());
  cellOf.resize(n);
  sorted.resize(n);
  xs.resize(n);
  const bool anyPeriodic = box.any();
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    Vec<D> p = x[i];
    if (anyPeriodic) box.wrap(p);
    std::int64_t c = 0;
    for (int a = 0; a < D; ++a) {
      // Clamped before the conversion: a particle outside the grid goes to the edge cell.
      const double k = std::min(std::max((p[a] - lo[a]) * invCell[a], 0.0), double(nc[a] - 1));
      c += std::int64_t(k) * stride[a];
    }
    cellOf[i] = Index(c);
  }
  cellStart.assign(numCells + 1, 0);
  for (Index i = 0; i < n; ++i) ++cellStart[cellOf[i] + 1];
  for (std::int64_t c = 0; c < numCells; ++c) cellStart[c + 1] += cellStart[c];
  // stable scatter: inside a cell particles keep increasing index
  if (cursor.size() < std::size_t(numCells)) cursor.resize(numCells);
  Index* fill = cursor.data();
  std::copy(cellStart.begin(), cellStart.end() - 1, fill);
  for (Index i = 0; i < n; ++i) sorted[fill[cellOf[i]]++] = i;
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    Vec<D> p = x[sorted[k]];
    if (anyPeriodic) box.wrap(p);
    xs[k] = p;
  }
}

template <int D>
int NeighbourSearch<D>::Impl::neighbourRanges(std::int64_t c, const PeriodicBox<D>& box, Index* ranges) const {
  // per direction: the distinct neighbour cell coordinates
  int list[D][3] = {}, len[D] = {};
  for (int a = 0; a < D; ++a) {
    const int k = int((c / stride[a]) % nc[a]);
    for (int o = -1; o <= 1; ++o) {
      int m = k + o;
      if (box.periodic[a]) {
        m = (m + nc[a]) % nc[a];
        bool seen = false;
        for (int t = 0; t < len[a]; ++t) seen |= (list[a][t] == m);
        if (seen) continue;
      } else if (m < 0 || m >= nc[a]) {
        continue;
      }
      list[a][len[a]++] = m;
    }
  }
  int num = 0;
  auto add = [&](std::int64_t cell) {
    const Index b = cellStart[cell], e = cellStart[cell + 1];
    if (b == e) return;
    if (num > 0 && ranges[2 * num - 1] == b) {
      ranges[2 * num - 1] = e;  // contiguous with the previous range
    } else {
      ranges[2 * num] = b;
      ranges[2 * num + 1] = e;
      ++num;
    }
  };
  if constexpr (D == 2) {
    for (int b = 0; b < len[1]; ++b)
      for (int a = 0; a < len[0]; ++a) add(list[0][a] + list[1][b] * stride[1]);
  } else {
    for (int g = 0; g < len[2]; ++g)
      for (int b = 0; b < len[1]; ++b)
        for (int a = 0; a < len[0]; ++a) add(list[0][a] + list[1][b] * stride[1] + list[2][g] * stride[2]);
  }
  return num;
}

// ---------------------------------------------------------------- search
template <int D>
NeighbourSearch<D>::NeighbourSearch(double radius, PeriodicBox<D> box)
    : radius_(radius), box_(box), impl_(std::make_shared<Impl>()) {
  if (!(radius > 0) || !std::isfinite(radius))
    throw InputError("neighbour search: radius must be positive");
  for (int a = 0; a < D; ++a) {
    if (!box.periodic[a]) continue;
    const double L = box.hi[a] - box.lo[a];
    if (!(L >= 2 * radius))
      throw InputError("periodic direction " + std::to_string(a) + ": the periodic length " +
                       std::to_string(L) + " must be at least twice the search radius " +
                       std::to_string(radius) + " (2h support)");
  }
}

// The rows of the scan, in particle order and sorted by j. An offset t of particle i's
// row is the t-th particle of the ranges of i's cell (recomputed once per cell a thread
// meets); a position is the cell-order position itself.
template <int D>
template <class T>
void NeighbourSearch<D>::Impl::copyRows(NeighbourList<D>& out, const std::vector<std::vector<T>>& buffers,
                                        const PeriodicBox<D>& box) {
  constexpr bool offsets = !std::is_same_v<T, Index>;
  const Index n = Index(out.offset.size()) - 1;
  const Index* offset = out.offset.data();
  resizeForOverwrite(out.j, std::size_t(offset[n]));  // every row is copied below
  Index* oj = out.j.data();
#pragma omp parallel
  {
    Index ranges[2 * 27], first[28];
    std::int64_t cell = -1;
#pragma omp for schedule(static)
    for (Index i = 0; i < n; ++i) {
      if (offsets && cellOf[i] != cell) {
        cell = cellOf[i];
        const int nr = neighbourRanges(cell, box, ranges);
        first[0] = 0;
        for (int q = 0; q < nr; ++q) first[q + 1] = first[q] + ranges[2 * q + 1] - ranges[2 * q];
      }
      const T* src = buffers[rowThread[i]].data() + rowStart[i];
      const Index len = offset[i + 1] - offset[i];
      Index* row = oj + offset[i];
      bool isSorted = true;
      Index last = -1;
      int q = 0;
      for (Index t = 0; t < len; ++t) {
        Index l = Index(src[t]);
        if constexpr (offsets) {
          while (l >= first[q + 1]) ++q;  // offsets ascend along the row
          l = ranges[2 * q] + l - first[q];
        }
        const Index j = sorted[l];
        isSorted &= (j > last);
        last = j;
        row[t] = j;
      }
      // rare (particles not in cell order, or a periodic wrap)
      if (!isSorted) std::sort(row, row + len);
    }
  }
}

template <int D>
void NeighbourSearch<D>::build(const std::vector<Vec<D>>& x, NeighbourList<D>& out) {
  Impl& m = *impl_;
  const Index n = Index(x.size());
  m.setupGrid(x, radius_, box_);
  m.sortByCell(x, box_);
  const double r2max = radius_ * radius_;
  const bool periodic = box_.any();
  const Index* cellStart = m.cellStart.data();
  const Index* sorted = m.sorted.data();
  const Vec<D>* xs = m.xs.data();
  const Vec<D> period = m.period, half = m.halfPeriod;
  const std::array<bool, D> per = box_.periodic;
  auto minImage = [&](Vec<D>& d) {
    for (int a = 0; a < D; ++a) {
      if (!per[a]) continue;
      if (d[a] > half[a]) d[a] -= period[a];
      else if (d[a] < -half[a]) d[a] += period[a];
    }
  };

  out.offset.resize(std::size_t(n) + 1);
  Index* offset = out.offset.data();
  offset[0] = 0;
  m.rowStart.resize(n);
  m.rowThread.resize(n);
  const int nt = std::min(omp_get_max_threads(), 255);

  // --- scan: a thread's neighbours into its buffer, row lengths into offset[i+1];
  // then the prefix sum and the rows
  auto scan = [&](auto& buffers) {
    using T = typename std::decay_t<decltype(buffers)>::value_type::value_type;
    if (int(buffers.size()) < nt) buffers.resize(nt);
#pragma omp parallel num_threads(nt)
    {
      const int t = omp_get_thread_num(), team = omp_get_num_threads();
      auto& found = buffers[t];  // size = capacity; `used` entries valid
      std::size_t used = 0;
      Index ranges[2 * 27];
      // The thread's cells: a run holding an equal share of the particles (cellStart is
      // their running count), so each buffer holds about 1/team of the pairs, the same
      // share in every build, and its capacity does not drift up with the scheduling.
      const std::int64_t cBegin = m.firstCellOfShare(t, team), cEnd = m.firstCellOfShare(t + 1, team);
      for (std::int64_t c = cBegin; c < cEnd; ++c) {
        const Index b = cellStart[c], e = cellStart[c + 1];
        if (b == e) continue;
        const int nr = m.neighbourRanges(c, box_, ranges);
        std::size_t candidates = 0;
        for (int q = 0; q < nr; ++q) candidates += std::size_t(ranges[2 * q + 1] - ranges[2 * q]);
        for (Index k = b; k < e; ++k) {
          if (found.size() < used + candidates) {
            // Grown by a quarter, not doubled: the buffers stay allocated between builds,
            // so their slack counts in every step's peak memory.
            const std::size_t grown = std::max(found.size() + found.size() / 4, used + candidates);
            found.reserve(grown);
            found.resize(grown);
          }
          T* dst = found.data() + used;
          const Vec<D> xi = xs[k];
          std::size_t cnt = 0;
          Index local = 0;  // the candidate's offset in the cell's ranges
          for (int q = 0; q < nr; ++q) {
            for (Index l = ranges[2 * q]; l < ranges[2 * q + 1]; ++l, ++local) {
              Vec<D> d = xi - xs[l];
              if (periodic) minImage(d);
              dst[cnt] = T(std::is_same_v<T, Index> ? l : local);  // branch-free append
              cnt += (d.squaredNorm() < r2max) & (l != k);
            }
          }
          const Index i = sorted[k];
          offset[i + 1] = Index(cnt);
          m.rowStart[i] = Index(used);
          m.rowThread[i] = std::uint8_t(t);
          used += cnt;
        }
      }
    }
    for (Index i = 0; i < n; ++i) offset[i + 1] += offset[i];
    m.copyRows(out, buffers, box_);
  };
  m.narrow = m.offsetsFit();
  if (m.narrow) scan(m.foundNarrow);
  else scan(m.found);
  out.attach(x, box_);
}

template <int D>
std::vector<Index> NeighbourSearch<D>::cellOrder(const std::vector<Vec<D>>& x) {
  impl_->setupGrid(x, radius_, box_);
  impl_->sortByCell(x, box_);
  return impl_->sorted;
}

template <int D>
std::int64_t NeighbourSearch<D>::numCells() const { return impl_->numCells; }

template <int D>
double NeighbourSearch<D>::cellSize(int a) const { return 1.0 / impl_->invCell[a]; }

template <int D>
bool NeighbourSearch<D>::usedOffsets() const { return impl_->narrow; }

// ---------------------------------------------------------------- reference
template <int D>
void bruteForceNeighbours(const std::vector<Vec<D>>& x, double radius, const PeriodicBox<D>& box,
                          NeighbourList<D>& out) {
  const std::size_t n = x.size();
  out.offset.assign(n + 1, 0);
  out.j.clear();
  out.attach(x, box);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      const Vec<D> d = box.difference(x[i], x[j]);
      const double r = d.norm();
      if (r < radius) {
        out.j.push_back(Index(j));
      }
    }
    out.offset[i + 1] = Index(out.j.size());
  }
}

template struct PeriodicBox<2>;
template struct PeriodicBox<3>;
template class NeighbourSearch<2>;
template class NeighbourSearch<3>;
template void bruteForceNeighbours<2>(const std::vector<Vec<2>>&, double, const PeriodicBox<2>&,
                                      NeighbourList<2>&);
template void bruteForceNeighbours<3>(const std::vector<Vec<3>>&, double, const PeriodicBox<3>&,
                                      NeighbourList<3>&);

}  // namespace shizuku
