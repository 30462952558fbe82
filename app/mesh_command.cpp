// `altfem mesh`: builds a method's mesh without solving, writes it as VTU and prints its
// facts, so users look at a mesh before they pay for a run.
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "dg/dg_scene_block.hpp"
#include "shared/common/error.hpp"
#include "shared/fem/fem_mesh.hpp"
#include "shared/io/polyhedral_grid.hpp"
#include "shared/io/vtu_writer.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/scene/scene.hpp"
#include "shared/scene/scene_geometry.hpp"

namespace altfem::cli {

namespace {

nlohmann::json mesh_facts(const PolyhedralMesh& mesh, double geometry_volume) {
  int tetrahedra = 0, hexahedra = 0;
  for (PolyhedralCellKind kind : mesh.cell_kinds) (kind == PolyhedralCellKind::tetrahedron ? tetrahedra : hexahedra)++;
  int boundary_faces = 0;
  for (int face = 0; face < mesh.face_count(); ++face) boundary_faces += mesh.is_boundary_face(face);
  const double volume = mesh.cell_volumes.sum();
  return {{"cells", {{"total", mesh.cell_count()}, {"tetrahedra", tetrahedra}, {"hexahedra", hexahedra}}},
          {"faces", {{"interior", mesh.face_count() - boundary_faces}, {"boundary", boundary_faces}}},
          {"nodes", mesh.nodes.rows()},
          {"volume", volume},
          {"geometry_volume", geometry_volume},
          {"volume_relative_difference", geometry_volume > 0 ? (volume - geometry_volume) / geometry_volume : 0.0},
          {"smallest_cell_volume", mesh.cell_volumes.minCoeff()},
          {"largest_cell_volume", mesh.cell_volumes.maxCoeff()}};
}

}  // namespace

int mesh_command(const std::filesystem::path& scene_file, const MeshCommandOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const std::string& method = options.method;
  if (method == "fcm") throw InputError("--method fcm: the fcm mesh is not in this build (dg, harmonic or fem)");
  if (method != "dg" && method != "harmonic" && method != "fem")
    throw InputError("--method: expected dg, harmonic, fem or fcm, got '" + method + "'");
  const bool polyhedral = method != "fem";
  if (polyhedral && options.source != "convert")
    throw InputError("--source " + options.source + ": only 'convert' (the fem mesh, cell by cell) is in this build");
  const Scene scene = load_scene(scene_file);
  const SceneGeometry geometry = load_scene_geometry(scene);
  for (const auto& warning : geometry.warnings) std::fprintf(stderr, "altfem: warning: %s\n", warning.c_str());

  // dg and harmonic: the fem mesh converted cell by cell (Kaufmann et al. 2009 §9 and
  // Martin et al. 2008 §7 also slice a grid; not in this build). fem: its own mesh; its
  // facts come from the same conversion (straight-sided cells from the corners).
  // dg reads the mesh keys of its own block (the same rules as fem's).
  const VolumeMesh volume_mesh = build_fem_mesh(method == "dg" ? dg::dg_spec(scene).mesh : fem_spec(scene), geometry);
  const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(volume_mesh);
  const double build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::filesystem::path out = options.output_directory.empty()
                                        ? std::filesystem::path("out") / (scene.name + "-mesh-" + method)
                                        : options.output_directory;
  std::filesystem::create_directories(out);
  const std::filesystem::path vtu = out / "mesh.vtu";
  write_vtu(vtu, polyhedral ? grid_from_polyhedral_mesh(mesh) : grid_from_volume_mesh(volume_mesh));

  nlohmann::json facts = mesh_facts(mesh, geometry.volume);
  facts["method"] = method;
  if (!polyhedral) facts["nodes"] = volume_mesh.nodes.rows();  // the written mesh's, higher-order nodes included
  facts["source"] = polyhedral ? options.source : std::string(element_name(volume_mesh.element_type));
  facts["build_time_s"] = build_seconds;
  facts["file"] = vtu.string();
  if (options.json) {
    std::printf("%s\n", facts.dump(2).c_str());
    return 0;
  }
  std::printf("%s mesh of '%s' (%s): %lld cells (%d tetrahedra, %d hexahedra), %lld nodes\n", method.c_str(),
              scene.name.c_str(), facts["source"].get<std::string>().c_str(), facts["cells"]["total"].get<long long>(),
              facts["cells"]["tetrahedra"].get<int>(), facts["cells"]["hexahedra"].get<int>(),
              facts["nodes"].get<long long>());
  std::printf("faces: %d interior, %d boundary\n", facts["faces"]["interior"].get<int>(),
              facts["faces"]["boundary"].get<int>());
  std::printf("volume: %.10g (geometry %.10g, relative difference %.3e)\n", facts["volume"].get<double>(),
              geometry.volume, facts["volume_relative_difference"].get<double>());
  std::printf("cell volume: smallest %.4g, largest %.4g\nbuild time: %.3f s\nwritten: %s\n",
              facts["smallest_cell_volume"].get<double>(), facts["largest_cell_volume"].get<double>(), build_seconds,
              vtu.c_str());
  return 0;
}

}  // namespace altfem::cli
