#include "app/compare_runner.hpp"

#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "shared/compare/child_process.hpp"
#include "shared/compare/results_table.hpp"

namespace altfem::cli {

namespace {

using Clock = std::chrono::steady_clock;

// The last non-empty line of a file (a failed run's one-line error).
std::string last_line(const std::filesystem::path& file) {
  std::ifstream stream(file);
  std::string line, last;
  while (std::getline(stream, line))
    if (!line.empty()) last = line;
  return last;
}

void finish(PendingRun& run, const FinishedChild& child, double wall_seconds) {
  RunRecord& record = run.record;
  record.exit_code = child.exit_code;
  record.status = status_of_exit(child.exit_code, child.signal);
  record.wall_seconds = wall_seconds;
  record.peak_memory_mib = child.peak_memory_mib;
  if (!record.ok()) {
    record.message = last_line(run.partial / "stderr.txt");
    for (const std::string prefix : {"altfem: error: ", "altfem: numerical failure: ", "altfem: internal error: "})
      if (record.message.rfind(prefix, 0) == 0) record.message.erase(0, prefix.size());
  }
  // summary.json exists for a finished run and for a numerical failure (docs/conventions.md).
  if (std::ifstream summary(run.partial / "summary.json"); summary) {
    try {
      add_summary(record, nlohmann::json::parse(summary));
    } catch (const nlohmann::json::exception& error) {
      record.message += std::string(record.message.empty() ? "" : "; ") + "unreadable summary.json: " + error.what();
    }
  }
  write_results_csv(run.partial / "record.csv", {record});
  std::filesystem::remove_all(run.folder);
  std::filesystem::rename(run.partial, run.folder);
}

class ProgressLine {
public:
  explicit ProgressLine(std::size_t total) : total_(total), enabled_(::isatty(2) != 0), start_(Clock::now()) {}
  void show(std::size_t done, std::size_t running, const std::string& label) const {
    if (!enabled_) return;
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    std::string eta = "ETA --";
    if (done > 0) {
      char text[32];
      std::snprintf(text, sizeof text, "ETA %.0f s", elapsed / static_cast<double>(done) * (total_ - done));
      eta = text;
    }
    std::fprintf(stderr, "\r\033[Kcompare: run %zu of %zu (%zu running), %s: %s", done + 1, total_, running,
                 eta.c_str(), label.c_str());
    std::fflush(stderr);
  }
  void clear() const {
    if (enabled_) std::fprintf(stderr, "\r\033[K");
  }

private:
  std::size_t total_;
  bool enabled_;
  Clock::time_point start_;
};

}  // namespace

std::string status_of_exit(int exit_code, int signal) {
  if (signal != 0) return "crashed (signal " + std::to_string(signal) + ")";
  switch (exit_code) {
    case 0: return "ok";
    case 2: return "invalid input";
    case 3: return "numerical failure";
    case 127: return "could not start";
    default: return "internal error";
  }
}

bool run_pending(std::vector<PendingRun>& pending, int jobs, int threads_per_run) {
  catch_interrupts();
  const std::string executable = std::filesystem::read_symlink("/proc/self/exe").string();
  const std::vector<std::string> environment{"OMP_NUM_THREADS=" + std::to_string(threads_per_run)};
  std::map<pid_t, std::pair<PendingRun*, Clock::time_point>> running;
  ProgressLine progress(pending.size());
  std::size_t next = 0, done = 0;
  while (done < pending.size() && !interrupted()) {
    while (running.size() < static_cast<std::size_t>(jobs) && next < pending.size()) {
      PendingRun& run = pending[next++];
      std::filesystem::remove_all(run.partial);
      std::filesystem::create_directories(run.partial);
      std::vector<std::string> arguments{executable};
      arguments.insert(arguments.end(), run.arguments.begin(), run.arguments.end());
      const pid_t pid = start_child(arguments, environment, run.partial / "stdout.txt", run.partial / "stderr.txt");
      running[pid] = {&run, Clock::now()};
      progress.show(done, running.size(), run.record.label);
    }
    const FinishedChild child = wait_for_any_child();
    const auto found = running.find(child.pid);
    if (found == running.end()) continue;  // EINTR (checked by the loop) or not ours
    const double wall = std::chrono::duration<double>(Clock::now() - found->second.second).count();
    finish(*found->second.first, child, wall);
    running.erase(found);
    ++done;
    if (done < pending.size()) progress.show(done, running.size(), "");
  }
  progress.clear();
  if (!interrupted()) return true;
  // Ctrl-C: a terminal already sent SIGINT to the children; make sure, then clean up.
  for (const auto& [pid, run] : running) ::kill(pid, SIGTERM);
  while (!running.empty()) {
    const FinishedChild child = wait_for_any_child();
    if (child.pid < 0 && errno != EINTR) break;  // no child left to wait for
    const auto found = running.find(child.pid);
    if (found == running.end()) continue;
    std::filesystem::remove_all(found->second.first->partial);
    running.erase(found);
  }
  return false;
}

}  // namespace altfem::cli
