// altfem: one scene, every method. This file only parses the command line and turns
// exceptions into the exit codes of DESIGN.md (0 ok, 1 internal, 2 bad input,
// 3 numerical failure), each with a one-line message on stderr.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "app/commands.hpp"
#include "shared/common/error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"altfem: elastic solids with alternative discretizations on identical scenes"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Show help for every subcommand");

  auto* info = app.add_subcommand("info", "Version, build options and the libraries linked at run time");

  auto* check = app.add_subcommand("check", "Validate a scene, resolve its defaults and describe its geometry");
  std::string check_scene;
  bool check_json = false;
  check->add_option("scene", check_scene, "Scene file (JSON)")->required();
  check->add_flag("--json", check_json, "Print the resolved scene and geometry facts as JSON");

  auto* run = app.add_subcommand("run", "Simulate a scene with one method");
  std::string run_scene, method, output;
  run->add_option("scene", run_scene, "Scene file (JSON)")->required();
  run->add_option("--method", method, "Discretization: fem (fcm, dg, harmonic in later builds)")->required();
  run->add_option("--out", output, "Output folder (default out/<scene>-<method>)");

  auto* mesh = app.add_subcommand("mesh", "Build a method's mesh without solving, write it as VTU, print its facts");
  std::string mesh_scene;
  altfem::cli::MeshCommandOptions mesh_options;
  mesh->add_option("scene", mesh_scene, "Scene file (JSON)")->required();
  mesh->add_option("--method", mesh_options.method, "dg, harmonic, fem (fcm in a later build)")->required();
  mesh->add_option("--source", mesh_options.source, "dg/harmonic mesh source: convert (the fem mesh, cell by cell)");
  mesh->add_option("--out", mesh_options.output_directory, "Output folder (default out/<scene>-mesh-<method>)");
  mesh->add_flag("--json", mesh_options.json, "Print the mesh facts as JSON");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? 0 : altfem::exit_bad_input;
  }

  try {
    if (*info) return altfem::cli::info_command();
    if (*check) return altfem::cli::check_command(check_scene, check_json);
    if (*mesh) return altfem::cli::mesh_command(mesh_scene, mesh_options);
    if (*run) return altfem::cli::run_command(run_scene, method, output);
  } catch (const altfem::InputError& error) {
    std::fprintf(stderr, "altfem: error: %s\n", error.what());
    return altfem::exit_bad_input;
  } catch (const altfem::NumericalError& error) {
    std::fprintf(stderr, "altfem: numerical failure: %s\n", error.what());
    return altfem::exit_numerical;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "altfem: internal error: %s\n", error.what());
    return altfem::exit_internal;
  }
  return altfem::exit_internal;
}
