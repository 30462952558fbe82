#pragma once
// What the two deal.II peer programs share: their command line, a stopwatch, the rigid-body
// modes that AMG needs for elasticity, and the two solvers (UMFPACK; CG + Trilinos ML).
// Both programs print one line of key=value pairs that scripts/bench-peers parses.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <Teuchos_ParameterList.hpp>
#include <algorithm>
#include <array>
#include <chrono>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace peers {

using namespace dealii;

// --key value pairs; every key has a default, so a missing one is not an error.
class Options {
 public:
  Options(int argc, char** argv) {
    for (int i = 1; i + 1 < argc; i += 2) {
      const std::string key = argv[i];
      if (key.rfind("--", 0) != 0) throw std::invalid_argument("expected --key value, got " + key);
      values_[key.substr(2)] = argv[i + 1];
    }
  }
  std::string text(const std::string& key, const std::string& fallback) const {
    const auto found = values_.find(key);
    return found == values_.end() ? fallback : found->second;
  }
  int integer(const std::string& key, int fallback) const { return std::stoi(text(key, std::to_string(fallback))); }

 private:
  std::map<std::string, std::string> values_;
};

// "20,2,2" -> {20, 2, 2}
inline std::vector<unsigned int> cell_counts(const std::string& text) {
  std::vector<unsigned int> counts;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    counts.push_back(std::stoul(text.substr(start, comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (counts.size() != 3) throw std::invalid_argument("--cells wants three counts, e.g. 20,2,2");
  return counts;
}

// Wall-clock seconds since construction.
class Stopwatch {
 public:
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// The six rigid-body modes (three translations, three rotations about the origin) as
// coefficient vectors of `dof_handler`'s space. Every element used here (FE_Q, FE_DGQ, FE_DGP
// of degree >= 1) contains the affine functions, so a cell-wise L2 projection of 1, x, y, z
// reproduces them exactly, also for FE_DGP, which has no support points to interpolate at.
// Projected per scalar component: the system's mass matrix is block diagonal by component.
inline std::vector<std::vector<double>> rigid_body_modes(const DoFHandler<3>& dof_handler, const Quadrature<3>& quadrature) {
  const FiniteElement<3>& fe = dof_handler.get_fe();
  const unsigned int scalar_count = fe.n_dofs_per_cell() / 3;
  FEValues<3> fe_values(fe, quadrature, update_values | update_quadrature_points | update_JxW_values);
  std::vector<std::vector<double>> modes(6, std::vector<double>(dof_handler.n_dofs(), 0.0));
  std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
  // scalar_dof[c][b]: the system DOF of component c whose base function is b
  std::vector<std::array<unsigned int, 3>> system_dof(scalar_count);
  for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i) {
    const auto [component, base] = fe.system_to_component_index(i);
    system_dof[base][component] = i;
  }
  FullMatrix<double> mass(scalar_count, scalar_count), inverse(scalar_count, scalar_count);
  FullMatrix<double> moments(scalar_count, 4), coefficients(scalar_count, 4);  // of 1, x, y, z
  for (const auto& cell : dof_handler.active_cell_iterators()) {
    fe_values.reinit(cell);
    cell->get_dof_indices(dof_indices);
    mass = 0;
    moments = 0;
    for (unsigned int q = 0; q < quadrature.size(); ++q) {
      const Point<3>& x = fe_values.quadrature_point(q);
      const double affine[4] = {1.0, x[0], x[1], x[2]};
      for (unsigned int a = 0; a < scalar_count; ++a) {
        const double value_a = fe_values.shape_value(system_dof[a][0], q) * fe_values.JxW(q);
        for (unsigned int b = 0; b < scalar_count; ++b) mass(a, b) += value_a * fe_values.shape_value(system_dof[b][0], q);
        for (unsigned int f = 0; f < 4; ++f) moments(a, f) += value_a * affine[f];
      }
    }
    inverse.invert(mass);
    inverse.mmult(coefficients, moments);
    for (unsigned int a = 0; a < scalar_count; ++a) {
      const double one = coefficients(a, 0), x = coefficients(a, 1), y = coefficients(a, 2), z = coefficients(a, 3);
      const types::global_dof_index u = dof_indices[system_dof[a][0]], v = dof_indices[system_dof[a][1]],
                                    w = dof_indices[system_dof[a][2]];
      modes[0][u] = one, modes[1][v] = one, modes[2][w] = one;
      modes[3][u] = -y, modes[3][v] = x;  // rotation about z: (-y, x, 0)
      modes[4][v] = -z, modes[4][w] = y;  // about x: (0, -z, y)
      modes[5][u] = z, modes[5][w] = -x;  // about y: (z, 0, -x)
    }
  }
  return modes;
}

struct SolveResult {
  double seconds = 0;
  unsigned int iterations = 0;
};

// Sparse direct: UMFPACK's analysis, factorisation and solve, all timed.
inline SolveResult solve_direct(const SparseMatrix<double>& matrix, const Vector<double>& load, Vector<double>& solution) {
  Stopwatch timer;
  SparseDirectUMFPACK umfpack;
  umfpack.initialize(matrix);
  solution = load;
  umfpack.solve(solution);
  return {timer.seconds(), 0};
}

// CG to a relative residual of 1e-8, preconditioned by one V-cycle of Trilinos ML's smoothed
// aggregation with deal.II's default settings (Chebyshev smoother, 2 sweeps, KLU on the
// coarsest level) and the six rigid-body modes as its near null space (deal.II's
// AdditionalData::constant_modes holds only the translations). The mode projection and the
// AMG set-up are inside the timing.
inline SolveResult solve_amg(const TrilinosWrappers::SparseMatrix& matrix, const TrilinosWrappers::MPI::Vector& load,
                             TrilinosWrappers::MPI::Vector& solution, const DoFHandler<3>& dof_handler, bool higher_order) {
  Stopwatch timer;
  const std::vector<std::vector<double>> modes =
      rigid_body_modes(dof_handler, QGauss<3>(dof_handler.get_fe().degree + 1));
  TrilinosWrappers::PreconditionAMG::AdditionalData settings;
  settings.elliptic = true;
  settings.higher_order_elements = higher_order;
  Teuchos::ParameterList parameters;
  std::unique_ptr<Epetra_MultiVector> unused_translations;
  settings.set_parameters(parameters, unused_translations, matrix);
  // ML reads the null space as 6 columns of n values each, kept alive until initialize() copies them
  const std::size_t n = dof_handler.n_dofs();
  std::vector<double> null_space(6 * n);
  for (std::size_t mode = 0; mode < 6; ++mode) std::copy(modes[mode].begin(), modes[mode].end(), null_space.begin() + mode * n);
  parameters.set("null space: type", "pre-computed");
  parameters.set("null space: dimension", 6);
  parameters.set("null space: vectors", null_space.data());
  TrilinosWrappers::PreconditionAMG amg;
  amg.initialize(matrix, parameters);
  SolverControl control(10000, 1e-8 * load.l2_norm());
  SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
  solution = 0;
  cg.solve(matrix, solution, load, amg);
  return {timer.seconds(), control.last_step()};
}

}  // namespace peers
