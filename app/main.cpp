// altfem: one scene, every method. This file only parses the command line and turns
// exceptions into the exit codes of docs/conventions.md (0 ok, 1 internal, 2 bad input,
// 3 numerical failure), each with a one-line message on stderr.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "app/commands.hpp"
#include "app/compare_command.hpp"
#include "app/method_registry.hpp"
#include "app/process_environment.hpp"
#include "shared/common/error.hpp"
#include "shared/solve/process_ranks.hpp"

int main(int argc, char** argv) {
  altfem::cli::restart_with_tuned_environment(argv);
  CLI::App app{"altfem: elastic solids with alternative discretizations on identical scenes"};
  std::string method_list;  // the registry's, so a new method needs no edit here
  for (const std::string& name : altfem::cli::available_methods())
    method_list += (method_list.empty() ? "" : ", ") + name;
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Show help for every subcommand");

  auto* info = app.add_subcommand("info", "Version, build options and the libraries linked at run time");

  auto* check = app.add_subcommand("check", "Validate a scene, resolve its defaults and describe its geometry");
  std::string check_scene;
  bool check_json = false;
  check->add_option("scene", check_scene, "Scene file (JSON)")->required();
  std::string check_method;
  check->add_option("--method", check_method, "Check and build only this method (default: every method of the build)");
  check->add_flag("--json", check_json, "Print the resolved scene, geometry and method facts as JSON");

  auto* run = app.add_subcommand("run", "Simulate a scene with one method");
  std::string run_scene, method, output;
  run->add_option("scene", run_scene, "Scene file (JSON)")->required();
  run->add_option("--method", method, "Discretization: " + method_list)->required();
  run->add_option("--out", output, "Output folder (default out/<scene>-<method>)");
  std::vector<std::string> overrides;
  run->add_option("--set", overrides, "KEY=VALUE: set the scene's JSON pointer KEY to VALUE (JSON, else a string)")
      ->allow_extra_args(false);

  auto* compare = app.add_subcommand("compare", "Run methods x sweeps on one scene; report accuracy against cost");
  altfem::cli::CompareArguments comparison;
  compare->add_option("scene", comparison.scene, "Scene file (JSON)")->required();
  compare->add_option("--methods", comparison.methods, "Comma-separated methods (default: the scene's compare block)")
      ->delimiter(',')
      ->allow_extra_args(false);
  compare->add_option("--sweep", comparison.sweeps, "KEY=V1,V2,...: values of a scene JSON pointer (repeatable)")
      ->allow_extra_args(false);
  compare->add_option("--reference", comparison.reference, "METHOD[:KEY=VALUE,...] (default: the finest run)");
  compare->add_option("--jobs", comparison.jobs, "Runs at a time (threads are shared among them)");
  compare->add_flag("--force", comparison.force, "Rerun configurations already in DIR/runs");
  compare->add_option("--out", comparison.output, "Output folder: results.csv, report.md, plots, runs/")->required();

  // `quadrature monomials` (Longva et al. 2020, §4.6) and `quadrature cell` (one cut cell's rules).
  auto* quadrature = app.add_subcommand("quadrature", "Cut-cell quadrature tools (fcm)");
  quadrature->require_subcommand(1);
  auto* monomials = quadrature->add_subcommand("monomials", "Fig. 4 of Longva et al. 2020: monomial errors");
  auto* quadrature_cell = quadrature->add_subcommand("cell", "The rules of one background cell as VTU points");
  auto* conditioning =
      quadrature->add_subcommand("conditioning", "Fig. 5 of Longva et al. 2020: kappa and PCG iterations");
  std::string conditioning_cell;
  bool conditioning_json = false;
  conditioning->add_option("--cell", conditioning_cell, "tet4|tet10|hex8|hex20")->required();
  conditioning->add_flag("--json", conditioning_json, "Print JSON");
  double conditioning_ghost_penalty = altfem::cli::default_conditioning_ghost_penalty;
  conditioning
      ->add_option("--ghost-penalty", conditioning_ghost_penalty,
                   "gamma of the face ghost penalty in the comparison rows (stabilisation 0)")
      ->check(CLI::PositiveNumber);
  std::string quadrature_cell_type = "hex20", quadrature_scene, quadrature_index, quadrature_resolution = "4";
  std::string simplifier = "caratheodory", quadrature_output = "out/quadrature-cell";
  int quadrature_order = 4;
  bool quadrature_json = false;
  monomials->add_option("--cell", quadrature_cell_type, "hex8|hex20|hex27|tet4|tet10")->required();
  quadrature_cell->add_option("--scene", quadrature_scene, "Scene file (JSON)")->required();
  quadrature_cell->add_option("--cell", quadrature_index, "Grid cube i,j,k")->required();
  quadrature_cell->add_option("--cell-type", quadrature_cell_type, "Background cell type (default hex20)");
  quadrature_cell->add_option("--resolution", quadrature_resolution, "Grid cells: n or nx,ny,nz (default 4)");
  quadrature_cell->add_option("--out", quadrature_output, "Output folder (default out/quadrature-cell)");
  for (auto* command : {monomials, quadrature_cell}) {
    command->add_option("--order", quadrature_order, "Polynomial degree m (default 4)");
    command->add_option("--simplifier", simplifier, "caratheodory, nnls or lp (default caratheodory)");
    command->add_flag("--json", quadrature_json, "Print JSON");
  }

  auto* mesh = app.add_subcommand("mesh", "Build a method's mesh without solving, write it as VTU, print its facts");
  std::string mesh_scene;
  altfem::cli::MeshCommandOptions mesh_options;
  mesh->add_option("scene", mesh_scene, "Scene file (JSON)")->required();
  mesh->add_option("--method", mesh_options.method, "Discretization: " + method_list)->required();
  mesh->add_option("--source", mesh_options.source,
                   "polyhedral methods' mesh source: convert (the fem mesh, cell by cell) or slice (a grid cut by the "
                   "geometry); "
                   "default: the mesh of the method's scene block, as run builds it");
  mesh->add_option("--resolution", mesh_options.resolution,
                   "--source slice: grid cells along the geometry's longest side (default 16)");
  mesh->add_option("--sliver-fraction", mesh_options.sliver_fraction,
                   "--source slice: merge cut pieces below this fraction of a cell (default 1e-3; 0 keeps all)");
  mesh->add_option("--octree-levels", mesh_options.octree_levels,
                   "--source slice: join inside cells into octree cells of up to 2^L grid cells per side (default 0)");
  mesh->add_option("--out", mesh_options.output_directory,
                   "Output folder for mesh.vtu (default out/<scene>-mesh-<method>), or a file ending in .vtu");
  mesh->add_flag("--json", mesh_options.json, "Print the mesh facts as JSON");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // --help and --version print and succeed; any other parse error is one line, like
    // every other error (CLI11 would print its message and a usage hint on two lines).
    if (error.get_exit_code() == 0) return app.exit(error);
    std::fprintf(stderr, "altfem: error: %s (see altfem --help)\n", error.what());
    return altfem::exit_bad_input;
  }

  // Over several processes (mpirun) every rank fails alike, and rank 0 alone says so.
  const auto report = [](const char* kind, const std::exception& error) {
    if (altfem::ranks::index() == 0) std::fprintf(stderr, "altfem: %s: %s\n", kind, error.what());
  };
  try {
    altfem::ranks::start();
    if (altfem::ranks::distributed() && !*run)
      throw altfem::InputError("mpirun: only `altfem run` runs over several processes");
    if (*info) return altfem::cli::info_command();
    if (*check) return altfem::cli::check_command(check_scene, check_method, check_json);
    if (*mesh) return altfem::cli::mesh_command(mesh_scene, mesh_options);
    if (*run) return altfem::cli::run_command(run_scene, method, output, overrides);
    if (*compare) return altfem::cli::compare_command(comparison);
    if (*monomials)
      return altfem::cli::quadrature_monomials_command(quadrature_cell_type, quadrature_order, simplifier,
                                                       quadrature_json);
    if (*conditioning)
      return altfem::cli::quadrature_conditioning_command(conditioning_cell, conditioning_ghost_penalty,
                                                          conditioning_json);
    if (*quadrature_cell)
      return altfem::cli::quadrature_cell_command(quadrature_scene, quadrature_index, quadrature_cell_type,
                                                  quadrature_resolution, quadrature_order, simplifier,
                                                  quadrature_output, quadrature_json);
  } catch (const altfem::InputError& error) {
    report("error", error);
    return altfem::exit_bad_input;
  } catch (const altfem::NumericalError& error) {
    report("numerical failure", error);
    return altfem::exit_numerical;
  } catch (const std::exception& error) {
    report("internal error", error);
    return altfem::exit_internal;
  }
  return altfem::exit_internal;
}
