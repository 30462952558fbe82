#include "shared/quadrature/witherden_vincent.hpp"

#include "shared/common/data_directory.hpp"
#include "shared/common/error.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace altfem {
namespace {

std::vector<std::string_view> split_whitespace(std::string_view line) {
  std::vector<std::string_view> tokens;
  const std::string_view space = " \t\r\v\f";
  for (std::size_t begin = line.find_first_not_of(space); begin != std::string_view::npos;) {
    const std::size_t end = std::min(line.find_first_of(space, begin), line.size());
    tokens.push_back(line.substr(begin, end - begin));
    begin = line.find_first_not_of(space, end);
  }
  return tokens;
}

// std::from_chars rounds correctly (the tables carry 38 digits) and is locale-free.
bool parse_double(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  return error == std::errc() && end == token.data() + token.size() && std::isfinite(value);
}

bool parse_int(std::string_view token, int& value) {
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  return error == std::errc() && end == token.data() + token.size();
}

// The tables' simplex has its vertices at −1 (Witherden & Vincent 2015, §2); altfem's is
// the unit simplex: x ↦ (x + 1)/2, which scales measures by 2^−dimension.
void map_to_unit_simplex(QuadratureRule& rule) {
  const auto dimension = rule.points.cols();
  rule.points = (rule.points.array() + 1.0) / 2.0;
  rule.weights /= std::exp2(static_cast<double>(dimension));
}

std::vector<QuadratureRule> load_rules(ReferenceDomain domain) {
  const std::filesystem::path folder = data_directory() / "quadrature" / std::string(reference_domain_name(domain));
  if (!std::filesystem::is_directory(folder))
    throw InputError(input_message(folder.string(), "", "expected a folder of quadrature tables, found none"));
  std::vector<QuadratureRule> rules;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() != ".txt") continue;
    const std::string stem = entry.path().stem().string();
    const std::size_t dash = stem.find('-');
    int strength = 0, point_count = 0;
    if (dash == std::string::npos || !parse_int(std::string_view(stem).substr(0, dash), strength) ||
        !parse_int(std::string_view(stem).substr(dash + 1), point_count) || strength < 0 || point_count < 1)
      throw InputError(input_message(entry.path().string(), "file name",
                                     "expected <strength>-<points>.txt, got " + entry.path().filename().string()));
    QuadratureRule rule = read_quadrature_table(entry.path(), reference_dimension(domain), strength);
    if (rule.weights.size() != point_count)
      throw InputError(input_message(entry.path().string(), "line " + std::to_string(rule.weights.size() + 1),
                                     "expected " + std::to_string(point_count) + " points (from the file name), got " +
                                         std::to_string(rule.weights.size())));
    if (domain == ReferenceDomain::triangle || domain == ReferenceDomain::tetrahedron) map_to_unit_simplex(rule);
    rules.push_back(std::move(rule));
  }
  std::sort(rules.begin(), rules.end(),
            [](const QuadratureRule& a, const QuadratureRule& b) { return a.strength < b.strength; });
  return rules;
}

// One function-local static per domain: initialised once, thread-safe ([stmt.dcl]/4),
// retried on the next call if loading threw, and a broken folder of one domain does
// not affect the others.
template <ReferenceDomain domain>
const std::vector<QuadratureRule>& cached_rules() {
  static const std::vector<QuadratureRule> rules = load_rules(domain);
  return rules;
}

}  // namespace

QuadratureRule read_quadrature_table(const std::filesystem::path& file, int dimension, int strength) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("read_quadrature_table: dimension must be 2 or 3, got " + std::to_string(dimension));
  std::ifstream stream(file);
  if (!stream)
    throw InputError(input_message(file.string(), "", "expected a readable quadrature table, cannot open it"));
  std::vector<double> values;  // row-major, dimension + 1 per point
  std::string line;
  for (int line_number = 1; std::getline(stream, line); ++line_number) {
    const std::vector<std::string_view> tokens = split_whitespace(line);
    if (tokens.empty()) continue;
    const std::string where = "line " + std::to_string(line_number);
    if (static_cast<int>(tokens.size()) != dimension + 1)
      throw InputError(input_message(file.string(), where,
                                     "expected " + std::to_string(dimension + 1) + " numbers (" +
                                         (dimension == 2 ? "x y" : "x y z") + " weight), got " +
                                         std::to_string(tokens.size())));
    for (const std::string_view token : tokens) {
      double value = 0;
      if (!parse_double(token, value))
        throw InputError(
            input_message(file.string(), where, "expected a finite number, got '" + std::string(token) + "'"));
      values.push_back(value);
    }
    if (!(values.back() > 0.0))
      throw InputError(
          input_message(file.string(), where, "expected a positive weight, got " + std::string(tokens.back())));
  }
  if (values.empty()) throw InputError(input_message(file.string(), "line 1", "expected quadrature points, got none"));

  const auto point_count = static_cast<Eigen::Index>(values.size()) / (dimension + 1);
  const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> table(
      values.data(), point_count, dimension + 1);
  QuadratureRule rule;
  rule.points = table.leftCols(dimension);
  rule.weights = table.col(dimension);
  rule.strength = strength;
  return rule;
}

const std::vector<QuadratureRule>& witherden_vincent_rules(ReferenceDomain domain) {
  switch (domain) {
    case ReferenceDomain::quadrilateral: return cached_rules<ReferenceDomain::quadrilateral>();
    case ReferenceDomain::triangle: return cached_rules<ReferenceDomain::triangle>();
    case ReferenceDomain::hexahedron: return cached_rules<ReferenceDomain::hexahedron>();
    case ReferenceDomain::tetrahedron: return cached_rules<ReferenceDomain::tetrahedron>();
  }
  throw std::invalid_argument("witherden_vincent_rules: unknown reference domain");
}

}  // namespace altfem
