#pragma once
// A structural check of ASCII OFF text before CGAL reads it: CGAL's reader only
// returns false, without a line (docs/environment.md), so the common mistakes get a
// "file: line N" message here.
#include <string>
#include <string_view>

namespace altfem {

/// Checks the header counts against the vertices and faces present, finite vertex
/// coordinates and face vertex indices in range. Binary and n-dimensional OFF are left
/// to CGAL. Throws InputError "file: line N: what".
void check_off_text(std::string_view text, const std::string& file_name);

}  // namespace altfem
