#include "fcm/conditioning_experiment.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>

#include "fcm/box_cell_quadrature.hpp"
#include "fcm/intersection_cell_quadrature.hpp"
#include "fcm/fcm_discretization.hpp"
#include "shared/material/material.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/solve/additive_schwarz_preconditioner.hpp"

namespace altfem::fcm {

namespace {

// max |λ| / min |λ| of S^{1/2} A S^{1/2} (similar to SA), S given as its dense matrix.
double condition_number(const Eigen::MatrixXd& A, const Eigen::MatrixXd& S) {
  const Eigen::LLT<Eigen::MatrixXd> cholesky(S);
  const Eigen::MatrixXd L = cholesky.matrixL();
  const Eigen::VectorXd eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(L.transpose() * A * L, Eigen::EigenvaluesOnly).eigenvalues();
  return eigenvalues.cwiseAbs().maxCoeff() / eigenvalues.cwiseAbs().minCoeff();
}

// Preconditioned conjugate gradients on A x = b from x = 0 with the preconditioner
// matrix S (x ↦ S r): iterations to ‖r‖ ≤ 1e-8 ‖b‖. Dense: the experiment is small.
int pcg_iterations(const Eigen::MatrixXd& A, const Eigen::MatrixXd& S) {
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
  const auto material = make_material(MaterialModel::stable_neo_hookean, 2.679e6, 0.25, 1000);
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
    const Eigen::MatrixXd jacobi = dense.diagonal().cwiseAbs().cwiseInverse().asDiagonal();
    const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(free, free);
    const Eigen::MatrixXd schwarz_matrix = 0.5 * (S + S.transpose());
    rows.push_back({std::pow(2.0, -k), condition_number(dense, identity), condition_number(dense, jacobi),
                    condition_number(dense, schwarz_matrix), pcg_iterations(dense, identity),
                    pcg_iterations(dense, jacobi), pcg_iterations(dense, schwarz_matrix)});
  }
  return rows;
}

}  // namespace altfem::fcm
