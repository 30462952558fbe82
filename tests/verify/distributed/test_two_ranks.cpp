// Distributed assembly and solve (issue #37, step 2; docs/scaling.md), run by ctest as
// `mpirun -n 2 verify_distributed`: each rank assembles the elements METIS gave it and the
// faces it owns, the sums make the whole (PETSc sums the Hessian's shares itself), and
// PETSc solves across the ranks. In the same processes, ranks::Alone builds the one-process problem,
// which each method's two-rank energy, forces, Hessian and solution must equal:
//   - the Hessian to 1e-13 of its largest entry (the same entries summed in another order);
//   - the solution of CG + GAMG to 1e-12 within 1e-8 and the same Newton iterations;
//   (GAMG's iterations are compared where a rank holds 10,000 DOFs,
//   test_two_ranks_iterations.cpp: on these small scenes, whose partition boundary holds a
//   large share of the nodes, aggregates that do not cross it part the counts by a fifth
//   and more, e.g. harmonic's warped cantilever at 10 × 2 × 2: 99 against 82).
// fcm on the half-ball has cut cells, and with the ghost penalty its faces on both sides of
// the partition, dg with a nonlinear material its interior faces (each rank tabulating the
// faces it owns), dg's stiffness warping its cells' and faces' blocks. Every method hands
// PETSc shares, whose rows follow the elements' partition.
// Every rank must reach every collective call, so the
// checks are EXPECTs (an ASSERT's early return would leave the other rank waiting).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "dg/definiteness_certificate.hpp"
#include "shared/fem/lagrange_discretization.hpp"
#include "shared/material/material.hpp"
#include "shared/mesh/hexahedral_forest.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/body_force_load.hpp"
#include "shared/simulation/simulation.hpp"
#include "shared/solve/process_ranks.hpp"
#include "tests/support/static_solve.hpp"
#include "tests/unit/dg/hex_grid_cells.hpp"
#include "tests/verify/distributed/two_rank_case.hpp"

namespace altfem {
namespace {

using Case = test::TwoRankCase;
using test::Built;
using test::Solved;

const std::vector<Case>& cases() {
  static const std::vector<Case> all{
      {"fem_hex20", "fem", "scenes/cantilever.json", {}},
      {"fem_tet10",
       "fem",
       "scenes/cantilever.json",
       {"discretization/fem/element=tet10", "discretization/fem/resolution=[10,2,2]"}},
      {"fcm_cut_half_ball",
       "fcm",
       "scenes/manufactured_half_ball.json",
       {"discretization/fcm/resolution=[4,4,2]", "discretization/fcm/cell=hex8"}},
      // The ghost penalty's faces across the partition: each rank tabulates the faces it owns.
      {"fcm_ghost_penalty",
       "fcm",
       "scenes/manufactured_half_ball.json",
       {"discretization/fcm/resolution=[6,6,3]", "discretization/fcm/ghost_penalty=0.1",
        "discretization/fcm/stabilization=0"}},
      // A linear dg integrates its matrices exactly once (DgLinearSystem), each rank its
      // cells and faces; another material is tabulated and divided, faces included.
      {"dg_linear", "dg", "scenes/cantilever.json", {"discretization/dg/resolution=[10,2,2]"}},
      {"dg_neo_hookean",
       "dg",
       "scenes/cantilever.json",
       {"discretization/dg/resolution=[10,2,2]", "material/model=neo_hookean"}},
      // Stiffness warping: each rank rotates the blocks of its cells and of the faces it owns.
      {"dg_warped",
       "dg",
       "scenes/cantilever.json",
       {"discretization/dg/resolution=[10,2,2]", "discretization/dg/warping=true"}},
      {"harmonic", "harmonic", "scenes/cantilever.json", {"discretization/harmonic/convert/resolution=[10,2,2]"}},
      {"harmonic_warped",
       "harmonic",
       "scenes/cantilever.json",
       {"discretization/harmonic/convert/resolution=[10,2,2]", "discretization/harmonic/warping=true"}},
      // Backward Euler with Rayleigh damping and an end turned by a prescribed motion: the
      // mass, the damping and the lifting of the prescribed increments, each from shares.
      {"fem_twisting_damped",
       "fem",
       "scenes/twisting_beam.json",
       {R"(discretization/fem={"element": "hex20", "mesh": "grid", "resolution": [8, 2, 2]})",
        R"(time/rayleigh_damping={"mass": 0.5, "stiffness": 0.002})"}},
  };
  return all;
}

struct Assembled {
  double energy = 0;
  Eigen::VectorXd gradient;
  Eigen::SparseMatrix<double> hessian;
};

// Energy, forces and Hessian at a displacement every rank builds alike (smooth, nonzero).
Assembled assemble(const Discretization& discretization) {
  Eigen::VectorXd u(discretization.dof_count());
  for (Eigen::Index dof = 0; dof < u.size(); ++dof) u[dof] = 1e-4 * std::sin(0.37 * static_cast<double>(dof));
  Assembled result;
  result.energy = discretization.energy(u);
  discretization.gradient(u, result.gradient);
  result.hessian = discretization.hessian_pattern();
  discretization.hessian(u, result.hessian, false);
  return result;
}

class TwoRanks : public ::testing::TestWithParam<Case> {};

TEST_P(TwoRanks, EnergyForcesAndHessianAreTheWholes) {
  EXPECT_EQ(ranks::count(), 2) << "run by mpirun -n 2";
  const Assembled together = assemble(Built(GetParam()).simulation->discretization());
  Assembled alone;
  {
    const ranks::Alone one_process;
    alone = assemble(Built(GetParam()).simulation->discretization());
  }
  EXPECT_NEAR(together.energy, alone.energy, 1e-13 * std::abs(alone.energy));
  EXPECT_LE((together.gradient - alone.gradient).lpNorm<Eigen::Infinity>(),
            1e-13 * alone.gradient.lpNorm<Eigen::Infinity>());
  EXPECT_EQ(together.hessian.nonZeros(), alone.hessian.nonZeros());
  if (together.hessian.nonZeros() == alone.hessian.nonZeros()) {
    const Eigen::Map<const Eigen::VectorXd> two(together.hessian.valuePtr(), together.hessian.nonZeros());
    const Eigen::Map<const Eigen::VectorXd> one(alone.hessian.valuePtr(), alone.hessian.nonZeros());
    EXPECT_LE((two - one).lpNorm<Eigen::Infinity>(), 1e-13 * one.lpNorm<Eigen::Infinity>());
  }
}

// `share`, placed by its rows and columns into `whole`'s pattern and summed over the
// ranks, against `whole`: the largest difference relative to whole's largest entry, or
// infinity when the share holds an entry the whole pattern does not.
double shares_against_whole(const Eigen::SparseMatrix<double>& share, const Eigen::SparseMatrix<double>& whole) {
  Eigen::VectorXd summed = Eigen::VectorXd::Zero(whole.nonZeros());
  double outside = 0;
  for (Eigen::Index column = 0; column < share.outerSize(); ++column)
    for (Eigen::SparseMatrix<double>::InnerIterator entry(share, column); entry; ++entry) {
      const int* first = whole.innerIndexPtr() + whole.outerIndexPtr()[column];
      const int* last = whole.innerIndexPtr() + whole.outerIndexPtr()[column + 1];
      const int* found = std::lower_bound(first, last, static_cast<int>(entry.row()));
      if (found == last || *found != entry.row()) outside = 1;
      else summed[found - whole.innerIndexPtr()] += entry.value();
    }
  ranks::sum(std::span<double>(summed.data(), static_cast<size_t>(summed.size())));
  if (ranks::sum(outside) > 0) return std::numeric_limits<double>::infinity();
  const Eigen::Map<const Eigen::VectorXd> one(whole.valuePtr(), whole.nonZeros());
  return (summed - one).lpNorm<Eigen::Infinity>() / one.lpNorm<Eigen::Infinity>();
}

// Each rank's share of the Hessian and of the mass on its own pattern (a solver that sums
// them, PETSc, asked for): the shares, placed by their rows and columns into one process's
// pattern and summed over the ranks, are one process's matrices; each share holds fewer
// entries than the whole, and every rank's rows have an owner.
TEST_P(TwoRanks, HessianSharesSumToTheWhole) {
  const std::vector<std::string> petsc{"solver/linear=petsc"};
  const Built together(GetParam(), petsc);
  const Discretization& shared = together.simulation->discretization();
  EXPECT_FALSE(shared.matrix_share_owners().empty());
  if (shared.matrix_share_owners().empty()) return;
  const Assembled share = assemble(shared);
  Eigen::SparseMatrix<double> share_mass = shared.hessian_pattern();
  shared.add_mass(1.0, share_mass);
  Assembled alone;
  Eigen::SparseMatrix<double> whole_mass;
  {
    const ranks::Alone one_process;
    const Built built(GetParam(), petsc);
    alone = assemble(built.simulation->discretization());
    whole_mass = built.simulation->discretization().hessian_pattern();
    built.simulation->discretization().add_mass(1.0, whole_mass);
  }
  EXPECT_LT(share.hessian.nonZeros(), alone.hessian.nonZeros());
  EXPECT_EQ(static_cast<Eigen::Index>(3 * shared.matrix_share_owners().size()), alone.hessian.rows());
  EXPECT_LE(shares_against_whole(share.hessian, alone.hessian), 1e-13);
  EXPECT_LE(shares_against_whole(share_mass, whole_mass), 1e-13);
}

// What a method computes from its tabulation for every element or the whole body, at a
// displacement every rank builds alike: the elements' stresses (the frames' cell data, what
// refinement marks by), the volume and the load of a uniform body force.
struct FromTabulation {
  Eigen::MatrixXd stresses;
  double volume = 0;
  Eigen::VectorXd body_force;
};

FromTabulation from_tabulation(const Built& built) {
  const Discretization& discretization = built.simulation->discretization();
  Eigen::VectorXd u(discretization.dof_count());
  for (Eigen::Index dof = 0; dof < u.size(); ++dof) u[dof] = 1e-4 * std::sin(0.37 * static_cast<double>(dof));
  FromTabulation result{discretization.element_cauchy_stress(u), built.simulation->method().volume().value_or(0), {}};
  if (const std::optional<FieldQuadrature> quadrature = built.simulation->method().field_quadrature(0))
    result.body_force = integrate_against_basis(
        *quadrature, Eigen::MatrixXd::Constant(quadrature->points.rows(), 3, 9.81), discretization.dof_count());
  return result;
}

// Each rank holds the quadrature points of its own elements only (dg's linear system
// tabulates nothing): with PETSc summing the matrices' shares, fem and fcm tabulate only
// their own (ElementTabulator), the others tabulate every element and keep their own
// (TabulatedElements::keep_only), as every method does with another solver. The points
// the ranks hold sum to the whole tabulation, each holding fewer, and what is computed from
// the tabulation for every element or the whole body is one process's, the sums of the
// ranks' parts.
void expect_whole_from_shares(const Case& c, const std::vector<std::string>& settings) {
  const Built together(c, settings);
  if (const std::optional<FieldQuadrature> quadrature = together.simulation->method().field_quadrature(0);
      quadrature && quadrature->elements->is_share()) {
    const auto held = static_cast<double>(quadrature->elements->point_count());
    const auto whole = static_cast<double>(quadrature->elements->whole_point_count());
    EXPECT_LT(held, whole);
    EXPECT_EQ(ranks::sum(held), whole);
  }
  const FromTabulation two = from_tabulation(together);
  FromTabulation one;
  {
    const ranks::Alone one_process;
    one = from_tabulation(Built(c, settings));
  }
  EXPECT_EQ(two.stresses.rows(), one.stresses.rows());
  if (two.stresses.rows() == one.stresses.rows()) {
    EXPECT_LE((two.stresses - one.stresses).lpNorm<Eigen::Infinity>(), 1e-13 * one.stresses.lpNorm<Eigen::Infinity>());
  }
  EXPECT_NEAR(two.volume, one.volume, 1e-13 * one.volume);
  EXPECT_EQ(two.body_force.size(), one.body_force.size());
  if (two.body_force.size() == one.body_force.size()) {
    EXPECT_LE((two.body_force - one.body_force).lpNorm<Eigen::Infinity>(),
              1e-13 * one.body_force.lpNorm<Eigen::Infinity>());
  }
}

TEST_P(TwoRanks, EachRankHoldsItsElementsPointsAndComputesTheWholes) {
  expect_whole_from_shares(GetParam(), {});
  expect_whole_from_shares(GetParam(), {"solver/linear=petsc"});
}

// harmonic on a sliced half-ball: the cut cells have MFS bases, whose rules a rank makes
// for every cell (their point counts divide the cells) and tabulates for its own only.
TEST(TwoRanksHarmonic, SlicedCellsTabulatedPerRankGiveTheWholes) {
  expect_whole_from_shares({"harmonic_sliced",
                            "harmonic",
                            "scenes/manufactured_half_ball.json",
                            {R"(discretization/harmonic={"mesh": "slice", "slice": {"resolution": 4}})"}},
                           {"solver/linear=petsc"});
}

// fem on a Hex20 grid with a refined cell, its hanging nodes' functions handed to their
// masters (make_lagrange_discretization with constraints), each rank tabulating its own
// cells for PETSc's shares: the energy and forces summed and the Hessian's shares, placed
// into one process's pattern, are one process's, as are M v and the lumped mass.
TEST(TwoRanksHangingNodes, EachRankTabulatesItsCellsOfARefinedGrid) {
  const HexahedralForest forest = refine_forest(
      grid_forest({Eigen::Vector3d::Zero(), Eigen::Vector3d(4, 1, 1)}, Eigen::Vector3i(4, 2, 2), ElementType::hex20),
      {5});
  const ConstrainedHexahedralMesh refined = forest_mesh(forest);
  EXPECT_GT(refined.constraints.hanging_nodes(), 0);
  const auto material = make_material(MaterialModel::neo_hookean, 1e6, 0.3, 1000);
  const auto build = [&] {
    return make_lagrange_discretization(refined.mesh, {material.get()}, {}, {}, 4, "test", &refined.constraints);
  };
  const bool shared_before = ranks::shares_matrices();
  ranks::share_matrices(true);
  const auto together = build();
  ranks::share_matrices(shared_before);
  const TabulatedElements& share = together->elements();
  EXPECT_TRUE(share.is_share());
  EXPECT_LT(share.point_count(), share.whole_point_count());
  EXPECT_EQ(ranks::sum(static_cast<double>(share.point_count())), static_cast<double>(share.whole_point_count()));
  const Assembled two = assemble(*together);
  Eigen::VectorXd v(together->dof_count());
  for (Eigen::Index dof = 0; dof < v.size(); ++dof) v[dof] = std::cos(0.11 * static_cast<double>(dof));
  const Eigen::VectorXd two_mass_times = together->mass_times(v);
  const Eigen::VectorXd two_lumped = together->explicit_mass().multiply(v);
  Assembled one;
  Eigen::VectorXd one_mass_times, one_lumped;
  {
    const ranks::Alone one_process;
    const auto alone = build();
    one = assemble(*alone);
    one_mass_times = alone->mass_times(v);
    one_lumped = alone->explicit_mass().multiply(v);
  }
  EXPECT_NEAR(two.energy, one.energy, 1e-13 * std::abs(one.energy));
  EXPECT_LE((two.gradient - one.gradient).lpNorm<Eigen::Infinity>(), 1e-13 * one.gradient.lpNorm<Eigen::Infinity>());
  EXPECT_LE(shares_against_whole(two.hessian, one.hessian), 1e-13);
  EXPECT_LE((two_mass_times - one_mass_times).lpNorm<Eigen::Infinity>(),
            1e-13 * one_mass_times.lpNorm<Eigen::Infinity>());
  EXPECT_LE((two_lumped - one_lumped).lpNorm<Eigen::Infinity>(), 1e-13 * one_lumped.lpNorm<Eigen::Infinity>());
}

Solved solve(const Case& c) { return test::solve_first_step(c, "1e-12"); }

TEST_P(TwoRanks, PetscSolutionIsTheOneProcessSolution) {
  const Solved together = solve(GetParam());
  Solved alone;
  {
    const ranks::Alone one_process;
    alone = solve(GetParam());
  }
  EXPECT_LE((together.displacement - alone.displacement).norm(), 1e-8 * alone.displacement.norm());
  EXPECT_EQ(together.newton_iterations, alone.newton_iterations);
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, TwoRanks, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return info.param.name; });

// dg's exact linear system (its default path): each rank integrates the cells METIS gave
// it and the faces it owns, every cell and face a class of its own here, and K, the mass
// and the definiteness certificate are one process's; left each rank's share (for PETSc),
// K sums to one process's with fewer entries on each rank.
TEST(TwoRanksDg, EachRankIntegratesItsCellsAndKIsTheWhole) {
  const test::GridCells grid = test::hex_grid_cells(4);
  dg::DgSettings settings{2, dg::Flux::interior_penalty, 30, 2.0, 1.5};
  settings.reuse_similar_cells = false;
  dg::DgSettings sharing = settings;
  sharing.share_stiffness = true;
  const dg::DgLinearSystem share(grid.cells, grid.faces, sharing);
  const dg::DgLinearSystem together(grid.cells, grid.faces, settings);
  int owned = 0;
  for (int cell = 0; cell < together.cell_count(); ++cell) owned += together.owns_cell(cell);
  EXPECT_GT(owned, 0);
  EXPECT_LT(owned, together.cell_count());
  EXPECT_EQ(static_cast<int>(ranks::sum(owned)), together.cell_count());
  const dg::DefinitenessCertificate certificate = dg::certify_definiteness(together);
  Eigen::SparseMatrix<double> whole_stiffness;
  {
    const ranks::Alone one_process;
    whole_stiffness = dg::DgLinearSystem(grid.cells, grid.faces, settings).stiffness();
  }
  EXPECT_LT(share.stiffness().nonZeros(), whole_stiffness.nonZeros());
  EXPECT_LE(shares_against_whole(share.stiffness(), whole_stiffness), 1e-13);
  EXPECT_EQ(share.share_row_owners().size(), static_cast<size_t>(whole_stiffness.rows() / 3));
  const ranks::Alone one_process;
  const dg::DgLinearSystem alone(grid.cells, grid.faces, settings);
  for (const auto& [two, one] : {std::pair{together.stiffness(), alone.stiffness()}, {together.mass(), alone.mass()}}) {
    EXPECT_EQ(two.nonZeros(), one.nonZeros());
    if (two.nonZeros() != one.nonZeros()) continue;
    const Eigen::Map<const Eigen::VectorXd> two_values(two.valuePtr(), two.nonZeros());
    const Eigen::Map<const Eigen::VectorXd> one_values(one.valuePtr(), one.nonZeros());
    EXPECT_LE((two_values - one_values).lpNorm<Eigen::Infinity>(), 1e-13 * one_values.lpNorm<Eigen::Infinity>());
  }
  EXPECT_LE((together.function_integrals() - alone.function_integrals()).lpNorm<Eigen::Infinity>(), 1e-15);
  const dg::DefinitenessCertificate whole = dg::certify_definiteness(alone);
  EXPECT_EQ(certificate.cells_checked, whole.cells_checked);
  EXPECT_NEAR(certificate.largest_ratio, whole.largest_ratio, 1e-12 * whole.largest_ratio);
}

}  // namespace
}  // namespace altfem

// MPI starts before the tests and stops at exit; rank 0 prints, and the run fails when
// a test failed on any rank.
int main(int argc, char** argv) {
  altfem::ranks::start();
  ::testing::InitGoogleTest(&argc, argv);
  if (altfem::ranks::index() != 0) {
    ::testing::TestEventListeners& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const int failed = RUN_ALL_TESTS();
  return altfem::ranks::sum(static_cast<double>(failed)) != 0 ? 1 : 0;
}
