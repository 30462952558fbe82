#pragma once
// The cell across each face of a conforming volume mesh, faces matched by their corner
// nodes: the node copies a cut made on its blade keep its two sides apart.
#include <vector>

#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

struct FaceNeighbour {
  int cell = -1, face = -1;  ///< the cell across a face and that face's local index; −1: none
};

/// #cells × F entries, F = element_faces(shape).size(): entry cell · F + f is the cell
/// across local face f (element_faces order). A face shared by more than two cells (a
/// mesh that is not a manifold) meets its first side (in cell order) from each later
/// one, and the first meets the last.
std::vector<FaceNeighbour> face_neighbours(const VolumeMesh& mesh);

}  // namespace altfem
