#include "shared/fem/mesh_previews.hpp"

#include <cstdio>

#include "shared/common/error.hpp"
#include "shared/fem/fem_mesh.hpp"
#include "shared/fem/fem_scene_block.hpp"
#include "shared/io/polyhedral_grid.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"

namespace altfem {

namespace {

std::string format(const char* pattern, auto... values) {
  char line[512];
  std::snprintf(line, sizeof line, pattern, values...);
  return line;
}

// The lines every polyhedral preview prints.
std::string describe(const std::string& method, const Scene& scene, const nlohmann::json& facts,
                     const SlicedMesh* sliced, double geometry_volume) {
  std::string text = format(
      "%s mesh of '%s' (%s): %lld cells (%d tetrahedra, %d hexahedra, %d cut, %d merged, %d coarse), "
      "%lld nodes\n",
      method.c_str(), scene.name.c_str(), facts["source"].get<std::string>().c_str(),
      facts["cells"]["total"].get<long long>(), facts["cells"]["tetrahedra"].get<int>(),
      facts["cells"]["hexahedra"].get<int>(), facts["cells"]["cut"].get<int>(), facts["cells"]["merged"].get<int>(),
      facts["cells"]["coarse"].get<int>(), facts["nodes"].get<long long>());
  if (sliced)
    text += format(
        "slicing: %d x %d x %d grid of cells %.4g, %d cut pieces, %d grid cells split by topology, "
        "%d slivers merged\n",
        sliced->grid_cells(0), sliced->grid_cells(1), sliced->grid_cells(2), sliced->cell_size, sliced->cut_pieces,
        sliced->split_grid_cells, sliced->merged_slivers);
  text += format("faces: %d interior, %d boundary\n", facts["faces"]["interior"].get<int>(),
                 facts["faces"]["boundary"].get<int>());
  text += format("volume: %.10g (geometry %.10g, relative difference %.3e)\n", facts["volume"].get<double>(),
                 geometry_volume, facts["volume_relative_difference"].get<double>());
  text += format("cell volume: smallest %.4g, largest %.4g\n", facts["smallest_cell_volume"].get<double>(),
                 facts["largest_cell_volume"].get<double>());
  return text;
}

}  // namespace

nlohmann::json polyhedral_mesh_facts(const PolyhedralMesh& mesh, double geometry_volume) {
  int tetrahedra = 0, hexahedra = 0, cut = 0, merged = 0, coarse = 0, refined = 0, split = 0;
  for (PolyhedralCellKind kind : mesh.cell_kinds) {
    switch (kind) {
      case PolyhedralCellKind::tetrahedron: ++tetrahedra; break;
      case PolyhedralCellKind::hexahedron: ++hexahedra; break;
      case PolyhedralCellKind::cut: ++cut; break;
      case PolyhedralCellKind::merged: ++merged; break;
      case PolyhedralCellKind::coarse: ++coarse; break;
      case PolyhedralCellKind::refined: ++refined; break;
      case PolyhedralCellKind::split: ++split; break;
    }
  }
  int boundary_faces = 0;
  for (int face = 0; face < mesh.face_count(); ++face) boundary_faces += mesh.is_boundary_face(face);
  const double volume = mesh.cell_volumes.sum();
  return {{"cells",
           {{"total", mesh.cell_count()},
            {"tetrahedra", tetrahedra},
            {"hexahedra", hexahedra},
            {"cut", cut},
            {"merged", merged},
            {"coarse", coarse},
            {"refined", refined},
            {"split", split}}},
          {"faces", {{"interior", mesh.face_count() - boundary_faces}, {"boundary", boundary_faces}}},
          {"nodes", mesh.nodes.rows()},
          {"volume", volume},
          {"geometry_volume", geometry_volume},
          {"volume_relative_difference", geometry_volume > 0 ? (volume - geometry_volume) / geometry_volume : 0.0},
          {"smallest_cell_volume", mesh.cell_volumes.minCoeff()},
          {"largest_cell_volume", mesh.cell_volumes.maxCoeff()}};
}

MeshPreview polyhedral_mesh_preview(const std::string& method, const Scene& scene, const SceneGeometry& geometry,
                                    PolyhedralMeshSource source, const MeshPreviewOptions& options) {
  if (!options.source.empty() && options.source != "convert" && options.source != "slice")
    throw InputError("--source: expected convert or slice, got '" + options.source + "'");
  if (options.source == "slice") source.slicing = options.slicing;
  if (options.source == "convert" && source.slicing) {
    source.slicing.reset();
    source.convert = fem_spec(scene);
  }
  const PolyhedralSceneMesh built = build_polyhedral_scene_mesh(source, geometry);
  MeshPreview preview;
  preview.grid = grid_from_polyhedral_mesh(built.sliced.mesh);
  preview.facts = polyhedral_mesh_facts(built.sliced.mesh, geometry.volume);
  preview.facts.update(built.facts);
  if (source.slicing) preview.facts["slicing"]["sliver_fraction"] = source.slicing->sliver_fraction;
  const bool sliced = built.facts["source"] == "slice";
  preview.summary = describe(method, scene, preview.facts, sliced ? &built.sliced : nullptr, geometry.volume);
  return preview;
}

MeshPreview fem_mesh_preview(const Scene& scene, const SceneGeometry& geometry, const MeshPreviewOptions& options) {
  if (!options.source.empty())
    throw InputError("--source " + options.source + ": only for the polyhedral methods (fem's mesh is its block's)");
  const VolumeMesh mesh = build_fem_mesh(fem_spec(scene), geometry);
  MeshPreview preview;
  preview.grid = grid_from_volume_mesh(mesh);
  preview.facts = polyhedral_mesh_facts(polyhedral_mesh_from_volume_mesh(mesh), geometry.volume);
  preview.facts["nodes"] = mesh.nodes.rows();  // the written mesh's, higher-order nodes included
  preview.facts["source"] = std::string(element_name(mesh.element_type));
  preview.summary = describe("fem", scene, preview.facts, nullptr, geometry.volume);
  return preview;
}

}  // namespace altfem
