#include "shared/io/output_folder.hpp"

#include <unistd.h>
#include <fstream>
#include <string>

#include "shared/common/error.hpp"

namespace altfem {

namespace {

[[noreturn]] void reject(const std::filesystem::path& folder, const std::string& reason) {
  throw InputError(input_message("--out " + folder.string(), "", reason));
}

// Whether a file can be created in `folder` (root ignores permission bits, so ask the
// file system itself with a probe file, removed at once).
bool writable(const std::filesystem::path& folder) {
  const std::filesystem::path probe = folder / (".altfem-write-probe-" + std::to_string(getpid()));
  {
    std::ofstream stream(probe);
    if (!stream) return false;
  }
  std::error_code ignored;
  std::filesystem::remove(probe, ignored);
  return true;
}

}  // namespace

void check_output_folder(const std::filesystem::path& folder) {
  std::error_code error;
  std::filesystem::path existing = std::filesystem::absolute(folder, error);
  if (error) reject(folder, "not a usable path (" + error.message() + ")");
  while (!std::filesystem::exists(existing, error) && existing.has_parent_path() && existing != existing.parent_path())
    existing = existing.parent_path();
  if (!std::filesystem::is_directory(existing, error))
    reject(folder, existing == std::filesystem::absolute(folder) ? "is an existing file, expected a folder"
                                                                 : existing.string() + " is a file, not a folder");
  if (!writable(existing)) reject(folder, "cannot write in " + existing.string() + " (read-only or no permission)");
}

}  // namespace altfem
