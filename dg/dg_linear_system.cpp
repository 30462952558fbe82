#include "dg/dg_linear_system.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <exception>
#include <span>
#include <stdexcept>
#include <string>

#include "dg/cell_block_pattern.hpp"
#include "dg/cell_partition.hpp"
#include "dg/cell_similarity.hpp"
#include "dg/class_batches.hpp"
#include "dg/dg_integral_memory.hpp"
#include "dg/exact_element_matrices.hpp"
#include "dg/strong_conditions.hpp"
#include "shared/common/eigen_decompositions.hpp"
#include "shared/geometry/polygon_moments.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"
#include "shared/solve/process_ranks.hpp"

namespace altfem::dg {

namespace {

// area(∂K): the sum of the face polygons' areas.
double surface_area(const Polyhedron& cell) {
  double area = 0;
  Eigen::MatrixXd polygon;
  for (const std::vector<int>& loop : cell.faces) {
    polygon.resize(static_cast<Eigen::Index>(loop.size()), 3);
    for (size_t v = 0; v < loop.size(); ++v) polygon.row(static_cast<Eigen::Index>(v)) = cell.vertices.row(loop[v]);
    area += polygon_area_vector(polygon).norm();
  }
  return area;
}

// A class of the build before that a new class matches (-1: none), unless it is gone:
// `gone` holds the classes an earlier new class claimed (their matrices are moved out
// once; two classes here within the tolerance of one there, not of each other, leave the
// second to be integrated) and those that an earlier rebuild from the same build emptied.
int claim(int earlier, std::vector<char>& gone) {
  if (earlier < 0 || gone[earlier]) return -1;
  gone[earlier] = 1;
  return earlier;
}

// Cells and faces whose translation-invariant geometry agrees to this fraction of the
// cell's diameter share their matrices (dg/cell_similarity.hpp).
constexpr double similarity_relative_tolerance = 1e-12;
}  // namespace

DgLinearSystem::DgLinearSystem(std::vector<Polyhedron> cells, std::vector<DgFace> faces, const DgSettings& settings,
                               DgCellMaterials cell_materials, IntegralReuse reuse)
    : cells_(std::move(cells)),
      faces_(std::move(faces)),
      settings_(settings),
      cell_materials_(std::move(cell_materials)) {
  if (cell_materials_.ids.size() != (cell_materials_.materials.empty() ? 0 : cells_.size()))
    throw std::invalid_argument("DgLinearSystem: " + std::to_string(cell_materials_.ids.size()) + " material ids for " +
                                std::to_string(cell_materials_.materials.size()) + " materials and " +
                                std::to_string(cells_.size()) + " cells");
  for (int id : cell_materials_.ids)
    if (id < 0 || id >= static_cast<int>(cell_materials_.materials.size()))
      throw std::invalid_argument("DgLinearSystem: material id " + std::to_string(id) + " of " +
                                  std::to_string(cell_materials_.materials.size()) + " materials");
  for (const Polyhedron& cell : cells_) bases_.push_back(cell_monomial_basis(cell, settings.degree));
  offsets_.push_back(0);
  for (const MonomialBasis& basis : bases_) offsets_.push_back(offsets_.back() + basis.size());
  std::vector<std::vector<int>> strong_faces(cells_.size());
  for (size_t f = 0; f < faces_.size(); ++f)
    if (faces_[f].strong && faces_[f].plus < 0 && faces_[f].condition >= 0)
      strong_faces[faces_[f].minus].push_back(static_cast<int>(f));
  for (int c = 0; c < static_cast<int>(cells_.size()); ++c) {
    if (strong_faces[c].empty()) continue;
    // The constrained and free combinations of the monomials as the cell's functions.
    strong_cells_.push_back(strong_cell(c, bases_[c], faces_, strong_faces[c]));
    const StrongCell& strong = strong_cells_.back();
    // Its constrained coefficients take their values from every condition on its strong faces.
    ConditionSet conditions = 0;
    for (int f : strong_faces[c]) conditions |= condition_bit(faces_[f].condition);
    for (int j = 0; j < strong.constrained; ++j)
      for (int i = 0; i < 3; ++i)
        if (strong.components[i]) {
          constrained_dofs_.push_back(3 * (offsets_[c] + j) + i);
          constraint_holders_.push_back({conditions, conditions});
        }
    bases_[c].combine(strong.combination);
  }
  std::vector<std::array<int, 2>> couplings;
  for (const DgFace& face : faces_)
    if (face.plus >= 0) couplings.push_back({face.minus, face.plus});
  // Over several ranks each integrates its part of the cells and the faces it owns, and K
  // is their sum (docs/scaling.md): summed into every rank's copy on the whole pattern, or
  // left each rank's share, on the blocks of its cells and faces (and of the cells beyond
  // its faces); every other cell keeps only its diagonal entries, which Dirichlet
  // elimination needs of every DOF.
  std::vector<char> diagonal_only;
  if (ranks::distributed()) {
    rank_ = ranks::index();
    cell_parts_ = partition_cells(cells_, bases_, couplings, ranks::count());
    if (settings_.share_stiffness) {
      couplings.clear();
      diagonal_only.assign(cells_.size(), 1);
      for (std::size_t c = 0; c < cells_.size(); ++c)
        if (owns_cell(static_cast<int>(c))) diagonal_only[c] = 0;
      for (const DgFace& face : faces_) {
        if (!owns_face(face)) continue;
        diagonal_only[face.minus] = 0;
        if (face.plus < 0) continue;
        diagonal_only[face.plus] = 0;
        couplings.push_back({face.minus, face.plus});
      }
    }
  }
  const CellBlockPattern pattern(offsets_, couplings, std::move(diagonal_only));
  pattern.make_zero_matrix(stiffness_);
  DgIntegralMemory* previous = reuse.previous && reuse.previous->integrates_as(settings_, cell_materials_.materials)
                                   ? reuse.previous.get()
                                   : nullptr;
  if (reuse.remember && settings_.reuse_similar_cells)
    memory_ = std::make_shared<DgIntegralMemory>(DgIntegralMemory{.settings = settings_,
                                                                  .materials = cell_materials_.materials,
                                                                  .cell_classes = {},
                                                                  .cells = {},
                                                                  .face_classes = {},
                                                                  .faces = {}});
  const std::vector<int> previous_cell_classes = add_element_matrices(pattern, previous);
  add_face_matrices(pattern, previous, previous_cell_classes);
  if (previous) {
    previous_cell_classes_ = previous_cell_classes;
    previous_certificates_ = std::move(previous->certificate_ratios);
  }
  if (!cell_parts_.empty()) {
    if (!settings_.share_stiffness)
      ranks::sum(std::span<double>(stiffness_.valuePtr(), static_cast<std::size_t>(stiffness_.nonZeros())));
    distributed_mass_ = mass();
    ranks::sum(std::span<double>(distributed_mass_.valuePtr(), static_cast<std::size_t>(distributed_mass_.nonZeros())));
  }
}

std::vector<int> DgLinearSystem::add_element_matrices(const CellBlockPattern& pattern, DgIntegralMemory* previous) {
  const int cell_count = static_cast<int>(cells_.size());

  // Classes of translates of the same material (deal.II's CellSimilarity::translation);
  // a cell whose functions are combinations for its strongly held faces is a class of
  // its own, never taken from the build before (its combination is not in the key).
  SimilarityClasses cell_similarity(settings_.reuse_similar_cells);
  std::vector<int> previous_classes;  // per class
  std::vector<char> gone_cells;
  if (previous)
    for (const DgCellIntegrals& integrals : previous->cells) gone_cells.push_back(integrals.stiffness.size() == 0);
  for (int c = 0; c < cell_count; ++c) {
    const int own = bases_[c].combination().size() == 0 ? -1 : c;
    SimilarityKey key = cell_similarity_key(cells_[c], bases_[c].centre(), bases_[c].scale(), {material_id(c), own},
                                            similarity_relative_tolerance);
    const int earlier = previous && own < 0 ? previous->cell_classes.find(key) : -1;
    const SimilarityClasses::Assignment assignment = cell_similarity.classify(std::move(key));
    if (assignment.created) previous_classes.push_back(claim(earlier, gone_cells));
    cell_classes_.push_back(assignment.index);
  }
  const int class_count = cell_similarity.class_count();
  masses_.resize(class_count);
  stiffnesses_.resize(class_count);
  std::vector<Eigen::VectorXd> class_integrals(class_count);
  std::vector<double> class_volumes(class_count), class_inverse_lengths(class_count);
  if (memory_) memory_->cells.resize(class_count);
  // Stiffness, mass and ∫ φ_a once per class.
  integrals_ = Eigen::VectorXd::Zero(offsets_.back());
  volumes_.assign(cells_.size(), 0.0);
  inverse_lengths_.assign(cells_.size(), 0.0);
  std::vector<int> integrated = cell_classes_;  // -1: another rank's cell
  for (int c = 0; c < cell_count; ++c)
    if (!owns_cell(c)) integrated[c] = -1;
  for_each_item_by_class(
      integrated, class_count,
      [&](int c) {
        const int k = cell_classes_[c];
        DgCellIntegrals integrals;
        if (previous_classes[k] >= 0) {
          integrals = std::move(previous->cells[previous_classes[k]]);
        } else {
          const DgMaterial cell_material = material(c);
          ElementMatrices matrices = exact_element_matrices(cells_[c], bases_[c], cell_material.lambda,
                                                            cell_material.mu, cell_material.density);
          // ∫ m₀ dV (m₀ = 1); combined functions integrate to Cᵀ ∫ m, and C is orthogonal.
          const Eigen::MatrixXd& combination = bases_[c].combination();
          integrals.volume =
              combination.size() == 0 ? matrices.integrals[0] : combination.row(0).dot(matrices.integrals);
          integrals.inverse_length = surface_area(cells_[c]) / (6 * integrals.volume);
          integrals.integrals = std::move(matrices.integrals);
          integrals.mass = std::move(matrices.mass);
          integrals.stiffness = std::move(matrices.stiffness);
        }
        if (memory_) memory_->cells[k] = integrals;
        class_volumes[k] = integrals.volume;
        class_inverse_lengths[k] = integrals.inverse_length;
        class_integrals[k] = std::move(integrals.integrals);
        masses_[k] = std::move(integrals.mass);
        stiffnesses_[k] = std::move(integrals.stiffness);
        return stiffnesses_[k];
      },
      [&](int c, const Eigen::MatrixXd& stiffness) {
        const int k = cell_classes_[c];
        volumes_[c] = class_volumes[k];
        inverse_lengths_[c] = class_inverse_lengths[k];
        integrals_.segment(offsets_[c], bases_[c].size()) = class_integrals[k];
        pattern.add_block(stiffness_, c, c, stiffness);
      });
  if (!cell_parts_.empty()) {  // every rank needs every cell's size (the faces' penalties) and ∫ φ_a
    ranks::sum(volumes_);
    ranks::sum(inverse_lengths_);
    ranks::sum(std::span<double>(integrals_.data(), static_cast<std::size_t>(integrals_.size())));
  }
  similarity_.cells = cell_count;
  similarity_.cell_classes = class_count;
  similarity_.remembered_cell_classes =
      static_cast<int>(std::count_if(previous_classes.begin(), previous_classes.end(), [](int p) { return p >= 0; }));
  if (memory_) memory_->cell_classes = std::move(cell_similarity);
  return previous_classes;
}

void DgLinearSystem::add_face_matrices(const CellBlockPattern& pattern, DgIntegralMemory* previous,
                                       const std::vector<int>& previous_cell_classes) {
  // Face matrices once per class of faces between the same classes of cells at the same
  // relative position (their penalty η_f follows from the cells' classes and the face).
  SimilarityClasses face_similarity(settings_.reuse_similar_cells);
  std::vector<int>& face_classes = face_classes_;
  face_classes.assign(faces_.size(), -1);
  std::vector<int> previous_classes;  // per class, its class in `previous` (-1: none)
  std::vector<char> gone_faces;
  if (previous)
    for (const Eigen::MatrixXd& matrix : previous->faces) gone_faces.push_back(matrix.size() == 0);
  for (size_t f = 0; f < faces_.size(); ++f) {
    const DgFace& face = faces_[f];
    if (face.plus < 0 && (face.condition < 0 || face.strong)) continue;  // free, or held strongly: no face term
    const MonomialBasis& minus = bases_[face.minus];
    std::vector<int> structure{cell_classes_[face.minus], face.plus >= 0 ? cell_classes_[face.plus] : -1};
    structure.insert(structure.end(), face.components.begin(), face.components.end());
    SimilarityKey key = face_similarity_key(face.polygon, face.normal, minus.centre(), minus.scale(),
                                            face.plus >= 0 ? &bases_[face.plus].centre() : nullptr,
                                            std::move(structure), similarity_relative_tolerance);
    // There, the key names the cells' classes of that build.
    int earlier = -1;
    const int minus_before = previous ? previous_cell_classes[key.structure[0]] : -1;
    const int plus_before = face.plus >= 0 && minus_before >= 0 ? previous_cell_classes[key.structure[1]] : -1;
    if (minus_before >= 0 && (face.plus < 0 || plus_before >= 0)) {
      SimilarityKey there = key;
      there.structure[0] = minus_before;
      there.structure[1] = plus_before;
      earlier = previous->face_classes.find(there);
    }
    const SimilarityClasses::Assignment assignment = face_similarity.classify(std::move(key));
    if (assignment.created) previous_classes.push_back(claim(earlier, gone_faces));
    face_classes[f] = assignment.index;
  }
  if (memory_) memory_->faces.resize(face_similarity.class_count());
  std::vector<int> integrated = face_classes;  // -1: a face another rank owns
  for (std::size_t f = 0; f < faces_.size(); ++f)
    if (!owns_face(faces_[f])) integrated[f] = -1;
  for_each_item_by_class(
      integrated, face_similarity.class_count(),
      [&](int f) {
        const int k = face_classes[f];
        Eigen::MatrixXd matrix;
        if (previous_classes[k] >= 0) {
          matrix.swap(previous->faces[previous_classes[k]]);
        } else {
          const DgFace& face = faces_[f];
          const MonomialBasis* plus = face.plus >= 0 ? &bases_[face.plus] : nullptr;
          const DgMaterial minus_material = material(face.minus);
          const DgMaterial plus_material = face.plus >= 0 ? material(face.plus) : minus_material;
          matrix = exact_face_matrix(
              face.polygon, face.normal, bases_[face.minus], plus, {minus_material.lambda, minus_material.mu},
              {plus_material.lambda, plus_material.mu}, face_penalty(face), settings_.flux, face.components);
        }
        if (memory_) memory_->faces[k] = matrix;
        return matrix;
      },
      [&](int f, const Eigen::MatrixXd& matrix) {
        const DgFace& face = faces_[f];
        const Eigen::Index minus_size = 3 * bases_[face.minus].size();
        pattern.add_block(stiffness_, face.minus, face.minus, matrix.topLeftCorner(minus_size, minus_size));
        if (face.plus < 0) return;
        const Eigen::Index plus_size = matrix.rows() - minus_size;
        pattern.add_block(stiffness_, face.plus, face.minus, matrix.bottomLeftCorner(plus_size, minus_size));
        pattern.add_block(stiffness_, face.minus, face.plus, matrix.topRightCorner(minus_size, plus_size));
        pattern.add_block(stiffness_, face.plus, face.plus, matrix.bottomRightCorner(plus_size, plus_size));
      });
  similarity_.faces = face_similarity.key_count();
  similarity_.face_classes = face_similarity.class_count();
  similarity_.remembered_face_classes =
      static_cast<int>(std::count_if(previous_classes.begin(), previous_classes.end(), [](int p) { return p >= 0; }));
  if (memory_) memory_->face_classes = std::move(face_similarity);
  if (previous) previous_face_classes_ = std::move(previous_classes);
}

DgLinearSystem::~DgLinearSystem() = default;

JumpPenalty DgLinearSystem::face_penalty(const DgFace& face) const {
  JumpPenalty penalty = side_penalty(face, face.minus);
  if (face.plus < 0) return penalty;
  const JumpPenalty plus = side_penalty(face, face.plus);
  return {penalty.normal + plus.normal, penalty.tangential + plus.tangential};
}

JumpPenalty DgLinearSystem::side_penalty(const DgFace& face, int cell) const {
  // The cell's own η over its length: eq. (20)'s vol(K)/area(f), or ℓ(K) (PenaltyScaling).
  const bool by_face = settings_.scaling == PenaltyScaling::face_area;
  const double area = by_face && face.polygon.rows() >= 3 ? polygon_area_vector(face.polygon).norm() : 0.0;
  const double factor = face.plus >= 0 ? 1.0 : settings_.boundary_penalty_factor;
  const DgMaterial cell_material = material(cell);
  const double eta = factor * cell_material.penalty * (by_face ? area / volumes_[cell] : inverse_lengths_[cell]);
  return {eta, cell_material.tangential_fraction * eta};
}

DgMaterial DgLinearSystem::material(int cell) const {
  if (cell_materials_.materials.empty())
    return {settings_.lambda, settings_.mu, settings_.density, settings_.penalty, settings_.tangential_fraction};
  return cell_materials_.materials[material_id(cell)];
}

std::vector<int> DgLinearSystem::share_row_owners() const {
  if (!settings_.share_stiffness || cell_parts_.empty()) return {};
  std::vector<int> owners(static_cast<std::size_t>(offsets_.back()));
  for (std::size_t c = 0; c < cells_.size(); ++c)
    std::fill(owners.begin() + offsets_[c], owners.begin() + offsets_[c + 1], cell_parts_[c]);
  return owners;
}

Eigen::SparseMatrix<double> DgLinearSystem::mass() const {
  if (distributed_mass_.size() > 0) return distributed_mass_;
  std::vector<Eigen::Triplet<double>> triplets;
  for (size_t c = 0; c < cells_.size(); ++c) {
    const int first = offsets_[c], size = bases_[c].size();
    // Another rank's cell: its block with zeros, so that every rank's pattern is the same.
    const bool own = owns_cell(static_cast<int>(c));
    for (int a = 0; a < size; ++a)
      for (int b = 0; b < size; ++b) {
        const double value = own ? masses_[cell_classes_[c]](a, b) : 0.0;
        for (int i = 0; i < 3; ++i) triplets.emplace_back(3 * (first + a) + i, 3 * (first + b) + i, value);
      }
  }
  Eigen::SparseMatrix<double> matrix(dof_count(), dof_count());
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  return matrix;
}

}  // namespace altfem::dg
