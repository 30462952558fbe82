// FaceAssembler (issue #14, item 3): the jump penalty on the face between two cubes
// against a hand computation, finite-difference derivatives of a quadratic and a
// non-quadratic kernel on faces of fixed (8, 20) and dynamic (13) sizes, and misuse.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <stdexcept>

#include "tests/unit/assembly/face_fixture.hpp"
#include "tests/unit/assembly/face_term.hpp"
#include "tests/unit/random_vectors.hpp"

namespace altfem {
namespace {

constexpr double penalty = 2.0;

// On x = 1 with s = y − 1/2, t = z − 1/2 ∈ [−1/2, 1/2], the jump of basis function a
// is j_a = c_a + d_a s + e_a t: cube 0's monomials 1, x − 1/2, s, t from the minus side,
// minus cube 1's monomials 1, x − 3/2, s, t from the plus side.
struct LinearTrace {
  double c, d, e;
};
const LinearTrace traces[8] = {{1, 0, 0},  {0.5, 0, 0}, {0, 1, 0},  {0, 0, 1},
                               {-1, 0, 0}, {0.5, 0, 0}, {0, -1, 0}, {0, 0, -1}};
// ∫ j_a j_b dA over the unit square: ∫1 = 1, ∫s = ∫t = ∫st = 0, ∫s² = ∫t² = 1/12.
double jump_product_integral(int a, int b) {
  return traces[a].c * traces[b].c + (traces[a].d * traces[b].d + traces[a].e * traces[b].e) / 12;
}

using test::random_vector;

TEST(FaceAssembler, JumpPenaltyBetweenTwoCubesMatchesHandComputation) {
  const TabulatedFaces faces = test::two_cube_face(3);
  const test::FaceTerm<JumpPenaltyKernel> term(faces, JumpPenaltyKernel(std::vector<double>{penalty}));
  ASSERT_EQ(term.dof_count(), 24);
  const Eigen::VectorXd u = random_vector(24, 5);

  // [[u]] = C + D s + E t with C = Σ c_a u_a etc.; E = η/2 (|C|² + (|D|² + |E|²)/12).
  Eigen::Vector3d C = Eigen::Vector3d::Zero(), D = C, E = C;
  for (int a = 0; a < 8; ++a) {
    C += traces[a].c * u.segment<3>(3 * a);
    D += traces[a].d * u.segment<3>(3 * a);
    E += traces[a].e * u.segment<3>(3 * a);
  }
  const double energy = penalty / 2 * (C.squaredNorm() + (D.squaredNorm() + E.squaredNorm()) / 12);
  EXPECT_NEAR(term.assembler.energy(u), energy, 1e-13 * energy);

  // f_a = η (c_a C + (d_a D + e_a E)/12).
  const Eigen::VectorXd gradient = term.gradient(u);
  for (int a = 0; a < 8; ++a) {
    const Eigen::Vector3d force = penalty * (traces[a].c * C + (traces[a].d * D + traces[a].e * E) / 12);
    EXPECT_LT((gradient.segment<3>(3 * a) - force).norm(), 1e-13) << "basis " << a;
  }

  // K_(3a+i)(3b+k) = η δ_ik ∫ j_a j_b.
  const Eigen::MatrixXd stiffness = Eigen::MatrixXd(term.hessian(u));
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b)
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
          EXPECT_NEAR(stiffness(3 * a + i, 3 * b + k), i == k ? penalty * jump_product_integral(a, b) : 0.0, 1e-14)
              << a << i << " " << b << k;
  // A few entries written out: constants, the x-monomials (1/2 on both sides: same
  // sign, since the plus side's is −1/2 and enters with a minus), and the y-monomials.
  EXPECT_NEAR(stiffness(0, 0), 2.0, 1e-14);
  EXPECT_NEAR(stiffness(0, 12), -2.0, 1e-14);
  EXPECT_NEAR(stiffness(4, 16), 0.5, 1e-14);
  EXPECT_NEAR(stiffness(3, 15), 0.5, 1e-14);
  EXPECT_NEAR(stiffness(8, 20), -1.0 / 6, 1e-14);
  EXPECT_NEAR(stiffness(11, 11), 1.0 / 6, 1e-14);
  EXPECT_NEAR(stiffness(0, 1), 0.0, 1e-14);
  EXPECT_NEAR(stiffness(3, 6), 0.0, 1e-14);  // x- and y-monomials of cube 0: ∫ s = 0
  // A rigid translation has no jump.
  Eigen::VectorXd translation(24);
  for (int a = 0; a < 8; ++a)
    translation.segment<3>(3 * a) = (a % 4 == 0) ? Eigen::Vector3d(1, -2, 3) : Eigen::Vector3d::Zero();
  EXPECT_NEAR(term.assembler.energy(translation), 0.0, 1e-14);
}

// Faces of sizes 8, 20 (fixed-size paths) and 13 (dynamic path) over a pool of 30
// basis functions, random traces.
TabulatedFaces mixed_faces() {
  std::mt19937 random(11);
  TabulatedFaces faces;
  for (int size : {8, 20, 13, 8, 13, 20}) {
    std::vector<int> pool(30);
    std::iota(pool.begin(), pool.end(), 0);
    std::shuffle(pool.begin(), pool.end(), random);
    pool.resize(size);
    test::add_random_face(faces, pool, size / 2, 5, random);
  }
  return faces;
}

template <typename Kernel>
void expect_derivatives_match_finite_differences(Kernel kernel) {
  const TabulatedFaces faces = mixed_faces();
  const test::FaceTerm<Kernel> term(faces, std::move(kernel));
  const Eigen::VectorXd u = 0.3 * random_vector(term.dof_count(), 7);
  const Eigen::VectorXd gradient = term.gradient(u);
  const Eigen::MatrixXd hessian = Eigen::MatrixXd(term.hessian(u));
  EXPECT_GT(gradient.norm(), 0.0);
  EXPECT_LT((hessian - hessian.transpose()).norm(), 1e-12 * hessian.norm());

  const double h = 1e-5;
  Eigen::VectorXd shifted = u;
  for (Eigen::Index i = 0; i < u.size(); ++i) {
    shifted[i] = u[i] + h;
    const double energy_plus = term.assembler.energy(shifted);
    const Eigen::VectorXd gradient_plus = term.gradient(shifted);
    shifted[i] = u[i] - h;
    const double energy_minus = term.assembler.energy(shifted);
    const Eigen::VectorXd gradient_minus = term.gradient(shifted);
    shifted[i] = u[i];
    EXPECT_NEAR((energy_plus - energy_minus) / (2 * h), gradient[i], 1e-7 * (1 + gradient.norm())) << "dof " << i;
    const Eigen::VectorXd column = (gradient_plus - gradient_minus) / (2 * h);
    EXPECT_LT((column - hessian.col(i)).norm(), 1e-7 * (1 + hessian.norm())) << "dof " << i;
  }
}

TEST(FaceAssembler, JumpPenaltyDerivativesMatchFiniteDifferencesOnMixedSizes) {
  expect_derivatives_match_finite_differences(JumpPenaltyKernel(std::vector<double>{1.0, 2.0, 3.0, 0.5, 4.0, 1.5}));
}

TEST(FaceAssembler, TensorJumpPenaltyDerivativesMatchFiniteDifferencesOnMixedSizes) {
  // A symmetric, not diagonal T_f per face (a split DG penalty's η_t I + (η_n − η_t) n nᵀ).
  std::vector<Eigen::Matrix3d> tensors;
  for (int f = 0; f < 6; ++f) {
    const Eigen::Vector3d n = Eigen::Vector3d(1.0, 0.3 * f, -0.2).normalized();
    tensors.push_back((0.5 + f) * Eigen::Matrix3d::Identity() + (2.0 + f) * n * n.transpose());
  }
  expect_derivatives_match_finite_differences(JumpPenaltyKernel(std::move(tensors)));
}

TEST(FaceAssembler, QuarticKernelDerivativesMatchFiniteDifferencesOnMixedSizes) {
  expect_derivatives_match_finite_differences(test::QuarticJumpKernel());
}

// One rank's share (EnergyTerm::assemble_only): the shares of disjoint face sets sum to
// the whole term, on the non-quadratic kernel and faces of fixed and dynamic sizes.
TEST(FaceAssembler, SharesOfDisjointFacesSumToTheWhole) {
  const TabulatedFaces faces = mixed_faces();
  const test::FaceTerm<test::QuarticJumpKernel> whole(faces, test::QuarticJumpKernel());
  test::FaceTerm<test::QuarticJumpKernel> first(faces, test::QuarticJumpKernel()),
      second(faces, test::QuarticJumpKernel());
  const std::vector<char> some{1, 0, 0, 1, 1, 0}, others{0, 1, 1, 0, 0, 1};
  EXPECT_TRUE(first.assembler.assemble_only(some));
  EXPECT_TRUE(second.assembler.assemble_only(others));
  const Eigen::VectorXd u = 0.3 * random_vector(whole.dof_count(), 7);
  const double energy = whole.assembler.energy(u);
  EXPECT_NEAR(first.assembler.energy(u) + second.assembler.energy(u), energy, 1e-13 * energy);
  EXPECT_LE((first.gradient(u) + second.gradient(u) - whole.gradient(u)).norm(), 1e-13 * whole.gradient(u).norm());
  EXPECT_LE((SparseMatrix(first.hessian(u) + second.hessian(u)) - whole.hessian(u)).norm(),
            1e-13 * whole.hessian(u).norm());
  EXPECT_GT(first.gradient(u).norm(), 0.1 * whole.gradient(u).norm()) << "each share is a real part";
  EXPECT_THROW(first.assembler.assemble_only({1, 0}), std::invalid_argument);
}

// The faces of `whole` that `here` holds, copied, and the others listed: a FaceTabulator.
TabulatedFaces share_of(const TabulatedFaces& whole, const TabulatedHere& here) {
  TabulatedFaces faces;
  for (int f = 0; f < whole.size(); ++f) {
    const FaceView face = whole[f];
    if (here && !here(f)) {
      faces.add_held_elsewhere(face.basis, face.minus, face.plus);
      continue;
    }
    const Eigen::Index rows = face.point_count() * face.basis_count();
    faces.add(face.basis, face.weights, FaceView::Gradients(face.normals, face.point_count(), 3), face.values_minus,
              face.values_plus, FaceView::Gradients(face.gradients_minus, rows, 3),
              FaceView::Gradients(face.gradients_plus, rows, 3), face.minus, face.plus);
  }
  return faces;
}

// With a FaceTabulator the term lists its faces first (their couplings, no points), then
// tabulates only the faces of its share (assemble_only: one rank's, docs/scaling.md), or
// every face when it is bound without one, and assembles what the tabulated faces give.
TEST(FaceAssembler, ATabulatorTabulatesTheShareOnlyOrEveryFaceWhenBound) {
  const TabulatedFaces whole = mixed_faces();
  int calls = 0;
  const FaceTabulator tabulate = [&](const TabulatedHere& here) {
    ++calls;
    return share_of(whole, here);
  };
  const auto make_kernel = [](const TabulatedFaces&) { return test::QuarticJumpKernel(); };
  FaceAssembler<test::QuarticJumpKernel> shared(tabulate, make_kernel), everything(tabulate, make_kernel);
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(shared.faces().size(), whole.size());
  EXPECT_EQ(shared.faces().point_count(), 0);
  EXPECT_EQ(shared.couplings().size(), whole.size());
  for (int f = 0; f < whole.size(); ++f)
    EXPECT_TRUE(std::ranges::equal(shared.couplings()[f], whole.basis_groups()[f]));

  const std::vector<char> some{1, 0, 0, 1, 1, 0};
  EXPECT_TRUE(shared.assemble_only(some));
  long long share_points = 0;
  for (int f = 0; f < whole.size(); ++f) share_points += some[f] ? whole[f].point_count() : 0;
  EXPECT_EQ(shared.faces().point_count(), share_points);
  EXPECT_LT(share_points, whole.point_count());

  const TabulatedElements no_elements;
  const BlockSparsity sparsity(no_elements, whole.basis_groups());
  shared.bind(sparsity, 0);
  everything.bind(sparsity, 0);
  EXPECT_EQ(calls, 4);
  EXPECT_EQ(everything.faces().point_count(), whole.point_count());

  test::FaceTerm<test::QuarticJumpKernel> reference(whole, test::QuarticJumpKernel()),
      reference_share(whole, test::QuarticJumpKernel());
  reference_share.assembler.assemble_only(some);
  const Eigen::VectorXd u = 0.3 * random_vector(reference.dof_count(), 7);
  EXPECT_EQ(shared.energy(u), reference_share.assembler.energy(u));
  EXPECT_EQ(everything.energy(u), reference.assembler.energy(u));
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero(reference.dof_count());
  shared.add_gradient(u, gradient);
  EXPECT_EQ(gradient, reference_share.gradient(u));
  SparseMatrix hessian = sparsity.pattern();
  everything.add_hessian(u, hessian);
  EXPECT_EQ((hessian - reference.hessian(u)).norm(), 0.0);
}

TEST(FaceAssembler, HessianBeforeBindThrows) {
  const TabulatedFaces faces = test::two_cube_face(3);
  const FaceAssembler<JumpPenaltyKernel> assembler(faces, JumpPenaltyKernel(std::vector<double>{penalty}));
  SparseMatrix hessian(24, 24);
  EXPECT_THROW(assembler.add_hessian(Eigen::VectorXd::Zero(24), hessian), std::logic_error);
}

TEST(TabulatedFaces, RejectsMismatchedSizesAndNonUnitNormals) {
  TabulatedFaces faces;
  const std::vector<int> basis{0, 1};
  const std::vector<double> weights{0.5, 0.5};
  Eigen::MatrixXd normals(2, 3);
  normals << 0, 0, 1, 0, 0, 1;
  const Eigen::MatrixXd values = Eigen::MatrixXd::Ones(2, 2), gradients = Eigen::MatrixXd::Zero(4, 3);
  EXPECT_NO_THROW(faces.add(basis, weights, normals, values, values, gradients, gradients, 0, -1));
  // values with 3 columns for 2 basis functions; gradients with too few rows; 2 normals
  // for 1 weight.
  EXPECT_THROW(faces.add(basis, weights, normals, Eigen::MatrixXd::Ones(2, 3), values, gradients, gradients, 0, -1),
               std::invalid_argument);
  EXPECT_THROW(faces.add(basis, weights, normals, values, values, gradients, Eigen::MatrixXd::Zero(3, 3), 0, -1),
               std::invalid_argument);
  EXPECT_THROW(faces.add(basis, std::vector<double>{1.0}, normals, values, values, gradients, gradients, 0, -1),
               std::invalid_argument);
  Eigen::MatrixXd long_normals = normals;
  long_normals(1, 2) = 1.01;
  EXPECT_THROW(faces.add(basis, weights, long_normals, values, values, gradients, gradients, 0, -1),
               std::invalid_argument);
  EXPECT_EQ(faces.size(), 1);  // the rejected faces left nothing behind
  EXPECT_EQ(faces.point_count(), 2);
  EXPECT_TRUE(faces[0].is_boundary());
}

}  // namespace
}  // namespace altfem
