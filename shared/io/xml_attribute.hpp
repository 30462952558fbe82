#pragma once
// Text for XML attribute values of the VTK files (array names, file names).
#include <string>
#include <string_view>

namespace altfem {

/// `text` with &, <, >, " and ' replaced by their entities, for use inside a
/// double-quoted XML attribute.
std::string xml_attribute(std::string_view text);

}  // namespace altfem
