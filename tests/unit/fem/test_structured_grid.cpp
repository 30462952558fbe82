// structured_grid and elevate_order: counts, positive volumes filling the box, and
// higher-order nodes where the element's straight map puts them.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <string>

#include "shared/element/reference_element.hpp"
#include "shared/fem/tabulate_lagrange.hpp"
#include "tests/unit/fem/test_meshes.hpp"

namespace altfem {
namespace {

const Eigen::AlignedBox3d box(Eigen::Vector3d(0.0, -1.0, 0.3), Eigen::Vector3d(2.0, 0.5, 1.0));
const Eigen::Vector3i resolution(3, 2, 1);

// Node counts from the lattice: Kuhn's triangulation has the Freudenthal property
// that the degree-p Lagrange nodes of all its tets are exactly the lattice points of
// spacing h/p, so Tet10/Hex27 have (2n+1)³ and Tet20 (3n+1)³ nodes; Hex20 has the
// corners plus one node per grid edge.
long expected_nodes(ElementType type, const Eigen::Vector3i& n) {
  const auto lattice = [&](int p) { return long(p * n.x() + 1) * (p * n.y() + 1) * (p * n.z() + 1); };
  const long grid_edges = long(n.x()) * (n.y() + 1) * (n.z() + 1) + long(n.x() + 1) * n.y() * (n.z() + 1) +
                          long(n.x() + 1) * (n.y() + 1) * n.z();
  switch (type) {
    case ElementType::tet4:
    case ElementType::hex8: return lattice(1);
    case ElementType::tet10:
    case ElementType::hex27: return lattice(2);
    case ElementType::tet20: return lattice(3);
    case ElementType::hex20: return lattice(1) + grid_edges;
  }
  return -1;
}

class EveryElementType : public ::testing::TestWithParam<ElementType> {};

TEST_P(EveryElementType, CountsAndPositiveVolumesFillingTheBox) {
  const ElementType type = GetParam();
  const VolumeMesh mesh = structured_grid(box, resolution, type);
  const long cubes = long(resolution.prod());
  EXPECT_EQ(mesh.element_type, type);
  EXPECT_EQ(mesh.cells.rows(), element_shape(type) == ElementShape::tetrahedron ? 6 * cubes : cubes);
  EXPECT_EQ(mesh.cells.cols(), element_node_count(type));
  EXPECT_EQ(mesh.nodes.rows(), expected_nodes(type, resolution));

  // Every node used, and no two nodes at one place (mid-nodes are shared).
  std::set<int> used(mesh.cells.data(), mesh.cells.data() + mesh.cells.size());
  EXPECT_EQ(static_cast<long>(used.size()), mesh.nodes.rows());
  EXPECT_EQ(*used.begin(), 0);
  std::vector<std::array<double, 3>> sorted;
  for (Eigen::Index i = 0; i < mesh.nodes.rows(); ++i)
    sorted.push_back({mesh.nodes(i, 0), mesh.nodes(i, 1), mesh.nodes(i, 2)});
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());

  // Quadrature weights are w_q |det J|: every one positive, and they sum to the box.
  const TabulatedElements elements = tabulate_lagrange(mesh, 2);
  double total = 0;
  for (int e = 0; e < elements.size(); ++e)
    for (double w : elements[e].weights) {
      EXPECT_GT(w, 0.0) << "element " << e;
      total += w;
    }
  EXPECT_NEAR(total, box.volume(), 1e-13 * box.volume());
  EXPECT_NEAR(volume_mesh_volume(mesh), box.volume(), 1e-13 * box.volume());
}

INSTANTIATE_TEST_SUITE_P(StructuredGrid, EveryElementType, ::testing::ValuesIn(test::all_element_types),
                         [](const auto& info) { return std::string(element_name(info.param)); });

// VTK edge tables, written out independently of the reference-node tables.
constexpr int tet_edges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
constexpr int hex_edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                  {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

TEST(ElevateOrder, QuadraticMidNodesAtEdgeMidpointsOfDistortedCells) {
  for (ElementType type : {ElementType::tet10, ElementType::hex20, ElementType::hex27}) {
    const VolumeMesh mesh = test::distorted_grid(test::unit_cube(), {3, 3, 3}, type, 0.15, 7);
    const bool tet = element_shape(type) == ElementShape::tetrahedron;
    const int edges = tet ? 6 : 12, corners = tet ? 4 : 8;
    double worst = 0;
    for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
      for (int edge = 0; edge < edges; ++edge) {
        const int* ends = tet ? tet_edges[edge] : hex_edges[edge];
        const Eigen::RowVector3d midpoint =
            0.5 * (mesh.nodes.row(mesh.cells(cell, ends[0])) + mesh.nodes.row(mesh.cells(cell, ends[1])));
        worst = std::max(worst, (mesh.nodes.row(mesh.cells(cell, corners + edge)) - midpoint).norm());
      }
    EXPECT_LT(worst, 1e-15) << element_name(type);
  }
}

TEST(ElevateOrder, EveryHigherOrderNodeOnTheStraightMap) {
  // Tet20 (edge thirds, face centroids) and Hex27 (face and cell centres): node i at
  // Σ_c N^linear_c(ξ_i) x_c, the affine / trilinear map of the corners.
  for (ElementType type : {ElementType::tet20, ElementType::hex27}) {
    const VolumeMesh mesh = test::distorted_grid(test::unit_cube(), {3, 3, 3}, type, 0.15, 11);
    const ReferenceElement& target = reference_element(type);
    const ReferenceElement& linear =
        reference_element(element_shape(type) == ElementShape::tetrahedron ? ElementType::tet4 : ElementType::hex8);
    Eigen::VectorXd weights(linear.node_count());
    double worst = 0;
    for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
      for (int node = linear.node_count(); node < target.node_count(); ++node) {
        linear.evaluate(target.nodes().row(node).transpose(), weights);
        Eigen::RowVector3d expected = Eigen::RowVector3d::Zero();
        for (int c = 0; c < linear.node_count(); ++c) expected += weights[c] * mesh.nodes.row(mesh.cells(cell, c));
        worst = std::max(worst, (mesh.nodes.row(mesh.cells(cell, node)) - expected).norm());
      }
    EXPECT_LT(worst, 1e-15) << element_name(type);
  }
}

}  // namespace
}  // namespace altfem
