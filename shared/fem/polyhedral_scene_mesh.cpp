#include "shared/fem/polyhedral_scene_mesh.hpp"

#include <stdexcept>

#include "shared/fem/fem_mesh.hpp"
#include "shared/mesh/boundary_surface.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"
#include "shared/scene/scene_slicing.hpp"

namespace altfem {

SurfaceMesh boundary_faces_surface(const PolyhedralMesh& mesh) {
  std::vector<int> vertex_of(static_cast<size_t>(mesh.nodes.rows()), -1);
  std::vector<std::array<int, 3>> triangles;
  int vertex_count = 0;
  for (int face = 0; face < mesh.face_count(); ++face) {
    if (!mesh.is_boundary_face(face)) continue;
    const std::vector<int>& loop = mesh.faces[face];  // outward: its one cell owns it
    for (const auto& corners : triangulate_face(mesh.nodes, loop)) {
      std::array<int, 3> triangle;
      for (int k = 0; k < 3; ++k) {
        int& vertex = vertex_of[loop[corners[k]]];
        if (vertex < 0) vertex = vertex_count++;
        triangle[k] = vertex;
      }
      triangles.push_back(triangle);
    }
  }
  SurfaceMesh surface;
  surface.vertices.resize(vertex_count, 3);
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node)
    if (vertex_of[node] >= 0) surface.vertices.row(vertex_of[node]) = mesh.nodes.row(node);
  surface.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (size_t t = 0; t < triangles.size(); ++t)
    surface.triangles.row(static_cast<Eigen::Index>(t)) << triangles[t][0], triangles[t][1], triangles[t][2];
  return surface;
}

const SurfaceMesh& deformed_surface(const PolyhedralSceneMesh& mesh, const SceneGeometry& geometry) {
  if (mesh.surface.triangles.rows() > 0) return mesh.surface;
  if (const SurfaceMesh* surface = geometry.common_surface()) return *surface;
  throw std::logic_error("deformed_surface: neither the mesh nor the geometry has a surface");
}

PolyhedralSceneMesh build_polyhedral_scene_mesh(const PolyhedralMeshSource& source, const SceneGeometry& geometry) {
  PolyhedralSceneMesh result;
  if (source.slicing) {
    result.sliced = slice_scene_geometry(geometry, *source.slicing);
    if (!geometry.common_surface()) result.surface = boundary_surface(*geometry.mesh).surface;
    result.load_surface = boundary_faces_surface(result.sliced.mesh);
    result.facts = {{"source", "slice"}, {"slicing", slicing_facts(result.sliced)}};
    return result;
  }
  result.converted = build_fem_mesh(source.convert, geometry);
  result.sliced.mesh = polyhedral_mesh_from_volume_mesh(*result.converted);
  result.load_surface = boundary_surface(*result.converted).surface;
  if (!geometry.common_surface()) result.surface = result.load_surface;
  result.facts = {{"source", "convert"}};
  return result;
}

PolyhedralSceneMesh handed_polyhedral_scene_mesh(const PolyhedralMesh& mesh, const SurfaceMesh* own_surface,
                                                 const SurfaceMesh& load_surface, const nlohmann::json& facts,
                                                 const std::vector<int>& cell_levels) {
  return {.sliced = {.mesh = mesh},
          .surface = own_surface ? *own_surface : SurfaceMesh{},
          .load_surface = load_surface,
          .facts = facts,
          .converted = std::nullopt,
          .node_sources = {},
          .parent_cells = {},
          .merged_parts = {},
          .cell_levels = cell_levels};
}

}  // namespace altfem
