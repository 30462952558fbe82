// The per-Newton-iteration work of DG stiffness warping (Kaufmann et al. 2009 §6,
// issue #18): the warped internal force and the rotated tangent Σ R_S K_S R_Sᵀ + K_3 of
// a 10 × 10 × 10 hexahedral grid with k = 2 (30,000 DOFs) in a rigidly rotated and
// slightly stretched state, on 1 and 2 threads (the argument). Medians with
//   bench_dg_warping --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <omp.h>

#include <Eigen/Geometry>

#include "dg/polyhedral_mesh_faces.hpp"
#include "dg/warped_dg_discretization.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/structured_grid.hpp"

namespace {

using namespace altfem;

struct WarpedGrid {
  std::unique_ptr<dg::WarpedDgDiscretization> discretization;
  Eigen::VectorXd displacement;
};

// The grid clamped weakly at x = 0, E = 1, ν = 0.3, and the coefficients of
// u(x) = (1.05 R − I) x with R a 0.7 rad rotation.
const WarpedGrid& warped_grid() {
  static const WarpedGrid grid = [] {
    const VolumeMesh volume = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()),
                                              {10, 10, 10}, ElementType::hex8);
    const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(volume);
    std::vector<dg::DgFace> faces = dg::mesh_faces(mesh);
    for (dg::DgFace& face : faces)
      if (face.plus < 0 && face.normal.x() < -0.5) face.condition = 0;
    const dg::DgSettings settings{2, dg::Flux::interior_penalty, 20, 0.3 / (1.3 * 0.4), 1 / 2.6};
    const dg::DgLinearSystem system(dg::mesh_cells(mesh), faces, settings);
    std::vector<std::vector<int>> element_dofs(system.cell_count());
    for (int cell = 0; cell < system.cell_count(); ++cell)
      for (int dof = 3 * system.offset(cell); dof < 3 * system.offset(cell + 1); ++dof)
        element_dofs[cell].push_back(dof);
    WarpedGrid result;
    result.discretization = std::make_unique<dg::WarpedDgDiscretization>(
        system, settings, system.function_integrals(), std::move(element_dofs),
        [&](double) { return Eigen::VectorXd::Zero(system.dof_count()).eval(); });
    const Eigen::Matrix3d map =
        1.05 * Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix() -
        Eigen::Matrix3d::Identity();
    result.displacement = system.interpolate([&](const Eigen::Vector3d& x) { return (map * x).eval(); });
    return result;
  }();
  return grid;
}

void BM_WarpedGradient(benchmark::State& state) {
  const WarpedGrid& grid = warped_grid();  // built with every thread's scratch
  omp_set_num_threads(static_cast<int>(state.range(0)));
  Eigen::VectorXd gradient;
  for (auto _ : state) {
    grid.discretization->gradient(grid.displacement, gradient);
    benchmark::DoNotOptimize(gradient.data());
  }
}
BENCHMARK(BM_WarpedGradient)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_WarpedTangent(benchmark::State& state) {
  const WarpedGrid& grid = warped_grid();  // built with every thread's scratch
  omp_set_num_threads(static_cast<int>(state.range(0)));
  Eigen::SparseMatrix<double> hessian;
  for (auto _ : state) {
    grid.discretization->hessian(grid.displacement, hessian, false);
    benchmark::DoNotOptimize(hessian.valuePtr());
  }
}
BENCHMARK(BM_WarpedTangent)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
