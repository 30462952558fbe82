#pragma once
// An on-disk cache of a polyhedral mesh's harmonic bases (issue #19: "cached per mesh
// like the FCM's rules", shared/cut_cells/rule_cache.hpp), so a second run of a scene skips the MFS
// fits. What is stored is everything the method assembles and embeds the surface with:
// each cell's nodes, its closed-form type or its MFS kernel centres, coefficients, fit
// misfit and boundary integrals. The key is a 64-bit hash (CacheKeyHasher) of the mesh (nodes,
// face loops, face cells, cell faces, cell kinds), the basis kind, the MFS options and
// the format version; the file is written atomically and read back whole or ignored.
#include <cstdint>
#include <filesystem>

#include "polyhedral/harmonic_element_bases.hpp"

namespace altfem::harmonic {

std::uint64_t harmonic_bases_key(const PolyhedralMesh& mesh, HarmonicBasisKind kind, const MfsOptions& options);

/// HarmonicElementBases(mesh, kind, options), read from `directory`/<key>.harmonic when
/// present and complete (bit-identical to computing them), else computed and stored there
/// (the folder is created). `reused` tells which happened. Throws std::runtime_error
/// naming the path if the file cannot be written, NumericalError as the bases do.
HarmonicElementBases cached_harmonic_bases(const PolyhedralMesh& mesh, HarmonicBasisKind kind,
                                           const MfsOptions& options, const std::filesystem::path& directory,
                                           bool* reused = nullptr);

}  // namespace altfem::harmonic
