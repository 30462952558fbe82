#include "dg/dg_transfer.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <vector>

#include "dg/face_polynomials.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"

namespace altfem::dg {

namespace {

bool same_matrix(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() && a == b;
}

// The cell and its functions as they were: the same vertices, and the same monomials
// (centre, scale, degree) combined the same way (strong conditions change the functions).
bool same_cell(const DgLinearSystem& system, const DgLinearSystem& previous, int cell) {
  if (cell >= previous.cell_count()) return false;
  const MonomialBasis& basis = system.basis(cell);
  const MonomialBasis& before = previous.basis(cell);
  return basis.degree() == before.degree() && basis.centre() == before.centre() && basis.scale() == before.scale() &&
         same_matrix(basis.combination(), before.combination()) &&
         same_matrix(system.cell(cell).vertices, previous.cell(cell).vertices);
}

// The parent's functions as polynomials in the child's frame (#monomials × #parent
// functions), then in the child's functions: φ_child = Σ_a C_aj m_a, so the
// coefficients over the child's functions are C⁻¹ times those over its monomials.
Eigen::MatrixXd parent_in_child(const MonomialBasis& parent, const MonomialBasis& child) {
  const Eigen::MatrixXd monomials = in_frame(parent, child.centre(), child.scale(), child.degree()).values;
  if (child.combination().size() == 0) return monomials;
  return child.combination().partialPivLu().solve(monomials);
}

// The L2 projection's solution M c = r on `cell` (r: a column per component of each
// field) into the cell's rows of `result`.
void write_projection(const DgLinearSystem& system, int cell, const Eigen::MatrixXd& mass,
                      const Eigen::MatrixXd& moments, Eigen::MatrixXd& result) {
  const Eigen::MatrixXd coefficients = mass.ldlt().solve(moments);  // #functions × 3·#fields
  for (Eigen::Index a = 0; a < coefficients.rows(); ++a)
    for (Eigen::Index field = 0; field < result.cols(); ++field)
      result.block<3, 1>(3 * (system.offset(cell) + a), field) = coefficients.block<1, 3>(a, 3 * field).transpose();
}

// The field's coefficients on `cell` (written into `result`): the L2 projection M c = r,
// M_ab = ∫ φ_a φ_b by the cone rule on the cell, r_a = Σ_parts ∫_part φ_a u_parent by a rule on
// each part, u_parent its parent's polynomial: both integrands polynomials of degree 2k,
// so both integrals are exact (polyhedron_rule), and with the constants among the φ_a
// the projection keeps ∫ u over the cell, the sum of the parts'.
void project_parts(const DgLinearSystem& system, const DgLinearSystem& previous, const Eigen::MatrixXd& fields,
                   int cell, const std::vector<ParentPart>& parts, int strength, Eigen::MatrixXd& result) {
  const Eigen::Index field_count = fields.cols();
  const MonomialBasis& basis = system.basis(cell);
  Eigen::VectorXd phi, parent_phi;
  Eigen::MatrixXd gradients;
  Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(basis.size(), basis.size());
  // The cone rule, exact on any polyhedron (its weights may be negative), as the body's
  // loads and so its momentum are integrated (not cell_rule's positive simplification).
  const PolyhedronRule rule = polyhedron_rule(system.cell(cell), strength);
  for (Eigen::Index q = 0; q < rule.points.rows(); ++q) {
    basis.evaluate(rule.points.row(q).transpose(), phi, gradients);
    mass.noalias() += rule.weights[q] * phi * phi.transpose();
  }
  Eigen::MatrixXd moments = Eigen::MatrixXd::Zero(basis.size(), 3 * field_count);
  Eigen::RowVectorXd value(3 * field_count);
  for (const ParentPart& part : parts) {
    const MonomialBasis& parent = previous.basis(part.parent);
    const PolyhedronRule part_rule = polyhedron_rule(part.piece, strength);
    for (Eigen::Index q = 0; q < part_rule.points.rows(); ++q) {
      const Eigen::Vector3d x = part_rule.points.row(q).transpose();
      basis.evaluate(x, phi, gradients);
      parent.evaluate(x, parent_phi, gradients);
      for (Eigen::Index field = 0; field < field_count; ++field)
        value.segment<3>(3 * field) =
            Eigen::Map<const Eigen::MatrixXd>(fields.col(field).data() + 3 * previous.offset(part.parent), 3,
                                              parent.size()) *
            parent_phi;
      moments.noalias() += part_rule.weights[q] * phi * value;
    }
  }
  write_projection(system, cell, mass, moments, result);
}

}  // namespace

Eigen::MatrixXd transfer_dg_field(const DgLinearSystem& system, const DgLinearSystem& previous,
                                  const ElementBasisEvaluator& previous_basis, const Eigen::MatrixXd& fields,
                                  const std::vector<int>& parent_cells,
                                  const std::vector<std::vector<ParentPart>>& merged_parts) {
  const Eigen::Index field_count = fields.cols();
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(system.dof_count(), field_count);
  // The cells to project, their rules, and all their points for one embedding.
  std::vector<int> projected;
  std::vector<PolyhedronRule> rules;
  Eigen::Index point_count = 0;
  const int strength = 2 * system.basis(0).degree();
  for (int cell = 0; cell < system.cell_count(); ++cell) {
    const int size = 3 * system.basis(cell).size();
    if (same_cell(system, previous, cell)) {
      result.middleRows(3 * system.offset(cell), size) = fields.middleRows(3 * previous.offset(cell), size);
      continue;
    }
    const int parent = parent_cells.empty() ? -1 : parent_cells[cell];
    if (parent >= 0 && system.basis(cell).degree() == previous.basis(parent).degree()) {
      // Coefficient of function a, component i: Σ_b R_ab c_parent(b, i), R = parent_in_child.
      const Eigen::MatrixXd restriction = parent_in_child(previous.basis(parent), system.basis(cell));
      const Eigen::Index parent_size = restriction.cols();
      for (Eigen::Index field = 0; field < field_count; ++field) {
        const Eigen::Map<const Eigen::MatrixXd> coefficients(fields.col(field).data() + 3 * previous.offset(parent), 3,
                                                             parent_size);  // component × function
        Eigen::Map<Eigen::MatrixXd>(result.col(field).data() + 3 * system.offset(cell), 3, restriction.rows()) =
            coefficients * restriction.transpose();
      }
      continue;
    }
    if (!merged_parts.empty() && !merged_parts[cell].empty()) {
      project_parts(system, previous, fields, cell, merged_parts[cell], strength, result);
      continue;
    }
    projected.push_back(cell);
    rules.push_back(system.cell_rule(cell, strength));
    point_count += rules.back().points.rows();
  }
  if (projected.empty()) return result;
  Eigen::MatrixXd points(point_count, 3);
  Eigen::Index row = 0;
  for (const PolyhedronRule& rule : rules) {
    points.middleRows(row, rule.points.rows()) = rule.points;
    row += rule.points.rows();
  }
  // The old fields at every point: #points × 3 per field, side by side.
  const BasisEmbedding embedding(previous_basis, points);
  Eigen::MatrixXd old_values(point_count, 3 * field_count);
  for (Eigen::Index field = 0; field < field_count; ++field)
    old_values.middleCols<3>(3 * field) = embedding.displacement(fields.col(field));
  Eigen::VectorXd phi;
  Eigen::MatrixXd gradients;
  row = 0;
  for (std::size_t i = 0; i < projected.size(); ++i) {
    const int cell = projected[i];
    const MonomialBasis& basis = system.basis(cell);
    const PolyhedronRule& rule = rules[i];
    // M c = r: M_ab = ∫ φ_a φ_b, r_a = ∫ φ_a u_old (a column per component of each field).
    Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(basis.size(), basis.size());
    Eigen::MatrixXd moments = Eigen::MatrixXd::Zero(basis.size(), 3 * field_count);
    for (Eigen::Index q = 0; q < rule.points.rows(); ++q, ++row) {
      basis.evaluate(rule.points.row(q).transpose(), phi, gradients);
      mass.noalias() += rule.weights[q] * phi * phi.transpose();
      moments.noalias() += rule.weights[q] * phi * old_values.row(row);
    }
    write_projection(system, cell, mass, moments, result);
  }
  return result;
}

}  // namespace altfem::dg
