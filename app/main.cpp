// altfem: one scene, every method. This file only parses the command line and turns
// exceptions into the exit codes of docs/conventions.md (0 ok, 1 internal, 2 bad input,
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

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // --help and --version print and succeed; any other parse error is one line, like
    // every other error (CLI11 would print its message and a usage hint on two lines).
    if (error.get_exit_code() == 0) return app.exit(error);
    std::fprintf(stderr, "altfem: error: %s (see altfem --help)\n", error.what());
    return altfem::exit_bad_input;
  }

  try {
    if (*info) return altfem::cli::info_command();
    if (*check) return altfem::cli::check_command(check_scene, check_json);
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
