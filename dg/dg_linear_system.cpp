#include "dg/dg_linear_system.hpp"

#include <Eigen/QR>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dg/exact_element_matrices.hpp"
#include "dg/strong_conditions.hpp"
#include "shared/geometry/polygon_moments.hpp"
#include "shared/geometry/polyhedron_moments.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"

namespace altfem::dg {

namespace {

// Centre and size of a cell: its centroid and diameter (Kaufmann et al. §5).
MonomialBasis cell_basis(const Polyhedron& cell, int degree) {
  const Eigen::VectorXd first = polyhedron_moments(cell, 1);
  const Eigen::Vector3d centroid = first.segment<3>(1) / first[0];
  double diameter = 0;
  for (Eigen::Index i = 0; i < cell.vertices.rows(); ++i)
    for (Eigen::Index j = i + 1; j < cell.vertices.rows(); ++j)
      diameter = std::max(diameter, (cell.vertices.row(i) - cell.vertices.row(j)).norm());
  return MonomialBasis(degree, centroid, diameter);
}

// area(∂K): the sum of the face polygons' areas.
double surface_area(const Polyhedron& cell) {
  double area = 0;
  Eigen::MatrixXd polygon;
  for (const std::vector<int>& loop : cell.faces) {
    polygon.resize(static_cast<Eigen::Index>(loop.size()), 3);
    for (size_t v = 0; v < loop.size(); ++v) polygon.row(static_cast<Eigen::Index>(v)) = cell.vertices.row(loop[v]);
    area += polygon_area_vector(polygon).norm();
  }
  return area;
}

// Zeros kept: K stores whole element and face blocks, so an element's 3n coefficients
// share one pattern and the direct solver orders elements, not coefficients
// (block_fill_reducing_ordering.hpp).
void add_block(std::vector<Eigen::Triplet<double>>& triplets, const Eigen::MatrixXd& block,
               const std::vector<int>& dofs) {
  for (Eigen::Index i = 0; i < block.rows(); ++i)
    for (Eigen::Index j = 0; j < block.cols(); ++j) triplets.emplace_back(dofs[i], dofs[j], block(i, j));
}

}  // namespace

DgLinearSystem::DgLinearSystem(std::vector<Polyhedron> cells, std::vector<DgFace> faces, const DgSettings& settings,
                               DgCellMaterials cell_materials)
    : cells_(std::move(cells)), faces_(std::move(faces)), settings_(settings), cell_materials_(std::move(cell_materials)) {
  if (cell_materials_.ids.size() != (cell_materials_.materials.empty() ? 0 : cells_.size()))
    throw std::invalid_argument("DgLinearSystem: " + std::to_string(cell_materials_.ids.size()) +
                                " material ids for " + std::to_string(cell_materials_.materials.size()) +
                                " materials and " + std::to_string(cells_.size()) + " cells");
  for (int id : cell_materials_.ids)
    if (id < 0 || id >= static_cast<int>(cell_materials_.materials.size()))
      throw std::invalid_argument("DgLinearSystem: material id " + std::to_string(id) + " of " +
                                  std::to_string(cell_materials_.materials.size()) + " materials");
  offsets_.push_back(0);
  std::vector<std::vector<int>> strong_faces(cells_.size());
  for (size_t f = 0; f < faces_.size(); ++f)
    if (faces_[f].strong && faces_[f].plus < 0 && faces_[f].condition >= 0)
      strong_faces[faces_[f].minus].push_back(static_cast<int>(f));
  std::vector<Eigen::Triplet<double>> triplets;
  for (size_t c = 0; c < cells_.size(); ++c) {
    const Polyhedron& cell = cells_[c];
    const DgMaterial cell_material = material(static_cast<int>(c));
    bases_.push_back(cell_basis(cell, settings.degree));
    if (!strong_faces[c].empty()) {
      // The constrained and free combinations of the monomials as the cell's functions.
      strong_cells_.push_back(strong_cell(static_cast<int>(c), bases_.back(), faces_, strong_faces[c]));
      const StrongCell& strong = strong_cells_.back();
      for (int j = 0; j < strong.constrained; ++j)
        for (int i = 0; i < 3; ++i)
          if (strong.components[i]) constrained_dofs_.push_back(3 * (offsets_.back() + j) + i);
      bases_.back().combine(strong.combination);
    }
    ElementMatrices matrices =
        exact_element_matrices(cell, bases_.back(), cell_material.lambda, cell_material.mu, cell_material.density);
    // ∫ m₀ dV (m₀ = 1); combined functions integrate to Cᵀ ∫ m, and C is orthogonal.
    const Eigen::MatrixXd& combination = bases_.back().combination();
    volumes_.push_back(combination.size() == 0 ? matrices.integrals[0] : combination.row(0).dot(matrices.integrals));
    inverse_lengths_.push_back(surface_area(cell) / (6 * volumes_.back()));
    masses_.push_back(std::move(matrices.mass));
    integrals_.conservativeResize(offsets_.back() + bases_.back().size());
    integrals_.tail(bases_.back().size()) = matrices.integrals;
    std::vector<int> dofs;
    for (int k = 0; k < 3 * bases_.back().size(); ++k) dofs.push_back(3 * offsets_.back() + k);
    add_block(triplets, matrices.stiffness, dofs);
    offsets_.push_back(offsets_.back() + bases_.back().size());
  }
  for (const DgFace& face : faces_) {
    if (face.plus < 0 && (face.condition < 0 || face.strong)) continue;  // free, or held strongly: no face term
    const MonomialBasis* plus = face.plus >= 0 ? &bases_[face.plus] : nullptr;
    const DgMaterial minus_material = material(face.minus);
    const DgMaterial plus_material = face.plus >= 0 ? material(face.plus) : minus_material;
    const Eigen::MatrixXd matrix = exact_face_matrix(
        face.polygon, face.normal, bases_[face.minus], plus, {minus_material.lambda, minus_material.mu},
        {plus_material.lambda, plus_material.mu}, face_penalty(face), settings.flux, face.components);
    std::vector<int> dofs;
    for (int side : {face.minus, face.plus}) {
      if (side < 0) continue;
      for (int k = 0; k < 3 * bases_[side].size(); ++k) dofs.push_back(3 * offsets_[side] + k);
    }
    add_block(triplets, matrix, dofs);
  }
  stiffness_.resize(dof_count(), dof_count());
  stiffness_.setFromTriplets(triplets.begin(), triplets.end());
}

DgLinearSystem::~DgLinearSystem() = default;

Eigen::VectorXd DgLinearSystem::constrained_values(const ConditionData& data) const {
  Eigen::VectorXd values(static_cast<Eigen::Index>(constrained_dofs_.size()));
  Eigen::Index next = 0;
  for (const StrongCell& strong : strong_cells_) {
    const MonomialBasis& basis = bases_[strong.cell];
    const MonomialBasis monomials(basis.degree(), basis.centre(), basis.scale());
    const Eigen::MatrixXd cell_values = dg::constrained_values(strong, monomials, faces_, data);
    // In constrained_dofs_ order: combination j, then component.
    for (int j = 0; j < strong.constrained; ++j)
      for (Eigen::Index row = 0; row < cell_values.rows(); ++row) values[next++] = cell_values(row, j);
  }
  return values;
}

JumpPenalty DgLinearSystem::face_penalty(const DgFace& face) const {
  // Each side's own η over its length: eq. (20)'s vol(K)/area(f), or ℓ(K) (PenaltyScaling).
  const bool by_face = settings_.scaling == PenaltyScaling::face_area;
  const double area = by_face && face.polygon.rows() >= 3 ? polygon_area_vector(face.polygon).norm() : 0.0;
  const double factor = face.plus >= 0 ? 1.0 : settings_.boundary_penalty_factor;
  JumpPenalty penalty{0.0, 0.0};
  for (int side : {face.minus, face.plus}) {
    if (side < 0) continue;
    const DgMaterial side_material = material(side);
    const double eta = factor * side_material.penalty * (by_face ? area / volumes_[side] : inverse_lengths_[side]);
    penalty.normal += eta;
    penalty.tangential += side_material.tangential_fraction * eta;
  }
  return penalty;
}

DgMaterial DgLinearSystem::material(int cell) const {
  if (cell_materials_.materials.empty())
    return {settings_.lambda, settings_.mu, settings_.density, settings_.penalty, settings_.tangential_fraction};
  return cell_materials_.materials[material_id(cell)];
}

Eigen::SparseMatrix<double> DgLinearSystem::mass() const {
  std::vector<Eigen::Triplet<double>> triplets;
  for (size_t c = 0; c < cells_.size(); ++c) {
    const int first = offsets_[c];
    for (Eigen::Index a = 0; a < masses_[c].rows(); ++a)
      for (Eigen::Index b = 0; b < masses_[c].cols(); ++b)
        for (int i = 0; i < 3; ++i)
          triplets.emplace_back(3 * (first + a) + i, 3 * (first + b) + i, masses_[c](a, b));
  }
  Eigen::SparseMatrix<double> matrix(dof_count(), dof_count());
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  return matrix;
}

template <typename Body>
void DgLinearSystem::for_each_cell_point(int strength, Body&& body) const {
  Eigen::VectorXd phi;
  Eigen::MatrixXd unused;
  for (size_t c = 0; c < cells_.size(); ++c) {
    const PolyhedronRule rule = polyhedron_rule(cells_[c], strength);
    for (Eigen::Index q = 0; q < rule.weights.size(); ++q) {
      const Eigen::Vector3d x = rule.points.row(q).transpose();
      bases_[c].evaluate(x, phi, unused);
      body(static_cast<int>(c), x, rule.weights[q], phi);
    }
  }
}

Eigen::VectorXd DgLinearSystem::body_load(const VectorField& force_density) const {
  Eigen::VectorXd load = Eigen::VectorXd::Zero(dof_count());
  for_each_cell_point(2 * settings_.degree + 2, [&](int c, const Eigen::Vector3d& x, double w, const Eigen::VectorXd& phi) {
    const Eigen::Vector3d f = w * force_density(x);
    for (int a = 0; a < bases_[c].size(); ++a) load.segment<3>(3 * (offsets_[c] + a)) += phi[a] * f;
  });
  return load;
}

double DgLinearSystem::l2_error(const Eigen::VectorXd& coefficients, const VectorField& field) const {
  double squared = 0;
  for_each_cell_point(2 * settings_.degree + 4, [&](int c, const Eigen::Vector3d& x, double w, const Eigen::VectorXd& phi) {
    Eigen::Vector3d value = Eigen::Vector3d::Zero();
    for (int a = 0; a < bases_[c].size(); ++a) value += phi[a] * coefficients.segment<3>(3 * (offsets_[c] + a));
    squared += w * (value - field(x)).squaredNorm();
  });
  return std::sqrt(squared);
}

Eigen::VectorXd DgLinearSystem::interpolate(const VectorField& field) const {
  Eigen::VectorXd coefficients(dof_count());
  for (size_t c = 0; c < cells_.size(); ++c) {
    const MonomialBasis& basis = bases_[c];
    // Collocation on a (k+2)³ grid of the frame's [-¼, ¼]³: exact for fields in P_k.
    const int per_axis = basis.degree() + 2;
    const int points = per_axis * per_axis * per_axis;
    Eigen::MatrixXd system(points, basis.size()), values(points, 3);
    Eigen::VectorXd phi;
    Eigen::MatrixXd unused;
    int row = 0;
    for (int i = 0; i < per_axis; ++i)
      for (int j = 0; j < per_axis; ++j)
        for (int k = 0; k < per_axis; ++k, ++row) {
          const Eigen::Vector3d xi = (Eigen::Vector3d(i, j, k) / (per_axis - 1)).array() * 0.5 - 0.25;
          const Eigen::Vector3d x = basis.centre() + basis.scale() * xi;
          basis.evaluate(x, phi, unused);
          system.row(row) = phi.transpose();
          values.row(row) = field(x).transpose();
        }
    const Eigen::MatrixXd solution = system.colPivHouseholderQr().solve(values);  // #functions × 3
    for (int a = 0; a < basis.size(); ++a) coefficients.segment<3>(3 * (offsets_[c] + a)) = solution.row(a).transpose();
  }
  return coefficients;
}

Eigen::VectorXd DgLinearSystem::dirichlet_load(const ConditionData& data, bool penalty_only) const {
  Eigen::VectorXd load = Eigen::VectorXd::Zero(dof_count());
  Eigen::VectorXd phi;
  Eigen::MatrixXd gradients;
  for (const DgFace& face : faces_) {
    if (face.plus >= 0 || face.condition < 0 || face.strong) continue;
    const MonomialBasis& basis = bases_[face.minus];
    const DgMaterial side = material(face.minus);
    const PolyhedronRule rule = polygon_rule(face.polygon, 2 * settings_.degree + 2);
    const Eigen::Vector3d& n = face.normal;
    const Eigen::Matrix3d penalty = face_penalty(face).tensor(n);
    for (Eigen::Index q = 0; q < rule.weights.size(); ++q) {
      const Eigen::Vector3d x = rule.points.row(q).transpose();
      Eigen::Vector3d g = data(face.condition, x);
      for (int i = 0; i < 3; ++i)
        if (!face.components[i]) g[i] = 0;  // P g
      basis.evaluate(x, phi, gradients);
      for (int a = 0; a < basis.size(); ++a) {
        // η_f (T Pg)·φ_a e_i, and for IP −g·σ(φ_a e_i)n with
        // (σ(φ_a e_i)n)_k = μ(δ_ik ∇φ_a·n + n_i ∂_kφ_a) + λ n_k ∂_iφ_a.
        const Eigen::Vector3d grad = gradients.row(a).transpose();
        Eigen::Vector3d entry = phi[a] * (penalty * g);
        for (int i = 0; i < 3; ++i)
          if (!face.components[i]) entry[i] = 0;  // P T P g
        if (settings_.flux == Flux::interior_penalty && !penalty_only)
          entry -= side.mu * (grad.dot(n) * g + g.dot(grad) * n) + side.lambda * g.dot(n) * grad;
        load.segment<3>(3 * (offset(face.minus) + a)) += rule.weights[q] * entry;
      }
    }
  }
  return load;
}

}  // namespace altfem::dg
