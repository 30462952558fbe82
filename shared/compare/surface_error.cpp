#include "shared/compare/surface_error.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "shared/common/error.hpp"
#include "shared/mesh/surface_mesh.hpp"
#include "shared/mesh/surface_projection.hpp"

namespace altfem {

namespace {

// The value of attribute `name` in the XML tag that starts at `tag`.
std::string attribute(const std::string& text, std::size_t tag, const std::string& name) {
  const std::size_t end = text.find('>', tag);
  const std::size_t at = text.find(" " + name + "=\"", tag);
  if (at == std::string::npos || at > end) return "";
  const std::size_t begin = at + name.size() + 3;
  return text.substr(begin, text.find('"', begin) - begin);
}

class VtuArrays {
public:
  explicit VtuArrays(const std::filesystem::path& file) : file_(file.string()) {
    std::ifstream stream(file, std::ios::binary);
    if (!stream) fail("expected a readable VTU file");
    std::ostringstream content;
    content << stream.rdbuf();
    text_ = content.str();
    const std::size_t appended = text_.find("<AppendedData encoding=\"raw\">");
    if (appended == std::string::npos || text_.find("header_type=\"UInt64\"") == std::string::npos)
      fail("expected appended raw data with UInt64 headers (as altfem run writes)");
    data_ = text_.find('_', appended) + 1;
    const std::size_t piece = text_.find("<Piece");
    points_ = piece == std::string::npos ? 0 : std::stoll(attribute(text_, piece, "NumberOfPoints"));
  }

  /// The Float64 array [points × 3] of the first DataArray after `section` named `name` ("" for any).
  Eigen::MatrixX3d read(const std::string& section, const std::string& name) const {
    const std::string bytes = array_bytes(section, name, "Float64", "3", points_ * 3 * sizeof(double));
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> values(points_, 3);
    std::memcpy(values.data(), bytes.data(), bytes.size());
    return values;
  }

  /// The triangles [cells × 3] of a surface of triangles (Int64 connectivity).
  Eigen::MatrixXi triangles() const {
    const std::size_t piece = text_.find("<Piece");
    const long long cells = std::stoll(attribute(text_, piece, "NumberOfCells"));
    const std::string bytes = array_bytes("Cells", "connectivity", "Int64", "", cells * 3 * sizeof(std::int64_t));
    Eigen::Matrix<std::int64_t, Eigen::Dynamic, 3, Eigen::RowMajor> values(cells, 3);
    std::memcpy(values.data(), bytes.data(), bytes.size());
    return values.cast<int>();
  }

private:
  // The raw bytes of a DataArray, checked for its type, components and size.
  std::string array_bytes(const std::string& section, const std::string& name, const std::string& type,
                          const std::string& components, std::size_t expected) const {
    std::size_t tag = text_.find("<" + section);
    while (tag != std::string::npos) {
      tag = text_.find("<DataArray", tag + 1);
      if (tag == std::string::npos || tag > data_) break;
      if (!name.empty() && attribute(text_, tag, "Name") != name) continue;
      if (attribute(text_, tag, "type") != type || attribute(text_, tag, "NumberOfComponents") != components)
        fail("expected " + section + " '" + name + "' as " + type + " with " + components + " components");
      const std::size_t offset = data_ + std::stoull(attribute(text_, tag, "offset"));
      std::uint64_t bytes = 0;
      if (offset + sizeof bytes > text_.size()) fail("appended data ends early");
      std::memcpy(&bytes, text_.data() + offset, sizeof bytes);
      if (bytes != expected || offset + sizeof bytes + bytes > text_.size())
        fail("array '" + name + "' has " + std::to_string(bytes) + " bytes, expected " + std::to_string(expected));
      return text_.substr(offset + sizeof bytes, bytes);
    }
    fail("no " + section + (name.empty() ? "" : " array '" + name + "'"));
  }

  [[noreturn]] void fail(const std::string& what) const { throw InputError(input_message(file_, "", what)); }

  std::string file_, text_;
  std::size_t data_ = 0;
  long long points_ = 0;
};

}  // namespace

SurfaceFrame read_surface_frame(const std::filesystem::path& file) {
  const VtuArrays arrays(file);
  return {arrays.read("Points", ""), arrays.read("PointData", "displacement"), arrays.triangles()};
}

Eigen::MatrixX3d reference_at(const SurfaceFrame& reference, const Eigen::MatrixX3d& rest_points) {
  SurfaceMesh rest_surface;
  rest_surface.vertices = reference.deformed - reference.displacement;
  rest_surface.triangles = reference.triangles;
  const SurfaceProjection projection(rest_surface);
  Eigen::MatrixX3d deformed(rest_points.rows(), 3);
  for (Eigen::Index i = 0; i < rest_points.rows(); ++i) {
    const auto [point, triangle] = projection.closest_point_and_triangle(rest_points.row(i).transpose());
    const Eigen::Vector3i corners = reference.triangles.row(triangle).transpose();
    const Eigen::Vector3d a = rest_surface.vertices.row(corners[0]), b = rest_surface.vertices.row(corners[1]),
                          c = rest_surface.vertices.row(corners[2]);
    // Barycentric coordinates of the closest point (it lies on the triangle).
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    const double area = normal.squaredNorm();
    const double beta = (point - a).cross(c - a).dot(normal) / area;
    const double gamma = (b - a).cross(point - a).dot(normal) / area;
    const Eigen::RowVector3d displacement = (1 - beta - gamma) * reference.displacement.row(corners[0]) +
                                            beta * reference.displacement.row(corners[1]) +
                                            gamma * reference.displacement.row(corners[2]);
    deformed.row(i) = rest_points.row(i) + displacement;
  }
  return deformed;
}

double rest_diagonal(const SurfaceFrame& frame) {
  const Eigen::MatrixX3d rest = frame.deformed - frame.displacement;
  return (rest.colwise().maxCoeff() - rest.colwise().minCoeff()).norm();
}

SurfaceError surface_error(const Eigen::MatrixX3d& deformed, const Eigen::MatrixX3d& reference_deformed,
                           const Eigen::MatrixX3d& reference_displacement, double diagonal) {
  if (deformed.rows() != reference_deformed.rows() || reference_displacement.rows() != reference_deformed.rows())
    throw InputError(input_message(
        "surface", "",
        "expected " + std::to_string(reference_deformed.rows()) + " vertices, got " + std::to_string(deformed.rows())));
  if (deformed.rows() == 0) throw InputError(input_message("surface", "", "expected surface vertices, got none"));
  const Eigen::VectorXd distance = (deformed - reference_deformed).rowwise().norm();
  const double count = static_cast<double>(distance.size());
  const double rms = std::sqrt(distance.squaredNorm() / count);
  const double reference_rms = std::sqrt(reference_displacement.squaredNorm() / count);
  return {rms / diagonal, distance.maxCoeff() / diagonal,
          reference_rms > 0 ? rms / reference_rms : std::numeric_limits<double>::infinity()};
}

SurfaceError surface_error(const SurfaceFrame& run, const SurfaceFrame& reference) {
  const double diagonal = rest_diagonal(reference);
  const bool same_surface = run.deformed.rows() == reference.deformed.rows() &&
                            run.triangles.rows() == reference.triangles.rows() &&
                            run.triangles == reference.triangles &&
                            (run.deformed - run.displacement).isApprox(reference.deformed - reference.displacement);
  if (same_surface) return surface_error(run.deformed, reference.deformed, reference.displacement, diagonal);
  const Eigen::MatrixX3d rest = run.deformed - run.displacement;
  const Eigen::MatrixX3d reference_deformed = reference_at(reference, rest);
  return surface_error(run.deformed, reference_deformed, reference_deformed - rest, diagonal);
}

}  // namespace altfem
