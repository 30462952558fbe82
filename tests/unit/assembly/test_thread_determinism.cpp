// Graph-coloured assembly gives bit-identical results for 1 and 2 threads
// (element_coloring.hpp promises identical, not merely close, results).
#include <gtest/gtest.h>
#include <omp.h>

#include <random>
#include <vector>

#include "tests/unit/assembly/assembly_fixture.hpp"
#include "tests/unit/assembly/face_fixture.hpp"
#include "tests/unit/assembly/face_term.hpp"

namespace altfem {
namespace {

struct Results {
  double energy;
  std::vector<double> gradient, hessian;
};

Results assemble(const ElasticAssembler& assembler, const Eigen::VectorXd& u) {
  Results results;
  results.energy = assembler.energy(u);
  Eigen::VectorXd gradient;
  assembler.gradient(u, gradient);
  results.gradient.assign(gradient.data(), gradient.data() + gradient.size());
  SparseMatrix hessian = assembler.pattern();
  assembler.hessian(u, hessian);
  results.hessian.assign(hessian.valuePtr(), hessian.valuePtr() + hessian.nonZeros());
  return results;
}

class ThreadsOfType : public ::testing::TestWithParam<ElementType> {};

TEST_P(ThreadsOfType, OneAndTwoThreadsBitIdentical) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(2);  // the assembler sizes its per-thread scratch for this
  // Large enough (more than 64 elements) that the assembly loops run in parallel regions.
  const test::AssemblyProblem problem(GetParam(), {10, 10, 10}, MaterialModel::stable_neo_hookean);
  const Eigen::VectorXd u = problem.displacement(test::moderate_deformation(), 0.05, 3);
  ASSERT_EQ(omp_get_max_threads(), 2);
  const Results two = assemble(*problem.assembler, u);
  omp_set_num_threads(1);
  const Results one = assemble(*problem.assembler, u);
  omp_set_num_threads(saved);

  EXPECT_EQ(one.energy, two.energy);
  EXPECT_EQ(one.gradient, two.gradient);
  EXPECT_EQ(one.hessian, two.hessian);
  EXPECT_GT(std::abs(one.energy), 0.0);
}

INSTANTIATE_TEST_SUITE_P(ElasticAssembler, ThreadsOfType,
                         ::testing::Values(ElementType::tet10, ElementType::hex20, ElementType::hex27),
                         [](const auto& info) { return std::string(element_name(info.param)); });

TEST(FaceAssembler, OneAndTwoThreadsBitIdentical) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(2);  // the assembler sizes its per-thread scratch for this
  // 8³ cells of 4, 6 or 10 functions: 1344 faces of 8 to 20 functions (8 and 20 fixed,
  // the rest dynamic), over 64 per colour, so every colour runs in a parallel region.
  const TabulatedFaces faces = test::grid_faces(8, test::random_cell_sizes(512, {4, 6, 10}, 2), 4, 9);
  const test::FaceTerm<test::QuarticJumpKernel> term(faces, test::QuarticJumpKernel());
  const auto colors = color_groups(faces.basis_groups());
  for (const auto& color : colors) ASSERT_GE(color.size(), parallel::minimum_parallel_items);
  std::mt19937 random(4);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd u(term.dof_count());
  for (auto& value : u) value = uniform(random);

  const auto assemble_faces = [&] {
    Results results;
    results.energy = term.assembler.energy(u);
    const Eigen::VectorXd gradient = term.gradient(u);
    results.gradient.assign(gradient.data(), gradient.data() + gradient.size());
    const SparseMatrix hessian = term.hessian(u);
    results.hessian.assign(hessian.valuePtr(), hessian.valuePtr() + hessian.nonZeros());
    return results;
  };
  const Results two = assemble_faces();
  omp_set_num_threads(1);
  const Results one = assemble_faces();
  omp_set_num_threads(saved);

  EXPECT_EQ(one.energy, two.energy);
  EXPECT_EQ(one.gradient, two.gradient);
  EXPECT_EQ(one.hessian, two.hessian);
  EXPECT_GT(one.energy, 0.0);
}

}  // namespace
}  // namespace altfem
