#include "shared/solve/preconditioner.hpp"

#include "shared/common/error.hpp"
#include "shared/solve/incomplete_cholesky_preconditioner.hpp"
#include "shared/solve/jacobi_preconditioner.hpp"

#include <string>

namespace altfem {

std::unique_ptr<Preconditioner> make_preconditioner(std::string_view name) {
  if (name == "none") return std::make_unique<IdentityPreconditioner>();
  if (name == "jacobi") return std::make_unique<JacobiPreconditioner>();
  if (name == "incomplete_cholesky") return std::make_unique<IncompleteCholeskyPreconditioner>();
  std::string expected;
  for (std::string_view known : preconditioner_names) expected += (expected.empty() ? "" : ", ") + std::string(known);
  throw InputError("solver preconditioner: expected one of " + expected + ", got \"" + std::string(name) + "\"");
}

}  // namespace altfem
