#include "polyhedral/harmonic_basis_cache.hpp"

#include "shared/io/binary_cache.hpp"

namespace altfem::harmonic {

namespace {

// v2: the fits by the normal equations (mfs_least_squares.hpp) give other bits than v1's QR.
// v3: fitted on the canonical cell (canonical_cell.hpp), linear precision restored.
constexpr char magic[] = "altfem-harmonic-bases-v3";

}  // namespace

std::uint64_t harmonic_bases_key(const PolyhedralMesh& mesh, HarmonicBasisKind kind, const MfsOptions& options) {
  CacheKeyHasher hasher;
  hasher.bytes(magic, sizeof magic);
  hasher.matrix(mesh.nodes);
  const auto lists = [&hasher](const std::vector<std::vector<int>>& lists) {
    hasher.scalar<std::int64_t>(static_cast<std::int64_t>(lists.size()));
    for (const std::vector<int>& list : lists) {
      hasher.scalar<std::int64_t>(static_cast<std::int64_t>(list.size()));
      hasher.bytes(list.data(), sizeof(int) * list.size());
    }
  };
  lists(mesh.faces);
  hasher.matrix(mesh.face_cells);
  lists(mesh.cell_faces);
  for (PolyhedralCellKind cell_kind : mesh.cell_kinds)
    hasher.scalar<std::int32_t>(static_cast<std::int32_t>(cell_kind));
  hasher.scalar<std::int32_t>(static_cast<std::int32_t>(kind));
  hasher.scalar<std::int32_t>(options.edge_samples);
  hasher.scalar<std::int32_t>(options.collocation_factor);
  hasher.scalar<double>(options.offset);
  return hasher.value();
}

HarmonicElementBases cached_harmonic_bases(const PolyhedralMesh& mesh, HarmonicBasisKind kind,
                                           const MfsOptions& options, const std::filesystem::path& directory,
                                           bool* reused) {
  const std::filesystem::path path = cache_file_path(directory, harmonic_bases_key(mesh, kind, options), ".harmonic");
  if (const auto bytes = read_cache_file(path)) {
    BinaryReader reader(*bytes, magic);
    if (auto bases = HarmonicElementBases::read(mesh, reader)) {
      if (reused) *reused = true;
      return std::move(*bases);
    }
  }
  HarmonicElementBases bases(mesh, kind, options);
  BinaryWriter writer(magic);
  bases.write(writer);
  write_cache_file(path, writer.bytes());
  if (reused) *reused = false;
  return bases;
}

}  // namespace altfem::harmonic
