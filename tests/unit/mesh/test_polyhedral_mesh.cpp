// Conversion of tet and hex meshes to polyhedral meshes: volumes, centroids, face
// adjacency (interior faces the same polygon with opposite normals) and the divergence
// theorem on the boundary (area-weighted normals sum to zero for a closed object).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "shared/common/error.hpp"
#include "shared/geometry/polygon_moments.hpp"
#include "shared/geometry/polyhedron_moments.hpp"
#include "shared/io/polyhedral_grid.hpp"
#include "shared/io/vtu_writer.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/structured_grid.hpp"

namespace altfem {
namespace {

struct Case {
  ElementType type;
  Eigen::Vector3i resolution;
};

class PolyhedralConversion : public ::testing::TestWithParam<Case> {};

TEST_P(PolyhedralConversion, VolumesFacesAndAdjacencyAreConsistent) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d(-0.3, 0.1, 2.0), Eigen::Vector3d(0.9, 1.6, 2.7));
  const VolumeMesh volume_mesh = structured_grid(box, GetParam().resolution, GetParam().type);
  const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(volume_mesh);
  const Eigen::Vector3i n = GetParam().resolution;
  const bool tetrahedral = GetParam().type == ElementType::tet4 || GetParam().type == ElementType::tet10;

  ASSERT_EQ(mesh.cell_count(), volume_mesh.cells.rows());
  EXPECT_EQ(mesh.nodes.rows(), (n.array() + 1).prod());  // corner nodes only
  const double box_volume = box.volume();
  EXPECT_NEAR(mesh.cell_volumes.sum(), box_volume, 1e-13 * box_volume);
  EXPECT_NEAR(mesh.cell_volumes.sum(), volume_mesh_volume(volume_mesh), 1e-13 * box_volume);

  // The volume-weighted centroids give the box's centre.
  const Eigen::Vector3d centre = (mesh.cell_centroids.transpose() * mesh.cell_volumes) / mesh.cell_volumes.sum();
  EXPECT_LT((centre - box.center()).norm(), 1e-13);

  // Counting faces: every boundary face lies on the box, and the boundary area is the box's.
  const Eigen::Vector3d size = box.sizes();
  const double box_area = 2 * (size.x() * size.y() + size.y() * size.z() + size.z() * size.x());
  double boundary_area = 0;
  Eigen::Vector3d boundary_flux = Eigen::Vector3d::Zero();
  int boundary_faces = 0;
  for (int face = 0; face < mesh.face_count(); ++face) {
    const int owner = mesh.face_cells(face, 0), neighbour = mesh.face_cells(face, 1);
    ASSERT_GE(owner, 0);
    const Eigen::Vector3d normal = mesh.face_normals.row(face);
    EXPECT_NEAR(normal.norm(), 1.0, 1e-14);
    // Outward from the owner: from its centroid towards the face.
    const Eigen::Vector3d to_face = mesh.face_centroids.row(face) - mesh.cell_centroids.row(owner);
    EXPECT_GT(normal.dot(to_face), 0) << "face " << face;
    if (neighbour < 0) {
      ++boundary_faces;
      boundary_area += mesh.face_areas(face);
      boundary_flux += mesh.face_areas(face) * normal;
    } else {
      // The neighbour sees the same polygon, reversed: its outward normal is -normal.
      const Eigen::Vector3d to_neighbour = mesh.cell_centroids.row(neighbour) - mesh.face_centroids.row(face);
      EXPECT_GT(normal.dot(to_neighbour), 0) << "face " << face;
    }
  }
  EXPECT_NEAR(boundary_area, box_area, 1e-13 * box_area);
  EXPECT_LT(boundary_flux.norm(), 1e-13 * box_area);
  const int grid_boundary_quads = 2 * (n.x() * n.y() + n.y() * n.z() + n.z() * n.x());
  EXPECT_EQ(boundary_faces, tetrahedral ? 2 * grid_boundary_quads : grid_boundary_quads);

  // Each cell's faces close its surface: Σ area·normal (outward for that cell) = 0.
  for (int cell = 0; cell < mesh.cell_count(); ++cell) {
    Eigen::Vector3d flux = Eigen::Vector3d::Zero();
    for (int face : mesh.cell_faces[cell]) {
      const double sign = mesh.face_cells(face, 0) == cell ? 1.0 : -1.0;
      ASSERT_TRUE(sign > 0 || mesh.face_cells(face, 1) == cell);
      flux += sign * mesh.face_areas(face) * mesh.face_normals.row(face).transpose();
    }
    EXPECT_LT(flux.norm(), 1e-14) << "cell " << cell;
    EXPECT_EQ(mesh.cell_faces[cell].size(), tetrahedral ? 4u : 6u);
  }

  // A cell's exact moments through cell_polyhedron match the standalone cell volume.
  const Polyhedron first = cell_polyhedron(mesh, 0);
  EXPECT_NEAR(polyhedron_moments(first, 0)(0), mesh.cell_volumes(0), 1e-15);
  const double hex_diagonal = size.cwiseQuotient(n.cast<double>()).norm();
  EXPECT_NEAR(mesh.cell_diameters(0), hex_diagonal, 1e-14);
}

INSTANTIATE_TEST_SUITE_P(TetAndHex, PolyhedralConversion,
                         ::testing::Values(Case{ElementType::hex8, {3, 2, 4}}, Case{ElementType::hex27, {2, 2, 1}},
                                           Case{ElementType::tet4, {2, 3, 2}}, Case{ElementType::tet10, {1, 2, 2}}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return std::string(element_name(info.param.type));
                         });

TEST(PolyhedralMesh, InvertedCellIsANumericalErrorNamingTheCell) {
  VolumeMesh volume_mesh = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()),
                                           {2, 1, 1}, ElementType::hex8);
  // Mirror cell 1 by swapping its bottom and top faces.
  for (int corner = 0; corner < 4; ++corner) std::swap(volume_mesh.cells(1, corner), volume_mesh.cells(1, corner + 4));
  try {
    polyhedral_mesh_from_volume_mesh(volume_mesh);
    FAIL() << "expected a NumericalError";
  } catch (const NumericalError& error) {
    EXPECT_NE(std::string(error.what()).find("cell 1"), std::string::npos) << error.what();
  }
}

TEST(PolyhedralMesh, VtuGridHasOnePolyhedronPerCellWithOutwardFacesAndCellData) {
  const VolumeMesh volume_mesh = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 1, 1)),
                                                 {2, 1, 1}, ElementType::hex8);
  const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(volume_mesh);
  const UnstructuredGrid grid = grid_from_polyhedral_mesh(mesh);
  ASSERT_EQ(grid.cell_count(), 2);
  EXPECT_EQ(grid.cell_types, (std::vector<int>{vtk_polyhedron, vtk_polyhedron}));
  for (int cell = 0; cell < 2; ++cell) {
    // Outward faces: the area vectors of a closed outward surface give V = ⅓ Σ c_f · A_f n_f.
    double volume = 0;
    ASSERT_EQ(grid.polyhedron_faces[cell].size(), 6u);
    for (const auto& face : grid.polyhedron_faces[cell]) {
      Eigen::MatrixXd polygon(face.size(), 3);
      for (std::size_t i = 0; i < face.size(); ++i) polygon.row(i) = grid.points.row(face[i]);
      volume += polygon_area_vector(polygon).dot(polygon.colwise().mean()) / 3;
    }
    EXPECT_NEAR(volume, 1.0, 1e-14) << "cell " << cell;
  }
  ASSERT_EQ(grid.cell_data.size(), 2u);
  EXPECT_EQ(grid.cell_data[0].first, "volume");
  EXPECT_NEAR(grid.cell_data[0].second(1, 0), 1.0, 1e-14);
  EXPECT_EQ(grid.cell_data[1].first, "kind");
  EXPECT_EQ(grid.cell_data[1].second(0, 0), static_cast<double>(PolyhedralCellKind::hexahedron));
  // The writer accepts it (its own checks: sizes, ids, finite values).
  EXPECT_NE(vtu_text(grid, "grid.vtu").find("faceoffsets"), std::string::npos);
}

TEST(PolyhedralMesh, MalformedFacesAreRejectedBeforeAnyComputation) {
  PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(structured_grid(
      Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()), {1, 1, 1}, ElementType::tet4));
  PolyhedralMesh short_face = mesh;
  short_face.faces[2].pop_back();
  short_face.faces[2].pop_back();
  EXPECT_THROW(compute_polyhedral_geometry(short_face), std::invalid_argument);
  PolyhedralMesh out_of_range = mesh;
  out_of_range.faces[0][1] = static_cast<int>(mesh.nodes.rows());
  EXPECT_THROW(compute_polyhedral_geometry(out_of_range), std::invalid_argument);
}

}  // namespace
}  // namespace altfem
