#pragma once
// Runs the altfem executable as a user would and captures what it prints.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace altfem::test {

struct CommandResult {
  int exit_code = -1;
  std::string out;  ///< standard output
  std::string err;  ///< standard error
};

/// Runs `altfem <arguments>` with optional extra environment ("NAME=value ...").
CommandResult run_altfem(const std::vector<std::string>& arguments, const std::string& environment = "");
/// Runs `mpirun -n <ranks> --oversubscribe altfem <arguments>` (allowed as root, one
/// OpenMP thread per rank).
CommandResult run_altfem_on_ranks(int ranks, const std::vector<std::string>& arguments);
/// A fresh empty folder under the system temporary folder, removed when the test process
/// exits unless ALTFEM_KEEP_TEST_FOLDERS is set.
std::filesystem::path fresh_directory(const std::string& name);
std::filesystem::path source_path(const std::string& relative);
/// The summary.json a run wrote into `folder`.
nlohmann::json read_summary(const std::filesystem::path& folder);
/// The last step's line of log.txt in `folder`: step time dofs iterations linear_iterations
/// residual total_energy max_von_mises (docs/conventions.md).
std::vector<double> last_step_of_log(const std::filesystem::path& folder);
/// Lines of a text, without the trailing empty one.
std::vector<std::string> lines_of(const std::string& text);

}  // namespace altfem::test
