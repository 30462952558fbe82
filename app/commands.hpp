#pragma once
// The `altfem` subcommands (docs/conventions.md, "Command line and outputs"). Each returns the
// process exit code; errors are thrown as InputError / NumericalError and turned into
// exit codes 2 / 3 by main.
#include <filesystem>
#include <string>
#include <vector>

namespace altfem::cli {

int info_command();
int check_command(const std::filesystem::path& scene_file, bool json);
/// `overrides` are the --set KEY=VALUE assignments (docs/scene-schema.md, "Overrides").
int run_command(const std::filesystem::path& scene_file, const std::string& method,
                const std::filesystem::path& output_directory, const std::vector<std::string>& overrides);

}  // namespace altfem::cli
