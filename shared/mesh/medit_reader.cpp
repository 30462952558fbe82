// Medit .mesh ASCII reader (Frey, "MEDIT: an interactive mesh visualization software",
// INRIA RT-0253, 2001, appendix "the .mesh file format"): keyword sections, 1-based indices,
// a reference number after every entity.
#include <array>
#include <climits>
#include <optional>
#include <string>
#include <vector>

#include "shared/common/error.hpp"
#include "shared/mesh/text_tokenizer.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

namespace {

struct MeditKeyword {
  std::string_view name;
  int tokens_per_entry;  ///< numbers per entity, reference included
};

// Sections altfem skips: lower-dimensional entities and geometric attributes.
constexpr std::array<MeditKeyword, 15> skipped_keywords{{
    {"Edges", 3},
    {"Triangles", 4},
    {"Quadrilaterals", 5},
    {"Corners", 1},
    {"Ridges", 1},
    {"RequiredVertices", 1},
    {"RequiredEdges", 1},
    {"RequiredTriangles", 1},
    {"Normals", 3},
    {"NormalAtVertices", 2},
    {"Tangents", 3},
    {"TangentAtEdges", 3},
    {"EdgesP2", 4},
    {"TrianglesP2", 7},
    {"QuadrilateralsQ2", 10},
}};

constexpr long long largest_count = INT_MAX;

class MeditParser {
public:
  MeditParser(std::string_view text, const std::string& file_name) : tokens_(text, file_name, '#') {}

  VolumeMesh parse() {
    if (tokens_.at_end()) tokens_.fail("empty file, expected a Medit mesh starting with MeshVersionFormatted");
    const std::string_view first = tokens_.next("MeshVersionFormatted");
    if (first != "MeshVersionFormatted") tokens_.fail_expected("MeshVersionFormatted (a Medit .mesh file)", first);
    tokens_.next_integer("the mesh version", 1, 4);
    while (!tokens_.at_end()) {
      const std::string_view keyword = tokens_.next("a keyword");
      if (keyword == "End") break;
      read_section(keyword);
    }
    if (!vertices_read_) tokens_.fail("the file has no Vertices section");
    if (!type_) tokens_.fail("the file has no Tetrahedra or Hexahedra section");
    VolumeMesh mesh;
    mesh.element_type = *type_;
    mesh.nodes = nodes_;
    mesh.cells = cells_;
    return mesh;
  }

private:
  void read_section(std::string_view keyword) {
    if (keyword == "Dimension") {
      const long long dimension = tokens_.next_integer("the dimension", 0, 100);
      if (dimension != 3) tokens_.fail("expected dimension 3, got " + std::to_string(dimension));
    } else if (keyword == "Vertices") {
      read_vertices();
    } else if (keyword == "Tetrahedra") {
      read_cells(keyword, ElementType::tet4);
    } else if (keyword == "Hexahedra" || keyword == "Hexaedra") {  // Hexaedra: MMG's spelling
      read_cells(keyword, ElementType::hex8);
    } else if (keyword == "TetrahedraP2" || keyword == "HexahedraQ2" || keyword == "Prisms" || keyword == "Pyramids") {
      tokens_.fail(std::string(keyword) + " cells are not supported (altfem reads Tetrahedra and Hexahedra from " +
                   "Medit; use Gmsh MSH for quadratic cells)");
    } else {
      for (const auto& skipped : skipped_keywords)
        if (skipped.name == keyword) return skip_entries(skipped);
      tokens_.fail("unknown Medit keyword " + quoted_token(keyword));
    }
  }

  long long read_count(std::string_view keyword) {
    return tokens_.next_integer("the number of " + std::string(keyword), 0, largest_count);
  }

  void skip_entries(const MeditKeyword& keyword) {
    const long long count = read_count(keyword.name);
    for (long long i = 0; i < count * keyword.tokens_per_entry; ++i) tokens_.next(keyword.name);
  }

  void read_vertices() {
    if (vertices_read_) tokens_.fail("a second Vertices section");
    vertices_read_ = true;
    const long long count = read_count("vertices");
    std::vector<double> coordinates;
    for (long long i = 0; i < count; ++i) {
      for (const char* axis : {"a vertex x coordinate", "a vertex y coordinate", "a vertex z coordinate"})
        coordinates.push_back(tokens_.next_real(axis));
      tokens_.next_integer("a vertex reference number", LLONG_MIN, LLONG_MAX);
    }
    nodes_ = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
        coordinates.data(), static_cast<Eigen::Index>(count), 3);
  }

  void read_cells(std::string_view keyword, ElementType type) {
    if (!vertices_read_) tokens_.fail("cells before the Vertices section");
    if (type_) tokens_.fail("a second cell section, altfem reads one cell type per mesh");
    type_ = type;
    const long long count = read_count(keyword);
    const int per_cell = element_node_count(type);
    std::vector<int> indices;
    for (long long i = 0; i < count; ++i) {
      for (int corner = 0; corner < per_cell; ++corner) {
        const long long vertex = tokens_.next_integer("a vertex index", LLONG_MIN, LLONG_MAX);
        if (vertex < 1 || vertex > nodes_.rows())
          tokens_.fail("cell " + std::to_string(i + 1) + " refers to vertex " + std::to_string(vertex) +
                       ", expected 1 to " + std::to_string(nodes_.rows()));
        indices.push_back(static_cast<int>(vertex - 1));
      }
      tokens_.next_integer("a cell reference number", LLONG_MIN, LLONG_MAX);
    }
    cells_ = Eigen::Map<const Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        indices.data(), static_cast<Eigen::Index>(count), per_cell);
  }

  TextTokenizer tokens_;
  bool vertices_read_ = false;
  std::optional<ElementType> type_;
  Eigen::MatrixXd nodes_;
  Eigen::MatrixXi cells_;
};

}  // namespace

VolumeMesh parse_medit(std::string_view text, const std::string& file_name) {
  return MeditParser(text, file_name).parse();
}

}  // namespace altfem
