#include "fcm/conditioning_experiment.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>

#include "fcm/box_cell_quadrature.hpp"
#include "shared/common/eigen_decompositions.hpp"
#include "shared/cut_cells/fcm_discretization.hpp"
#include "shared/cut_cells/intersection_cell_quadrature.hpp"
#include "shared/material/material.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/solve/additive_schwarz_preconditioner.hpp"

namespace altfem::fcm {

namespace {

// max |λ| / min |λ| of the symmetric matrix B = S^{1/2} A S^{1/2} (similar to SA).
double condition_number(const Eigen::MatrixXd& B) {
  const Eigen::VectorXd eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(B, Eigen::EigenvaluesOnly).eigenvalues();
  return eigenvalues.cwiseAbs().maxCoeff() / eigenvalues.cwiseAbs().minCoeff();
}

// Preconditioned conjugate gradients on A x = b from x = 0 with the preconditioner
// matrix S (x ↦ S r): iterations to ‖r‖ ≤ 1e-8 ‖b‖. Sparse or diagonal products: dense
// ones made these 2000-iteration runs most of the experiment's time.
template <typename Preconditioner>
int pcg_iterations(const Eigen::SparseMatrix<double>& A, const Preconditioner& S) {
  const Eigen::VectorXd b = A * Eigen::VectorXd::Ones(A.rows());
  Eigen::VectorXd x = Eigen::VectorXd::Zero(A.rows()), r = b, z = S * r, p = z;
  double rz = r.dot(z);
  const int cap = 2000;
  for (int iteration = 1; iteration <= cap; ++iteration) {
    const Eigen::VectorXd Ap = A * p;
    const double alpha = rz / p.dot(Ap);
    x += alpha * p;
    r -= alpha * Ap;
    if (r.norm() <= 1e-8 * b.norm()) return iteration;
    z = S * r;
    const double next = r.dot(z);
    p = z + (next / rz) * p;
    rz = next;
  }
  return cap;
}

}  // namespace

std::vector<ConditioningRow> conditioning_experiment(ElementType cell, const std::vector<int>& exponents,
                                                     double stabilization, double ghost_penalty) {
  const Eigen::AlignedBox3d domain(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(4.0 / 3.0));
  const VolumeMesh grid = structured_grid(domain, {4, 4, 4}, cell);
  const auto material =
      make_material(MaterialModel::stable_neo_hookean, conditioning_youngs_modulus, conditioning_poisson_ratio, 1000);
  DirichletCondition clamp;
  clamp.region.box = Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-1), Eigen::Vector3d(0, 2, 2));
  clamp.pointer = "/boundary_conditions/0";
  const double dt = 1.0 / 60.0;
  const int degree = element_degree(cell);

  std::vector<ConditioningRow> rows;
  for (int k : exponents) {
    const double epsilon = std::pow(2.0, -k / 3.0);  // smallest fraction ε³ = 2^-k
    const Eigen::AlignedBox3d body(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(1 + epsilon / 3));
    FcmOptions options;
    options.quadrature_strength = 2 * degree;
    options.mass_quadrature_strength = 2 * degree + 2;
    options.discard_fraction = 0;  // "discarding off"
    options.stabilization = stabilization;
    options.ghost_penalty = ghost_penalty;
    // Hexahedra: the exact rules of a box in a box; tetrahedra: intersection rules
    // against the body split into six tetrahedra (§4.5), unsimplified.
    const CellQuadratureSource rules =
        element_shape(cell) == ElementShape::hexahedron
            ? box_cell_quadrature(grid, body)
            : intersection_cell_quadrature(grid, structured_grid(body, {1, 1, 1}, ElementType::tet4), std::nullopt);
    const FcmDiscretization fcm = build_fcm_discretization(grid, rules, *material, {clamp}, options);
    const TabulatedDiscretization& discretization = *fcm.discretization;

    Eigen::VectorXd u(discretization.dof_count());
    for (Eigen::Index node = 0; node < fcm.mesh.nodes.rows(); ++node)
      u.segment<3>(3 * node) = fcm.mesh.nodes(node, 0) * Eigen::Vector3d(1, 1, -1);
    Eigen::SparseMatrix<double> A = discretization.hessian_pattern();
    discretization.hessian(u, A, false);
    A = discretization.mass_matrix() + dt * dt * A;

    // The free DOFs only (u = 0 at X = 0 removes the clamped ones).
    std::vector<int> free_index(static_cast<size_t>(discretization.dof_count()), -1);
    std::vector<bool> constrained(free_index.size(), false);
    for (int dof : discretization.constrained_dofs()) constrained[dof] = true;
    int free = 0;
    for (size_t dof = 0; dof < free_index.size(); ++dof)
      if (!constrained[dof]) free_index[dof] = free++;
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(free, free);
    for (Eigen::Index column = 0; column < A.outerSize(); ++column)
      for (Eigen::SparseMatrix<double>::InnerIterator entry(A, column); entry; ++entry)
        if (free_index[entry.row()] >= 0 && free_index[column] >= 0)
          dense(free_index[entry.row()], free_index[column]) = entry.value();

    // Schwarz blocks of the small cut cells, on the free DOFs.
    std::vector<std::vector<int>> blocks;
    for (size_t c = 0; c < fcm.volume_fractions.size(); ++c) {
      if (fcm.volume_fractions[c] >= options.schwarz_fraction) continue;
      std::vector<int> block;
      for (Eigen::Index a = 0; a < fcm.mesh.cells.cols(); ++a)
        for (int i = 0; i < 3; ++i)
          if (const int index = free_index[3 * fcm.mesh.cells(static_cast<Eigen::Index>(c), a) + i]; index >= 0)
            block.push_back(index);
      blocks.push_back(block);
    }
    AdditiveSchwarzPreconditioner schwarz(blocks, options.schwarz_epsilon);
    schwarz.compute(dense.sparseView());
    Eigen::MatrixXd S(free, free);
    Eigen::VectorXd column;
    for (int j = 0; j < free; ++j) {
      schwarz.apply(Eigen::VectorXd::Unit(free, j), column);
      S.col(j) = column;
    }
    const Eigen::MatrixXd schwarz_matrix = 0.5 * (S + S.transpose());
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(free);
    const Eigen::VectorXd jacobi = dense.diagonal().cwiseAbs().cwiseInverse();
    // S^{1/2} A S^{1/2} as Lᵀ A L with S = L Lᵀ: a scaling for the diagonal preconditioners.
    const Eigen::MatrixXd L = Eigen::LLT<Eigen::MatrixXd>(schwarz_matrix).matrixL();
    const Eigen::MatrixXd AL = dense * L.triangularView<Eigen::Lower>();
    const Eigen::MatrixXd schwarz_scaled = L.transpose().triangularView<Eigen::Upper>() * AL;
    const Eigen::VectorXd jacobi_root = jacobi.cwiseSqrt();
    const Eigen::MatrixXd jacobi_scaled = jacobi_root.asDiagonal() * dense * jacobi_root.asDiagonal();
    const Eigen::SparseMatrix<double> sparse = dense.sparseView(), schwarz_sparse = schwarz_matrix.sparseView();
    rows.push_back({std::pow(2.0, -k), condition_number(dense), condition_number(jacobi_scaled),
                    condition_number(schwarz_scaled), pcg_iterations(sparse, ones.asDiagonal()),
                    pcg_iterations(sparse, jacobi.asDiagonal()), pcg_iterations(sparse, schwarz_sparse)});
  }
  return rows;
}

}  // namespace altfem::fcm
