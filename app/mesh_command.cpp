// `altfem mesh`: builds a method's mesh without solving, writes it as VTU and prints its
// facts, so users look at a mesh before they pay for a run.
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/method_registry.hpp"
#include "fcm/fcm_method.hpp"
#include "dg/dg_scene_block.hpp"
#include "polyhedral/harmonic_scene_block.hpp"
#include "shared/common/error.hpp"
#include "shared/fem/fem_mesh.hpp"
#include "shared/fem/polyhedral_scene_mesh.hpp"
#include "shared/io/polyhedral_grid.hpp"
#include "shared/io/vtu_writer.hpp"
#include "shared/mesh/boundary_surface.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/scene/scene.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/scene/scene_slicing.hpp"

namespace altfem::cli {

namespace {

nlohmann::json mesh_facts(const PolyhedralMesh& mesh, double geometry_volume) {
  int tetrahedra = 0, hexahedra = 0, cut = 0, merged = 0, coarse = 0;
  for (PolyhedralCellKind kind : mesh.cell_kinds) {
    switch (kind) {
      case PolyhedralCellKind::tetrahedron: ++tetrahedra; break;
      case PolyhedralCellKind::hexahedron: ++hexahedra; break;
      case PolyhedralCellKind::cut: ++cut; break;
      case PolyhedralCellKind::merged: ++merged; break;
      case PolyhedralCellKind::coarse: ++coarse; break;
    }
  }
  int boundary_faces = 0;
  for (int face = 0; face < mesh.face_count(); ++face) boundary_faces += mesh.is_boundary_face(face);
  const double volume = mesh.cell_volumes.sum();
  return {{"cells",
           {{"total", mesh.cell_count()}, {"tetrahedra", tetrahedra}, {"hexahedra", hexahedra}, {"cut", cut}, {"merged", merged}, {"coarse", coarse}}},
          {"faces", {{"interior", mesh.face_count() - boundary_faces}, {"boundary", boundary_faces}}},
          {"nodes", mesh.nodes.rows()},
          {"volume", volume},
          {"geometry_volume", geometry_volume},
          {"volume_relative_difference", geometry_volume > 0 ? (volume - geometry_volume) / geometry_volume : 0.0},
          {"smallest_cell_volume", mesh.cell_volumes.minCoeff()},
          {"largest_cell_volume", mesh.cell_volumes.maxCoeff()}};
}

// The command line's slicing options, checked with messages naming the flags.
SlicingOptions slicing_options(const MeshCommandOptions& options) {
  if (options.resolution < 1) throw InputError("--resolution: must be >= 1, got " + std::to_string(options.resolution));
  if (!(options.sliver_fraction >= 0 && options.sliver_fraction < 1))
    throw InputError("--sliver-fraction: must be in [0, 1), got " + std::to_string(options.sliver_fraction));
  if (options.octree_levels < 0 || options.octree_levels > 10)
    throw InputError("--octree-levels: must be in 0..10, got " + std::to_string(options.octree_levels));
  SlicingOptions slicing;
  slicing.resolution = options.resolution;
  slicing.sliver_fraction = options.sliver_fraction;
  slicing.octree_levels = options.octree_levels;
  return slicing;
}

// fcm: the kept background cells with their volume fractions and quadrature points,
// built as `run` builds them (the cut-cell rules included).
int fcm_mesh_command(const std::filesystem::path& scene_file, const MeshCommandOptions& options,
                     std::chrono::steady_clock::time_point start) {
  if (!options.source.empty())
    throw InputError("--source " + options.source + ": fcm's mesh is its background grid (no --source)");
  Scene scene = load_scene(scene_file);
  resolve_method_blocks(scene, {"fcm"});
  const SceneGeometry geometry = load_scene_geometry(scene);
  for (const auto& warning : geometry.warnings) std::fprintf(stderr, "altfem: warning: %s\n", warning.c_str());
  const std::unique_ptr<MethodInstance> instance = fcm::make_fcm_method(scene, geometry);
  for (const auto& warning : instance->warnings()) std::fprintf(stderr, "altfem: warning: %s\n", warning.c_str());
  const double build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::filesystem::path out = options.output_directory.empty()
                                        ? std::filesystem::path("out") / (scene.name + "-mesh-fcm")
                                        : options.output_directory;
  const std::filesystem::path vtu = out.extension() == ".vtu" ? out : out / "mesh.vtu";
  if (!vtu.parent_path().empty()) std::filesystem::create_directories(vtu.parent_path());
  write_vtu(vtu, instance->volume_grid(Eigen::VectorXd::Zero(instance->discretization().dof_count())));
  nlohmann::json facts = instance->facts();
  facts["method"] = "fcm";
  facts["elements"] = instance->element_counts();
  facts["quadrature_points"] = instance->quadrature_points();
  facts["build_time_s"] = build_seconds;
  facts["file"] = vtu.string();
  if (options.json) {
    std::printf("%s\n", facts.dump(2).c_str());
    return 0;
  }
  const nlohmann::json& cells = facts["cells"];
  std::printf("fcm mesh of '%s': %s background grid, %d inside, %d cut, %d discarded, %d outside cells (%d split "
              "into pieces); %lld quadrature points (cut cells: %lld -> %lld)\nbuild time: %.3f s\nwritten: %s\n",
              scene.name.c_str(), facts["background_resolution"].dump().c_str(), cells["inside"].get<int>(),
              cells["cut"].get<int>(), cells["discarded"].get<int>(), cells["outside"].get<int>(), cells["split"].get<int>(),
              facts["quadrature_points"].get<long long>(), facts["cut_cell_points"]["initial"].get<long long>(),
              facts["cut_cell_points"]["final"].get<long long>(), build_seconds, vtu.c_str());
  return 0;
}

}  // namespace

int mesh_command(const std::filesystem::path& scene_file, const MeshCommandOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const std::string& method = options.method;
  if (method == "fcm") return fcm_mesh_command(scene_file, options, start);
  if (method != "dg" && method != "harmonic" && method != "fem")
    throw InputError("--method: expected dg, harmonic, fem or fcm, got '" + method + "'");
  const bool polyhedral = method != "fem";
  if (!options.source.empty() && options.source != "convert" && options.source != "slice")
    throw InputError("--source: expected convert or slice, got '" + options.source + "'");
  if (!polyhedral && options.source == "slice")
    throw InputError("--source " + options.source + ": only for the polyhedral methods (dg, harmonic)");
  Scene scene = load_scene(scene_file);
  resolve_method_blocks(scene, {method});
  const SceneGeometry geometry = load_scene_geometry(scene);
  for (const auto& warning : geometry.warnings) std::fprintf(stderr, "altfem: warning: %s\n", warning.c_str());

  // dg and harmonic: the mesh their block names, as `run` builds it, unless --source
  // asks for the fem mesh converted cell by cell or the geometry sliced by the flags'
  // grid. fem: its own mesh; its facts come from the same conversion (straight-sided
  // cells from the corners).
  VolumeMesh volume_mesh;
  SlicedMesh sliced;
  nlohmann::json source_facts = {{"source", "convert"}};
  if (polyhedral) {
    PolyhedralMeshSource source = method == "dg" ? dg::dg_spec(scene).mesh : harmonic::harmonic_spec(scene).mesh;
    if (options.source == "slice") source.slicing = slicing_options(options);
    if (options.source == "convert" && source.slicing) {
      source.slicing.reset();
      source.convert = fem_spec(scene);
    }
    PolyhedralSceneMesh built = build_polyhedral_scene_mesh(source, geometry);
    sliced = std::move(built.sliced);
    source_facts = std::move(built.facts);
    if (source.slicing) source_facts["slicing"]["sliver_fraction"] = source.slicing->sliver_fraction;
  } else {
    volume_mesh = build_fem_mesh(fem_spec(scene), geometry);
    sliced.mesh = polyhedral_mesh_from_volume_mesh(volume_mesh);
  }
  const bool slice = source_facts["source"] == "slice";
  const PolyhedralMesh& mesh = sliced.mesh;
  const double build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // --out DIR writes DIR/mesh.vtu; --out FILE.vtu writes that file.
  const std::filesystem::path out = options.output_directory.empty()
                                        ? std::filesystem::path("out") / (scene.name + "-mesh-" + method)
                                        : options.output_directory;
  const bool out_is_file = out.extension() == ".vtu";
  const std::filesystem::path vtu = out_is_file ? out : out / "mesh.vtu";
  if (!vtu.parent_path().empty()) std::filesystem::create_directories(vtu.parent_path());
  write_vtu(vtu, polyhedral ? grid_from_polyhedral_mesh(mesh) : grid_from_volume_mesh(volume_mesh));

  nlohmann::json facts = mesh_facts(mesh, geometry.volume);
  facts["method"] = method;
  if (!polyhedral) facts["nodes"] = volume_mesh.nodes.rows();  // the written mesh's, higher-order nodes included
  if (polyhedral) facts.update(source_facts);
  else facts["source"] = std::string(element_name(volume_mesh.element_type));
  facts["build_time_s"] = build_seconds;
  facts["file"] = vtu.string();
  if (options.json) {
    std::printf("%s\n", facts.dump(2).c_str());
    return 0;
  }
  std::printf("%s mesh of '%s' (%s): %lld cells (%d tetrahedra, %d hexahedra, %d cut, %d merged, %d coarse), %lld nodes\n",
              method.c_str(), scene.name.c_str(), facts["source"].get<std::string>().c_str(),
              facts["cells"]["total"].get<long long>(), facts["cells"]["tetrahedra"].get<int>(),
              facts["cells"]["hexahedra"].get<int>(), facts["cells"]["cut"].get<int>(),
              facts["cells"]["merged"].get<int>(), facts["cells"]["coarse"].get<int>(), facts["nodes"].get<long long>());
  if (slice)
    std::printf("slicing: %d x %d x %d grid of cells %.4g, %d cut pieces, %d grid cells split by topology, "
                "%d slivers merged\n",
                sliced.grid_cells(0), sliced.grid_cells(1), sliced.grid_cells(2), sliced.cell_size, sliced.cut_pieces,
                sliced.split_grid_cells, sliced.merged_slivers);
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
