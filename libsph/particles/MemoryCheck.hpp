// The memory a case will need, checked before its particles are allocated
// (docs/reliability.md, "Memory"): the particle count times the bytes a particle costs
// the solver (every per-particle array: the particle set, the flow state, the neighbour
// list with its weights, the pressure matrix and the linear solver; measured as peak RSS
// over particle count between two sizes of one case), against the memory available
// (MemAvailable of /proc/meminfo, and what RLIMIT_AS leaves). A case beyond it is an
// InputError naming the bytes needed and available, instead of a std::bad_alloc later.
// Reads no keys; the generator hands it the count and the dictionary to blame.
#pragma once
#include "core/Dictionary.hpp"
#include <string>

namespace shizuku {

// Bytes per particle the solver holds in D dimensions (measured, rounded up).
double bytesPerParticle(int dimension);

// Bytes this process may still allocate, and what limits it ("MemAvailable in
// /proc/meminfo" or "RLIMIT_AS (ulimit -v)"); a negative value when neither is known.
double availableBytes(std::string& limitedBy);

// Throws InputError on `d`/`key` when `particles` would need more than is available.
void checkMemoryFor(const Dictionary& d, const std::string& key, double particles, int dimension);

}  // namespace shizuku
