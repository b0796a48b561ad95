// resizeForOverwrite (core/OverwriteBuffer.hpp): growing a per-pair buffer past its capacity
// must not hold the old and the new storage at once (the peak memory of a step), must leave a
// quarter of headroom, and must not reallocate while the size stays within the capacity.
#define BOOST_TEST_MODULE core_overwriteBuffer
#include "core/OverwriteBuffer.hpp"
#include <boost/test/unit_test.hpp>
#include <algorithm>
#include <cstdlib>

using namespace shizuku;

namespace {

// Counts the bytes alive through it and their largest total.
struct Tally {
  static inline std::size_t alive = 0, peak = 0, allocations = 0;
};

template <class T>
struct CountingAllocator {
  using value_type = T;
  CountingAllocator() = default;
  template <class U> CountingAllocator(const CountingAllocator<U>&) {}
  T* allocate(std::size_t n) {
    Tally::alive += n * sizeof(T);
    Tally::peak = std::max(Tally::peak, Tally::alive);
    ++Tally::allocations;
    return static_cast<T*>(std::malloc(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) {
    Tally::alive -= n * sizeof(T);
    std::free(p);
  }
  template <class U> bool operator==(const CountingAllocator<U>&) const { return true; }
  template <class U> bool operator!=(const CountingAllocator<U>&) const { return false; }
};

using Buffer = std::vector<double, CountingAllocator<double>>;

}  // namespace

BOOST_AUTO_TEST_CASE(growth_frees_the_old_storage_before_taking_the_new) {
  Buffer v;
  resizeForOverwrite(v, 1000);
  BOOST_TEST(v.size() == 1000u);
  BOOST_TEST(v.capacity() == 1250u);
  Tally::peak = Tally::alive;
  resizeForOverwrite(v, 1300);  // past the capacity: a new buffer of 1300 + 325
  BOOST_TEST(v.size() == 1300u);
  BOOST_TEST(v.capacity() == 1625u);
  // At no time more than the new buffer: std::vector::resize would hold 1250 + 2500 doubles.
  BOOST_TEST(Tally::peak == 1625u * sizeof(double));
}

BOOST_AUTO_TEST_CASE(sizes_within_the_capacity_do_not_reallocate) {
  Buffer v;
  resizeForOverwrite(v, 800);
  const std::size_t before = Tally::allocations;
  const double* data = v.data();
  for (std::size_t n : {900u, 1000u, 700u, 1000u}) {
    resizeForOverwrite(v, n);
    BOOST_TEST(v.size() == n);
  }
  BOOST_TEST(Tally::allocations == before);
  BOOST_TEST(v.data() == data);
}
