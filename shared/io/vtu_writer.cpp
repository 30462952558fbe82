#include "shared/io/vtu_writer.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <set>
#include <stdexcept>
#include <utility>

#include "shared/common/error.hpp"
#include "shared/io/atomic_file.hpp"
#include "shared/io/xml_attribute.hpp"

namespace altfem {

namespace {

// The raw appended bytes are the host's; the header declares LittleEndian.
static_assert(std::endian::native == std::endian::little, "write_vtu assumes a little-endian host");

using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// Points per cell of the fixed-size VTK cell types (vtkCellType.h); nullopt for
/// types whose size varies (Lagrange cells, polyhedra) or that altfem does not know.
std::optional<int64_t> fixed_point_count(int vtk_type) {
  switch (vtk_type) {
    case 1: return 1;    // vertex
    case 3: return 2;    // line
    case 5: return 3;    // triangle
    case 9: return 4;    // quad
    case 10: return 4;   // tetra
    case 12: return 8;   // hexahedron
    case 13: return 6;   // wedge
    case 14: return 5;   // pyramid
    case 21: return 3;   // quadratic edge
    case 22: return 6;   // quadratic triangle
    case 24: return 10;  // quadratic tetra
    case 25: return 20;  // quadratic (serendipity) hexahedron
    case 29: return 27;  // triquadratic hexahedron
    default: return std::nullopt;
  }
}

constexpr int vtk_lagrange_tetrahedron = 71;  // vtkCellType.h

/// A VTK_LAGRANGE_TETRAHEDRON of order p has (p+1)(p+2)(p+3)/6 points, p ≥ 1.
bool is_lagrange_tetrahedron_size(int64_t points) {
  for (int64_t order = 1;; ++order) {
    const int64_t size = (order + 1) * (order + 2) * (order + 3) / 6;
    if (size >= points) return size == points;
  }
}

struct GridChecker {
  const UnstructuredGrid& grid;
  const std::string& file_name;

  [[noreturn]] void fail(const std::string& what) const {
    throw std::invalid_argument("write_vtu: " + file_name + ": " + what);
  }

  void check_point_id(int64_t id, int64_t cell) const {
    if (id < 0 || id >= grid.points.rows())
      fail("cell " + std::to_string(cell) + ": point id " + std::to_string(id) + " not in [0, " +
           std::to_string(grid.points.rows()) + ")");
  }

  void check_cells() const {
    if (grid.points.cols() != 3) fail("points must have 3 columns, got " + std::to_string(grid.points.cols()));
    const int64_t cells = grid.cell_count();
    if (static_cast<int64_t>(grid.offsets.size()) != cells)
      fail("expected " + std::to_string(cells) + " offsets (one per cell), got " + std::to_string(grid.offsets.size()));
    if (!grid.polyhedron_faces.empty() && static_cast<int64_t>(grid.polyhedron_faces.size()) != cells)
      fail("polyhedron_faces must be empty or hold one entry per cell");
    int64_t begin = 0;
    for (int64_t cell = 0; cell < cells; ++cell) {
      const int64_t end = grid.offsets[cell];
      if (end < begin || end > static_cast<int64_t>(grid.connectivity.size()))
        fail("cell " + std::to_string(cell) + ": offset " + std::to_string(end) +
             " out of order or past the connectivity");
      const int type = grid.cell_types[cell];
      if (type < 0 || type > 255)
        fail("cell " + std::to_string(cell) + ": VTK type " + std::to_string(type) + " is not a UInt8");
      const int64_t size = end - begin;
      const auto fixed = fixed_point_count(type);
      if ((fixed && size != *fixed) || (type == vtk_lagrange_tetrahedron && !is_lagrange_tetrahedron_size(size)))
        fail("cell " + std::to_string(cell) + ": VTK type " + std::to_string(type) + " cannot have " +
             std::to_string(size) + " points");
      for (int64_t k = begin; k < end; ++k) check_point_id(grid.connectivity[k], cell);
      const bool has_faces = !grid.polyhedron_faces.empty() && !grid.polyhedron_faces[cell].empty();
      if (has_faces != (type == vtk_polyhedron))
        fail("cell " + std::to_string(cell) + ": faces are required for VTK_POLYHEDRON (42) and only for it");
      if (has_faces)
        for (const auto& face : grid.polyhedron_faces[cell])
          for (const int64_t id : face) check_point_id(id, cell);
      begin = end;
    }
    if (begin != static_cast<int64_t>(grid.connectivity.size()))
      fail("the last offset " + std::to_string(begin) + " must equal the connectivity size " +
           std::to_string(grid.connectivity.size()));
  }

  void check_data(const std::vector<std::pair<std::string, Eigen::MatrixXd>>& data, Eigen::Index rows,
                  const std::string& kind) const {
    std::set<std::string> names;
    for (const auto& [name, values] : data) {
      if (name.empty() || !names.insert(name).second)
        fail(kind + " names must be unique and non-empty: '" + name + "'");
      if (values.rows() != rows || values.cols() < 1)
        fail(kind + " '" + name + "': expected " + std::to_string(rows) + " rows, got " +
             std::to_string(values.rows()) + " × " + std::to_string(values.cols()));
      check_finite(values, kind + " '" + name + "'");
    }
  }

  void check_finite(const Eigen::MatrixXd& values, const std::string& what) const {
    for (Eigen::Index row = 0; row < values.rows(); ++row)
      if (!values.row(row).allFinite())
        throw NumericalError("write_vtu: " + file_name + ": " + what + ", row " + std::to_string(row) +
                             ": expected finite values, got NaN or inf");
  }
};

/// The XML of the DataArray elements and the appended block they point into.
class AppendedArrays {
public:
  void add(std::string_view type, std::string_view name, std::optional<Eigen::Index> components, const void* data,
           std::size_t bytes, std::string_view indent) {
    xml_ += std::string(indent) + "<DataArray type=\"" + std::string(type) + "\" Name=\"" + xml_attribute(name) + "\"";
    if (components) xml_ += " NumberOfComponents=\"" + std::to_string(*components) + "\"";
    xml_ += " format=\"appended\" offset=\"" + std::to_string(block_.size()) + "\"/>\n";
    const uint64_t header = bytes;  // header_type="UInt64": the byte count of the array
    block_.append(reinterpret_cast<const char*>(&header), sizeof header);
    block_.append(static_cast<const char*>(data), bytes);
  }
  void add_doubles(std::string_view name, const Eigen::MatrixXd& values, std::string_view indent) {
    const RowMajorMatrix row_major = values;  // VTK stores components of a tuple together
    add("Float64", name, values.cols(), row_major.data(), sizeof(double) * row_major.size(), indent);
  }
  template <class Integer>
  void add_integers(std::string_view type, std::string_view name, const std::vector<Integer>& values,
                    std::string_view indent) {
    add(type, name, std::nullopt, values.data(), sizeof(Integer) * values.size(), indent);
  }
  /// Takes the DataArray XML written since the last call.
  std::string take_xml() { return std::exchange(xml_, {}); }
  const std::string& block() const { return block_; }

private:
  std::string xml_;
  std::string block_;
};

std::string data_section(AppendedArrays& arrays, std::string_view tag,
                         const std::vector<std::pair<std::string, Eigen::MatrixXd>>& data) {
  if (data.empty()) return {};
  for (const auto& [name, values] : data) arrays.add_doubles(name, values, "        ");
  return "      <" + std::string(tag) + ">\n" + arrays.take_xml() + "      </" + std::string(tag) + ">\n";
}

/// VTK's legacy polyhedron stream (kept by the XML format): per polyhedron
/// [#faces, #points of face 0, ids..., #points of face 1, ids...], and per cell the
/// end of its part of that stream, or −1 for a cell that is not a polyhedron.
void add_polyhedron_arrays(AppendedArrays& arrays, const UnstructuredGrid& grid) {
  std::vector<int64_t> faces;
  std::vector<int64_t> face_offsets;
  for (int64_t cell = 0; cell < grid.cell_count(); ++cell) {
    if (grid.cell_types[cell] != vtk_polyhedron) {
      face_offsets.push_back(-1);
      continue;
    }
    const auto& cell_faces = grid.polyhedron_faces[cell];
    faces.push_back(static_cast<int64_t>(cell_faces.size()));
    for (const auto& face : cell_faces) {
      faces.push_back(static_cast<int64_t>(face.size()));
      faces.insert(faces.end(), face.begin(), face.end());
    }
    face_offsets.push_back(static_cast<int64_t>(faces.size()));
  }
  arrays.add_integers("Int64", "faces", faces, "        ");
  arrays.add_integers("Int64", "faceoffsets", face_offsets, "        ");
}

}  // namespace

std::string vtu_text(const UnstructuredGrid& grid, const std::string& file_name) {
  const GridChecker checker{grid, file_name};
  checker.check_cells();
  checker.check_finite(grid.points, "points");
  checker.check_data(grid.point_data, grid.points.rows(), "point data");
  checker.check_data(grid.cell_data, grid.cell_count(), "cell data");

  AppendedArrays arrays;
  const std::string point_data = data_section(arrays, "PointData", grid.point_data);
  const std::string cell_data = data_section(arrays, "CellData", grid.cell_data);
  arrays.add_doubles("Points", grid.points, "        ");
  const std::string points = arrays.take_xml();
  arrays.add_integers("Int64", "connectivity", grid.connectivity, "        ");
  arrays.add_integers("Int64", "offsets", grid.offsets, "        ");
  const std::vector<uint8_t> types(grid.cell_types.begin(), grid.cell_types.end());
  arrays.add_integers("UInt8", "types", types, "        ");
  bool has_polyhedra = false;
  for (const int type : grid.cell_types) has_polyhedra = has_polyhedra || type == vtk_polyhedron;
  if (has_polyhedra) add_polyhedron_arrays(arrays, grid);
  const std::string cells = arrays.take_xml();

  std::string text =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      "  <UnstructuredGrid>\n"
      "    <Piece NumberOfPoints=\"" +
      std::to_string(grid.points.rows()) + "\" NumberOfCells=\"" + std::to_string(grid.cell_count()) + "\">\n" +
      point_data + cell_data + "      <Points>\n" + points +
      "      </Points>\n"
      "      <Cells>\n" +
      cells +
      "      </Cells>\n"
      "    </Piece>\n"
      "  </UnstructuredGrid>\n"
      "  <AppendedData encoding=\"raw\">\n"
      "   _";
  text += arrays.block();
  // meshio finds the end of the raw block at the last newline before </AppendedData>.
  text += "\n  </AppendedData>\n</VTKFile>\n";
  return text;
}

void write_vtu(const std::filesystem::path& path, const UnstructuredGrid& grid) {
  write_file_atomically(path, vtu_text(grid, path.string()));
}

}  // namespace altfem
