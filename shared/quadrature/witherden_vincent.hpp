#pragma once
// The symmetric Witherden–Vincent rules shipped in data/quadrature/<domain>/
// (F. D. Witherden, P. E. Vincent, On the identification of symmetric quadrature rules
// for finite element methods, Comput. Math. Appl. 69 (2015) 1232–1241): positive
// weights, interior points, far fewer points than product rules of the same strength.
#include "shared/quadrature/quadrature_rule.hpp"
#include "shared/quadrature/reference_domain.hpp"

#include <filesystem>
#include <vector>

namespace altfem {

/// Reads one table in polyquad's expanded format: one point a line, `x y [z] weight`
/// (dimension + 1 numbers), blank lines ignored. Returns the rule as written (no change
/// of reference domain), points #points × dimension, with the given strength.
/// Throws InputError "file: line N: expected …, got …" for a missing file, a line
/// without exactly dimension + 1 finite numbers, a weight <= 0, or no points at all;
/// std::invalid_argument for a dimension other than 2 or 3.
QuadratureRule read_quadrature_table(const std::filesystem::path& file, int dimension, int strength);

/// Every table in data_directory()/quadrature/<reference_domain_name(domain)>/, named
/// `<strength>-<points>.txt`, mapped onto altfem's reference domain (reference_domain.hpp:
/// the tables' simplices with vertices at −1 are mapped affinely onto the unit simplex),
/// sorted by increasing strength. Read on first use and cached for the process; safe to
/// call from several threads. Throws InputError for a missing folder, a badly named
/// file, a point count that differs from the file name, or a malformed table.
const std::vector<QuadratureRule>& witherden_vincent_rules(ReferenceDomain domain);

}  // namespace altfem
