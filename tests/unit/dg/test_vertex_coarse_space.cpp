// The vertex coarse space of DG's two-level preconditioner (dg/vertex_coarse_space.hpp):
// the values A x + b of an affine field at the mesh's vertices map to element coefficients
// whose polynomials equal A x + b — on a hexahedral grid and on a sliced sphere whose cut
// cells have many vertices, shared with neighbours or not — for k = 1 and k = 2, also in cells
// whose functions a strong condition has recombined.
#include <gtest/gtest.h>

#include "dg/polyhedral_mesh_faces.hpp"
#include "dg/vertex_coarse_space.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "tests/unit/dg/field_error_at_cell_points.hpp"
#include "tests/unit/surfaces.hpp"

namespace altfem::dg {
namespace {

// The largest |u_h(x) − (A x + b)| over every cell's vertices and centroid, u_h = P (values
// of A x + b at the coarse vertices).
// strong: the boundary faces at x = 0 carry a strong condition, so their cells' functions are
// combinations of monomials (dg/strong_conditions.hpp).
double affine_reproduction_error(const PolyhedralMesh& mesh, int degree, bool strong = false) {
  std::vector<DgFace> faces = mesh_faces(mesh);
  if (strong)
    for (DgFace& face : faces)
      if (face.plus < 0 && face.polygon.col(0).maxCoeff() < 1e-12) face.condition = 0, face.strong = true;
  const DgLinearSystem system(mesh_cells(mesh), faces, {degree, Flux::interior_penalty, 20, 1, 1});
  const VertexCoarseSpace space = vertex_coarse_space(mesh, system);
  Eigen::Matrix3d gradient;
  gradient << 0.3, -1.2, 0.7, 2.0, 0.1, -0.4, -0.9, 0.5, 1.1;
  const Eigen::Vector3d shift(0.25, -0.5, 1.5);
  const auto field = [&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return gradient * x + shift; };
  Eigen::VectorXd values(3 * space.nodes.size());
  for (size_t v = 0; v < space.nodes.size(); ++v) values.segment<3>(3 * v) = field(mesh.nodes.row(space.nodes[v]));
  const Eigen::VectorXd coefficients = space.prolongation * values;

  return field_error_at_cell_points(mesh, system, coefficients, field);
}

TEST(VertexCoarseSpace, ReproducesAffineFieldsOnAHexahedralGrid) {
  const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(structured_grid(
      Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 2, 1)), {3, 4, 2}, ElementType::hex8));
  for (int degree : {1, 2}) {
    EXPECT_LT(affine_reproduction_error(mesh, degree), 1e-12) << "k = " << degree;
    EXPECT_LT(affine_reproduction_error(mesh, degree, true), 1e-12) << "k = " << degree << ", strong condition";
  }
}

TEST(VertexCoarseSpace, ReproducesAffineFieldsOnASlicedMeshWithCutCells) {
  SlicingOptions options;
  options.resolution = 4;
  const SlicedMesh sliced =
      slice_into_polyhedra(test::sphere(0.8, 12, 24, Eigen::Vector3d(0.03, -0.02, 0.01)), options);
  ASSERT_GT(sliced.cut_pieces, 0);
  for (int degree : {1, 2}) EXPECT_LT(affine_reproduction_error(sliced.mesh, degree), 1e-12) << "k = " << degree;
}

}  // namespace
}  // namespace altfem::dg
