// Neighbour search by a cell-linked list (methods.md 13 step 1): all pairs
// 0 < |r_ij| < radius in CSR form, O(N), minimum image in periodic directions.
//
// build(): (1) a uniform grid over the bounding box (periodic directions: over
// the periodic box, cell size L/floor(L/radius)), cell size >= radius;
// (2) counting sort of particles by cell (wrapped positions copied in cell
// order for locality); (3) parallel count pass over cells, prefix sum;
// (4) parallel fill pass writing each row, sorted by j. Every buffer lives in
// Impl and the output vectors only grow, so a rebuild allocates nothing once
// the capacity has been reached. Rows are identical for any thread count.
// Reads no dictionary keys (radius and box come from the caller).
#include "particles/NeighbourList.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <omp.h>

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

template <int D>
Vec<D> PeriodicBox<D>::difference(const Vec<D>& a, const Vec<D>& b) const {
  Vec<D> d = a - b;
  for (int k = 0; k < D; ++k) {
    if (!periodic[k]) continue;
    const double L = hi[k] - lo[k];
    d[k] -= L * std::nearbyint(d[k] / L);
  }
  return d;
}

// ---------------------------------------------------------------- Impl
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
  // per-thread scratch for rows that are not already sorted by j
  struct Entry {
    Index j;
    Vec<D> rij;
    double r;
  };
  std::vector<std::vector<Entry>> scratch;

  void setupGrid(const std::vector<Vec<D>>& x, double radius, const PeriodicBox<D>& box);
  void sortByCell(const std::vector<Vec<D>>& x, const PeriodicBox<D>& box);
  // Distinct neighbour cells of cell c (including c), returned in `cells`.
  int neighbourCells(std::int64_t c, const PeriodicBox<D>& box, std::int64_t* cells) const;
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

  // Cell size >= radius; enlarged if the grid would have far more cells than
  // particles (e.g. a few particles far away), which keeps the search correct
  // (any cell size >= radius is) and the memory bounded.
  const double maxCells = std::min(8.0 * double(n) + 4096.0, double(1 << 30));
  double cs = radius;
  for (;;) {
    double total = 1;
    for (int a = 0; a < D; ++a) {
      int m;
      if (box.periodic[a]) {
        const double L = box.hi[a] - box.lo[a];
        m = std::max(1, int(std::floor(L / cs)));
        lo[a] = box.lo[a];
        invCell[a] = m / L;
        period[a] = L;
        halfPeriod[a] = 0.5 * L;
      } else {
        const double ext = mx[a] - mn[a];
        const double mm = std::floor(ext / cs) + 1;
        m = mm > 2e9 ? 2000000000 : int(mm);
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
      int k = int((p[a] - lo[a]) * invCell[a]);
      k = std::min(std::max(k, 0), nc[a] - 1);
      c += k * stride[a];
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
int NeighbourSearch<D>::Impl::neighbourCells(std::int64_t c, const PeriodicBox<D>& box,
                                             std::int64_t* cells) const {
  // per direction: the distinct neighbour cell coordinates
  int list[D][3] = {}, len[D] = {};
  for (int a = 0; a < D; ++a) {
    const int k = int((c / stride[a]) % nc[a]);
    len[a] = 0;
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
  if constexpr (D == 2) {
    for (int b = 0; b < len[1]; ++b)
      for (int a = 0; a < len[0]; ++a) cells[num++] = list[0][a] + list[1][b] * stride[1];
  } else {
    for (int g = 0; g < len[2]; ++g)
      for (int b = 0; b < len[1]; ++b)
        for (int a = 0; a < len[0]; ++a)
          cells[num++] = list[0][a] + list[1][b] * stride[1] + list[2][g] * stride[2];
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

template <int D>
void NeighbourSearch<D>::build(const std::vector<Vec<D>>& x, NeighbourList<D>& out) {
  Impl& m = *impl_;
  const Index n = Index(x.size());
  m.setupGrid(x, radius_, box_);
  m.sortByCell(x, box_);
  const double r2max = radius_ * radius_;
  const bool periodic = box_.any();
  const std::int64_t numCells = m.numCells;
  const Index* cellStart = m.cellStart.data();
  const Index* sorted = m.sorted.data();
  const Vec<D>* xs = m.xs.data();
  const Vec<D> period = m.period, half = m.halfPeriod;
  std::array<bool, D> per = box_.periodic;

  out.offset.resize(std::size_t(n) + 1);
  Index* offset = out.offset.data();
  offset[0] = 0;

  auto minImage = [&](Vec<D>& d) {
    for (int a = 0; a < D; ++a) {
      if (!per[a]) continue;
      if (d[a] > half[a]) d[a] -= period[a];
      else if (d[a] < -half[a]) d[a] += period[a];
    }
  };

  // --- count pass: row lengths into offset[i+1]
#pragma omp parallel
  {
    std::int64_t cells[27];
#pragma omp for schedule(dynamic, 64)
    for (std::int64_t c = 0; c < numCells; ++c) {
      const Index b = cellStart[c], e = cellStart[c + 1];
      if (b == e) continue;
      const int nn = m.neighbourCells(c, box_, cells);
      for (Index k = b; k < e; ++k) {
        const Vec<D> xi = xs[k];
        Index cnt = 0;
        for (int q = 0; q < nn; ++q) {
          const Index qb = cellStart[cells[q]], qe = cellStart[cells[q] + 1];
          for (Index l = qb; l < qe; ++l) {
            Vec<D> d = xi - xs[l];
            if (periodic) minImage(d);
            cnt += (d.squaredNorm() < r2max) & (l != k);
          }
        }
        offset[sorted[k] + 1] = cnt;
      }
    }
  }
  for (Index i = 0; i < n; ++i) offset[i + 1] += offset[i];
  const std::size_t numPairs = std::size_t(offset[n]);
  out.j.resize(numPairs);
  out.rij.resize(numPairs);
  out.r.resize(numPairs);
  Index* oj = out.j.data();
  Vec<D>* orij = out.rij.data();
  double* orr = out.r.data();

  // --- fill pass: rows written in candidate order, then sorted by j if needed
  const int nt = omp_get_max_threads();
  if (int(m.scratch.size()) < nt) m.scratch.resize(nt);
#pragma omp parallel
  {
    std::int64_t cells[27];
    auto& scratch = m.scratch[omp_get_thread_num()];
#pragma omp for schedule(dynamic, 64)
    for (std::int64_t c = 0; c < numCells; ++c) {
      const Index b = cellStart[c], e = cellStart[c + 1];
      if (b == e) continue;
      const int nn = m.neighbourCells(c, box_, cells);
      for (Index k = b; k < e; ++k) {
        const Vec<D> xi = xs[k];
        const Index i = sorted[k];
        const Index p0 = offset[i];
        Index p = p0;
        bool isSorted = true;
        Index last = -1;
        for (int q = 0; q < nn; ++q) {
          const Index qb = cellStart[cells[q]], qe = cellStart[cells[q] + 1];
          for (Index l = qb; l < qe; ++l) {
            Vec<D> d = xi - xs[l];
            if (periodic) minImage(d);
            const double r2 = d.squaredNorm();
            if (r2 < r2max && l != k) {
              const Index j = sorted[l];
              isSorted &= (j > last);
              last = j;
              oj[p] = j;
              orij[p] = d;
              orr[p] = std::sqrt(r2);
              ++p;
            }
          }
        }
        if (!isSorted) {
          const Index len = p - p0;
          if (Index(scratch.size()) < len) scratch.resize(len);
          for (Index t = 0; t < len; ++t) scratch[t] = {oj[p0 + t], orij[p0 + t], orr[p0 + t]};
          std::sort(scratch.begin(), scratch.begin() + len,
                    [](const typename Impl::Entry& u, const typename Impl::Entry& v) { return u.j < v.j; });
          for (Index t = 0; t < len; ++t) {
            oj[p0 + t] = scratch[t].j;
            orij[p0 + t] = scratch[t].rij;
            orr[p0 + t] = scratch[t].r;
          }
        }
      }
    }
  }
}

template <int D>
std::vector<Index> NeighbourSearch<D>::cellOrder(const std::vector<Vec<D>>& x) {
  impl_->setupGrid(x, radius_, box_);
  impl_->sortByCell(x, box_);
  return impl_->sorted;
}

// ---------------------------------------------------------------- reference
template <int D>
void bruteForceNeighbours(const std::vector<Vec<D>>& x, double radius, const PeriodicBox<D>& box,
                          NeighbourList<D>& out) {
  const std::size_t n = x.size();
  out.offset.assign(n + 1, 0);
  out.j.clear();
  out.rij.clear();
  out.r.clear();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      const Vec<D> d = box.difference(x[i], x[j]);
      const double r = d.norm();
      if (r < radius) {
        out.j.push_back(Index(j));
        out.rij.push_back(d);
        out.r.push_back(r);
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
