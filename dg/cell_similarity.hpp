#pragma once
// Classes of DG cells and faces that are translates of each other, so that their exactly
// integrated matrices are computed once per class (the idea of deal.II's
// CellSimilarity::translation in FEValues, which skips recomputing shape data for a cell
// that is a translate of the previous one). DG's monomials are centred at the cell's
// centroid and scaled by its size (Kaufmann et al. 2009 §5), so every volume integral of
// eqs. (23), the mass and ∫ φ_a depends only on the cell's geometry relative to its
// centroid, and every face integral of eqs. (24)-(26) only on the face and the two
// centroids relative to the minus cell's centroid: the interior cells of a hexahedral
// slicing (and of any grid) fall into a handful of classes.
//
// A key holds what a matrix depends on, made translation invariant: integers compared
// exactly (face loops, material, the classes of the cells a face joins) and coordinates
// (positions relative to a centroid) compared within a tolerance. Keys are hashed with
// their coordinates quantised on a grid much coarser than the tolerance and every
// candidate of the same hash is verified coordinate by coordinate, so a class is never
// shared by keys farther apart than the tolerance (no false hit); two keys within the
// tolerance that straddle a quantisation step fall into two classes (a missed hit, with
// probability ~ tolerance / step ~ 1e-6 per coordinate), which costs one recomputation.
#include <cstddef>
#include <unordered_map>
#include <vector>

#include "shared/geometry/polyhedron.hpp"

namespace altfem::dg {

struct SimilarityKey {
  std::vector<int> structure;       ///< compared exactly
  std::vector<double> coordinates;  ///< compared within `tolerance`
  /// The size of what the coordinates describe (a cell's diameter): the hash quantises
  /// coordinates in steps of 2⁻²⁰ length, so it must agree between similar keys up to
  /// round-off.
  double length = 1;
  /// The largest difference of a coordinate between similar keys, absolute (the larger
  /// of the two keys' tolerances is used).
  double tolerance = 0;
};

/// The tolerance for coordinates that are differences of positions of size up to
/// `magnitude` describing something of size `length`: relative_tolerance · length, plus
/// the round-off of the differences (16 ε · magnitude), so that translates far from the
/// origin are still recognised. relative_tolerance: e.g. 1e-12.
double similarity_tolerance(double length, double magnitude, double relative_tolerance);

/// The key of a cell's geometry relative to `centre` (its centroid), independent of how
/// the cell numbers its vertices and orders its faces: vertices sorted by their position
/// relative to the centre (on the hash's grid), each face loop from its lowest vertex,
/// loops sorted. structure = vertex count, then each face's size and vertex indices, then
/// `extra` (a material id, say); coordinates = the sorted vertices − centre; length =
/// `diameter`.
SimilarityKey cell_similarity_key(const Polyhedron& cell, const Eigen::Vector3d& centre, double diameter,
                                  const std::vector<int>& extra, double relative_tolerance);

/// The key of a face between cells (or on a cell's boundary) relative to `centre` (the
/// minus cell's centroid): structure = `structure` (the classes of the cells it joins and
/// whatever else its matrix depends on exactly), then the vertex count; coordinates =
/// polygon − centre (the loop from its lowest vertex relative to the centre, orientation
/// kept), normal · length, and other_centre − centre if given (the plus cell's centroid);
/// length: the minus cell's diameter.
SimilarityKey face_similarity_key(const Eigen::MatrixXd& polygon, const Eigen::Vector3d& normal,
                                  const Eigen::Vector3d& centre, double length, const Eigen::Vector3d* other_centre,
                                  std::vector<int> structure, double relative_tolerance);

/// Assigns keys to classes: the first key of a class is its representative; a later key
/// joins the class of an earlier representative whose structure equals its own and whose
/// coordinates are all within tolerance, else it opens a new class. Disabled, every key
/// opens its own class (to compare against recomputation).
class SimilarityClasses {
public:
  explicit SimilarityClasses(bool enabled = true) : enabled_(enabled) {}

  struct Assignment {
    int index;     ///< of the class, in order of first appearance
    bool created;  ///< a new class: its matrices are to be computed
  };
  Assignment classify(SimilarityKey key);
  /// The class a key would join, without classifying it; -1 when it would open a new one
  /// (and always when disabled).
  int find(const SimilarityKey& key) const;
  int class_count() const { return class_count_; }
  /// Keys classified so far.
  int key_count() const { return key_count_; }

private:
  static std::size_t hash(const SimilarityKey& key);
  int find(const SimilarityKey& key, std::size_t code) const;
  static bool similar(const SimilarityKey& a, const SimilarityKey& b);

  bool enabled_;
  int class_count_ = 0, key_count_ = 0;
  std::unordered_multimap<std::size_t, int> buckets_;  // hash → class
  std::vector<SimilarityKey> representatives_;         // #classes when enabled
};

}  // namespace altfem::dg
