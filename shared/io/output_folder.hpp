#pragma once
#include <filesystem>

namespace altfem {

/// Checks, before any work, that `folder` can become the output folder: it is an
/// existing folder we can write in, or it does not exist and its nearest existing
/// ancestor is a folder we can write in. Creates nothing that stays (a probe file is
/// removed again). Throws InputError "--out PATH: what is wrong" otherwise.
void check_output_folder(const std::filesystem::path& folder);

}  // namespace altfem
