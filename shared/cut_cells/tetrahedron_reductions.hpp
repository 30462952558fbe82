#pragma once
// An affine cell's mass rule as its reduction alone, summed tetrahedron by tetrahedron.
// Mass rules are never simplified (Longva et al. 2020 §6); on an affine cell the masses
// are the rule's reduction Σ_q w_q N_a(ξ_q) N_b(ξ_q) times det J, which never reads the
// points again (lagrange_element_masses). The reduction is a sum over the clips of the
// cell's embedded tetrahedra (eqs. (11)–(12) put a rule on each clip), so each
// tetrahedron's share can be kept: a cut changes a few of the tetrahedra in a cell, and
// a rebuild takes the others' shares from the build before instead of clipping and
// integrating them again (the sharpened pencil's tip cell holds thousands of them).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "shared/cut_cells/cut_cell_rule.hpp"
#include "shared/fem/lagrange_element_masses.hpp"
#include "shared/io/binary_cache.hpp"

namespace altfem {

/// The reduction of one tetrahedron's clip by a cell, or of several summed.
struct TetrahedronReduction {
  ReferenceProducts products;   ///< empty (0 × 0) where the clip is empty
  double clipped_volume = 0.0;  ///< physical volume of the clip
  Eigen::Index points = 0;      ///< points of the clip's rule (the rule itself is not kept)
  int taken = 0;                ///< of the tetrahedra summed, those whose share came from a memory
};

/// Shares by a key of everything one reads: the rule's options, the cell's corners, the
/// tetrahedron's corners (a 64-bit hash, CacheKeyHasher). Held by pointer: a rebuild hands
/// the shares it takes on to the next one, about a reduction's 3.4 KB each (Hex20).
using TetrahedronReductionMemory = std::unordered_map<std::uint64_t, std::shared_ptr<const TetrahedronReduction>>;
/// (key, share) of each tetrahedron summed, in order.
using RememberedShares = std::vector<std::pair<std::uint64_t, std::shared_ptr<const TetrahedronReduction>>>;

/// A cell's tetrahedra are summed in blocks of this many, in order, and the blocks'
/// sums in order: a fixed grouping, so that a cell of many tetrahedra is summed block by
/// block by all threads and gives the bits one thread gives.
constexpr std::size_t reduction_block = 64;

/// How one cell's tetrahedra are clipped, integrated and keyed.
struct TetrahedronReductionRule {
  const CellGeometry& cell;  ///< affine
  int order = 0;             ///< strength of each clip piece's rule
  PieceFan fan = PieceFan::centroid;
  CacheKeyHasher cell_key;  ///< the options and the cell's corners hashed: each tetrahedron's key continues it
};

/// Σ over `tetrahedra`, in order, of each one's share, taken from `previous` by key where
/// it is there; with `remembered`, each tetrahedron's key and share are appended to it.
TetrahedronReduction reduce_tetrahedra(const TetrahedronReductionRule& rule,
                                       std::span<const TetrahedronCorners> tetrahedra,
                                       const TetrahedronReductionMemory* previous, RememberedShares* remembered);

/// sum += addend (an empty `products` is zero).
void add_reduction(TetrahedronReduction& sum, const TetrahedronReduction& addend);

}  // namespace altfem
