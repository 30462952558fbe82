#include "dg/definiteness_certificate.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include "dg/dg_integral_memory.hpp"
#include "dg/face_polynomials.hpp"
#include "shared/solve/process_ranks.hpp"

namespace altfem::dg {
namespace {

constexpr int rigid_modes = 6;
constexpr double margin = 1e-8;  // far above the round-off of the eigenvalues, far below any useful penalty's slack

// ∫_f (σ(u)n)ᵀ G σ(v)n for every pair u = φ_b e_k, v = φ_a e_i of one side's functions
// (3n square, local DOF 3a + i), with that side's λ, μ.
Eigen::MatrixXd trace_matrix(const DgFace& face, const MonomialBasis& basis, const DgMaterial& material,
                             const Eigen::Matrix3d& weight) {
  const int degree = basis.degree();
  const FaceIntegrals integrals(face.polygon, degree, basis.centre(), basis.scale());
  const FunctionsInFrame functions = in_frame(basis, basis.centre(), basis.scale(), degree);
  const Eigen::Vector3d& n = face.normal;
  const Eigen::Index count = functions.values.rows(), size = 3 * basis.size();
  // Component i of σ(φ_b e_k)n = μ(δ_ik ∇φ_b·n + n_k ∂_iφ_b) + λ n_i ∂_kφ_b, as polynomials.
  std::array<Eigen::MatrixXd, 3> traction;
  for (Eigen::MatrixXd& component : traction) component = Eigen::MatrixXd::Zero(count, size);
  for (int b = 0; b < basis.size(); ++b) {
    Eigen::VectorXd normal_derivative = Eigen::VectorXd::Zero(count);
    for (int d = 0; d < 3; ++d) normal_derivative += n[d] * functions.gradients[d].col(b);
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) {
        auto column = traction[i].col(3 * b + k);
        column =
            material.mu * n[k] * functions.gradients[i].col(b) + material.lambda * n[i] * functions.gradients[k].col(b);
        if (i == k) column += material.mu * normal_derivative;
      }
  }
  Eigen::MatrixXd matrix = Eigen::MatrixXd::Zero(size, size);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (weight(i, j) != 0) matrix += weight(i, j) * integrals.products(traction[i], traction[j]);
  return matrix;
}

// G of one side of a face: ¼ T_K⁻¹ of the side's share on an interior face, (P T_f P)⁺ on a
// Dirichlet face. Empty when a share is not positive (no bound: the certificate fails).
Eigen::Matrix3d trace_weight(const DgLinearSystem& system, const DgFace& face, int cell, bool& bounded) {
  const Eigen::Vector3d& n = face.normal;
  const Eigen::Matrix3d normal_part = n * n.transpose(), tangential_part = Eigen::Matrix3d::Identity() - normal_part;
  if (face.plus >= 0) {
    const JumpPenalty share = system.side_penalty(face, cell);
    bounded = share.normal > 0 && share.tangential > 0;
    return bounded ? Eigen::Matrix3d(0.25 * (normal_part / share.normal + tangential_part / share.tangential))
                   : Eigen::Matrix3d::Zero();
  }
  Eigen::Matrix3d held = system.face_penalty(face).tensor(n);
  for (int i = 0; i < 3; ++i)
    if (!face.components[i]) held.row(i).setZero(), held.col(i).setZero();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> decomposition(held);
  const Eigen::Vector3d values = decomposition.eigenvalues();
  const double cutoff = 1e-12 * values.cwiseAbs().maxCoeff();
  Eigen::Vector3d inverse = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k)
    if (values[k] > cutoff) inverse[k] = 1 / values[k];
  // A prescribed component whose penalty vanishes leaves its traction unbounded.
  const int prescribed = static_cast<int>(face.components[0] + face.components[1] + face.components[2]);
  bounded = (inverse.array() > 0).count() == prescribed;
  return decomposition.eigenvectors() * inverse.asDiagonal() * decomposition.eigenvectors().transpose();
}

// The largest eigenvalue of N relative to A off A's rigid modes; +∞ when A has more.
double relative_eigenvalue(const Eigen::MatrixXd& stiffness, const Eigen::MatrixXd& traces) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> decomposition(stiffness);
  const Eigen::VectorXd& values = decomposition.eigenvalues();
  const Eigen::Index rest = values.size() - rigid_modes;
  if (rest <= 0 || values[rigid_modes] <= 1e-12 * values.tail(1)[0]) return std::numeric_limits<double>::infinity();
  const Eigen::MatrixXd scaled =
      decomposition.eigenvectors().rightCols(rest) * values.tail(rest).cwiseSqrt().cwiseInverse().asDiagonal();
  const Eigen::MatrixXd relative = scaled.transpose() * traces * scaled;
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(relative, Eigen::EigenvaluesOnly).eigenvalues().tail(1)[0];
}

// The ratio the build before computed for the combination `key` (this build's classes) as
// its classes there; false when a class was integrated here or the combination is new.
bool ratio_before(const DgLinearSystem& system, const std::vector<int>& key, double& ratio) {
  const std::map<std::vector<int>, double>& before = system.previous_certificate_ratios();
  if (before.empty()) return false;
  std::vector<int> there;
  there.reserve(key.size());
  for (std::size_t k = 0; k + 1 < key.size(); ++k) {
    const int face_class = system.previous_face_class(key[k] / 2);
    if (face_class < 0) return false;
    there.push_back(2 * face_class + key[k] % 2);
  }
  std::sort(there.begin(), there.end());
  const int cell_class = system.previous_cell_class(key.back());
  if (cell_class < 0) return false;
  there.push_back(cell_class);
  const auto found = before.find(there);
  if (found == before.end()) return false;
  ratio = found->second;
  return true;
}

}  // namespace

DefinitenessCertificate certify_definiteness(const DgLinearSystem& system) {
  // Each cell's sides of faces with a term, as (face class, side) pairs: faces of one class
  // are translates joining cells of the same classes, so their trace matrices are equal.
  const std::vector<DgFace>& faces = system.faces();
  std::vector<std::vector<int>> cell_sides(system.cell_count());
  std::vector<int> side_representative;  // per (face class, side): a face
  for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
    const int face_class = system.face_class(f);
    if (face_class < 0) continue;
    if (static_cast<int>(side_representative.size()) < 2 * (face_class + 1))
      side_representative.resize(2 * (face_class + 1), -1);
    for (const int side : {0, 1}) {
      const int cell = side == 0 ? faces[f].minus : faces[f].plus;
      if (cell < 0 || !system.owns_cell(cell)) continue;
      cell_sides[cell].push_back(2 * face_class + side);
      if (side_representative[2 * face_class + side] < 0) side_representative[2 * face_class + side] = f;
    }
  }
  // A cell's certificate depends on its class and its sides: one per distinct combination.
  std::map<std::vector<int>, int> combination_index;
  std::vector<int> combination_cell;
  for (int cell = 0; cell < system.cell_count(); ++cell) {
    if (!system.owns_cell(cell)) continue;  // another rank's: it holds that class's stiffness
    std::vector<int> key = cell_sides[cell];
    std::sort(key.begin(), key.end());
    key.push_back(system.cell_class(cell));
    if (combination_index.emplace(std::move(key), static_cast<int>(combination_cell.size())).second)
      combination_cell.push_back(cell);
  }

  // A combination of classes the build before had (matrices taken bit for bit) keeps its
  // ratio; only the others' sides' traces and eigenproblems are computed.
  std::vector<double> ratios(combination_cell.size(), 0);
  std::vector<char> known(combination_cell.size(), 0);
  for (const auto& [key, index] : combination_index) known[index] = ratio_before(system, key, ratios[index]);
  std::vector<char> side_needed(side_representative.size(), 0);
  for (std::size_t k = 0; k < combination_cell.size(); ++k)
    if (!known[k])
      for (const int side : cell_sides[combination_cell[k]]) side_needed[side] = 1;

  std::vector<Eigen::MatrixXd> side_traces(side_representative.size());
  std::vector<char> side_bounded(side_representative.size(), 1);
#pragma omp parallel for schedule(dynamic, 8)
  for (int s = 0; s < static_cast<int>(side_representative.size()); ++s) {
    const int f = side_representative[s];
    if (f < 0 || !side_needed[s]) continue;
    const DgFace& face = faces[f];
    const int cell = s % 2 == 0 ? face.minus : face.plus;
    bool bounded = true;
    const Eigen::Matrix3d weight = trace_weight(system, face, cell, bounded);
    side_bounded[s] = bounded;
    if (bounded) side_traces[s] = trace_matrix(face, system.basis(cell), system.material(cell), weight);
  }

#pragma omp parallel for schedule(dynamic, 4)
  for (int k = 0; k < static_cast<int>(combination_cell.size()); ++k) {
    if (known[k]) continue;
    const int cell = combination_cell[k];
    const Eigen::MatrixXd& stiffness = system.class_stiffness(system.cell_class(cell));
    Eigen::MatrixXd traces = Eigen::MatrixXd::Zero(stiffness.rows(), stiffness.cols());
    bool bounded = true;
    for (const int side : cell_sides[cell]) {
      bounded &= side_bounded[side] != 0;
      if (side_bounded[side]) traces += side_traces[side];
    }
    ratios[k] = bounded ? relative_eigenvalue(stiffness, traces) : std::numeric_limits<double>::infinity();
  }
  if (const std::shared_ptr<DgIntegralMemory> memory = system.integral_memory())
    for (const auto& [key, index] : combination_index) memory->certificate_ratios[key] = ratios[index];
  DefinitenessCertificate certificate;
  certificate.cells_checked = static_cast<int>(std::count(known.begin(), known.end(), 0));
  certificate.largest_ratio = ratios.empty() ? 0 : *std::max_element(ratios.begin(), ratios.end());
  if (ranks::distributed()) {  // each rank checked its own cells
    certificate.cells_checked = static_cast<int>(ranks::sum(static_cast<double>(certificate.cells_checked)));
    const std::vector<double> largest = ranks::gather(certificate.largest_ratio);
    certificate.largest_ratio = *std::max_element(largest.begin(), largest.end());
  }
  certificate.certified = certificate.largest_ratio <= 1 - margin;
  return certificate;
}

}  // namespace altfem::dg
