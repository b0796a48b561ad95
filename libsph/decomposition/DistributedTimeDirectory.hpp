// The time directories of a run on several ranks (docs/parallel.md 7): each rank writes its
// own particles as one piece of <time>/particles.pvtp, and a restart reads the pieces back
// as the ranks' shares, on any number of ranks.
//   writeDistributedTime  the fields agreed across the ranks; rank 0 begins the write (the
//                         replace check, the temporary folder), every rank writes
//                         particles_<rank>.vtp of its first `owned` particles, rank 0 writes
//                         particles.pvtp and uniform/time and swaps the folder into place
//                         (TimeDirectory.hpp: atomic for the whole directory). A failure on
//                         any rank abandons the write: no rank's piece is left, and every rank
//                         throws the first failure's message. With writeFormat ascii the
//                         particles are also gathered on rank 0 for the one-file-per-field
//                         format (ParticleGather.hpp).
//   readDistributedShare  this rank's share of a time directory written on any number of
//                         ranks, or by a serial run (TimeDirectory.hpp, readTimeDirectory's
//                         part/parts), with the checks that span the ranks: one rank's
//                         corrupt piece stops every rank with its message; the pieces'
//                         mass, rho0 and spacing equal; every id held once over all ranks.
//                         The particles then go to their owners (DomainDecomposition::start).
// Both collective. Reads no dictionary keys.
#pragma once
#include "io/TimeDirectory.hpp"

namespace shizuku {

template <int D>
void writeDistributedTime(const std::string& caseDir, const std::string& timeName, ParticleSet<D>& P,
                          std::size_t owned, const TimeState& s, bool ascii);

template <int D>
ParticleSet<D> readDistributedShare(const std::string& caseDir, const std::string& timeName, TimeState& s);

}  // namespace shizuku
