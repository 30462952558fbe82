#include "shared/compare/surface_error.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "shared/common/error.hpp"

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
    std::size_t tag = text_.find("<" + section);
    while (tag != std::string::npos) {
      tag = text_.find("<DataArray", tag + 1);
      if (tag == std::string::npos || tag > data_) break;
      if (!name.empty() && attribute(text_, tag, "Name") != name) continue;
      if (attribute(text_, tag, "type") != "Float64" || attribute(text_, tag, "NumberOfComponents") != "3")
        fail("expected " + section + " '" + name + "' as Float64 with 3 components");
      const std::size_t offset = data_ + std::stoull(attribute(text_, tag, "offset"));
      std::uint64_t bytes = 0;
      if (offset + sizeof bytes > text_.size()) fail("appended data ends early");
      std::memcpy(&bytes, text_.data() + offset, sizeof bytes);
      if (bytes != static_cast<std::uint64_t>(points_) * 3 * sizeof(double) || offset + sizeof bytes + bytes > text_.size())
        fail("array '" + name + "' does not hold 3 doubles per point");
      Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> values(points_, 3);
      std::memcpy(values.data(), text_.data() + offset + sizeof bytes, bytes);
      return values;
    }
    fail("no " + section + (name.empty() ? "" : " array '" + name + "'"));
  }

private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(input_message(file_, "", what)); }

  std::string file_, text_;
  std::size_t data_ = 0;
  long long points_ = 0;
};

}  // namespace

SurfaceFrame read_surface_frame(const std::filesystem::path& file) {
  const VtuArrays arrays(file);
  return {arrays.read("Points", ""), arrays.read("PointData", "displacement")};
}

SurfaceError surface_error(const Eigen::MatrixX3d& deformed, const Eigen::MatrixX3d& reference_deformed,
                           const Eigen::MatrixX3d& reference_rest) {
  if (deformed.rows() != reference_deformed.rows() || reference_rest.rows() != reference_deformed.rows())
    throw InputError(input_message("surface", "", "expected the reference's " +
                                                      std::to_string(reference_deformed.rows()) +
                                                      " embedded surface vertices, got " + std::to_string(deformed.rows())));
  if (deformed.rows() == 0) throw InputError(input_message("surface", "", "expected surface vertices, got none"));
  const double diagonal = (reference_rest.colwise().maxCoeff() - reference_rest.colwise().minCoeff()).norm();
  const Eigen::VectorXd distance = (deformed - reference_deformed).rowwise().norm();
  return {std::sqrt(distance.squaredNorm() / static_cast<double>(distance.size())) / diagonal,
          distance.maxCoeff() / diagonal};
}

}  // namespace altfem
