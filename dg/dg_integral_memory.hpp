#pragma once
// The matrices one DgLinearSystem integrated, by class of translates (dg/cell_similarity.hpp),
// kept for the system an event rebuilds (a cut, a refinement): a cell or face the event
// left alone finds its class here and takes its matrices bit for bit instead of being
// integrated again. Kaufmann et al. 2009 §9.4 recompute "only the face and edge integrals"
// a cut crosses; issue #33 asks the same of every rebuild.
//
// A class is found by the same key that groups translates within one build, so a cell the
// event moved by a translation (none does) would find it too: the matrices depend only on
// the geometry relative to the cell's centroid. What they depend on besides the geometry —
// the settings and the materials, the penalty among them — must be the same, else nothing
// is taken (integrates_as).
#include <Eigen/Core>
#include <map>
#include <vector>

#include "dg/cell_similarity.hpp"
#include "dg/dg_linear_system.hpp"

namespace altfem::dg {

/// The exact volume integrals of one class of cells (exact_element_matrices) and what the
/// system derives from them.
struct DgCellIntegrals {
  Eigen::MatrixXd stiffness;  ///< 3n × 3n
  Eigen::MatrixXd mass;       ///< n × n
  Eigen::VectorXd integrals;  ///< n: ∫ φ_a dV
  double volume = 0;
  double inverse_length = 0;  ///< area(∂K) / (6 vol(K))
};

struct DgIntegralMemory {
  DgSettings settings;
  std::vector<DgMaterial> materials;  ///< DgCellMaterials::materials (empty: the settings')
  SimilarityClasses cell_classes;     ///< the build's classifier of cells, by key
  std::vector<DgCellIntegrals> cells;
  SimilarityClasses face_classes;      ///< of faces, their structure holding the cell classes above
  std::vector<Eigen::MatrixXd> faces;  ///< per face class, (3n⁻ + 3n⁺) square
  /// The penalty's definiteness certificate (definiteness_certificate.hpp) per combination
  /// of a cell class and its faces' (2 · face class + side), those sorted, the cell class
  /// last: the largest eigenvalue it computed there. A combination of classes taken from
  /// here has the same matrices, so the same eigenvalue.
  std::map<std::vector<int>, double> certificate_ratios;

  /// True when a system with these settings and materials integrates every class as this
  /// one did (everything the matrices read besides the geometry is equal).
  bool integrates_as(const DgSettings& other_settings, const std::vector<DgMaterial>& other_materials) const;
};

}  // namespace altfem::dg
