// The loads, interpolation and errors of a DgLinearSystem: rules on its cells and faces
// (dg/dg_linear_system.hpp); the matrices are integrated in dg_linear_system.cpp.
#include <cmath>
#include <map>

#include "dg/dg_linear_system.hpp"

#include "dg/strong_conditions.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"

namespace altfem::dg {

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

PolyhedronRule DgLinearSystem::cell_rule(int cell, int strength) const {
  return simplified_polyhedron_rule(cells_[cell], strength, settings_.rule_simplification);
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
  for_each_cell_point(2 * settings_.degree + 2,
                      [&](int c, const Eigen::Vector3d& x, double w, const Eigen::VectorXd& phi) {
                        const Eigen::Vector3d f = w * force_density(x);
                        for (int a = 0; a < bases_[c].size(); ++a) load.segment<3>(3 * (offsets_[c] + a)) += phi[a] * f;
                      });
  return load;
}

double DgLinearSystem::l2_error(const Eigen::VectorXd& coefficients, const VectorField& field) const {
  double squared = 0;
  for_each_cell_point(2 * settings_.degree + 4,
                      [&](int c, const Eigen::Vector3d& x, double w, const Eigen::VectorXd& phi) {
                        Eigen::Vector3d value = Eigen::Vector3d::Zero();
                        for (int a = 0; a < bases_[c].size(); ++a)
                          value += phi[a] * coefficients.segment<3>(3 * (offsets_[c] + a));
                        squared += w * (value - field(x)).squaredNorm();
                      });
  return std::sqrt(squared);
}

Eigen::VectorXd DgLinearSystem::interpolate(const VectorField& field) const {
  Eigen::VectorXd coefficients(dof_count());
  // Collocation on a (k+2)³ grid of the frame's [-¼, ¼]³: exact for fields in P_k. In its
  // frame a cell's monomials are those of every cell of its degree, so their collocation
  // matrix is factorised once per degree (a recombined cell's, strong conditions, its own):
  // an event measures the body in the new basis by this, and a QR per cell was most of it.
  std::map<int, Eigen::ColPivHouseholderQR<Eigen::MatrixXd>> monomials_by_degree;
  Eigen::VectorXd phi;
  Eigen::MatrixXd unused;
  for (size_t c = 0; c < cells_.size(); ++c) {
    const MonomialBasis& basis = bases_[c];
    const int per_axis = basis.degree() + 2;
    const int points = per_axis * per_axis * per_axis;
    const auto grid_point = [&](int row) {
      const Eigen::Vector3d ijk(row / (per_axis * per_axis), row / per_axis % per_axis, row % per_axis);
      const Eigen::Vector3d xi = (ijk / (per_axis - 1)).array() * 0.5 - 0.25;
      return (basis.centre() + basis.scale() * xi).eval();
    };
    const auto collocation = [&] {
      Eigen::MatrixXd system(points, basis.size());
      for (int row = 0; row < points; ++row) {
        basis.evaluate(grid_point(row), phi, unused);
        system.row(row) = phi.transpose();
      }
      return system.colPivHouseholderQr();
    };
    Eigen::MatrixXd values(points, 3);
    for (int row = 0; row < points; ++row) values.row(row) = field(grid_point(row)).transpose();
    Eigen::MatrixXd solution;  // #functions × 3
    if (basis.combination().size() > 0) {
      solution = collocation().solve(values);
    } else {
      auto factor = monomials_by_degree.find(basis.degree());
      if (factor == monomials_by_degree.end())
        factor = monomials_by_degree.emplace(basis.degree(), collocation()).first;
      solution = factor->second.solve(values);
    }
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
