// Gmsh MSH 2.2 and 4.1 ASCII reader (Gmsh reference manual, "MSH file format").
// Gmsh's own API is not used: it accepts NaN coordinates and reports no line numbers
// (docs/environment.md).
#include <climits>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "shared/common/error.hpp"
#include "shared/mesh/gmsh_element_types.hpp"
#include "shared/mesh/text_tokenizer.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

namespace {

constexpr long long largest_count = INT_MAX;
constexpr long long largest_tag = LLONG_MAX / 2;

class GmshParser {
public:
  GmshParser(std::string_view text, const std::string& file_name) : tokens_(text, file_name) {}

  VolumeMesh parse() {
    if (tokens_.at_end()) tokens_.fail("empty file, expected a Gmsh MSH file starting with $MeshFormat");
    const std::string_view first = tokens_.next("$MeshFormat");
    if (first != "$MeshFormat") tokens_.fail_expected("$MeshFormat (a Gmsh MSH file)", first);
    read_format();
    while (!tokens_.at_end()) {
      const std::string_view section = tokens_.next("a section");
      if (section == "$Nodes") {
        if (nodes_read_) tokens_.fail("a second $Nodes section");
        version_ == 4 ? read_nodes_v4() : read_nodes_v2();
        nodes_read_ = true;
      } else if (section == "$Elements") {
        if (!nodes_read_) tokens_.fail("$Elements before $Nodes");
        if (elements_read_) tokens_.fail("a second $Elements section");
        version_ == 4 ? read_elements_v4() : read_elements_v2();
        elements_read_ = true;
      } else if (section.size() > 1 && section[0] == '$' && !section.starts_with("$End")) {
        skip_section(section.substr(1));
      } else {
        tokens_.fail_expected("a section such as $Nodes or $Elements", section);
      }
    }
    if (!nodes_read_) tokens_.fail("the file has no $Nodes section");
    if (!elements_read_) tokens_.fail("the file has no $Elements section");
    if (!type_)
      tokens_.fail(
          "$Elements has no volume cells of a type altfem reads (4-node or 10-node tetrahedron; "
          "8-, 20- or 27-node hexahedron)");
    return compact_mesh();
  }

private:
  void read_format() {
    const std::string_view version = tokens_.next("the MSH version");
    if (version == "4.1") version_ = 4;
    else if (version == "2.2" || version == "2.1" || version == "2.0" || version == "2") version_ = 2;
    else tokens_.fail("MSH version " + quoted_token(version) + " is not supported, expected 2.2 or 4.1");
    if (tokens_.next_integer("the file type (0 for ASCII)", 0, 1) == 1)
      tokens_.fail("binary MSH is not supported, save the mesh as ASCII (gmsh -format msh41 without -bin)");
    tokens_.next_integer("the data size", 1, 16);
    tokens_.expect("$EndMeshFormat");
  }

  void skip_section(std::string_view name) {
    const std::string end = "$End" + std::string(name);
    while (tokens_.next(end) != end) {
    }
  }

  // A `$`-token where data was expected means the section holds fewer items than its header says.
  void check_not_section_end(const char* items, long long declared, long long read) {
    if (tokens_.peek().starts_with("$"))
      tokens_.fail("wrong count: " + std::to_string(declared) + " " + items + " declared, only " +
                   std::to_string(read) + " listed before " + quoted_token(tokens_.next(items)));
  }

  void expect_section_end(const char* end, const char* items, long long declared) {
    const std::string_view token = tokens_.next(end);
    if (token != end)
      tokens_.fail("wrong count: more " + std::string(items) + " than the " + std::to_string(declared) +
                   " declared, expected " + end + ", got " + quoted_token(token));
  }

  void add_node_tag(long long tag) {
    const auto index = static_cast<int>(node_index_.size());
    if (!node_index_.emplace(tag, index).second) tokens_.fail("duplicate node tag " + std::to_string(tag));
  }

  void add_coordinates(long long count) {
    for (long long i = 0; i < count; ++i)
      for (const char* axis : {"a node's x coordinate", "a node's y coordinate", "a node's z coordinate"})
        coordinates_.push_back(tokens_.next_real(axis));
  }

  void read_nodes_v2() {
    const long long count = tokens_.next_integer("the number of nodes", 0, largest_count);
    for (long long i = 0; i < count; ++i) {
      check_not_section_end("nodes", count, i);
      add_node_tag(tokens_.next_integer("a node tag", 1, largest_tag));
      add_coordinates(1);
    }
    expect_section_end("$EndNodes", "nodes", count);
  }

  void read_nodes_v4() {
    const long long blocks = tokens_.next_integer("the number of node blocks", 0, largest_count);
    const long long count = tokens_.next_integer("the number of nodes", 0, largest_count);
    tokens_.next_integer("the smallest node tag", 0, largest_tag);
    tokens_.next_integer("the largest node tag", 0, largest_tag);
    long long read = 0;
    for (long long block = 0; block < blocks; ++block) {
      check_not_section_end("node blocks", blocks, block);
      const long long dimension = tokens_.next_integer("an entity dimension", 0, 3);
      tokens_.next_integer("an entity tag", -largest_tag, largest_tag);
      const bool parametric = tokens_.next_integer("the parametric flag", 0, 1) == 1;
      const long long in_block = tokens_.next_integer("the number of nodes in the block", 0, largest_count);
      if (read + in_block > count)
        tokens_.fail("wrong count: node blocks hold more than the " + std::to_string(count) + " nodes declared");
      for (long long i = 0; i < in_block; ++i) {
        check_not_section_end("nodes", count, read + i);
        add_node_tag(tokens_.next_integer("a node tag", 1, largest_tag));
      }
      for (long long i = 0; i < in_block; ++i) {
        check_not_section_end("nodes", count, read + i);
        add_coordinates(1);
        // Parametric coordinates on the node's entity (u; u v; u v w) are not needed.
        for (long long p = 0; parametric && p < dimension; ++p) tokens_.next_real("a parametric coordinate");
      }
      read += in_block;
    }
    if (read != count)
      tokens_.fail("wrong count: " + std::to_string(count) + " nodes declared, the blocks hold " +
                   std::to_string(read));
    expect_section_end("$EndNodes", "node blocks", blocks);
  }

  const GmshElementType& element_type(long long number) {
    const GmshElementType* type = gmsh_element_type(number);
    if (!type) tokens_.fail("unknown Gmsh element type " + std::to_string(number));
    if (type->dimension == 3 && !type->altfem_type)
      tokens_.fail("Gmsh element type " + std::to_string(number) + " (" + std::string(type->name) +
                   ") is not supported, expected a tetrahedron (4 or 10 nodes) or hexahedron (8, 20 or 27 nodes)");
    return *type;
  }

  // Reads one element's node tags; volume cells are stored in VTK order.
  void read_element(const GmshElementType& type, long long element_tag) {
    if (!type.altfem_type) {
      for (int i = 0; i < type.nodes; ++i) tokens_.next_integer("a node tag", 1, largest_tag);
      return;
    }
    if (type_ && *type_ != *type.altfem_type)
      tokens_.fail("the mesh mixes " + std::string(element_name(*type_)) + " and " +
                   std::string(element_name(*type.altfem_type)) + " cells, altfem reads one cell type per mesh");
    type_ = type.altfem_type;
    gmsh_nodes_.clear();
    for (int i = 0; i < type.nodes; ++i) {
      const long long tag = tokens_.next_integer("a node tag", 1, largest_tag);
      const auto found = node_index_.find(tag);
      if (found == node_index_.end())
        tokens_.fail("element " + std::to_string(element_tag) + " refers to node " + std::to_string(tag) +
                     ", which $Nodes does not define");
      gmsh_nodes_.push_back(found->second);
    }
    for (const int gmsh_index : gmsh_to_vtk_order(*type_)) cells_.push_back(gmsh_nodes_[gmsh_index]);
  }

  void read_elements_v2() {
    const long long count = tokens_.next_integer("the number of elements", 0, largest_count);
    for (long long i = 0; i < count; ++i) {
      check_not_section_end("elements", count, i);
      const long long tag = tokens_.next_integer("an element tag", 1, largest_tag);
      const GmshElementType& type = element_type(tokens_.next_integer("an element type", 0, largest_tag));
      const long long tag_count = tokens_.next_integer("the number of element tags", 0, 1000);
      for (long long t = 0; t < tag_count; ++t) tokens_.next_integer("an element tag", -largest_tag, largest_tag);
      read_element(type, tag);
    }
    expect_section_end("$EndElements", "elements", count);
  }

  void read_elements_v4() {
    const long long blocks = tokens_.next_integer("the number of element blocks", 0, largest_count);
    const long long count = tokens_.next_integer("the number of elements", 0, largest_count);
    tokens_.next_integer("the smallest element tag", 0, largest_tag);
    tokens_.next_integer("the largest element tag", 0, largest_tag);
    long long read = 0;
    for (long long block = 0; block < blocks; ++block) {
      check_not_section_end("element blocks", blocks, block);
      tokens_.next_integer("an entity dimension", 0, 3);
      tokens_.next_integer("an entity tag", -largest_tag, largest_tag);
      const GmshElementType& type = element_type(tokens_.next_integer("an element type", 0, largest_tag));
      const long long in_block = tokens_.next_integer("the number of elements in the block", 0, largest_count);
      if (read + in_block > count)
        tokens_.fail("wrong count: element blocks hold more than the " + std::to_string(count) + " elements declared");
      for (long long i = 0; i < in_block; ++i) {
        check_not_section_end("elements", count, read + i);
        read_element(type, tokens_.next_integer("an element tag", 1, largest_tag));
      }
      read += in_block;
    }
    if (read != count)
      tokens_.fail("wrong count: " + std::to_string(count) + " elements declared, the blocks hold " +
                   std::to_string(read));
    expect_section_end("$EndElements", "element blocks", blocks);
  }

  // Nodes used only by ignored lower-dimensional cells (or by none) are dropped.
  VolumeMesh compact_mesh() const {
    const auto node_count = static_cast<int>(node_index_.size());
    std::vector<int> new_index(node_count, -1);
    int used = 0;
    for (const int node : cells_)
      if (new_index[node] < 0) new_index[node] = used++;
    VolumeMesh mesh;
    mesh.element_type = *type_;
    mesh.nodes.resize(used, 3);
    for (int node = 0; node < node_count; ++node)
      if (new_index[node] >= 0)
        for (int axis = 0; axis < 3; ++axis) mesh.nodes(new_index[node], axis) = coordinates_[3 * node + axis];
    const int per_cell = element_node_count(*type_);
    mesh.cells.resize(static_cast<Eigen::Index>(cells_.size()) / per_cell, per_cell);
    for (std::size_t i = 0; i < cells_.size(); ++i)
      mesh.cells(static_cast<Eigen::Index>(i) / per_cell, static_cast<Eigen::Index>(i) % per_cell) =
          new_index[cells_[i]];
    return mesh;
  }

  TextTokenizer tokens_;
  int version_ = 4;
  bool nodes_read_ = false;
  bool elements_read_ = false;
  std::unordered_map<long long, int> node_index_;  // Gmsh node tag → index in read order
  std::vector<double> coordinates_;                // 3 per node, in read order
  std::optional<ElementType> type_;
  std::vector<int> cells_;       // node indices (read order), VTK order within a cell
  std::vector<int> gmsh_nodes_;  // one element's node indices in Gmsh order
};

}  // namespace

VolumeMesh parse_gmsh(std::string_view text, const std::string& file_name) {
  return GmshParser(text, file_name).parse();
}

}  // namespace altfem
