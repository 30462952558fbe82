// Issue #9: a second Hessian, gradient or energy assembly of the same mesh must not
// touch the heap. This executable replaces every global operator new/delete (plain, array,
// aligned, nothrow) with counting versions and, because Eigen allocates through
// malloc rather than operator new, glibc's malloc family too (forwarding to glibc's
// __libc_* entry points). Counting is switched on only around the calls under test.
#include <gtest/gtest.h>

#include <atomic>
#include <cerrno>
#include <cstddef>
#include <cstdlib>
#include <new>

#include "shared/solve/additive_schwarz_preconditioner.hpp"
#include "shared/solve/two_level_preconditioner.hpp"
#include "tests/unit/assembly/assembly_fixture.hpp"
#include "tests/unit/assembly/face_fixture.hpp"
#include "tests/unit/assembly/face_term.hpp"

extern "C" {
void* __libc_malloc(size_t size);
void* __libc_calloc(size_t count, size_t size);
void* __libc_realloc(void* pointer, size_t size);
void* __libc_memalign(size_t alignment, size_t size);
void __libc_free(void* pointer);
}

namespace {
std::atomic<bool> counting{false};
std::atomic<long> operator_news{0};
std::atomic<long> mallocs{0};

void count_malloc() {
  if (counting.load(std::memory_order_relaxed)) mallocs.fetch_add(1, std::memory_order_relaxed);
}
void* counted_new(size_t size, size_t alignment) {
  if (counting.load(std::memory_order_relaxed)) operator_news.fetch_add(1, std::memory_order_relaxed);
  if (size == 0) size = 1;
  return alignment <= alignof(std::max_align_t) ? std::malloc(size) : __libc_memalign(alignment, size);
}
void* throwing_new(size_t size, size_t alignment) {
  void* pointer = counted_new(size, alignment);
  if (!pointer) throw std::bad_alloc();
  return pointer;
}
}  // namespace

extern "C" {
void* malloc(size_t size) {
  count_malloc();
  return __libc_malloc(size);
}
void* calloc(size_t count, size_t size) {
  count_malloc();
  return __libc_calloc(count, size);
}
void* realloc(void* pointer, size_t size) {
  count_malloc();
  return __libc_realloc(pointer, size);
}
void* memalign(size_t alignment, size_t size) {
  count_malloc();
  return __libc_memalign(alignment, size);
}
void* aligned_alloc(size_t alignment, size_t size) {
  count_malloc();
  return __libc_memalign(alignment, size);
}
int posix_memalign(void** result, size_t alignment, size_t size) {
  count_malloc();
  void* pointer = __libc_memalign(alignment, size);
  if (!pointer) return ENOMEM;
  *result = pointer;
  return 0;
}
void free(void* pointer) { __libc_free(pointer); }
}

void* operator new(size_t size) { return throwing_new(size, 0); }
void* operator new[](size_t size) { return throwing_new(size, 0); }
void* operator new(size_t size, std::align_val_t alignment) { return throwing_new(size, size_t(alignment)); }
void* operator new[](size_t size, std::align_val_t alignment) { return throwing_new(size, size_t(alignment)); }
void* operator new(size_t size, const std::nothrow_t&) noexcept { return counted_new(size, 0); }
void* operator new[](size_t size, const std::nothrow_t&) noexcept { return counted_new(size, 0); }
void* operator new(size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
  return counted_new(size, size_t(alignment));
}
void* operator new[](size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
  return counted_new(size, size_t(alignment));
}
void operator delete(void* pointer) noexcept { std::free(pointer); }
void operator delete[](void* pointer) noexcept { std::free(pointer); }
void operator delete(void* pointer, size_t) noexcept { std::free(pointer); }
void operator delete[](void* pointer, size_t) noexcept { std::free(pointer); }
void operator delete(void* pointer, std::align_val_t) noexcept { std::free(pointer); }
void operator delete[](void* pointer, std::align_val_t) noexcept { std::free(pointer); }
void operator delete(void* pointer, size_t, std::align_val_t) noexcept { std::free(pointer); }
void operator delete[](void* pointer, size_t, std::align_val_t) noexcept { std::free(pointer); }
void operator delete(void* pointer, const std::nothrow_t&) noexcept { std::free(pointer); }
void operator delete[](void* pointer, const std::nothrow_t&) noexcept { std::free(pointer); }
void operator delete(void* pointer, std::align_val_t, const std::nothrow_t&) noexcept { std::free(pointer); }
void operator delete[](void* pointer, std::align_val_t, const std::nothrow_t&) noexcept { std::free(pointer); }

namespace altfem {
namespace {

TEST(CountingAllocator, SeesOperatorNewAndEigenMalloc) {
  // The counters must work, or a zero below would prove nothing.
  counting = true;
  auto* boxed = new int(3);
  Eigen::VectorXd vector(100);
  // Escape both, so that the compiler may not elide the allocations.
  asm volatile("" : : "g"(boxed), "g"(vector.data()) : "memory");
  counting = false;
  delete boxed;
  EXPECT_EQ(operator_news.exchange(0), 1);
  EXPECT_GE(mallocs.exchange(0), 2);
  EXPECT_EQ(vector.size(), 100);
}

// Counts the allocations of a Hessian assembly and then of the rest, and expects none.
template <typename Hessian, typename Rest>
void expect_no_allocation(Hessian&& hessian, Rest&& rest) {
  operator_news = 0;
  mallocs = 0;
  counting = true;
  hessian();
  const long hessian_news = operator_news.exchange(0), hessian_mallocs = mallocs.exchange(0);
  rest();
  counting = false;
  EXPECT_EQ(hessian_news, 0);
  EXPECT_EQ(hessian_mallocs, 0);
  EXPECT_EQ(operator_news.load(), 0);
  EXPECT_EQ(mallocs.load(), 0);
}

class SecondAssembly : public ::testing::TestWithParam<ElementType> {};

TEST_P(SecondAssembly, AllocatesNothing) {
  // Large enough that the colours are assembled in parallel regions.
  const test::AssemblyProblem problem(GetParam(), {10, 10, 10}, MaterialModel::stable_neo_hookean);
  const ElasticAssembler& assembler = *problem.assembler;
  const Eigen::VectorXd u = problem.displacement(test::moderate_deformation(), 0.05, 4);
  SparseMatrix hessian = assembler.pattern();
  Eigen::VectorXd gradient;
  assembler.hessian(u, hessian);  // warm-up: sizes the gradient, starts the OpenMP pool
  assembler.gradient(u, gradient);

  double energy = 0;
  expect_no_allocation([&] { assembler.hessian(u, hessian); },
                       [&] {
                         assembler.gradient(u, gradient);
                         energy = assembler.energy(u);
                       });
  EXPECT_GT(gradient.norm(), 0.0);
  EXPECT_GT(energy, 0.0);
}

INSTANTIATE_TEST_SUITE_P(ElasticAssembler, SecondAssembly, ::testing::Values(ElementType::tet10, ElementType::hex20),
                         [](const auto& info) { return std::string(element_name(info.param)); });

TEST(FaceAssembler, SecondAssemblyAllocatesNothing) {
  // Faces of 8 and 20 functions (fixed-size paths) and of 10, 12, 14 and 16 (the
  // dynamic path, its sizes interleaved in every thread's share), enough per colour for
  // parallel regions, with a non-quadratic kernel.
  const TabulatedFaces faces = test::grid_faces(8, test::random_cell_sizes(512, {4, 6, 10}, 3), 4, 5);
  int sizes_seen[21] = {};
  for (int f = 0; f < faces.size(); ++f) ++sizes_seen[faces[f].basis_count()];
  for (int size : {8, 10, 12, 14, 16, 20}) ASSERT_GT(sizes_seen[size], 0) << size;
  const test::FaceTerm<test::QuarticJumpKernel> term(faces, test::QuarticJumpKernel());
  const Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(term.dof_count(), -0.5, 0.5);
  SparseMatrix hessian = term.sparsity.pattern();
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero(term.dof_count());
  term.assembler.add_hessian(u, hessian);  // warm-up: sizes the scratch, starts the OpenMP pool
  term.assembler.add_gradient(u, gradient);

  double energy = 0;
  expect_no_allocation([&] { term.assembler.add_hessian(u, hessian); },
                       [&] {
                         term.assembler.add_gradient(u, gradient);
                         energy = term.assembler.energy(u);
                       });
  EXPECT_GT(gradient.norm(), 0.0);
  EXPECT_GT(energy, 0.0);
}

// The two-level preconditioner's apply() runs every Krylov iteration (issue #18): once its
// coarse solver has sized its workspace (the first apply), it must not allocate.
TEST(TwoLevelPreconditioner, SecondApplyAllocatesNothing) {
  const int size = 60;  // a 1D Laplacian, blocks of 3 unknowns, piecewise constants on them
  std::vector<Eigen::Triplet<double>> entries, prolongation_entries;
  std::vector<std::vector<int>> blocks(size / 3);
  for (int i = 0; i < size; ++i) {
    entries.emplace_back(i, i, 2.0);
    if (i > 0) entries.emplace_back(i, i - 1, -1.0);
    if (i + 1 < size) entries.emplace_back(i, i + 1, -1.0);
    blocks[i / 3].push_back(i);
    prolongation_entries.emplace_back(i, i / 3, 1.0);
  }
  Eigen::SparseMatrix<double> matrix(size, size), prolongation(size, size / 3);
  matrix.setFromTriplets(entries.begin(), entries.end());
  prolongation.setFromTriplets(prolongation_entries.begin(), prolongation_entries.end());
  for (TwoLevelCycle cycle : {TwoLevelCycle::additive, TwoLevelCycle::multiplicative}) {
    TwoLevelPreconditioner preconditioner(std::make_unique<AdditiveSchwarzPreconditioner>(blocks), prolongation, cycle,
                                          0.8);
    preconditioner.compute(matrix);
    const Eigen::VectorXd residual = Eigen::VectorXd::LinSpaced(size, -1.0, 2.0);
    Eigen::VectorXd result(size);
    preconditioner.apply(residual, result);  // warm-up: CHOLMOD's solve workspace
    expect_no_allocation([&] { preconditioner.apply(residual, result); }, [] {});
  }
}

}  // namespace
}  // namespace altfem
