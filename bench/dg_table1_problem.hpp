#pragma once
// The scene of Kaufmann et al. 2009 Table 1 (issue #18), shared by the benchmarks that
// measure its phases: the unit cube as a 10 × 10 × 10 hexahedral grid, clamped weakly at
// x = 0, linear elasticity with E = 1, ν = 0.3.
#include <vector>

#include "dg/polyhedral_mesh_faces.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/structured_grid.hpp"

namespace altfem::bench {

struct DgTable1Problem {
  PolyhedralMesh mesh;
  std::vector<Polyhedron> cells;
  std::vector<dg::DgFace> faces;  // the boundary faces at x = 0 held by condition 0
  double youngs_modulus = 1, lambda = 0, mu = 0;
};

inline DgTable1Problem dg_table1_problem() {
  DgTable1Problem problem;
  problem.mesh = polyhedral_mesh_from_volume_mesh(structured_grid(
      Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()), {10, 10, 10}, ElementType::hex8));
  problem.cells = dg::mesh_cells(problem.mesh);
  problem.faces = dg::mesh_faces(problem.mesh);
  for (dg::DgFace& face : problem.faces)
    if (face.plus < 0 && face.normal.x() < -0.5) face.condition = 0;  // the clamp at x = 0
  const double poisson_ratio = 0.3;
  problem.lambda = problem.youngs_modulus * poisson_ratio / ((1 + poisson_ratio) * (1 - 2 * poisson_ratio));
  problem.mu = problem.youngs_modulus / (2 * (1 + poisson_ratio));
  return problem;
}

}  // namespace altfem::bench
