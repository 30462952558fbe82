#pragma once
// The processes of one run (docs/scaling.md): `mpirun -n N altfem run …` starts N copies
// of altfem, each holding the whole scene and mesh (replicated, as deal.II's step-17 does).
// Each assembles its own elements, and these sums make every copy see the global energy,
// forces and Hessian, so the integrators run unchanged and identically on every rank;
// PETSc solves across them. Without mpirun, or in a build without PETSc (which brings
// MPI), there is one rank and every sum is the value itself.
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace altfem::ranks {

/// Starts MPI when the process was launched by mpirun (Open MPI's environment says so),
/// before anything else may call it; MPI stops at exit. Throws InputError when mpirun
/// started several processes and the build has no MPI. Without mpirun it does nothing,
/// so a plain run pays nothing for MPI.
void start();
/// The MPI library this build runs over ("Open MPI v4.1.4"); empty without MPI.
std::string library();
/// This process's rank (0 … count() − 1).
int index();
/// How many processes run the scene.
int count();
inline bool distributed() { return count() > 1; }

/// Whether the discretizations built from now on hand each rank's share of their matrices
/// to a solver that sums the shares itself (PETSc's distributed matrix), on a pattern of
/// that rank's own elements, instead of the whole matrix on every rank (docs/scaling.md).
/// Set by the run from its scene (`solver.linear: "petsc"` with Newton); it counts only
/// over several ranks.
void share_matrices(bool share);
bool shares_matrices();

/// Each entry replaced by its sum over the ranks, the same bits on every rank.
void sum(std::span<double> values);
double sum(double value);
/// Each rank's `value`, on every rank (count() entries, in rank order).
std::vector<double> gather(double value);

/// Each rank's `bytes`, on every rank (count() strings, in rank order).
std::vector<std::string> gather(const std::string& bytes);

/// Rank 0's `values` on every rank.
void broadcast(std::span<int> values);

/// While it lives, this process counts as the only rank (index 0 of 1): what a test
/// builds then is the whole problem, to compare with the ranks' sums in the same run.
class Alone {
public:
  Alone();
  ~Alone();
  Alone(const Alone&) = delete;
  Alone& operator=(const Alone&) = delete;

private:
  int index_, count_;
};

/// The failure exchange of collectively(), which calls it only over several ranks.
void collectively_over_ranks(const std::function<void()>& body);

/// Runs `body` on every rank; if it throws on any rank, every rank throws: the lowest
/// failing rank's exception, a NumericalError or InputError with its message (so that no
/// rank waits forever in a sum the failing one never reaches). On one rank it is a plain
/// call: assembly calls it every time, and a std::function of its captures would allocate.
template <typename Body>
void collectively(Body&& body) {
  if (distributed()) collectively_over_ranks(std::function<void()>(std::ref(body)));
  else body();
}

}  // namespace altfem::ranks
