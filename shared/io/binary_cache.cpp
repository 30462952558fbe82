#include "shared/io/binary_cache.hpp"

#include <cstdio>
#include <fstream>
#include <iterator>

#include "shared/io/atomic_file.hpp"

namespace altfem {

std::filesystem::path cache_file_path(const std::filesystem::path& directory, std::uint64_t key,
                                      std::string_view extension) {
  char name[17];
  std::snprintf(name, sizeof name, "%016llx", static_cast<unsigned long long>(key));
  return directory / (std::string(name) + std::string(extension));
}

std::optional<std::string> read_cache_file(const std::filesystem::path& path) {
  std::ifstream file{path, std::ios::binary};
  if (!file) return std::nullopt;
  std::string bytes{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  if (file.bad()) return std::nullopt;
  return bytes;
}

void write_cache_file(const std::filesystem::path& path, std::string_view content) {
  std::error_code error;
  std::filesystem::create_directories(path.parent_path(),
                                      error);  // write_file_atomically names the path if this failed
  write_file_atomically(path, content);
}

}  // namespace altfem
