// MFEM example 17 as a peer (scenes/mfem_ex17_beam.json): the 8 × 1 × 1 beam of
// beam-hex.mesh, λ = μ = 50 for x < 4 and λ = μ = 1 for x > 4, u = (0, 0, −0.2x) imposed
// weakly on both end faces, symmetric interior penalty with MFEM's κ = (k+1)². dg of
// degree 1 and 2 on hexahedral grids 8×1×1 → 32×4×4 (→ 64×8×8 for k = 1) against fem Hex20
// on a 64×8×8 grid: the vertical displacement at the centre of the mid-span section
// (4, ½, ½) and the elastic energy ½ ∫ σ:ε dV (element by element, each element's own field
// for dg) converge, and the finest dg runs agree with the reference to 1% (k = 1's energy
// only on 160×20×20: MfemExample17FullSize, left out of ctest). Prints the table.
//
// k = 1's energy is coarser, not wrong: its error against the reference falls 11.0% → 3.81%
// → 1.11% → 0.76% from 32×4×4 to 64×8×8 to 128×16×16 to 160×20×20 (× 2.9, × 3.4 per halving,
// towards the h^2k = h² of a symmetric interior penalty method's energy, the square of its
// energy-norm error O(h^k)), from below (the end displacement is imposed weakly). Its finest
// grid, 768k DOFs, is solved by PCG with the multilevel preconditioner (11-14 iterations, a
// few GB; the direct factorisation took 20 GB) and without the definiteness test's
// factorisation (MFEM's κ = (k+1)² is definite here: no doubling on the coarser grids). The
// reference's own error is an order smaller: fem Hex20 32×4×4 is 0.25% above it, dg k = 2 on
// 64×8×8 0.01% below. The mid-span displacement of k = 1 is within 0.32% at 64×8×8 and 0.07%
// at 160×20×20. k = 2's energy falls at rates 2.1 and 2.3, short of its h⁴ on these grids
// (not asserted).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "dg/dg_method.hpp"
#include "shared/fem/method/fem_method.hpp"
#include "shared/simulation/basis_embedding.hpp"
#include "shared/simulation/scene_materials.hpp"
#include "tests/support/static_solve.hpp"

namespace altfem::dg {
namespace {

const std::filesystem::path scene_file = std::filesystem::path(ALTFEM_SOURCE_DIR) / "scenes/mfem_ex17_beam.json";

struct BeamResult {
  int dofs;
  double midspan;  ///< u_z at (4, ½, ½)
  double energy;   ///< ½ ∫ σ(u):ε(u) dV
};

// ½ ∫ λ (tr ε)² + 2μ ε:ε dV by the method's field quadrature, λ, μ of the material whose
// region holds the point (no point lies on the interface x = 4: it is a face of every grid).
double elastic_energy(const test::StaticRun& run) {
  const FieldQuadrature quadrature = *run.method->field_quadrature(2);
  const SceneMaterials materials(*run.scene);
  double energy = 0;
  Eigen::Index row = 0;
  for (int e = 0; e < quadrature.elements->size(); ++e) {
    const ElementView element = (*quadrature.elements)[e];
    for (int q = 0; q < element.point_count(); ++q, ++row) {
      Eigen::Matrix3d gradient = Eigen::Matrix3d::Zero();  // ∂u_i/∂X_j
      const auto basis_gradients = element.gradients_at(q);
      for (int a = 0; a < element.basis_count(); ++a)
        gradient +=
            run.displacement.segment<3>(3 * static_cast<Eigen::Index>(element.basis[a])) * basis_gradients.row(a);
      const Eigen::Matrix3d strain = 0.5 * (gradient + gradient.transpose());
      const LameParameters lame = materials.pointers()[materials.id_at(quadrature.points.row(row).transpose())]->lame();
      energy +=
          element.weights[q] * (0.5 * lame.lambda * strain.trace() * strain.trace() + lame.mu * strain.squaredNorm());
    }
  }
  return energy;
}

BeamResult solve(const MethodFactory& factory, const std::vector<std::string>& assignments) {
  const test::StaticRun run = test::static_run(scene_file, factory, assignments);
  const BasisEmbedding centre(run.method->basis_evaluator(), Eigen::RowVector3d(4, 0.5, 0.5));
  return {run.method->discretization().dof_count(), centre.displacement(run.displacement)(0, 2), elastic_energy(run)};
}

std::string grid(int n) {
  return "[" + std::to_string(8 * n) + "," + std::to_string(n) + "," + std::to_string(n) + "]";
}

void print_row(const std::string& label, const BeamResult& result, const BeamResult& reference) {
  std::printf("  %-24s %7d %12.6f %9.2e %12.6f %9.2e\n", label.c_str(), result.dofs, result.midspan,
              std::abs(result.midspan / reference.midspan - 1), result.energy,
              std::abs(result.energy / reference.energy - 1));
}

// The relative errors of dg against the reference, per grid (grid(n) for n in `grids`).
struct Errors {
  std::vector<int> grids;
  std::vector<double> midspan, energy;
};

// Degree 1 on `linear_grids`, degree 2 on 8×1×1 to 32×4×4, printed; both errors fall under
// every refinement (for the energy of k = 1 from 16×2×2 on, below).
std::map<int, Errors> beam_study(const std::vector<int>& linear_grids) {
  const BeamResult reference =
      solve(make_fem_method, {"/discretization/fem/element=hex20", "/discretization/fem/resolution=" + grid(8)});
  std::printf("  %-24s %7s %12s %9s %12s %9s\n", "method", "DOFs", "u_z(4,.5,.5)", "rel.", "energy", "rel.");
  print_row("fem Hex20 64x8x8 (ref.)", reference, reference);
  // MFEM's own cross-check: the end face x = 8 is displaced by −0.2 · 8 in z.
  const BeamResult fem_coarse =
      solve(make_fem_method, {"/discretization/fem/element=hex20", "/discretization/fem/resolution=" + grid(4)});
  print_row("fem Hex20 32x4x4", fem_coarse, reference);
  EXPECT_NEAR(fem_coarse.midspan, reference.midspan, 0.01 * std::abs(reference.midspan));

  std::map<int, Errors> errors;
  for (int degree : {1, 2}) {
    Errors& study = errors[degree];
    study.grids = degree == 1 ? linear_grids : std::vector<int>{1, 2, 4};
    for (int n : study.grids) {
      std::vector<std::string> assignments{"/discretization/dg/degree=" + std::to_string(degree),
                                           "/discretization/dg/resolution=" + grid(n)};
      if (n == 20)
        assignments.insert(assignments.end(), {"/solver/linear=pcg", "/solver/linear_tolerance=1e-9",
                                               "/discretization/dg/preconditioner=multilevel",
                                               "/discretization/dg/penalty/double_until_definite=false"});
      const BeamResult dg = solve(make_dg_method, assignments);
      print_row("dg k=" + std::to_string(degree) + " " + grid(n), dg, reference);
      study.midspan.push_back(std::abs(dg.midspan / reference.midspan - 1));
      study.energy.push_back(std::abs(dg.energy / reference.energy - 1));
    }
    // The energy of the coarsest k = 1 grid is close by chance (the weakly imposed end
    // displacement falls short and the energy with it): monotone from the 16×2×2 grid on.
    for (size_t i = 1; i < study.grids.size(); ++i) {
      EXPECT_LT(study.midspan[i], study.midspan[i - 1]) << "k = " << degree << ", refinement " << i;
      if (i >= 2 || degree == 2) {
        EXPECT_LT(study.energy[i], study.energy[i - 1]) << "k = " << degree << ", refinement " << i;
      }
    }
  }
  return errors;
}

TEST(MfemExample17, DgConvergesToTheFineFemBeam) {
  const std::map<int, Errors> errors = beam_study({1, 2, 4, 8});
  EXPECT_LT(errors.at(1).midspan.back(), 0.01);
  EXPECT_LT(errors.at(2).midspan.back(), 0.01);
  EXPECT_LT(errors.at(2).energy.back(), 0.01);
}

// With k = 1 on 160×20×20 as well (768k DOFs, minutes): its energy within 1% too, falling
// at the h² of k = 1 between 64×8×8 and 160×20×20 (measured 1.76).
TEST(MfemExample17FullSize, DgConvergesToTheFineFemBeam) {
  const std::map<int, Errors> errors = beam_study({1, 2, 4, 8, 20});
  for (int degree : {1, 2}) {
    EXPECT_LT(errors.at(degree).midspan.back(), 0.01) << "k = " << degree;
    EXPECT_LT(errors.at(degree).energy.back(), 0.01) << "k = " << degree;
  }
  const std::vector<double>& energy = errors.at(1).energy;
  const double rate = std::log(energy[3] / energy[4]) / std::log(20.0 / 8.0);
  std::printf("  k = 1 energy error rate, 64x8x8 -> 160x20x20: %.2f\n", rate);
  EXPECT_NEAR(rate, 2.0, 0.3);
}

}  // namespace
}  // namespace altfem::dg
