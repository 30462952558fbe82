#pragma once
// Which cells of a mesh touch across a face, and through which of their local faces. In a
// conforming mesh two cells share a whole face; in a refined grid (hexahedral_forest.hpp) a
// coarse cell's face touches the faces of up to four finer cells, which no matching of
// corner nodes finds.
#include <vector>

namespace altfem {

/// `cell`'s local face `face` (element_faces order) touches `other_cell`'s local face
/// `other_face` with positive area; each pair listed once.
struct CellFaceContact {
  int cell = 0, face = 0, other_cell = 0, other_face = 0;
};

}  // namespace altfem
