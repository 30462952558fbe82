#include "tests/cli/cli_support.hpp"

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>

namespace altfem::test {

namespace {
std::string quote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}
std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}
}  // namespace

namespace {
// The folders this test process made; removed when it exits, so a test run leaves
// nothing under the system temporary folder (ALTFEM_KEEP_TEST_FOLDERS=1 keeps them
// for a look at what a failing test's run wrote).
struct MadeFolders {
  std::vector<std::filesystem::path> paths;
  ~MadeFolders() {
    if (std::getenv("ALTFEM_KEEP_TEST_FOLDERS") != nullptr) return;
    std::error_code ignored;
    for (const auto& path : paths) std::filesystem::remove_all(path, ignored);
  }
};
}  // namespace

std::filesystem::path fresh_directory(const std::string& name) {
  static std::mt19937 random{std::random_device{}()};
  static MadeFolders made;
  const auto path = std::filesystem::temp_directory_path() / ("altfem-cli-" + name + "-" + std::to_string(random()));
  std::filesystem::remove_all(path);
  std::filesystem::create_directories(path);
  made.paths.push_back(path);
  return path;
}

namespace {
CommandResult run_command(const std::string& launcher, const std::vector<std::string>& arguments) {
  const auto capture = fresh_directory("capture");
  std::string command = launcher + " " + quote(ALTFEM_EXECUTABLE);
  for (const auto& argument : arguments) command += " " + quote(argument);
  command += " > " + quote((capture / "out").string()) + " 2> " + quote((capture / "err").string()) + " < /dev/null";
  const int status = std::system(command.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_all(capture / "out");
  result.err = read_all(capture / "err");
  std::filesystem::remove_all(capture);
  return result;
}
}  // namespace

CommandResult run_altfem(const std::vector<std::string>& arguments, const std::string& environment) {
  return run_command(environment, arguments);
}

CommandResult run_altfem_on_ranks(int ranks, const std::vector<std::string>& arguments) {
  return run_command("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1 mpirun -n " +
                         std::to_string(ranks) + " --oversubscribe",
                     arguments);
}

std::filesystem::path source_path(const std::string& relative) {
  return std::filesystem::path(ALTFEM_SOURCE_DIR) / relative;
}

nlohmann::json read_summary(const std::filesystem::path& folder) {
  std::ifstream file(folder / "summary.json");
  return nlohmann::json::parse(file);
}

std::vector<double> last_step_of_log(const std::filesystem::path& folder) {
  std::ifstream file(folder / "log.txt");
  std::string line, last;
  while (std::getline(file, line))
    if (!line.empty() && line[0] != '#') last = line;
  std::istringstream fields(last);
  std::vector<double> values;
  for (double value; fields >> value;) values.push_back(value);
  return values;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

}  // namespace altfem::test
