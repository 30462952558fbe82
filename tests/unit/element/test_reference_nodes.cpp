// VTK node order of every element type, written out coordinate by coordinate
// (independently of the edge tables that generate them in the library).
#include <gtest/gtest.h>

#include <vector>

#include "shared/element/reference_element.hpp"
#include "shared/element/reference_nodes.hpp"

namespace altfem {
namespace {

using Rows = std::vector<Eigen::RowVector3d>;

void expect_nodes(ElementType type, const Rows& expected) {
  const Eigen::MatrixXd nodes = reference_nodes(type);
  ASSERT_EQ(nodes.rows(), static_cast<Eigen::Index>(expected.size())) << element_name(type);
  ASSERT_EQ(nodes.cols(), 3);
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_LT((nodes.row(i) - expected[i]).norm(), 1e-15)
        << element_name(type) << " node " << i << ": got " << nodes.row(i) << ", expected " << expected[i];
  EXPECT_EQ(reference_element(type).nodes(), nodes) << element_name(type);
}

const Rows tet_vertices{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const Rows hex_corners{{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                       {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
// Midpoints of (0,1),(1,2),(2,3),(3,0),(4,5),(5,6),(6,7),(7,4),(0,4),(1,5),(2,6),(3,7).
const Rows hex_edge_midpoints{{0, -1, -1}, {1, 0, -1}, {0, 1, -1},  {-1, 0, -1}, {0, -1, 1}, {1, 0, 1},
                              {0, 1, 1},   {-1, 0, 1}, {-1, -1, 0}, {1, -1, 0},  {1, 1, 0},  {-1, 1, 0}};

Rows concatenate(std::initializer_list<Rows> parts) {
  Rows all;
  for (const Rows& part : parts) all.insert(all.end(), part.begin(), part.end());
  return all;
}

TEST(ReferenceNodes, Tet4) { expect_nodes(ElementType::tet4, tet_vertices); }

TEST(ReferenceNodes, Tet10) {
  // Edges (0,1),(1,2),(0,2),(0,3),(1,3),(2,3).
  expect_nodes(ElementType::tet10,
               concatenate({tet_vertices,
                            {{0.5, 0, 0}, {0.5, 0.5, 0}, {0, 0.5, 0}, {0, 0, 0.5}, {0.5, 0, 0.5}, {0, 0.5, 0.5}}}));
}

TEST(ReferenceNodes, Tet20) {
  const double a = 1.0 / 3.0, b = 2.0 / 3.0;
  expect_nodes(ElementType::tet20, concatenate({tet_vertices,
                                                {// edge (0,1)
                                                 {a, 0, 0},
                                                 {b, 0, 0},
                                                 // edge (1,2), from vertex 1 to vertex 2
                                                 {b, a, 0},
                                                 {a, b, 0},
                                                 // edge (2,0), from vertex 2 to vertex 0
                                                 {0, b, 0},
                                                 {0, a, 0},
                                                 // edges (0,3), (1,3), (2,3)
                                                 {0, 0, a},
                                                 {0, 0, b},
                                                 {b, 0, a},
                                                 {a, 0, b},
                                                 {0, b, a},
                                                 {0, a, b},
                                                 // face centroids of (0,1,3), (1,2,3), (0,2,3), (0,1,2)
                                                 {a, 0, a},
                                                 {a, a, a},
                                                 {0, a, a},
                                                 {a, a, 0}}}));
}

TEST(ReferenceNodes, Hex8) { expect_nodes(ElementType::hex8, hex_corners); }

TEST(ReferenceNodes, Hex20) { expect_nodes(ElementType::hex20, concatenate({hex_corners, hex_edge_midpoints})); }

TEST(ReferenceNodes, Hex27) {
  // Face centres x=-1, x=+1, y=-1, y=+1, z=-1, z=+1, then the body centre.
  expect_nodes(ElementType::hex27,
               concatenate({hex_corners,
                            hex_edge_midpoints,
                            {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}, {0, 0, 0}}}));
}

TEST(ReferenceNodes, CountsAndDegreesMatchTheTypeTable) {
  for (ElementType type : {ElementType::tet4, ElementType::tet10, ElementType::tet20, ElementType::hex8,
                           ElementType::hex20, ElementType::hex27}) {
    const ReferenceElement& element = reference_element(type);
    EXPECT_EQ(element.type(), type);
    EXPECT_EQ(element.node_count(), element_node_count(type));
    EXPECT_EQ(element.degree(), element_degree(type));
  }
}

}  // namespace
}  // namespace altfem
