#pragma once
// Dirichlet conditions act on background nodes (Longva et al. 2020 §6): a region whose
// boundary passes through the inside of a kept cell constrains nodes of that cell on
// both sides of it, some outside the material. The shipped scenes put their regions on
// grid planes; this finds the conditions that do not.
#include <string>
#include <vector>

#include "shared/mesh/volume_mesh.hpp"
#include "shared/scene/scene.hpp"

namespace altfem {

/// One warning per condition whose region's boundary cuts through the interior of at
/// least one cell of `cells` (sampled at the 27 points ξ ∈ {1/4, 1/2, 3/4}³ of the
/// cell's bounding box — the cells are a grid's), naming the condition and the count.
std::vector<std::string> conditions_cutting_cells(const VolumeMesh& cells,
                                                  const std::vector<DirichletCondition>& dirichlet);

}  // namespace altfem
