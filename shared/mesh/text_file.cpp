#include "shared/mesh/text_file.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <system_error>

#include "shared/common/error.hpp"

namespace altfem {

void check_input_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) throw InputError(input_message(name, "", "no such file"));
  if (std::filesystem::is_directory(status))
    throw InputError(input_message(name, "", "is a directory, expected a file"));
  const auto size = std::filesystem::file_size(path, error);
  if (error) throw InputError(input_message(name, "", "cannot read the file: " + error.message()));
  if (size == 0) throw InputError(input_message(name, "", "empty file"));
}

std::string read_text_file(const std::filesystem::path& path) {
  check_input_file(path);
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw InputError(input_message(path.string(), "", "cannot open the file for reading"));
  return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

std::string lowercase_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

}  // namespace altfem
