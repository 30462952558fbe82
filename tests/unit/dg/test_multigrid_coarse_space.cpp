// The coarse level of PETSc's multigrid for DG (dg/multigrid_coarse_space.hpp): one scalar
// function per mesh vertex whose near-null space, the rigid motions at the vertices, P maps
// to the rigid motions in every cell's monomials exactly; each placed with a cell's
// constant function; coarsened gently beyond degree 1; degree 2's affine functions where the vertex space would not be
// coarser; nothing for degree 1 then, nor under strong conditions.
#include <gtest/gtest.h>

#include <algorithm>

#include "dg/multigrid_coarse_space.hpp"
#include "dg/polyhedral_mesh_faces.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "tests/unit/dg/field_error_at_cell_points.hpp"
#include "tests/unit/surfaces.hpp"

namespace altfem::dg {
namespace {

PolyhedralMesh grid(const Eigen::Vector3i& cells) {
  return polyhedral_mesh_from_volume_mesh(structured_grid(
      Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 2, 1)), cells, ElementType::hex8));
}

DgLinearSystem system_of(const PolyhedralMesh& mesh, int degree, bool strong = false) {
  std::vector<DgFace> faces = mesh_faces(mesh);
  if (strong)
    for (DgFace& face : faces)
      if (face.plus < 0 && face.polygon.col(0).maxCoeff() < 1e-12) face.condition = 0, face.strong = true;
  return DgLinearSystem(mesh_cells(mesh), faces, {degree, Flux::interior_penalty, 20, 1, 1});
}

// P (the scalar prolongation, applied per component) times coarse values.
Eigen::VectorXd prolong(const CoarseSpace& space, const Eigen::VectorXd& coarse) {
  Eigen::VectorXd fine = Eigen::VectorXd::Zero(3 * space.prolongation.rows());
  for (Eigen::Index column = 0; column < space.prolongation.outerSize(); ++column)
    for (Eigen::SparseMatrix<double>::InnerIterator entry(space.prolongation, column); entry; ++entry)
      fine.segment<3>(3 * entry.row()) += entry.value() * coarse.segment<3>(3 * entry.col());
  return fine;
}

TEST(MultigridCoarseSpace, IsOneFunctionPerVertexWhoseRigidMotionsAreTheFineOnes) {
  const PolyhedralMesh mesh = grid(Eigen::Vector3i(3, 4, 2));
  for (int degree : {1, 2}) {
    const DgLinearSystem system = system_of(mesh, degree);
    const CoarseSpace space = multigrid_coarse_space(mesh, system);
    ASSERT_EQ(space.fine_function.size(), 4u * 5u * 3u) << "k = " << degree;
    ASSERT_EQ(space.near_null_space.rows(), 3 * 60);
    ASSERT_EQ(space.near_null_space.cols(), 6);
    EXPECT_EQ(space.coarsen_gently, degree == 2);
    for (int function : space.fine_function) {  // a cell's constant function
      int cell = 0;
      while (system.offset(cell + 1) <= function) ++cell;
      EXPECT_EQ(system.offset(cell), function);
    }
    for (int axis = 0; axis < 3; ++axis) {
      const Eigen::Vector3d direction = Eigen::Vector3d::Unit(axis);
      const Eigen::VectorXd translation = prolong(space, space.near_null_space.col(axis));
      const Eigen::VectorXd rotation = prolong(space, space.near_null_space.col(3 + axis));
      EXPECT_LT(
          field_error_at_cell_points(mesh, system, translation, [&](const Eigen::Vector3d&) { return direction; }),
          1e-12);
      EXPECT_LT(field_error_at_cell_points(mesh, system, rotation,
                                           [&](const Eigen::Vector3d& x) { return direction.cross(x); }),
                1e-12)
          << "k = " << degree << ", axis " << axis;
    }
  }
}

TEST(MultigridCoarseSpace, IsDegreeTwosAffineFunctionsWhereTheVerticesAreNotFewer) {
  const PolyhedralMesh one_cell = grid(Eigen::Vector3i(1, 1, 1));  // 8 vertices: 24 coarse unknowns
  // k = 1: 12 unknowns, no coarser space; k = 2: 30, so the vertex space.
  EXPECT_TRUE(multigrid_coarse_space(one_cell, system_of(one_cell, 1)).empty());
  EXPECT_EQ(multigrid_coarse_space(one_cell, system_of(one_cell, 2)).fine_function.size(), 8u);
  // Two cells, k = 1: 12 vertices (36 unknowns) against 24 DOFs.
  const PolyhedralMesh two_cells = grid(Eigen::Vector3i(2, 1, 1));
  EXPECT_TRUE(multigrid_coarse_space(two_cells, system_of(two_cells, 1)).empty());
  // A sliced ball's cut cells have many vertices: k = 2's affine functions, 4 a cell.
  SlicingOptions options;
  options.resolution = 2;
  const SlicedMesh sliced =
      slice_into_polyhedra(test::sphere(0.8, 12, 24, Eigen::Vector3d(0.03, -0.02, 0.01)), options);
  const DgLinearSystem quadratic = system_of(sliced.mesh, 2);
  const CoarseSpace affine = multigrid_coarse_space(sliced.mesh, quadratic);
  ASSERT_GE(3 * sliced.mesh.nodes.rows(), quadratic.dof_count());  // 27 cells, 402 vertices, 810 DOFs
  ASSERT_EQ(affine.fine_function.size(), 4u * static_cast<size_t>(sliced.mesh.cell_count()));
  EXPECT_EQ(affine.near_null_space.size(), 0);
  EXPECT_EQ(affine.prolongation.nonZeros(), affine.prolongation.cols());
  for (int cell = 0; cell < sliced.mesh.cell_count(); ++cell)
    for (int function = 0; function < 4; ++function) {  // 1, x, y, z of each cell, injected
      const int coarse = 4 * cell + function;
      EXPECT_EQ(affine.fine_function[coarse], quadratic.offset(cell) + function);
      EXPECT_EQ(affine.prolongation.coeff(quadratic.offset(cell) + function, coarse), 1.0);
    }
}

TEST(MultigridCoarseSpace, IsEmptyUnderStrongConditions) {
  const PolyhedralMesh mesh = grid(Eigen::Vector3i(3, 4, 2));
  EXPECT_TRUE(multigrid_coarse_space(mesh, system_of(mesh, 1, true)).empty());
  EXPECT_TRUE(multigrid_coarse_space(mesh, system_of(mesh, 2, true)).empty());
}

}  // namespace
}  // namespace altfem::dg
