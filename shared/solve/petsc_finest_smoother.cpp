#include "shared/solve/petsc_finest_smoother.hpp"

#ifdef ALTFEM_HAVE_PETSC
#include <cstring>

namespace altfem {

namespace {

// What the shell applies, with its work vectors (applied every smoothing step: no allocation).
struct ShellContext {
  const Preconditioner* preconditioner;
  const std::vector<Eigen::Index>* method_of_row;
  Eigen::VectorXd residual, correction;
};

PetscErrorCode apply_shell(PC pc, Vec x, Vec y) {
  void* raw = nullptr;
  PetscCall(PCShellGetContext(pc, &raw));
  auto& context = *static_cast<ShellContext*>(raw);
  const std::vector<Eigen::Index>& method_of_row = *context.method_of_row;
  const PetscScalar* in;
  PetscCall(VecGetArrayRead(x, &in));
  for (std::size_t row = 0; row < method_of_row.size(); ++row) context.residual[method_of_row[row]] = in[row];
  PetscCall(VecRestoreArrayRead(x, &in));
  context.preconditioner->apply(context.residual, context.correction);
  PetscScalar* out;
  PetscCall(VecGetArray(y, &out));
  for (std::size_t row = 0; row < method_of_row.size(); ++row) out[row] = context.correction[method_of_row[row]];
  PetscCall(VecRestoreArray(y, &out));
  return 0;
}

PetscErrorCode destroy_shell(PC pc) {
  void* raw = nullptr;
  PetscCall(PCShellGetContext(pc, &raw));
  delete static_cast<ShellContext*>(raw);
  return 0;
}

}  // namespace

PetscErrorCode FinestLevelSmoother::configure(PC pc, const std::string& petsc_options) const {
  if (!factory_ || petsc_options.find("pc_gamg_use_sa_esteig") != std::string::npos) return 0;
  PetscBool gamg = PETSC_FALSE;
  PetscCall(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(pc), PCGAMG, &gamg));
  if (gamg) PetscCall(PCGAMGSetUseSAEstEig(pc, PETSC_FALSE));
  return 0;
}

PetscErrorCode FinestLevelSmoother::install(PC pc, const Eigen::SparseMatrix<double>& matrix,
                                            std::vector<Eigen::Index> method_of_row) {
  if (!factory_) return 0;
  PCType type;
  PetscCall(PCGetType(pc, &type));
  if (std::strcmp(type, PCGAMG) != 0 && std::strcmp(type, PCMG) != 0) return 0;
  if (!preconditioner_) preconditioner_ = factory_();  // made once, computed at every set-up
  preconditioner_->compute(matrix);
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
    return 0;
  }
  PetscCall(PCSetType(shell, PCSHELL));
  PetscCall(PCShellSetContext(shell, new ShellContext{preconditioner_.get(), &method_of_row_,
                                                      Eigen::VectorXd::Zero(size), Eigen::VectorXd::Zero(size)}));
  PetscCall(PCShellSetApply(shell, apply_shell));
  PetscCall(PCShellSetDestroy(shell, destroy_shell));
  PetscCall(PCShellSetName(shell, "altfem's preconditioner of the method"));
  return 0;
}

}  // namespace altfem
#endif
