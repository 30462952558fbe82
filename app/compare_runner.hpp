#pragma once
// Runs the pending configurations of `altfem compare` as `altfem run` child processes,
// at most `jobs` at a time, each into runs/.partial-<hash> renamed to runs/<hash> when
// it ends (whatever its exit code), so runs/<hash> always holds a complete run.
#include <filesystem>
#include <string>
#include <vector>

#include "shared/compare/run_record.hpp"

namespace altfem::cli {

struct PendingRun {
  std::vector<std::string> arguments;  ///< after the executable: run SCENE --method M --set ...
  std::filesystem::path partial;       ///< runs/.partial-<hash>, passed as --out
  std::filesystem::path folder;        ///< runs/<hash>
  RunRecord record;                    ///< the configuration part and where it runs
};

/// Runs them all; record.csv in each folder. Progress on stderr when it is a terminal.
/// Returns false when SIGINT/SIGTERM stopped it: running children were killed and their
/// partial folders removed; completed runs stay and a rerun resumes.
bool run_pending(std::vector<PendingRun>& pending, int jobs, int threads_per_run);

/// Everything before the run itself failed (bad input, a crash) ends the run with this
/// status: "ok", "invalid input", "numerical failure", "internal error", "crashed", ...
std::string status_of_exit(int exit_code, int signal);

}  // namespace altfem::cli
