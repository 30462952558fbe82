#pragma once
// Runs of `altfem compare` are child processes, so a crash, an exit code and the
// peak memory (wait4's rusage) are captured per run, and Ctrl-C can stop them.
#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace altfem {

/// Starts `arguments[0]` with `arguments`, the parent's environment plus `extra_environment`
/// ("NAME=value", overriding), standard output and error into the two files, standard
/// input from /dev/null. Throws std::runtime_error if the process cannot be created.
pid_t start_child(const std::vector<std::string>& arguments, const std::vector<std::string>& extra_environment,
                  const std::filesystem::path& stdout_file, const std::filesystem::path& stderr_file);

struct FinishedChild {
  pid_t pid = -1;
  int exit_code = 0;           ///< the exit status, or 128 + the signal that killed it
  int signal = 0;              ///< the signal that killed it, 0 if it exited
  double peak_memory_mib = 0;  ///< ru_maxrss of the child
};

/// Waits for any child to finish. Returns pid -1 when a signal interrupted the wait
/// (see interrupted()) or there is no child.
FinishedChild wait_for_any_child();

/// Installs SIGINT/SIGTERM handlers (without SA_RESTART, so wait_for_any_child returns)
/// that only set the flag read by interrupted(); the caller stops its children and cleans up.
void catch_interrupts();
bool interrupted();

}  // namespace altfem
