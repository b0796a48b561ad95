// How a program starts its ranks (docs/parallel.md 2): `-parallel` starts MPI; without it a
// launcher that started several ranks is an error on every rank, reported once (by rank
// 0), before anything is read or written, since each rank would run the whole case and
// write the same files. In a distributed run the ranks other than 0 are silent.
// Reads no dictionary keys.
#pragma once
#include <optional>
#include <string>

namespace shizuku {

// Returns the exit status when the program must stop (1: the ranks and the option
// disagree, or -parallel in a build without MPI).
std::optional<int> startRanks(bool parallel, const std::string& program, int* argc, char*** argv);

}  // namespace shizuku
