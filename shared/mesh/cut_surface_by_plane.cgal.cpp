#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <set>
#include <stdexcept>
#include <utility>

#include "shared/mesh/cut_surface_pieces.hpp"
#include "shared/mesh/split_surface_by_plane.hpp"

namespace altfem::surface_cut {

namespace {

// The volume the closed `mesh` encloses, its tetrahedra from its first vertex (not the
// origin, which would cancel a small piece's volume away).
double enclosed_volume(const Mesh& mesh) {
  const Eigen::Vector3d apex = vector_of(mesh.point(*mesh.vertices().begin()));
  double volume = 0;
  for (const Mesh::Face_index f : mesh.faces()) {
    std::array<Eigen::Vector3d, 3> corner;
    int k = 0;
    for (const Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      corner[k++] = vector_of(mesh.point(v)) - apex;
    volume += corner[0].dot(corner[1].cross(corner[2])) / 6;
  }
  return volume;
}

// What the whole-plane split cannot close into two manifold sides (border loops that cross
// or meet after rounding): the piece is left whole, counted, and the next blade tries it.
struct UnsplitPiece : std::runtime_error {
  UnsplitPiece() : std::runtime_error("the plane's sides of the piece do not close") {}
};

}  // namespace

// The closed `piece` cut by the whole plane of `blade` (split_surface_by_plane: its sides
// exact predicates, each crossing point rounded once for both sides), each side's cut
// curve cleaned and its cap remeshed. A vertex of the input that both sides keep (on the
// plane) gets a copy for the positive side. Appends both sides to `out`.
bool cut_piece_by_plane(TrianglePiece piece, const ExactBlade& exact, double edge_length, CutPieces& out) {
  auto split = split_surface_by_plane(std::move(piece), exact, 1e-9 * edge_length);
  if (!split) throw UnsplitPiece();
  if (split->grazes) return false;
  // New points (input −1) and the input's on the plane: the cut curve and the cap.
  const auto on_plane_in = [&](const Mesh& half) {
    return
        [&half, &split, input_of = half.property_map<Mesh::Vertex_index, int>("v:input").first](Mesh::Vertex_index v) {
          return input_of[v] < 0 ||
                 std::binary_search(split->inputs_on_plane.begin(), split->inputs_on_plane.end(), input_of[v]);
        };
  };
  std::array<double, 2> volumes{};
  for (int side = 0; side < 2; ++side) {
    Mesh& half = split->sides[side];
    const auto on_plane = on_plane_in(half);
    cut_curve::clean(half, on_plane, 4.0 / 3 * edge_length);
    // Remeshed: the cap where it lies in the plane. Not around a vertex taken on it within
    // the snap: each side remeshes its own cap, and where the caps are not flat they would
    // part and the sides' volumes no longer sum to the piece's.
    const auto input_of = half.property_map<Mesh::Vertex_index, int>("v:input").first;
    cut_curve::remesh_cap(
        half,
        [&](Mesh::Face_index f) {
          for (const Mesh::Vertex_index v : CGAL::vertices_around_face(half.halfedge(f), half))
            if (input_of[v] >= 0 && exact.side(vector_of(half.point(v))) != 0) return false;
          return true;
        },
        edge_length);
    volumes[side] = enclosed_volume(half);
  }
  // A plane that grazes the piece (a chip far below the sliver rule, which the clean-up's
  // collapses flatten) opens nothing.
  if (std::min(volumes[0], volumes[1]) <= 1e-12 * (volumes[0] + volumes[1])) return false;
  std::set<int> used;
  for (Mesh& half : split->sides) {
    const auto input_of = half.property_map<Mesh::Vertex_index, int>("v:input").first;
    const auto on_plane = on_plane_in(half);
    std::vector<int> output_vertex(half.number_of_vertices() + half.number_of_removed_vertices(), -1);
    std::vector<char> on_curve(output_vertex.size(), 0);
    for (const Mesh::Vertex_index v : half.vertices()) {
      const std::size_t k = v.idx();
      const int input = input_of[v];
      on_curve[k] = on_plane(v);
      if (input >= 0 && used.insert(input).second) {
        output_vertex[k] = input;
      } else {
        output_vertex[k] = static_cast<int>(out.input_count + static_cast<Eigen::Index>(out.added.size()));
        out.added.push_back(vector_of(half.point(v)));
      }
      if (on_curve[k]) out.cut_vertices.push_back(output_vertex[k]);
    }
    for (const Mesh::Face_index f : half.faces()) {
      std::array<int, 3> triangle;
      bool cap = true;
      int k = 0;
      for (const Mesh::Vertex_index v : CGAL::vertices_around_face(half.halfedge(f), half)) {
        triangle[k++] = output_vertex[v.idx()];
        cap = cap && on_curve[v.idx()];
      }
      out.triangles.push_back(triangle);
      out.cap_triangles += cap;
    }
  }
  return true;
}

}  // namespace altfem::surface_cut
