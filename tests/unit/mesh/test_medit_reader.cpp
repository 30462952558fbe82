#include <gtest/gtest.h>

#include <string>

#include "shared/common/error.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {
namespace {

TEST(MeditReader, ReadsTetrahedraSkippingLowerDimensionalSections) {
  constexpr const char* text = R"(MeshVersionFormatted 2
# a comment line
Dimension
3
Vertices
5
0 0 0 1
1 0 0 1
0 1 0 1
0 0 1 1
1 1 1 1   # trailing comment
Triangles
1
1 2 3 7
Tetrahedra
2
1 2 3 4 1
2 3 4 5 2
Corners
1
1
End
)";
  const VolumeMesh mesh = parse_medit(text, "two.mesh");
  check_volume_mesh(mesh, "two.mesh");
  EXPECT_EQ(mesh.element_type, ElementType::tet4);
  ASSERT_EQ(mesh.cells.rows(), 2);
  EXPECT_EQ(mesh.cells(1, 3), 4);  // 1-based 5 → 0-based 4
  // det[(−1,1,0), (−1,0,1), (0,1,1)] = 2 for the second tet.
  EXPECT_NEAR(volume_mesh_volume(mesh), 1.0 / 6.0 + 2.0 / 6.0, 1e-15);
}

TEST(MeditReader, ReadsHexahedra) {
  constexpr const char* text =
      "MeshVersionFormatted 1\nDimension 3\nVertices\n8\n"
      "0 0 0 0\n2 0 0 0\n2 1 0 0\n0 1 0 0\n0 0 1 0\n2 0 1 0\n2 1 1 0\n0 1 1 0\n"
      "Hexahedra\n1\n1 2 3 4 5 6 7 8 0\nEnd\n";
  const VolumeMesh mesh = parse_medit(text, "box.mesh");
  check_volume_mesh(mesh, "box.mesh");
  EXPECT_EQ(mesh.element_type, ElementType::hex8);
  EXPECT_NEAR(volume_mesh_volume(mesh), 2.0, 1e-14);
}

TEST(MeditReader, ErrorsNameFileAndLine) {
  const auto message = [](const std::string& text) {
    try {
      parse_medit(text, "m.mesh");
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("MeshVersionFormatted 2\nDimension 2\n"), "m.mesh: line 2: expected dimension 3, got 2");
  EXPECT_EQ(message("MeshVersionFormatted 2\nDimension 3\nVertices\n2\n0 0 0 1\n"),
            "m.mesh: line 5: file ends early: expected a vertex x coordinate");
  EXPECT_EQ(message("MeshVersionFormatted 2\nDimension 3\nVertices\n0\nTetrahedraP2\n"),
            "m.mesh: line 5: TetrahedraP2 cells are not supported (altfem reads Tetrahedra and Hexahedra from "
            "Medit; use Gmsh MSH for quadratic cells)");
  EXPECT_EQ(message("MeshVersionFormatted 2\nVertices\n1\n0 0 0 1\n"),
            "m.mesh: line 4: the file has no Tetrahedra or Hexahedra section");
}

}  // namespace
}  // namespace altfem
