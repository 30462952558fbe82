#pragma once
// How flat a polyhedral mesh's cells are: a basis complete to degree 1 only (trilinear
// hexahedra, harmonic bases, dg k = 1) represents bending by shear, and a cell much
// wider than thick locks (the 1 mm plate on 31 mm slice cells bends 300 times too
// little). Methods use this to warn; the answer stays the method's own.
#include <optional>
#include <string>

#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem {

/// Per cell (#cells): its diameter over its thickness, the thickness being its volume
/// over its largest face's area (a cube: √3, a 31 × 31 × 1 plate cell: 44). Needs the
/// geometry arrays (compute_polyhedral_geometry).
Eigen::VectorXd cell_flatness(const PolyhedralMesh& mesh);

/// For a basis complete to degree 1 only: a warning when the median cell is flatter than
/// 20 (cell_flatness; about 14 times wider than thick): "<method>: the median cell is
/// about N times wider than thick …, lock in bending …; <remedy>". Empty otherwise.
std::optional<std::string> flat_cell_locking_warning(const PolyhedralMesh& mesh, const std::string& method,
                                                     const std::string& remedy);

}  // namespace altfem
