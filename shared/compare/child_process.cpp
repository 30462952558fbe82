#include "shared/compare/child_process.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <stdexcept>

extern char** environ;

namespace altfem {

namespace {
volatile std::sig_atomic_t interrupt_flag = 0;
void on_interrupt(int) { interrupt_flag = 1; }
}  // namespace

pid_t start_child(const std::vector<std::string>& arguments, const std::vector<std::string>& extra_environment,
                  const std::filesystem::path& stdout_file, const std::filesystem::path& stderr_file) {
  // Everything the child needs is built before fork: between fork and exec only
  // async-signal-safe calls are allowed.
  std::vector<std::string> environment;
  for (char** entry = environ; *entry != nullptr; ++entry) {
    const std::string variable(*entry);
    const std::string name = variable.substr(0, variable.find('=') + 1);
    bool overridden = false;
    for (const auto& extra : extra_environment) overridden |= extra.rfind(name, 0) == 0;
    if (!overridden) environment.push_back(variable);
  }
  environment.insert(environment.end(), extra_environment.begin(), extra_environment.end());
  std::vector<char*> argv, envp;
  for (const auto& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  for (const auto& variable : environment) envp.push_back(const_cast<char*>(variable.c_str()));
  argv.push_back(nullptr);
  envp.push_back(nullptr);
  const int out = ::open(stdout_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  const int err = ::open(stderr_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  const int in = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  if (out < 0 || err < 0 || in < 0) {
    for (const int fd : {out, err, in})
      if (fd >= 0) ::close(fd);
    throw std::runtime_error("cannot open the output files of a run in " + stdout_file.parent_path().string());
  }
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(in, 0);
    ::dup2(out, 1);
    ::dup2(err, 2);
    ::execve(argv[0], argv.data(), envp.data());
    ::_exit(127);  // the shell's "command not found"
  }
  ::close(out);
  ::close(err);
  ::close(in);
  if (pid < 0) throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
  return pid;
}

FinishedChild wait_for_any_child() {
  int status = 0;
  rusage usage{};
  const pid_t pid = ::wait4(-1, &status, 0, &usage);
  FinishedChild child;
  if (pid <= 0) return child;
  child.pid = pid;
  if (WIFSIGNALED(status)) {
    child.signal = WTERMSIG(status);
    child.exit_code = 128 + child.signal;
  } else {
    child.exit_code = WEXITSTATUS(status);
  }
  child.peak_memory_mib = static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: kibibytes
  return child;
}

void catch_interrupts() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;  // no SA_RESTART: a blocked wait4 returns EINTR
  ::sigaction(SIGINT, &action, nullptr);
  ::sigaction(SIGTERM, &action, nullptr);
}

bool interrupted() { return interrupt_flag != 0; }

}  // namespace altfem
