#include "shared/mesh/surface_cut_debris.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <limits>

#include "shared/geometry/polyhedron_moments.hpp"
#include "shared/mesh/bounding_box.hpp"
#include "shared/mesh/cut_polyhedral_pieces.hpp"
#include "shared/mesh/disjoint_sets.hpp"
#include "shared/mesh/merge_slivers.hpp"

namespace altfem {

void weld_coincident_neighbours(PolyhedralMesh& mesh, double tolerance) {
  DisjointSets same(static_cast<int>(mesh.nodes.rows()));
  bool any = false;
  for (const std::vector<int>& loop : mesh.faces)
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const int u = loop[k], v = loop[(k + 1) % loop.size()];
      if (u != v && (mesh.nodes.row(u) - mesh.nodes.row(v)).norm() <= tolerance) {
        same.join(std::min(u, v), std::max(u, v));
        any = true;
      }
    }
  if (!any) return;
  std::vector<std::vector<int>> faces;
  std::vector<std::array<int, 2>> face_cells;
  for (int face = 0; face < mesh.face_count(); ++face) {
    std::vector<int> loop;
    for (const int node : mesh.faces[face]) {
      const int kept = same.find(node);
      if (loop.empty() || loop.back() != kept) loop.push_back(kept);
    }
    while (loop.size() > 1 && loop.back() == loop.front()) loop.pop_back();
    if (loop.size() < 3) continue;
    faces.push_back(std::move(loop));
    face_cells.push_back({mesh.face_cells(face, 0), mesh.face_cells(face, 1)});
  }
  set_faces(mesh, std::move(faces), face_cells);
}

void snap_new_nodes_to_corners(PolyhedralMesh& mesh, Eigen::Index first_new,
                               const std::array<Eigen::Vector3d, 3>& corners, double tolerance) {
  for (Eigen::Index node = first_new; node < mesh.nodes.rows(); ++node)
    for (const Eigen::Vector3d& corner : corners)
      if ((mesh.nodes.row(node).transpose() - corner).norm() <= tolerance) mesh.nodes.row(node) = corner.transpose();
}

namespace {

double distance_to_segment(const Eigen::Vector3d& point, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double along = std::clamp((point - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return (point - a - along * (b - a)).norm();
}

// The distance from `point` to the blade's nearest triangle.
double distance_to_blade(const Eigen::Vector3d& point, const SurfaceBlade& blade) {
  double nearest = std::numeric_limits<double>::infinity();
  for (Eigen::Index t = 0; t < blade.triangles.rows(); ++t) {
    const Eigen::Vector3d a = blade.vertices.row(blade.triangles(t, 0)), b = blade.vertices.row(blade.triangles(t, 1)),
                          c = blade.vertices.row(blade.triangles(t, 2));
    const Eigen::Vector3d normal = (b - a).cross(c - a).normalized();
    const double height = normal.dot(point - a);
    const Eigen::Vector3d foot = point - height * normal;
    // Inside when the foot is on the inner side of each edge.
    const bool inside = (b - a).cross(foot - a).dot(normal) >= 0 && (c - b).cross(foot - b).dot(normal) >= 0 &&
                        (a - c).cross(foot - c).dot(normal) >= 0;
    nearest = std::min(nearest, inside ? std::abs(height)
                                       : std::min({distance_to_segment(point, a, b), distance_to_segment(point, b, c),
                                                   distance_to_segment(point, c, a)}));
  }
  return nearest;
}

}  // namespace

FacesSeparated separate_faces_of_rounding_area(PolyhedralMesh& mesh, const SurfaceBlade& blade) {
  const double diagonal = bounding_box(mesh.nodes).diagonal();
  const double rounding_width = 1e-12 * diagonal, rounding_length = 1e-9 * diagonal;
  std::vector<CutFace> faces;
  std::vector<bool> opened_node(static_cast<std::size_t>(mesh.nodes.rows()), false);
  FacesSeparated result;
  for (int face = 0; face < mesh.face_count(); ++face) {
    const std::vector<int>& loop = mesh.faces[face];
    const int first = mesh.face_cells(face, 0), second = mesh.face_cells(face, 1);
    bool separate = false;
    if (second >= 0) {
      double longest = 0;
      for (std::size_t k = 0; k < loop.size(); ++k)
        longest = std::max(longest, (mesh.nodes.row(loop[k]) - mesh.nodes.row(loop[(k + 1) % loop.size()])).norm());
      separate = (longest <= rounding_length || face_area_vector(mesh, loop).norm() <= rounding_width * longest) &&
                 distance_to_blade(mesh.nodes.row(loop[0]).transpose(), blade) <= rounding_length;
    }
    if (!separate) {
      faces.push_back({loop, first, second, +1, false});
      continue;
    }
    ++result.faces;
    for (const int node : loop) opened_node[node] = true;
    faces.push_back({loop, first, -1, +1, true});
    faces.push_back({std::vector<int>(loop.rbegin(), loop.rend()), second, -1, +1, true});
  }
  if (result.faces == 0) return result;
  std::vector<Eigen::Vector3d> nodes;
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node) nodes.push_back(mesh.nodes.row(node).transpose());
  std::vector<NodeSource> sources(nodes.size());  // not carried: a surface blade's cut has none
  result.duplicated_nodes = duplicate_separated_nodes(
      faces, opened_node, std::vector<int>(static_cast<std::size_t>(mesh.cell_count()), +1), nodes, sources);
  mesh.nodes.resize(static_cast<Eigen::Index>(nodes.size()), 3);
  for (std::size_t node = 0; node < nodes.size(); ++node)
    mesh.nodes.row(static_cast<Eigen::Index>(node)) = nodes[node].transpose();
  std::vector<std::vector<int>> loops;
  std::vector<std::array<int, 2>> cells;
  for (CutFace& face : faces) {
    loops.push_back(std::move(face.loop));
    cells.push_back({face.first, face.second});
  }
  set_faces(mesh, std::move(loops), cells);
  return result;
}

std::vector<bool> isolated_slivers(const PolyhedralMesh& mesh, const std::vector<int>& parent_cell,
                                   const PolyhedralMesh& parents) {
  constexpr double rounding_fraction = 1e-13;
  std::vector<bool> sliver(static_cast<std::size_t>(mesh.cell_count()), false);
  for (int cell = 0; cell < mesh.cell_count(); ++cell) {
    const bool alone = std::all_of(mesh.cell_faces[cell].begin(), mesh.cell_faces[cell].end(),
                                   [&](int face) { return mesh.face_cells(face, 1) < 0; });
    if (!alone) continue;
    if (mesh.cell_faces[cell].empty()) {  // welded to nothing
      sliver[cell] = true;
      continue;
    }
    const double parent_volume = polyhedron_moments(cell_polyhedron(parents, parent_cell[cell]), 0)(0);
    sliver[cell] = polyhedron_moments(cell_polyhedron(mesh, cell), 0)(0) <= rounding_fraction * parent_volume;
  }
  return sliver;
}

int drop_isolated_slivers(PolyhedralMesh& mesh, std::vector<int>& parent_cell, const PolyhedralMesh& parents) {
  std::vector<bool> keep = isolated_slivers(mesh, parent_cell, parents);
  keep.flip();
  const auto dropped = static_cast<int>(std::count(keep.begin(), keep.end(), false));
  if (dropped == 0) return 0;
  std::vector<int> kept;
  mesh = polyhedral_mesh_with_cells(mesh, keep, kept);
  drop_unused_nodes(mesh);
  std::vector<int> parents_kept;
  for (const int cell : kept) parents_kept.push_back(parent_cell[cell]);
  parent_cell = std::move(parents_kept);
  return dropped;
}

}  // namespace altfem
