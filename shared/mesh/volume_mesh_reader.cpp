#include "shared/common/error.hpp"
#include "shared/mesh/text_file.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

VolumeMesh read_volume_mesh(const std::filesystem::path& path) {
  const std::string name = path.string();
  const std::string extension = lowercase_extension(path);
  if (extension != ".msh" && extension != ".mesh")
    throw InputError(input_message(
        name, "", "unknown volume mesh format '" + extension + "', expected .msh (Gmsh) or .mesh (Medit)"));
  const std::string text = read_text_file(path);
  VolumeMesh mesh = extension == ".msh" ? parse_gmsh(text, name) : parse_medit(text, name);
  check_volume_mesh(mesh, name);
  return mesh;
}

}  // namespace altfem
