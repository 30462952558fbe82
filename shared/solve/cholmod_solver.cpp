#include "shared/solve/cholmod_solver.hpp"

#include "shared/common/error.hpp"
#include "shared/solve/blas_thread_choice.hpp"
#include "shared/solve/blas_threads.hpp"
#include "shared/solve/block_fill_reducing_ordering.hpp"
#include "shared/solve/factor_memory.hpp"
#include "shared/solve/huge_page_allocation.hpp"

#include <cholmod.h>

#include <algorithm>
#include <mutex>
#include <string>
#include <vector>

namespace altfem {
namespace {

// A non-owning CHOLMOD view of an Eigen matrix; stype −1 makes CHOLMOD read the
// lower triangle only and ignore the (identical) upper one.
cholmod_sparse lower_triangle_view(const Eigen::SparseMatrix<double>& matrix) {
  cholmod_sparse view{};
  view.nrow = static_cast<std::size_t>(matrix.rows());
  view.ncol = static_cast<std::size_t>(matrix.cols());
  view.nzmax = static_cast<std::size_t>(matrix.nonZeros());
  view.p = const_cast<int*>(matrix.outerIndexPtr());
  view.i = const_cast<int*>(matrix.innerIndexPtr());
  view.nz = const_cast<int*>(matrix.innerNonZeroPtr());  // null when compressed
  view.x = const_cast<double*>(matrix.valuePtr());
  view.stype = -1;
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = 1;  // Eigen keeps row indices sorted within each column
  view.packed = matrix.isCompressed() ? 1 : 0;
  return view;
}

// SuiteSparse allocates through one process-wide table of functions; the factor
// is the one large block, see huge_page_allocation.hpp for why it gets huge pages.
void allocate_suitesparse_memory_with_huge_pages() {
  static std::once_flag installed;
  std::call_once(installed, [] {
    SuiteSparse_config.malloc_func = allocate_with_huge_pages;
    SuiteSparse_config.calloc_func = allocate_zeroed_with_huge_pages;
  });
}

// CHOLMOD comes in two index widths: int (the default here: half the index memory) and
// SuiteSparse_long, for factors whose entries outgrow int (2^31; issue #35: a 897k-DOF
// Tet10 half-ball failed with "status -3"). The solver starts with int indices and
// switches when CHOLMOD's analysis says the factor is too large for them.
class CholmodSolver final : public LinearSolver {
public:
  CholmodSolver(CholmodFactorisation factorisation, CholmodIndices indices)
      : factorisation_(factorisation), wide_(indices == CholmodIndices::wide) {
    allocate_suitesparse_memory_with_huge_pages();
    start();
  }
  CholmodSolver(const CholmodSolver&) = delete;
  CholmodSolver& operator=(const CholmodSolver&) = delete;
  ~CholmodSolver() override { finish(); }

  std::string_view name() const override {
    return factorisation_ == CholmodFactorisation::simplicial_ldlt ? "ldlt" : "cholmod";
  }

protected:
  void analyze_pattern(const Eigen::SparseMatrix<double>& matrix) override {
    free_factor();
    std::vector<int> order = block_fill_reducing_ordering(matrix);
    if (!wide_) {
      cholmod_sparse view = lower_triangle_view(matrix);
      factor_ = cholmod_analyze_p(&view, order.data(), nullptr, 0, &common_);
      if (factor_ == nullptr && common_.status == CHOLMOD_TOO_LARGE) {
        // The factor's entries (common_.lnz) are counted before the supernodal symbolic
        // factor overflows the int indices, so the memory check can speak first.
        require_factor_fits(common_.lnz, sizeof(double) * common_.lnz, available_memory_bytes());
        finish();
        wide_ = true;
        start();
      }
    }
    if (wide_) {
      keep_wide_pattern(matrix);
      cholmod_sparse view = wide_view(matrix);
      std::vector<SuiteSparse_long> wide_order(order.begin(), order.end());
      factor_ = cholmod_l_analyze_p(&view, wide_order.data(), nullptr, 0, &common_);
    }
    if (factor_ == nullptr) throw NumericalError("CHOLMOD analysis failed (CHOLMOD status " + status() + ")");
    const double entries = common_.lnz;
    const double values = factor_->is_super ? static_cast<double>(factor_->xsize) : entries;
    require_factor_fits(entries, sizeof(double) * values, available_memory_bytes());
    record_factor_size(entries, common_.fl);
  }

  void factorize_values(const Eigen::SparseMatrix<double>& matrix) override {
    const double flops = statistics().factorisation_flops;
    const int threads =
        flops < minimum_flops_for_blas_threads
            ? 1
            : factorisation_blas_threads(flops, blas_thread_limit(), usable_cores(), runnable_threads_elsewhere());
    set_blas_threads(threads);
    record_blas_threads(threads);
    if (wide_) {
      cholmod_sparse view = wide_view(matrix);
      cholmod_l_factorize(&view, factor_, &common_);
    } else {
      cholmod_sparse view = lower_triangle_view(matrix);
      cholmod_factorize(&view, factor_, &common_);
    }
    if (common_.status == CHOLMOD_NOT_POSDEF) {
      std::string where = "CHOLMOD status " + status() + ", column " + std::to_string(factor_->minor);
      // The column in the fill-reducing order; the unknown it is, in the caller's numbering
      // (three per basis function, x y z).
      if (factor_->minor < factor_->n && factor_->Perm != nullptr) {
        const long unknown = wide_ ? static_cast<const SuiteSparse_long*>(factor_->Perm)[factor_->minor]
                                   : static_cast<const int*>(factor_->Perm)[factor_->minor];
        where += ": unknown " + std::to_string(unknown) + ", basis function " + std::to_string(unknown / 3) +
                 " component " + "xyz"[unknown % 3];
      }
      where += ")";
      if (factorisation_ == CholmodFactorisation::simplicial_ldlt)
        throw NumericalError("matrix has a zero pivot, it is not quasi-definite (" + where);
      throw NumericalError("matrix is not positive definite (" + where);
    }
    if (common_.status < CHOLMOD_OK)
      throw NumericalError("CHOLMOD factorisation failed (CHOLMOD status " + status() + ")");
  }

  long solve_system(const Eigen::VectorXd& rhs, Eigen::VectorXd& solution) override {
    cholmod_dense right_hand_side{};
    right_hand_side.nrow = right_hand_side.d = right_hand_side.nzmax = static_cast<std::size_t>(rhs.size());
    right_hand_side.ncol = 1;
    right_hand_side.x = const_cast<double*>(rhs.data());
    right_hand_side.xtype = CHOLMOD_REAL;
    right_hand_side.dtype = CHOLMOD_DOUBLE;
    set_blas_threads(1);  // one right-hand side: BLAS-2, bound by memory (blas_thread_choice.hpp)
    // cholmod_solve2 reuses its output and workspaces across calls (no allocation per solve).
    const int solved = wide_ ? cholmod_l_solve2(CHOLMOD_A, factor_, &right_hand_side, nullptr, &solution_, nullptr,
                                                &workspace_y_, &workspace_e_, &common_)
                             : cholmod_solve2(CHOLMOD_A, factor_, &right_hand_side, nullptr, &solution_, nullptr,
                                              &workspace_y_, &workspace_e_, &common_);
    if (!solved) throw NumericalError("CHOLMOD solve failed (CHOLMOD status " + status() + ")");
    solution.resize(rhs.size());
    const double* values = static_cast<const double*>(solution_->x);
    std::copy(values, values + rhs.size(), solution.data());
    return 0;
  }

private:
  std::string status() const { return std::to_string(common_.status); }

  void start() {
    if (wide_) cholmod_l_start(&common_);
    else cholmod_start(&common_);
    common_.print = 0;  // failures are reported as NumericalError, not printed
    // The ordering is computed on the graph of supervariables
    // (block_fill_reducing_ordering.hpp); CHOLMOD only postorders it and computes
    // the symbolic factor.
    common_.nmethods = 1;
    common_.method[0].ordering = CHOLMOD_GIVEN;
    if (factorisation_ == CholmodFactorisation::simplicial_ldlt) {
      common_.supernodal = CHOLMOD_SIMPLICIAL;
      common_.final_ll = 0;
    } else {
      common_.supernodal = CHOLMOD_SUPERNODAL;
      // Relaxed amalgamation four times CHOLMOD's default (nrelax 4/16/48, zrelax
      // 0.8/0.1/0.05): merging supernodes that differ by a few explicit zeros makes
      // fewer, larger BLAS-3 calls. On the 27,783-DOF Tet10 cube of bench_factorisation
      // it stored 19 % more entries in L and factorised in 0.40-0.43 s instead of
      // 0.62-0.90 s (a one-off comparison of relaxations ×1/×2/×4/×8, not in the repo).
      common_.nrelax[0] = 16;
      common_.nrelax[1] = 64;
      common_.nrelax[2] = 192;
      common_.zrelax[0] = 0.9;
      common_.zrelax[1] = 0.2;
      common_.zrelax[2] = 0.1;
    }
  }

  void free_factor() {
    if (wide_) cholmod_l_free_factor(&factor_, &common_);
    else cholmod_free_factor(&factor_, &common_);
  }

  void finish() {
    free_factor();
    for (cholmod_dense** dense : {&solution_, &workspace_y_, &workspace_e_}) {
      if (wide_) cholmod_l_free_dense(dense, &common_);
      else cholmod_free_dense(dense, &common_);
    }
    if (wide_) cholmod_l_finish(&common_);
    else cholmod_finish(&common_);
  }

  // The analysed pattern with SuiteSparse_long indices, and the values of an
  // uncompressed matrix compressed to match it.
  void keep_wide_pattern(const Eigen::SparseMatrix<double>& matrix) {
    const Eigen::SparseMatrix<double>& source = compressed(matrix);
    wide_column_starts_.assign(source.outerIndexPtr(), source.outerIndexPtr() + source.cols() + 1);
    wide_rows_.assign(source.innerIndexPtr(), source.innerIndexPtr() + source.nonZeros());
  }

  const Eigen::SparseMatrix<double>& compressed(const Eigen::SparseMatrix<double>& matrix) {
    if (matrix.isCompressed()) return matrix;
    compressed_ = matrix;
    compressed_.makeCompressed();
    return compressed_;
  }

  cholmod_sparse wide_view(const Eigen::SparseMatrix<double>& matrix) {
    const Eigen::SparseMatrix<double>& source = compressed(matrix);
    cholmod_sparse view{};
    view.nrow = static_cast<std::size_t>(source.rows());
    view.ncol = static_cast<std::size_t>(source.cols());
    view.nzmax = static_cast<std::size_t>(source.nonZeros());
    view.p = wide_column_starts_.data();
    view.i = wide_rows_.data();
    view.x = const_cast<double*>(source.valuePtr());
    view.stype = -1;
    view.itype = CHOLMOD_LONG;
    view.xtype = CHOLMOD_REAL;
    view.dtype = CHOLMOD_DOUBLE;
    view.sorted = 1;
    view.packed = 1;
    return view;
  }

  CholmodFactorisation factorisation_;
  bool wide_;
  cholmod_common common_{};
  cholmod_factor* factor_ = nullptr;
  cholmod_dense* solution_ = nullptr;
  cholmod_dense* workspace_y_ = nullptr;
  cholmod_dense* workspace_e_ = nullptr;
  std::vector<SuiteSparse_long> wide_column_starts_, wide_rows_;
  Eigen::SparseMatrix<double> compressed_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver(CholmodFactorisation factorisation, CholmodIndices indices) {
  return std::make_unique<CholmodSolver>(factorisation, indices);
}

}  // namespace altfem
