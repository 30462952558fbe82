#pragma once
// The `altfem` subcommands (DESIGN.md, "Command line and outputs"). Each returns the
// process exit code; errors are thrown as InputError / NumericalError and turned into
// exit codes 2 / 3 by main.
#include <filesystem>
#include <string>

namespace altfem::cli {

int info_command();
int check_command(const std::filesystem::path& scene_file, bool json);
/// Options of `altfem mesh` (main.cpp documents each).
struct MeshCommandOptions {
  std::string method;
  std::string source = "convert";
  std::filesystem::path output_directory;
  bool json = false;
};
int mesh_command(const std::filesystem::path& scene_file, const MeshCommandOptions& options);
int run_command(const std::filesystem::path& scene_file, const std::string& method,
                const std::filesystem::path& output_directory);

}  // namespace altfem::cli
