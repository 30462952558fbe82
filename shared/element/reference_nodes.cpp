#include "shared/element/reference_nodes.hpp"

#include <array>
#include <span>
#include <utility>

namespace altfem {

namespace {
using Edge = std::pair<int, int>;

const Eigen::Matrix<double, 4, 3> tet_vertices{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

// VTK_HEXAHEDRON (12): the bottom face z=-1 counter-clockwise seen from +z, then the top.
const Eigen::Matrix<double, 8, 3> hex_vertices{{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                               {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

// VTK_QUADRATIC_TETRA (24), vtkQuadraticTetra: mid-nodes 4-9 on these edges.
constexpr std::array<Edge, 6> quadratic_tet_edges{{{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}}};

// VTK_LAGRANGE_TETRAHEDRON (71), vtkHigherOrderTetra.cxx (VTK 9): EdgeVertices =
// {0,1},{1,2},{2,0},{0,3},{1,3},{2,3}; BarycentricIndex() puts an edge's interior
// nodes from its first vertex towards its second. Note edge 2 runs from vertex 2
// to vertex 0, unlike Tet10's third edge (0,2).
constexpr std::array<Edge, 6> lagrange_tet_edges{{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}};
// Same source: face f holds barycentric coordinate FaceMinCoord[f] = {1,3,0,2} at
// zero, i.e. the faces y=0, x+y+z=1, x=0, z=0 — vertices (0,1,3), (1,2,3), (0,2,3),
// (0,1,2). For degree 3 each face has one interior node, its centroid.
constexpr std::array<std::array<int, 3>, 4> lagrange_tet_faces{{{0, 1, 3}, {1, 2, 3}, {0, 2, 3}, {0, 1, 2}}};

// VTK_QUADRATIC_HEXAHEDRON (25) and VTK_TRIQUADRATIC_HEXAHEDRON (29): mid-nodes 8-19.
constexpr std::array<Edge, 12> hex_edges{
    {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};
// vtkTriQuadraticHexahedron.cxx HexFaces: node 20 on face (0,4,7,3) x=-1, 21 on
// (1,2,6,5) x=+1, 22 on (0,1,5,4) y=-1, 23 on (3,7,6,2) y=+1, 24 on (0,3,2,1) z=-1,
// 25 on (4,5,6,7) z=+1 (the class's header comment lists them differently; its
// diagram and HexFaces table agree with this order). Node 26 is the body centre.
const Eigen::Matrix<double, 7, 3> hex_face_and_body_centres{{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0},
                                                            {0, 0, -1}, {0, 0, 1}, {0, 0, 0}};

/// Appends, for each edge, the points at fractions 1/(parts), ..., (parts-1)/parts
/// from its first vertex to its second.
template <int corners>
void append_edge_nodes(const Eigen::Matrix<double, corners, 3>& vertices, std::span<const Edge> edges, int parts,
                       Eigen::MatrixXd& nodes, int& next) {
  for (const auto& [first, second] : edges)
    for (int k = 1; k < parts; ++k) {
      const double t = static_cast<double>(k) / parts;
      nodes.row(next++) = (1.0 - t) * vertices.row(first) + t * vertices.row(second);
    }
}
}  // namespace

Eigen::MatrixXd reference_nodes(ElementType type) {
  Eigen::MatrixXd nodes(element_node_count(type), 3);
  int next = 0;
  switch (type) {
    case ElementType::tet4: nodes = tet_vertices; break;
    case ElementType::tet10:
      nodes.topRows<4>() = tet_vertices;
      next = 4;
      append_edge_nodes<4>(tet_vertices, quadratic_tet_edges, 2, nodes, next);
      break;
    case ElementType::tet20:
      nodes.topRows<4>() = tet_vertices;
      next = 4;
      append_edge_nodes<4>(tet_vertices, lagrange_tet_edges, 3, nodes, next);
      for (const auto& face : lagrange_tet_faces)
        nodes.row(next++) = (tet_vertices.row(face[0]) + tet_vertices.row(face[1]) + tet_vertices.row(face[2])) / 3.0;
      break;
    case ElementType::hex8: nodes = hex_vertices; break;
    case ElementType::hex20:
    case ElementType::hex27:
      nodes.topRows<8>() = hex_vertices;
      next = 8;
      append_edge_nodes<8>(hex_vertices, hex_edges, 2, nodes, next);
      if (type == ElementType::hex27) nodes.bottomRows<7>() = hex_face_and_body_centres;
      break;
  }
  return nodes;
}

}  // namespace altfem
