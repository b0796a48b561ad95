// Resizing of a buffer whose contents the caller overwrites in full after the resize (the
// per-pair arrays rebuilt every step: neighbour indices, derivative weights). When the
// new size exceeds the capacity, std::vector::resize would allocate twice the old
// capacity and copy the old contents into it while both are alive: for a 3D case of 400k
// particles that transient held the SPH2 gradient weights twice over (0.49 GB old, 0.97 GB
// new) and set the run's peak memory. Here the old storage is released first and the new
// one reserved with a quarter of headroom: the peak is the new size, and the slowly growing
// pair count of a flow reallocates rarely. Reserved but untouched pages cost no memory.
#pragma once
#include <cstddef>
#include <vector>

namespace shizuku {

template <class T, class A>
void resizeForOverwrite(std::vector<T, A>& v, std::size_t n) {
  if (n > v.capacity()) {
    std::vector<T, A>().swap(v);
    v.reserve(n + n / 4);
  }
  v.resize(n);
}

}  // namespace shizuku
