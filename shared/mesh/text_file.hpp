#pragma once
// Reading a whole input file, with the clear errors every reader shares.
#include <filesystem>
#include <string>

namespace altfem {

/// Throws InputError "path: ..." for a missing file, a directory, an unreadable or
/// an empty file.
void check_input_file(const std::filesystem::path& path);
/// check_input_file, then the file's bytes.
std::string read_text_file(const std::filesystem::path& path);
/// The extension in lower case, with its dot (".msh").
std::string lowercase_extension(const std::filesystem::path& path);

}  // namespace altfem
