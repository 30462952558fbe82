// deal.II peer of bench/dg_table1_benchmark.cpp (Kaufmann et al. 2009 Table 1, issue #39):
// the unit cube as n x n x n hexahedra, clamped weakly at x = 0, body force (0, 0, -1),
// linear elasticity E = 1, nu = 0.3, symmetric interior penalty discretised by
//   FE_DGQ(k)^3 (tensor-product Q_k: (k+1)^3 functions per component and cell), or
//   FE_DGP(k)^3 (complete P_k, altfem's dg space: (k+1)(k+2)(k+3)/6 per component and cell).
// The bilinear form is altfem's (dg/dg_linear_system.hpp with its bench's settings):
//   sum_K int sigma(u):eps(v) - sum_f int ({sigma(u)} n . [v] + {sigma(v)} n . [u]) + sum_f eta_f int [u].[v]
// over interior faces and the clamped faces (where {.} is the cell's trace and [u] = u), with
// eta_f = eta (1/l(K-) + 1/l(K+)) inside and eta / l(K) on the clamp, eta = 20 E and
// l(K) = 6 vol(K) / area(dK) (the edge of a cube). Cells and faces are assembled by
// MeshWorker::mesh_loop (TBB threads up to --threads).
//
//   peer_sipg --space dgq|dgp --degree 1|2 --cells 10 --solver direct|amg --threads 1
//
// Prints: dofs, set-up, assembly and solve seconds, CG iterations, the compliance f . u and
// the z displacement at (1, 0.55, 0.55), inside a cell of the free end's face.
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_dgp.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_interface_values.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/meshworker/mesh_loop.h>
#include <deal.II/meshworker/scratch_data.h>
#include <deal.II/numerics/vector_tools.h>

#include <cstdio>
#include <memory>

#include "peer_common.hpp"

namespace {

using namespace dealii;
using namespace peers;

constexpr double youngs_modulus = 1, poisson_ratio = 0.3, penalty = 20 * youngs_modulus;
constexpr double lambda = youngs_modulus * poisson_ratio / ((1 + poisson_ratio) * (1 - 2 * poisson_ratio));
constexpr double mu = youngs_modulus / (2 * (1 + poisson_ratio));
constexpr types::boundary_id clamp = 0;  // the face x = 0 after colorize

Tensor<1, 3> traction(const Tensor<2, 3>& gradient, const Tensor<1, 3>& normal) {
  return lambda * trace(gradient) * normal + mu * (gradient * normal + transpose(gradient) * normal);
}

// l(K) = 6 vol(K) / area(dK): the penalty's length, as altfem's PenaltyScaling::cell_surface.
template <typename CellIterator>
double penalty_length(const CellIterator& cell) {
  double area = 0;
  for (const unsigned int face : cell->face_indices()) area += cell->face(face)->measure();
  return 6 * cell->measure() / area;
}

struct FaceCopy {
  FullMatrix<double> matrix;
  std::vector<types::global_dof_index> indices;
};

struct CopyData {
  FullMatrix<double> matrix;
  Vector<double> load;
  std::vector<types::global_dof_index> indices;
  std::vector<FaceCopy> faces;
};

template <typename Matrix, typename VectorType>
void assemble(const DoFHandler<3>& dof_handler, Matrix& stiffness, VectorType& load) {
  const FiniteElement<3>& fe = dof_handler.get_fe();
  const QGauss<3> quadrature(fe.degree + 1);
  const QGauss<2> face_quadrature(fe.degree + 1);
  const FEValuesExtractors::Vector displacement(0);
  const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
  const AffineConstraints<double> no_constraints;  // the clamp is weak
  MeshWorker::ScratchData<3> scratch(fe, quadrature, update_values | update_gradients | update_JxW_values,
                                     face_quadrature,
                                     update_values | update_gradients | update_normal_vectors | update_JxW_values);
  CopyData copy;

  const auto cell_worker = [&](const auto& cell, MeshWorker::ScratchData<3>& data, CopyData& out) {
    const FEValues<3>& fe_values = data.reinit(cell);
    out.matrix.reinit(dofs_per_cell, dofs_per_cell);
    out.load.reinit(dofs_per_cell);
    out.indices.resize(dofs_per_cell);
    cell->get_dof_indices(out.indices);
    out.faces.clear();
    // strains and divergences of all shape functions at one point, once per point, not per pair
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
          out.matrix(i, j) += (2 * mu * (strain[i] * strain[j]) + lambda * divergence[i] * divergence[j]) * weight;
        out.load(i) -= fe_values[displacement].value(i, q)[2] * weight;
      }
    }
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      for (unsigned int j = 0; j < i; ++j) out.matrix(i, j) = out.matrix(j, i);
  };

  // Nitsche's terms of the clamp u = 0, into the cell's own matrix.
  const auto boundary_worker = [&](const auto& cell, unsigned int face, MeshWorker::ScratchData<3>& data,
                                   CopyData& out) {
    if (cell->face(face)->boundary_id() != clamp) return;  // the other faces are free
    const FEValuesBase<3>& fe_face = data.reinit(cell, face);
    const double eta = penalty / penalty_length(cell);
    std::vector<Tensor<1, 3>> value(dofs_per_cell), stress_normal(dofs_per_cell);
    for (unsigned int q = 0; q < face_quadrature.size(); ++q) {
      const Tensor<1, 3>& normal = fe_face.normal_vector(q);
      for (unsigned int i = 0; i < dofs_per_cell; ++i) {
        value[i] = fe_face[displacement].value(i, q);
        stress_normal[i] = traction(fe_face[displacement].gradient(i, q), normal);
      }
      const double weight = fe_face.JxW(q);
      for (unsigned int i = 0; i < dofs_per_cell; ++i)
        for (unsigned int j = 0; j < dofs_per_cell; ++j)
          out.matrix(i, j) += (-stress_normal[j] * value[i] - stress_normal[i] * value[j] + eta * value[i] * value[j]) *
                              weight;
    }
  };

  const auto face_worker = [&](const auto& cell, unsigned int face, unsigned int subface, const auto& neighbour,
                               unsigned int neighbour_face, unsigned int neighbour_subface,
                               MeshWorker::ScratchData<3>& data, CopyData& out) {
    const FEInterfaceValues<3>& interface =
        data.reinit(cell, face, subface, neighbour, neighbour_face, neighbour_subface);
    FaceCopy& face_copy = out.faces.emplace_back();
    face_copy.indices = interface.get_interface_dof_indices();
    const unsigned int count = interface.n_current_interface_dofs();
    face_copy.matrix.reinit(count, count);
    const double eta = penalty * (1 / penalty_length(cell) + 1 / penalty_length(neighbour));
    const std::vector<Tensor<1, 3>>& normals = interface.get_normal_vectors();
    std::vector<Tensor<1, 3>> jump(count), average_traction(count);
    for (unsigned int q = 0; q < face_quadrature.size(); ++q) {
      for (unsigned int i = 0; i < count; ++i) {
        jump[i] = interface[displacement].jump_in_values(i, q);
        average_traction[i] = traction(interface[displacement].average_of_gradients(i, q), normals[q]);
      }
      const double weight = interface.JxW(q);
      for (unsigned int i = 0; i < count; ++i)
        for (unsigned int j = 0; j < count; ++j)
          face_copy.matrix(i, j) +=
              (-average_traction[j] * jump[i] - average_traction[i] * jump[j] + eta * jump[i] * jump[j]) * weight;
    }
  };

  const auto copier = [&](const CopyData& in) {
    no_constraints.distribute_local_to_global(in.matrix, in.load, in.indices, stiffness, load);
    for (const FaceCopy& face : in.faces)
      no_constraints.distribute_local_to_global(face.matrix, face.indices, stiffness);
  };
  MeshWorker::mesh_loop(dof_handler.begin_active(), dof_handler.end(), cell_worker, copier, scratch, copy,
                        MeshWorker::assemble_own_cells | MeshWorker::assemble_boundary_faces |
                            MeshWorker::assemble_own_interior_faces_once,
                        boundary_worker, face_worker);
}

}  // namespace

int main(int argc, char** argv) {
  const Options options(argc, argv);
  const unsigned int threads = options.integer("threads", 1);
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, threads);
  MultithreadInfo::set_thread_limit(threads);
  const int degree = options.integer("degree", 1);
  const unsigned int cells = options.integer("cells", 10);
  const std::string space = options.text("space", "dgp"), solver = options.text("solver", "direct");
  if ((space != "dgq" && space != "dgp") || (solver != "direct" && solver != "amg")) {
    std::fprintf(stderr, "--space must be dgq or dgp, --solver direct or amg\n");
    return 2;
  }

  Stopwatch setup_timer;
  Triangulation<3> triangulation;
  GridGenerator::subdivided_hyper_cube(triangulation, cells, 0, 1, true);
  const std::unique_ptr<FiniteElement<3>> scalar =
      space == "dgq" ? std::unique_ptr<FiniteElement<3>>(std::make_unique<FE_DGQ<3>>(degree))
                     : std::unique_ptr<FiniteElement<3>>(std::make_unique<FE_DGP<3>>(degree));
  const FESystem<3> fe(*scalar, 3);
  DoFHandler<3> dof_handler(triangulation);
  dof_handler.distribute_dofs(fe);
  DynamicSparsityPattern pattern(dof_handler.n_dofs());
  DoFTools::make_flux_sparsity_pattern(dof_handler, pattern);
  SparsityPattern sparsity;  // deal.II's own matrix format, for UMFPACK; Trilinos takes the dynamic pattern
  if (solver == "direct") sparsity.copy_from(pattern);
  const double setup_seconds = setup_timer.seconds();

  double assembly_seconds = 0, compliance = 0;
  SolveResult result;
  Vector<double> solution(dof_handler.n_dofs());
  if (solver == "direct") {
    Stopwatch timer;
    SparseMatrix<double> stiffness(sparsity);
    Vector<double> load(dof_handler.n_dofs());
    assemble(dof_handler, stiffness, load);
    assembly_seconds = timer.seconds();
    result = solve_direct(stiffness, load, solution);
    compliance = load * solution;
  } else {
    Stopwatch timer;
    TrilinosWrappers::SparseMatrix stiffness;
    stiffness.reinit(pattern);
    TrilinosWrappers::MPI::Vector load(complete_index_set(dof_handler.n_dofs()), MPI_COMM_WORLD);
    assemble(dof_handler, stiffness, load);
    stiffness.compress(VectorOperation::add);
    load.compress(VectorOperation::add);
    assembly_seconds = timer.seconds();
    TrilinosWrappers::MPI::Vector distributed_solution(load);
    result = solve_amg(stiffness, load, distributed_solution, dof_handler, degree > 1);
    compliance = load * distributed_solution;
    solution = distributed_solution;
  }
  Vector<double> tip(3);
  VectorTools::point_value(dof_handler, solution, Point<3>(1, 0.55, 0.55), tip);
  std::printf("dofs=%u setup_s=%.6f assembly_s=%.6f solve_s=%.6f iterations=%u compliance=%.10e tip_z=%.10e\n",
              dof_handler.n_dofs(), setup_seconds, assembly_seconds, result.seconds, result.iterations, compliance,
              tip[2]);
  return 0;
}
