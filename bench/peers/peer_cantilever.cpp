// deal.II peer of altfem's scenes/cantilever.json (issue #39): a 1 x 0.1 x 0.1 m beam,
// E = 1e9, nu = 0.3, rho = 1000 under gravity (0, 0, -9.81), clamped at x = 0, linear
// elasticity with continuous FE_Q(k)^3 on a grid of nx x ny x nz hexahedra, solved by
// UMFPACK or by CG + AMG. Assembly is threaded by MeshWorker::mesh_loop (TBB), limited to
// --threads.
//
//   peer_cantilever --degree 1|2 --cells 20,2,2 --solver direct|amg --threads 1
//
// Prints: dofs, set-up (grid, DOFs, constraints, sparsity), assembly and solve seconds, CG
// iterations, and the z displacement at the centre of the free end (1, 0.05, 0.05).
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/meshworker/copy_data.h>
#include <deal.II/meshworker/mesh_loop.h>
#include <deal.II/meshworker/scratch_data.h>
#include <deal.II/numerics/vector_tools.h>

#include <cstdio>

#include "peer_common.hpp"

namespace {

using namespace dealii;
using namespace peers;

constexpr double youngs_modulus = 1e9, poisson_ratio = 0.3, density = 1000, gravity = -9.81;
constexpr double lambda = youngs_modulus * poisson_ratio / ((1 + poisson_ratio) * (1 - 2 * poisson_ratio));
constexpr double mu = youngs_modulus / (2 * (1 + poisson_ratio));

// K and f of linear elasticity, with the clamp's constraints eliminated while adding in.
template <typename Matrix, typename VectorType>
void assemble(const DoFHandler<3>& dof_handler, const AffineConstraints<double>& constraints, Matrix& stiffness,
              VectorType& load) {
  const FiniteElement<3>& fe = dof_handler.get_fe();
  const QGauss<3> quadrature(fe.degree + 1);
  const FEValuesExtractors::Vector displacement(0);
  const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
  MeshWorker::ScratchData<3> scratch(fe, quadrature, update_gradients | update_values | update_JxW_values);
  MeshWorker::CopyData<1, 1, 1> copy(dofs_per_cell);

  const auto cell_worker = [&](const auto& cell, MeshWorker::ScratchData<3>& data, MeshWorker::CopyData<1, 1, 1>& out) {
    const FEValues<3>& fe_values = data.reinit(cell);
    FullMatrix<double>& matrix = out.matrices[0];
    Vector<double>& vector = out.vectors[0];
    matrix = 0;
    vector = 0;
    // strains and divergences of all shape functions at one point, computed once per point
    // rather than once per pair
    std::vector<SymmetricTensor<2, 3>> strain(dofs_per_cell);
    std::vector<double> divergence(dofs_per_cell);
    for (unsigned int q = 0; q < quadrature.size(); ++q) {
      const double weight = fe_values.JxW(q);
      for (unsigned int i = 0; i < dofs_per_cell; ++i) {
        strain[i] = fe_values[displacement].symmetric_gradient(i, q);
        divergence[i] = fe_values[displacement].divergence(i, q);
      }
      for (unsigned int i = 0; i < dofs_per_cell; ++i) {
        for (unsigned int j = i; j < dofs_per_cell; ++j)
          matrix(i, j) += (2 * mu * (strain[i] * strain[j]) + lambda * divergence[i] * divergence[j]) * weight;
        vector(i) += fe_values[displacement].value(i, q)[2] * density * gravity * weight;
      }
    }
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      for (unsigned int j = 0; j < i; ++j) matrix(i, j) = matrix(j, i);
    cell->get_dof_indices(out.local_dof_indices[0]);
  };
  const auto copier = [&](const MeshWorker::CopyData<1, 1, 1>& in) {
    constraints.distribute_local_to_global(in.matrices[0], in.vectors[0], in.local_dof_indices[0], stiffness, load);
  };
  MeshWorker::mesh_loop(dof_handler.begin_active(), dof_handler.end(), cell_worker, copier, scratch, copy,
                        MeshWorker::assemble_own_cells);
}

}  // namespace

int main(int argc, char** argv) {
  const Options options(argc, argv);
  const unsigned int threads = options.integer("threads", 1);
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, threads);
  MultithreadInfo::set_thread_limit(threads);
  const int degree = options.integer("degree", 1);
  const std::vector<unsigned int> cells = cell_counts(options.text("cells", "20,2,2"));
  const std::string solver = options.text("solver", "direct");

  Stopwatch setup_timer;
  Triangulation<3> triangulation;
  // colorize: the face at x = 0 gets boundary id 0, the others 1 ... 5
  GridGenerator::subdivided_hyper_rectangle(triangulation, cells, Point<3>(0, 0, 0), Point<3>(1, 0.1, 0.1), true);
  const FESystem<3> fe(FE_Q<3>(degree), 3);
  DoFHandler<3> dof_handler(triangulation);
  dof_handler.distribute_dofs(fe);
  AffineConstraints<double> constraints;
  VectorTools::interpolate_boundary_values(dof_handler, 0, Functions::ZeroFunction<3>(3), constraints);
  constraints.close();
  DynamicSparsityPattern pattern(dof_handler.n_dofs());
  DoFTools::make_sparsity_pattern(dof_handler, pattern, constraints, false);
  SparsityPattern sparsity;  // deal.II's own matrix format, for UMFPACK; Trilinos takes the dynamic pattern
  if (solver == "direct") sparsity.copy_from(pattern);
  const double setup_seconds = setup_timer.seconds();

  double assembly_seconds = 0;
  SolveResult result;
  Vector<double> solution(dof_handler.n_dofs());
  if (solver == "direct") {
    Stopwatch timer;
    SparseMatrix<double> stiffness(sparsity);
    Vector<double> load(dof_handler.n_dofs());
    assemble(dof_handler, constraints, stiffness, load);
    assembly_seconds = timer.seconds();
    result = solve_direct(stiffness, load, solution);
  } else if (solver == "amg") {
    Stopwatch timer;
    TrilinosWrappers::SparseMatrix stiffness;
    stiffness.reinit(pattern);
    TrilinosWrappers::MPI::Vector load(complete_index_set(dof_handler.n_dofs()), MPI_COMM_WORLD);
    assemble(dof_handler, constraints, stiffness, load);
    stiffness.compress(VectorOperation::add);
    load.compress(VectorOperation::add);
    assembly_seconds = timer.seconds();
    TrilinosWrappers::MPI::Vector distributed_solution(load);
    result = solve_amg(stiffness, load, distributed_solution, dof_handler, degree > 1);
    solution = distributed_solution;
  } else {
    std::fprintf(stderr, "--solver must be direct or amg\n");
    return 2;
  }
  constraints.distribute(solution);
  Vector<double> tip(3);
  VectorTools::point_value(dof_handler, solution, Point<3>(1, 0.05, 0.05), tip);
  std::printf("dofs=%u setup_s=%.6f assembly_s=%.6f solve_s=%.6f iterations=%u tip_z=%.10e\n", dof_handler.n_dofs(),
              setup_seconds, assembly_seconds, result.seconds, result.iterations, tip[2]);
  return 0;
}
