#pragma once
// Assembles a face term that a method writes as a kernel (DG fluxes, ghost penalties,
// weak boundary conditions) over TabulatedFaces, the way ElasticAssembler assembles
// volume elements: fixed-size local matrices for the common face sizes (8 and 20 basis
// functions: two DG elements of degree 1 or 2), a dynamic path for the rest with
// per-thread scratch allocated once per face size (in the first assembly), faces
// coloured so that OpenMP threads scatter without locks, and sums in face order so
// results do not depend on the thread count.
//
// A Kernel provides, for N fixed or Eigen::Dynamic (u: #basis × 3 face-local
// displacements, in the order of FaceView::basis):
//   bool is_quadratic() const;
//   template <int N> double energy(const FaceView&, const kernel::NodeMatrix<N>& u) const;
//   template <int N> void forces(const FaceView&, const kernel::NodeMatrix<N>& u,
//                                kernel::NodeMatrix<N>& forces) const;          // ∂E/∂u_a
//   template <int N> void stiffness(const FaceView&, const kernel::NodeMatrix<N>& u,
//                                   kernel::LocalMatrix<N>& stiffness) const;   // ∂²E/∂u_ai∂u_bk
// The outputs arrive uninitialised. Face matrices are never SPD-projected: an
// interior-penalty face matrix is indefinite on its own although the assembled sum is
// positive definite for a large enough penalty (Kaufmann et al. 2009 §4.1).
#include <omp.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "shared/assembly/element_coloring.hpp"
#include "shared/assembly/energy_term.hpp"
#include "shared/assembly/local_matrices.hpp"
#include "shared/assembly/parallel_loops.hpp"
#include "shared/assembly/tabulated_faces.hpp"
#include "shared/common/error.hpp"

namespace altfem {

template <typename Kernel>
class FaceAssembler final : public EnergyTerm {
public:
  /// Keeps a reference to `faces`.
  FaceAssembler(const TabulatedFaces& faces, Kernel kernel) : FaceAssembler(&faces, std::move(kernel)) {}
  /// Lists the faces with `tabulate` now and tabulates them later: over several ranks only
  /// those this rank assembles (assemble_only), else all of them (bind). `make_kernel`
  /// builds the kernel from the listing (which has every face's basis list, no points).
  template <typename MakeKernel>
  FaceAssembler(FaceTabulator tabulate, MakeKernel&& make_kernel)
      : FaceAssembler(std::make_unique<TabulatedFaces>(tabulate([](int) { return false; })), tabulate,
                      std::forward<MakeKernel>(make_kernel)) {}

  const BasisGroups& couplings() const override { return faces_->basis_groups(); }
  void bind(const BlockSparsity& sparsity, int first_group) override {
    if (tabulate_) tabulate_faces(nullptr);  // no share was given: every face
    sparsity_ = &sparsity;
    first_group_ = first_group;
  }
  bool is_quadratic() const override { return kernel_.is_quadratic(); }
  const Kernel& kernel() const { return kernel_; }
  /// The faces this term assembles over: with a FaceTabulator, the faces of its share
  /// tabulated and the others listed.
  const TabulatedFaces& faces() const { return *faces_; }
  /// Faces are the couplings' lists, one each.
  bool assemble_only(const std::vector<char>& owned) override {
    if (static_cast<int>(owned.size()) != faces_->size())
      throw std::invalid_argument("FaceAssembler::assemble_only: one entry per face expected");
    if (tabulate_) tabulate_faces([&owned](int f) { return owned[f] != 0; });
    owned_ = owned;
    for (std::vector<int>& color : colors_) std::erase_if(color, [&](int f) { return !owned_[f]; });
    std::erase_if(colors_, [](const std::vector<int>& color) { return color.empty(); });
    return true;
  }

  double energy(const Eigen::VectorXd& displacement) const override {
    parallel::for_each_index(static_cast<size_t>(faces_->size()), active_threads(), [&](size_t index) {
      const int f = static_cast<int>(index);
      if (!owned_.empty() && !owned_[f]) {
        face_energies_[index] = 0;
        return;
      }
      const FaceView face = (*faces_)[f];
      with_local<false>(face, displacement, [&]<int N>(const kernel::NodeMatrix<N>& u, auto&) {
        face_energies_[index] = kernel_.template energy<N>(face, u);
      });
    });
    double total = 0;
    for (double value : face_energies_) total += value;
    return total;
  }

  void add_gradient(const Eigen::VectorXd& displacement, Eigen::VectorXd& gradient) const override {
    parallel::FirstFailure failure;
    parallel::for_each_colored(colors_, static_cast<size_t>(faces_->size()), active_threads(), [&](int f) {
      const FaceView face = (*faces_)[f];
      with_local<false>(face, displacement, [&]<int N>(const kernel::NodeMatrix<N>& u, auto& scratch) {
        kernel::NodeMatrix<N> fixed_forces;
        kernel::NodeMatrix<N>& forces = select<N>(fixed_forces, scratch.forces);
        kernel_.template forces<N>(face, u, forces);
        if (!forces.allFinite()) failure.record(f);
        for (int a = 0; a < face.basis_count(); ++a)
          gradient.segment<3>(3 * face.basis[a]) += forces.row(a).transpose();
      });
    });
    if (failure.item() >= 0)
      throw NumericalError("face " + std::to_string(failure.item()) + ": non-finite face forces");
  }

  void add_hessian(const Eigen::VectorXd& displacement, SparseMatrix& hessian) const override {
    if (sparsity_ == nullptr) throw std::logic_error("FaceAssembler: add_hessian before bind");
    parallel::FirstFailure failure;
    double* values = hessian.valuePtr();
    const int* outer = hessian.outerIndexPtr();
    parallel::for_each_colored(colors_, static_cast<size_t>(faces_->size()), active_threads(), [&](int f) {
      const FaceView face = (*faces_)[f];
      with_local<true>(face, displacement, [&]<int N>(const kernel::NodeMatrix<N>& u, auto& scratch) {
        kernel::LocalMatrix<N> fixed_stiffness;
        kernel::LocalMatrix<N>& stiffness = select<N>(fixed_stiffness, scratch.stiffness);
        kernel_.template stiffness<N>(face, u, stiffness);
        if (!stiffness.allFinite()) {
          failure.record(f);
          return;
        }
        kernel::scatter<N>(face.basis, sparsity_->extra_pair_offsets(first_group_ + f), stiffness, outer, values);
      });
    });
    if (failure.item() >= 0)
      throw NumericalError("face " + std::to_string(failure.item()) + ": non-finite face stiffness");
  }

private:
  FaceAssembler(const TabulatedFaces* faces, Kernel kernel)
      : faces_(faces),
        kernel_(std::move(kernel)),
        colors_(color_groups(faces->basis_groups())),
        face_energies_(static_cast<size_t>(faces->size())),
        threads_(omp_get_max_threads()),
        scratch_(std::make_unique<std::vector<Scratch>[]>(threads_)) {
    for (int t = 0; t < threads_; ++t) scratch_[t].resize(static_cast<size_t>(faces->max_face_basis()) + 1);
  }
  template <typename MakeKernel>
  FaceAssembler(std::unique_ptr<TabulatedFaces> listed, FaceTabulator tabulate, MakeKernel&& make_kernel)
      : FaceAssembler(listed.get(), make_kernel(*listed)) {
    own_faces_ = std::move(listed);
    tabulate_ = std::move(tabulate);
  }

  // Replaces the listing by the tabulation of the faces `here` holds (all for empty).
  void tabulate_faces(const TabulatedHere& here) {
    TabulatedFaces tabulated = tabulate_(here);
    if (tabulated.size() != own_faces_->size())
      throw std::logic_error("FaceAssembler: the tabulator listed and tabulated different faces");
    *own_faces_ = std::move(tabulated);
    tabulate_ = nullptr;
  }

  struct Scratch {
    kernel::NodeMatrix<Eigen::Dynamic> u, forces;
    kernel::LocalMatrix<Eigen::Dynamic> stiffness;
  };

  int active_threads() const { return std::min(threads_, omp_get_max_threads()); }

  // The fixed-size object for a fixed N, else the thread's scratch (an empty
  // fixed-size matrix costs nothing: its storage is on the stack).
  template <int N, typename Fixed, typename Dynamic>
  static Fixed& select(Fixed& fixed, Dynamic& dynamic) {
    if constexpr (N == Eigen::Dynamic) return dynamic;
    else return fixed;
  }

  // Gathers the face's displacements into a matrix of the right size and calls
  // body<N>(u, scratch). With `needs_matrix`, dynamic scratch gets its 3n × 3n size.
  template <bool needs_matrix, typename Body>
  void with_local(const FaceView& face, const Eigen::VectorXd& displacement, Body&& body) const {
    const int n = face.basis_count();
    Scratch& scratch = scratch_[omp_get_thread_num()][n];
    const auto run = [&]<int N>() {
      if constexpr (N == Eigen::Dynamic) {
        // No-ops once this thread has met a face of n functions.
        scratch.u.resize(n, 3);
        scratch.forces.resize(n, 3);
        if constexpr (needs_matrix) scratch.stiffness.resize(3 * n, 3 * n);
        kernel::gather<N>(face.basis, displacement, scratch.u);
        body.template operator()<N>(scratch.u, scratch);
      } else {
        kernel::NodeMatrix<N> u;
        kernel::gather<N>(face.basis, displacement, u);
        body.template operator()<N>(u, scratch);
      }
    };
    switch (n) {
      case 8: run.template operator()<8>(); break;
      case 20: run.template operator()<20>(); break;
      default: run.template operator()<Eigen::Dynamic>(); break;
    }
  }

  const TabulatedFaces* faces_;
  std::unique_ptr<TabulatedFaces> own_faces_;  // with a FaceTabulator: the listing, then the tabulation
  FaceTabulator tabulate_;                     // until the faces are tabulated
  Kernel kernel_;
  std::vector<std::vector<int>> colors_;  // the owned faces, by colour
  std::vector<char> owned_;               // empty: every face
  const BlockSparsity* sparsity_ = nullptr;
  int first_group_ = 0;
  mutable std::vector<double> face_energies_;
  int threads_ = 1;
  // Per thread, one scratch per face size n (indexed by n), sized when the thread first
  // meets a dynamic face of that size: resizing one scratch between faces of different
  // sizes would reallocate at every change, i.e. in every assembly.
  std::unique_ptr<std::vector<Scratch>[]> scratch_;
};

}  // namespace altfem
