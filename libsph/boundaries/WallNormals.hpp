// The wall surface's normal at every wall particle (docs/method.md 11, eq. 11d), from the
// geometry of the wall region the particle belongs to (WallBox.hpp: the region whose layer
// region holds it, the one it lies least deep in when several do, the tied ones' normals
// summed where regions meet at an edge of the wall), taken at its rest
// position for a moving wall. Stored in the particle field `wallNormal` (unit, out of the
// wall; zero for other particles and for a wall particle no region holds) and, in a case with
// moving walls, also in `restNormal`, from which MovingWalls turns `wallNormal` with the wall. The wall rows take the normal a fluid particle sees from these
// (WallContacts): on a flat wall it is the face's normal exactly, wherever the fluid stands
// along the wall's lattice. A case without wall particles keeps the field empty.
// Reads no dictionary keys.
#pragma once
#include "particles/ParticleSet.hpp"
#include "particles/WallBox.hpp"
#include <vector>

namespace shizuku {

template <int D>
void assignWallNormals(ParticleSet<D>& P, const std::vector<WallBox<D>>& walls);

}  // namespace shizuku
