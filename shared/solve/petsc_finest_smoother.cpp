#include "shared/solve/petsc_finest_smoother.hpp"

#ifdef ALTFEM_HAVE_PETSC
#include <algorithm>
#include <cstring>

namespace altfem {

namespace {

// What the shell applies, with its work vectors (applied every smoothing step: no allocation).
struct ShellContext {
  const Preconditioner* preconditioner;
  const std::vector<Eigen::Index>* method_of_row;
  Eigen::VectorXd residual, correction;
  // Over several ranks: the gather of a level vector to every rank, and this rank's rows.
  VecScatter to_all = nullptr;
  Vec all = nullptr;
  PetscInt first_row = 0;
};

PetscErrorCode apply_shell(PC pc, Vec x, Vec y) {
  void* raw = nullptr;
  PetscCall(PCShellGetContext(pc, &raw));
  auto& context = *static_cast<ShellContext*>(raw);
  const std::vector<Eigen::Index>& method_of_row = *context.method_of_row;
  Vec whole = x;
  if (context.to_all) {
    PetscCall(VecScatterBegin(context.to_all, x, context.all, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(context.to_all, x, context.all, INSERT_VALUES, SCATTER_FORWARD));
    whole = context.all;
  }
  const PetscScalar* in;
  PetscCall(VecGetArrayRead(whole, &in));
  for (std::size_t row = 0; row < method_of_row.size(); ++row) context.residual[method_of_row[row]] = in[row];
  PetscCall(VecRestoreArrayRead(whole, &in));
  context.preconditioner->apply(context.residual, context.correction);
  PetscInt rows = 0;
  PetscCall(VecGetLocalSize(y, &rows));
  PetscScalar* out;
  PetscCall(VecGetArray(y, &out));
  for (PetscInt row = 0; row < rows; ++row) out[row] = context.correction[method_of_row[context.first_row + row]];
  PetscCall(VecRestoreArray(y, &out));
  return 0;
}

// The gather of the smoother's vectors to every rank, and where this rank's rows start.
PetscErrorCode gather_to_all(KSP smoother, ShellContext& context) {
  Mat operator_;
  PetscCall(KSPGetOperators(smoother, &operator_, nullptr));
  Vec layout;
  PetscCall(MatCreateVecs(operator_, &layout, nullptr));
  PetscCall(VecScatterDestroy(&context.to_all));
  PetscCall(VecDestroy(&context.all));
  PetscCall(VecScatterCreateToAll(layout, &context.to_all, &context.all));
  PetscInt last = 0;
  PetscCall(VecGetOwnershipRange(layout, &context.first_row, &last));
  return VecDestroy(&layout);
}

PetscErrorCode destroy_shell(PC pc) {
  void* raw = nullptr;
  PetscCall(PCShellGetContext(pc, &raw));
  auto* context = static_cast<ShellContext*>(raw);
  PetscCall(VecScatterDestroy(&context->to_all));
  PetscCall(VecDestroy(&context->all));
  delete context;
  return 0;
}

// The bounds of the Chebyshev smoother of the method's preconditioner S. PETSc's own
// estimate (a few Krylov steps from a random vector) can miss the modes the Schwarz blocks'
// overlaps make: e_i of a DOF in n blocks has a Rayleigh quotient of S A of at least n
// (Preconditioner::largest_eigenvalue_at_least), but where its cells hold a sliver of
// material a random start holds it with the weight of its tiny energy, and Chebyshev
// above its upper bound amplifies it: CG broke (DIVERGED_INDEFINITE_PC) on fcm's Hex8
// half-ball, whose estimate was 3.0 where blocks overlap eight times. So the bounds are set
// here: the larger of that and ten power steps' Rayleigh quotient, × 1.1, the lower bound
// a tenth of it (PETSc's transform). Collective over the smoother's ranks.
PetscErrorCode set_chebyshev_bounds(KSP smoother, PC shell, double at_least) {
  PetscBool chebyshev = PETSC_FALSE;
  PetscCall(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(smoother), KSPCHEBYSHEV, &chebyshev));
  if (!chebyshev) return 0;
  Mat matrix;
  PetscCall(KSPGetOperators(smoother, &matrix, nullptr));
  Vec x, product, preconditioned;
  PetscCall(MatCreateVecs(matrix, &x, &product));
  PetscCall(VecDuplicate(x, &preconditioned));
  PetscRandom random;
  PetscCall(PetscRandomCreate(PetscObjectComm(reinterpret_cast<PetscObject>(smoother)), &random));
  PetscCall(PetscRandomSetFromOptions(random));
  PetscCall(VecSetRandom(x, random));
  PetscCall(PetscRandomDestroy(&random));
  double largest = at_least;
  for (int step = 0; step < 10; ++step) {
    PetscReal norm = 0;
    PetscCall(VecNormalize(x, &norm));
    PetscCall(MatMult(matrix, x, product));  // A x
    PetscScalar energy = 0, quotient = 0;
    PetscCall(VecDot(x, product, &energy));
    PetscCall(PCApply(shell, product, preconditioned));  // S A x
    PetscCall(VecDot(product, preconditioned, &quotient));
    if (energy > 0) largest = std::max(largest, static_cast<double>(quotient / energy));
    PetscCall(VecCopy(preconditioned, x));
  }
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&product));
  PetscCall(VecDestroy(&preconditioned));
  return KSPChebyshevSetEigenvalues(smoother, 1.1 * largest, 0.11 * largest);
}

}  // namespace

FinestLevelSmoother::FinestLevelSmoother(PreconditionerFactory factory, bool over_ranks)
    : over_ranks_(over_ranks), factory_(std::move(factory)) {
  if (!over_ranks_ || !factory_) return;
  preconditioner_ = factory_();  // made once, computed at every set-up
  if (preconditioner_->computes_from_shares()) return;
  preconditioner_.reset();
  factory_ = nullptr;
}

PetscErrorCode FinestLevelSmoother::configure(PC pc, const std::string& petsc_options) {
  bounds_chosen_ = petsc_options.find("ksp_chebyshev_e") != std::string::npos;
  if (!factory_ || petsc_options.find("pc_gamg_use_sa_esteig") != std::string::npos) return 0;
  PetscBool gamg = PETSC_FALSE;
  PetscCall(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(pc), PCGAMG, &gamg));
  if (gamg) PetscCall(PCGAMGSetUseSAEstEig(pc, PETSC_FALSE));
  return 0;
}

PetscErrorCode FinestLevelSmoother::install(PC pc, const Eigen::SparseMatrix<double>& matrix,
                                            std::vector<Eigen::Index> method_of_row, bool matrix_is_share) {
  if (!factory_) return 0;
  PCType type;
  PetscCall(PCGetType(pc, &type));
  if (std::strcmp(type, PCGAMG) != 0 && std::strcmp(type, PCMG) != 0) return 0;
  if (!preconditioner_) preconditioner_ = factory_();  // made once, computed at every set-up
  if (matrix_is_share) preconditioner_->compute_from_shares(matrix);
  else preconditioner_->compute(matrix);
  method_of_row_ = std::move(method_of_row);
  PetscInt levels = 0;
  PetscCall(PCMGGetLevels(pc, &levels));
  if (levels < 1) return 0;
  KSP smoother;
  PetscCall(PCMGGetSmoother(pc, levels - 1, &smoother));
  PC shell;
  PetscCall(KSPGetPC(smoother, &shell));
  const auto size = static_cast<Eigen::Index>(method_of_row_.size());
  PetscBool already = PETSC_FALSE;
  PetscCall(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(shell), PCSHELL, &already));
  if (already) {  // set before (the last set-up): its context takes this preconditioner
    void* raw = nullptr;
    PetscCall(PCShellGetContext(shell, &raw));
    auto& context = *static_cast<ShellContext*>(raw);
    context.preconditioner = preconditioner_.get();
    context.method_of_row = &method_of_row_;
    context.residual.setZero(size);
    context.correction.setZero(size);
    if (over_ranks_) PetscCall(gather_to_all(smoother, context));
    return bounds_chosen_ ? 0 : set_chebyshev_bounds(smoother, shell, preconditioner_->largest_eigenvalue_at_least());
  }
  auto* context = new ShellContext{preconditioner_.get(), &method_of_row_, Eigen::VectorXd::Zero(size),
                                   Eigen::VectorXd::Zero(size)};
  if (over_ranks_) PetscCall(gather_to_all(smoother, *context));
  PetscCall(PCSetType(shell, PCSHELL));
  PetscCall(PCShellSetContext(shell, context));
  PetscCall(PCShellSetApply(shell, apply_shell));
  PetscCall(PCShellSetDestroy(shell, destroy_shell));
  PetscCall(PCShellSetName(shell, "altfem's preconditioner of the method"));
  return bounds_chosen_ ? 0 : set_chebyshev_bounds(smoother, shell, preconditioner_->largest_eigenvalue_at_least());
}

}  // namespace altfem
#endif
