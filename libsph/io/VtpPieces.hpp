// <time>/particles.pvtp, the particle file of a run on several ranks (docs/design.md 1.3,
// docs/parallel.md 7): VTK's parallel PolyData header (PPolyData) naming one piece per
// rank, particles_<k>.vtp, k = 0 .. n-1, each a particles.vtp of that rank's own particles
// (VtpFile.hpp). ParaView opens the pvtp, and a particles.pvd listing it, as one data set.
// Reading accepts only the form written here: a VTKFile of type PPolyData whose pieces
// are particles_0.vtp, particles_1.vtp, ... in that order, at most kMaxPieces of them, in
// a file of at most 64 MB; anything else is an InputError naming the file, so a hostile
// Source (another folder, another name) is never opened.
// Dictionary keys read: none.
#pragma once
#include "particles/ParticleSet.hpp"
#include <string>
#include <vector>

namespace shizuku {

constexpr int kMaxPieces = 1 << 22;

// "particles_<k>.vtp"
std::string pieceFileName(int k);
// Whether name is one of those ("particles_" digits ".vtp").
bool isPieceFileName(const std::string& name);

// Write the header for `pieces` pieces whose point arrays are the fields p holds
// (non-empty or mandatory; every piece holds the same fields). Throws
// std::runtime_error naming the file on a write failure.
template <int D>
void writePvtp(const std::string& path, const ParticleSet<D>& p, int pieces);

// The pieces' file names, in order. Throws InputError "corrupt particle file '<path>': ..."
// (or "cannot read ...") when the file is not one writePvtp wrote.
std::vector<std::string> readPvtpPieces(const std::string& path);

}  // namespace shizuku
