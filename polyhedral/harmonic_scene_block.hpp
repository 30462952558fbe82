#pragma once
// The `harmonic` block of a scene (docs/scene-schema.md, "harmonic"): its rules, the
// defaults that depend on the geometry, and the plain options the harmonic method reads.
#include <array>
#include <filesystem>
#include <string_view>

#include "polyhedral/harmonic_cell_rule.hpp"
#include "polyhedral/mfs_options.hpp"
#include "shared/fem/polyhedral_scene_mesh.hpp"
#include "shared/scene/method_scene_block.hpp"

namespace altfem::harmonic {

/// Where the polyhedral mesh comes from. `convert`: a tet or hex mesh built like fem's
/// (its block under `convert`), converted cell by cell; `slice`: the geometry sliced by a
/// grid (Martin et al. 2008, §7; its options under `slice`, shared/scene/scene_slicing.hpp).
inline constexpr std::array<std::string_view, 2> harmonic_mesh_names{"convert", "slice"};

/// Which cells get an MFS basis. `automatic`: plain Tet4/Hex8 cells keep their closed-form
/// linear/trilinear basis (the harmonic basis of a tet, and the trilinear one that the
/// MFS basis of a hex approaches), MFS on every other polyhedron; `mfs`: MFS everywhere.
enum class HarmonicBasisKind { automatic, mfs };
inline constexpr std::array<std::string_view, 2> harmonic_basis_names{"auto", "mfs"};

struct HarmonicSpec {
  PolyhedralMeshSource mesh;  ///< `slice` (slicing set) or `convert` (the resolved fem block)
  MfsOptions mfs;             ///< edge_samples and offset from the block
  int quadrature_order = 2;   ///< strength of each cell's rule (harmonic_cell_rule, tet_rule, hex_rule)
  /// The MFS cells' rule: `rule`, `simplifier`, `subdivision_levels`, `monte_carlo_points`.
  HarmonicQuadrature quadrature;
  HarmonicBasisKind basis = HarmonicBasisKind::automatic;
  /// Corotated stiffness warping of the linear material by shape matching (§6).
  bool warping = false;
  /// A cut's new cell whose MFS fit misses its boundary data by more than this RMS (or
  /// fails) merges into a neighbour instead (cut_piece_fits.hpp).
  double cut_piece_residual = 0.1;
  /// Folder of the on-disk basis cache (harmonic_basis_cache.hpp), absolute; empty: no cache.
  std::filesystem::path cache;
};

const MethodSceneBlock& harmonic_scene_block();

/// The resolved /discretization/harmonic of `scene` as options. Throws InputError for a bad block.
HarmonicSpec harmonic_spec(const Scene& scene);

}  // namespace altfem::harmonic
