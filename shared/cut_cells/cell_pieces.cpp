#include "shared/cut_cells/cell_pieces.hpp"

#include <algorithm>
#include <array>
#include <exception>
#include <type_traits>

#include "shared/cut_cells/cell_rules.hpp"
#include "shared/cut_cells/cut_cell_rule.hpp"
#include "shared/cut_cells/tetrahedron_buckets.hpp"
#include "shared/element/element_faces.hpp"
#include "shared/io/binary_cache.hpp"
#include "shared/mesh/disjoint_sets.hpp"
#include "shared/mesh/face_neighbours.hpp"
#include "shared/solve/rank_exchange.hpp"

namespace altfem {

namespace {

/// A corner within this fraction of a cell's diagonal of a plane lies on it: the
/// clip computes its new vertices in double precision.
constexpr double plane_tolerance = 1e-9;
// Of a tetrahedron's volume, the largest part in a cell that is rounding, not material.
constexpr double rounding_fraction = 1e-12;

/// The triangles of a tetrahedron (corner indices).
constexpr std::array<std::array<int, 3>, 4> tetrahedron_triangles{{{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}}};

struct Plane {
  Eigen::Vector3d normal;  ///< unit
  double offset;           ///< normal · x on the plane
  double distance(const Eigen::Vector3d& x) const { return std::abs(normal.dot(x) - offset); }
};

/// The plane through a face's first three corners (`corners` are the cell's corner rows).
template <typename Corners>
Plane face_plane(const Corners& corners, const std::array<int, 4>& face) {
  const Eigen::Vector3d a = corners.row(face[0]).transpose(), b = corners.row(face[1]).transpose(),
                        c = corners.row(face[2]).transpose();
  const Eigen::Vector3d normal = (b - a).cross(c - a).normalized();
  return {normal, normal.dot(a)};
}

/// The contacts of a conforming mesh's cells: their faces matched by corner nodes.
std::vector<CellFaceContact> conforming_contacts(const VolumeMesh& mesh) {
  const std::vector<FaceNeighbour> adjacency = face_neighbours(mesh);
  const auto face_count = static_cast<int>(element_faces(element_shape(mesh.element_type)).size());
  std::vector<CellFaceContact> contacts;
  for (int cell = 0; cell < static_cast<int>(mesh.cells.rows()); ++cell)
    for (int f = 0; f < face_count; ++f) {
      const FaceNeighbour across = adjacency[static_cast<std::size_t>(cell) * face_count + f];
      if (across.cell > cell) contacts.push_back({cell, f, across.cell, across.face});
    }
  return contacts;
}

/// An embedded tetrahedron clipped by one cell, with the areas by which the clipped
/// part touches the planes of the cell's faces and of the tetrahedron's faces.
struct Fragment {
  int tetrahedron = -1;
  std::array<double, 6> cell_face_area{};
  std::array<double, 4> tetrahedron_face_area{};
};

struct CellFragments {
  std::vector<Fragment> fragments;  ///< by ascending tetrahedron
  std::vector<int> piece;           ///< per fragment
  double distance_threshold = 0;
  bool filled = false;  ///< the fragments' volume is the cell's

  /// The fragment of tetrahedron t in this cell, or −1.
  int find(int t) const {
    const auto it = std::lower_bound(fragments.begin(), fragments.end(), t,
                                     [](const Fragment& fragment, int value) { return fragment.tetrahedron < value; });
    return it != fragments.end() && it->tetrahedron == t ? static_cast<int>(it - fragments.begin()) : -1;
  }
};

/// Adds to `areas[k]` the area of every triangle of the clipped tetrahedra lying in planes[k].
template <std::size_t N>
void add_contact_areas(const std::vector<TetrahedronCorners>& clipped, const std::array<Plane, N>& planes,
                       int plane_count, double distance_threshold, std::array<double, N>& areas) {
  for (const TetrahedronCorners& piece : clipped)
    for (const auto& triangle : tetrahedron_triangles) {
      const Eigen::Vector3d a = piece.row(triangle[0]).transpose(), b = piece.row(triangle[1]).transpose(),
                            c = piece.row(triangle[2]).transpose();
      for (int k = 0; k < plane_count && k < static_cast<int>(N); ++k) {
        const Plane& plane = planes[k];
        if (plane.distance(a) <= distance_threshold && plane.distance(b) <= distance_threshold &&
            plane.distance(c) <= distance_threshold)
          areas[k] += 0.5 * (b - a).cross(c - a).norm();
      }
    }
}

/// Whether a face plane of `tetrahedron` has every corner of the cell strictly outside it
/// by far more than rounding reaches (10⁻⁹ of the two's extent): the two then share no
/// point, and clipping the tetrahedron by the cell (exact decisions) would leave nothing. A
/// filter only: what it cannot decide is clipped. Where the embedded tetrahedra are larger
/// than the cells (a refined grid, issue #34's benchmark), most candidates the bucket grid
/// hands a cell only share its bounding box, and clipping each to nothing took a quarter
/// of the piece finding.
bool separated_by_a_face(const TetrahedronCorners& tetrahedron, const Eigen::MatrixXd& corners, double extent) {
  for (int opposite = 0; opposite < 4; ++opposite) {
    const Eigen::Vector3d a = tetrahedron.row((opposite + 1) % 4).transpose(),
                          b = tetrahedron.row((opposite + 2) % 4).transpose(),
                          c = tetrahedron.row((opposite + 3) % 4).transpose();
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    // Oriented towards the outside: away from the opposite corner.
    const double inside = normal.dot(tetrahedron.row(opposite).transpose() - a);
    const double margin = 1e-9 * normal.norm() * extent;
    if (!(std::abs(inside) > margin)) continue;  // a flat tetrahedron: leave it to the clip
    const double outward = inside > 0 ? -1.0 : 1.0;
    bool all_outside = true;
    for (Eigen::Index i = 0; i < corners.rows() && all_outside; ++i)
      all_outside = outward * normal.dot(corners.row(i).transpose() - a) > margin;
    if (all_outside) return true;
  }
  return false;
}

/// The fragments of one cell and their pieces: components of face adjacency through
/// contacts of positive area inside the cell. `fragment_of` (scratch, one entry per
/// embedded tetrahedron, −1) is −1 again on return.
CellFragments cell_fragments(const VolumeMesh& background, int cell, const TetrahedronBuckets& buckets,
                             const std::vector<std::array<int, 4>>& tetrahedron_neighbours,
                             std::vector<int>& candidates, std::vector<int>& fragment_of,
                             const ClippedTetrahedronMemory* previous,
                             std::vector<std::pair<std::uint64_t, ClippedTetrahedron>>* clips) {
  const ElementType type = background.element_type;
  const ElementShape shape = element_shape(type);
  const int corner_count = element_corner_count(type);
  Eigen::MatrixXd corners(corner_count, 3);
  for (int i = 0; i < corner_count; ++i) corners.row(i) = background.nodes.row(background.cells(cell, i));
  const Eigen::AlignedBox3d box(corners.colwise().minCoeff().transpose(), corners.colwise().maxCoeff().transpose());
  CellFragments result;
  const double diagonal = box.diagonal().norm();
  result.distance_threshold = plane_tolerance * diagonal;
  buckets.candidate_indices(box, candidates);
  if (candidates.empty()) return result;

  const CellGeometry geometry(type, corners);
  const auto cell_faces = element_faces(shape);
  std::array<Plane, 6> cell_planes;
  for (std::size_t f = 0; f < cell_faces.size(); ++f) cell_planes[f] = face_plane(corners, cell_faces[f]);
  CacheKeyHasher cell_key;
  cell_key.matrix(corners);
  const auto clip = [&](const TetrahedronCorners& tetrahedron) {
    ClippedTetrahedron result_of_clip;
    const double extent = diagonal + (tetrahedron.colwise().maxCoeff() - tetrahedron.colwise().minCoeff()).norm();
    if (separated_by_a_face(tetrahedron, corners, extent)) return result_of_clip;
    const std::vector<TetrahedronCorners> clipped = clip_tetrahedron(tetrahedron, geometry.planes());
    if (clipped.empty()) return result_of_clip;
    for (const TetrahedronCorners& piece : clipped) result_of_clip.volume += tetrahedron_jacobian(piece) / 6.0;
    // A part of rounding volume is a tetrahedron whose nodes on the cell's face were
    // rounded off it (a cut's new nodes): in the cell it would be a piece of no mass.
    if (result_of_clip.volume <= rounding_fraction * tetrahedron_jacobian(tetrahedron) / 6.0)
      return ClippedTetrahedron{};
    result_of_clip.touches = true;
    add_contact_areas(clipped, cell_planes, static_cast<int>(cell_faces.size()), result.distance_threshold,
                      result_of_clip.cell_face_area);
    std::array<Plane, 4> tetrahedron_planes;
    for (int f = 0; f < 4; ++f) tetrahedron_planes[f] = face_plane(tetrahedron, tetrahedron_faces[f]);
    add_contact_areas(clipped, tetrahedron_planes, 4, result.distance_threshold, result_of_clip.tetrahedron_face_area);
    return result_of_clip;
  };
  double clipped_volume = 0;
  for (const int t : candidates) {
    const TetrahedronCorners& tetrahedron = buckets.corners(t);
    ClippedTetrahedron clipped;
    if (previous || clips) {
      CacheKeyHasher key = cell_key;
      key.matrix(tetrahedron);
      const auto known = previous ? previous->find(key.value()) : ClippedTetrahedronMemory::const_iterator{};
      clipped = previous && known != previous->end() ? known->second : clip(tetrahedron);
      if (clips) clips->emplace_back(key.value(), clipped);
    } else {
      clipped = clip(tetrahedron);
    }
    if (!clipped.touches) continue;
    clipped_volume += clipped.volume;
    result.fragments.push_back({t, clipped.cell_face_area, clipped.tetrahedron_face_area});
  }

  const int count = static_cast<int>(result.fragments.size());
  for (int i = 0; i < count; ++i) fragment_of[result.fragments[i].tetrahedron] = i;
  DisjointSets components(count);
  for (int i = 0; i < count; ++i)
    for (int f = 0; f < 4; ++f) {
      const int neighbour = tetrahedron_neighbours[result.fragments[i].tetrahedron][f];
      const int other = neighbour >= 0 ? fragment_of[neighbour] : -1;
      if (other >= 0 && result.fragments[i].tetrahedron_face_area[f] > 0) components.join(i, other);
    }
  for (const Fragment& fragment : result.fragments) fragment_of[fragment.tetrahedron] = -1;
  // Pieces numbered in order of their first (smallest) tetrahedron.
  std::vector<int> piece_of_root(static_cast<std::size_t>(count), -1);
  int pieces = 0;
  result.piece.resize(count);
  for (int i = 0; i < count; ++i) {
    int& piece = piece_of_root[components.find(i)];
    if (piece < 0) piece = pieces++;
    result.piece[i] = piece;
  }
  const double volume = geometry.volume();
  result.filled = pieces == 1 && std::abs(clipped_volume - volume) <= filled_cell_tolerance * volume;
  return result;
}

/// Whether the embedded tetrahedron's face lies in `plane`.
bool face_in_plane(const VolumeMesh& embedded, int tetrahedron, int face, const Plane& plane, double threshold) {
  for (int c = 0; c < 3; ++c)
    if (plane.distance(embedded.nodes.row(embedded.cells(tetrahedron, tetrahedron_faces[face][c])).transpose()) >
        threshold)
      return false;
  return true;
}

}  // namespace

int CellPieces::split_cells() const {
  return static_cast<int>(
      std::count_if(tetrahedra.begin(), tetrahedra.end(), [](const auto& pieces) { return pieces.size() >= 2; }));
}

int CellPieces::piece_count() const {
  int count = 0;
  for (const auto& pieces : tetrahedra) count += static_cast<int>(pieces.size());
  return count;
}

// Every rank's cells (each rank found the fragments of every count()-th, from its index)
// into every rank's `cells`.
void gather_cell_fragments(std::vector<CellFragments>& cells) {
  const auto write = [&](BinaryWriter& out, std::size_t cell) {
    const CellFragments& here = cells[cell];
    out.put<std::int64_t>(static_cast<std::int64_t>(here.fragments.size()));
    for (std::size_t i = 0; i < here.fragments.size(); ++i) {
      const Fragment& fragment = here.fragments[i];
      out.put<std::int32_t>(fragment.tetrahedron);
      out.put<std::int32_t>(here.piece[i]);
      for (const double area : fragment.cell_face_area) out.put<double>(area);
      for (const double area : fragment.tetrahedron_face_area) out.put<double>(area);
    }
    out.put<double>(here.distance_threshold);
    out.put<std::int32_t>(here.filled);
  };
  const auto read = [&](BinaryReader& in, std::size_t cell) {
    const auto read_into = [&in](auto& value) {
      const auto read = in.get<std::remove_reference_t<decltype(value)>>();
      if (read) value = *read;
      return read.has_value();
    };
    CellFragments& there = cells[cell];
    std::int64_t count = 0;
    if (!read_into(count) || count < 0) return false;
    there.fragments.resize(static_cast<std::size_t>(count));
    there.piece.resize(static_cast<std::size_t>(count));
    for (std::size_t i = 0; i < there.fragments.size(); ++i) {
      Fragment& fragment = there.fragments[i];
      if (!read_into(fragment.tetrahedron) || !read_into(there.piece[i])) return false;
      for (double& area : fragment.cell_face_area)
        if (!read_into(area)) return false;
      for (double& area : fragment.tetrahedron_face_area)
        if (!read_into(area)) return false;
    }
    std::int32_t filled = 0;
    if (!read_into(there.distance_threshold) || !read_into(filled)) return false;
    there.filled = filled != 0;
    return true;
  };
  ranks::exchange_items(cells.size(), "altfem cell fragments of a rank 1", write, read);
}

CellPieces find_cell_pieces(const VolumeMesh& background, const VolumeMesh& embedded,
                            const std::vector<CellFaceContact>* contacts, const ClippedTetrahedronMemory* previous,
                            ClippedTetrahedronMemory* remember) {
  const TetrahedronBuckets buckets(embedded);
  const std::vector<FaceNeighbour> tetrahedron_adjacency = face_neighbours(embedded);
  std::vector<std::array<int, 4>> tetrahedron_neighbours(static_cast<std::size_t>(embedded.cells.rows()));
  for (std::size_t t = 0; t < tetrahedron_neighbours.size(); ++t)
    for (int f = 0; f < 4; ++f) tetrahedron_neighbours[t][f] = tetrahedron_adjacency[4 * t + f].cell;

  const int cell_count = static_cast<int>(background.cells.rows());
  std::vector<CellFragments> cells(static_cast<std::size_t>(cell_count));
  std::exception_ptr failure;
#pragma omp parallel
  {
    std::vector<int> candidates, fragment_of(static_cast<std::size_t>(embedded.cells.rows()), -1);
    std::vector<std::pair<std::uint64_t, ClippedTetrahedron>> clips;
#pragma omp for schedule(dynamic, 4)
    for (int cell = 0; cell < cell_count; ++cell) {
      if (!ranks::computes_item(static_cast<std::size_t>(cell))) continue;  // another rank's (gathered below)
      try {
        cells[cell] = cell_fragments(background, cell, buckets, tetrahedron_neighbours, candidates, fragment_of,
                                     previous, remember ? &clips : nullptr);
      } catch (...) {
#pragma omp critical(altfem_fcm_cell_pieces_failure)
        if (!failure) failure = std::current_exception();
      }
    }
    if (remember)
#pragma omp critical(altfem_fcm_cell_pieces_memory)
      remember->insert(clips.begin(), clips.end());
  }
  // Over several ranks every rank throws the first failing rank's exception; each found
  // the fragments of every count()-th cell, most of the pieces' time, and all are gathered.
  ranks::collectively([&] {
    if (failure) std::rethrow_exception(failure);
  });
  gather_cell_fragments(cells);

  CellPieces result;
  result.tetrahedra.resize(cell_count);
  result.neighbours.resize(cell_count);
  result.filled.resize(cell_count);
  for (int cell = 0; cell < cell_count; ++cell) {
    const CellFragments& fragments = cells[cell];
    result.filled[cell] = fragments.filled;
    const int pieces =
        fragments.piece.empty() ? 0 : *std::max_element(fragments.piece.begin(), fragments.piece.end()) + 1;
    result.tetrahedra[cell].resize(pieces);
    result.neighbours[cell].resize(pieces);
    for (std::size_t i = 0; i < fragments.fragments.size(); ++i)
      result.tetrahedra[cell][fragments.piece[i]].push_back(fragments.fragments[i].tetrahedron);
  }

  // Pieces of face neighbours connected through the shared face. Where a coarse cell's face
  // touches a finer cell's, both lie in one plane and the finer face within the coarser.
  const std::vector<CellFaceContact> conforming =
      contacts ? std::vector<CellFaceContact>{} : conforming_contacts(background);
  const auto cell_faces = element_faces(element_shape(background.element_type));
  const auto link = [&](int cell, int piece, int other_cell, int other_piece) {
    result.neighbours[cell][piece].emplace_back(other_cell, other_piece);
    result.neighbours[other_cell][other_piece].emplace_back(cell, piece);
  };
  Eigen::MatrixXd corners(element_corner_count(background.element_type), 3);
  for (const CellFaceContact& contact : contacts ? *contacts : conforming) {
    const int cell = contact.cell, f = contact.face, other_cell = contact.other_cell;
    const CellFragments &here = cells[cell], &there = cells[other_cell];
    if (here.fragments.empty() || there.fragments.empty()) continue;
    for (Eigen::Index i = 0; i < corners.rows(); ++i) corners.row(i) = background.nodes.row(background.cells(cell, i));
    const Plane plane = face_plane(corners, cell_faces[f]);
    const auto touches = [&](int fragment) {
      return fragment >= 0 && there.fragments[fragment].cell_face_area[contact.other_face] > 0;
    };
    for (std::size_t i = 0; i < here.fragments.size(); ++i) {
      const Fragment& fragment = here.fragments[i];
      if (fragment.cell_face_area[f] <= 0) continue;
      // The same tetrahedron on both sides: it crosses the face.
      if (const int same = there.find(fragment.tetrahedron); touches(same))
        link(cell, here.piece[i], other_cell, there.piece[same]);
      // A neighbouring tetrahedron through a face lying in the cell face.
      for (int g = 0; g < 4; ++g) {
        const int neighbour = tetrahedron_neighbours[fragment.tetrahedron][g];
        if (neighbour < 0 || !face_in_plane(embedded, fragment.tetrahedron, g, plane, here.distance_threshold))
          continue;
        if (const int other = there.find(neighbour); touches(other))
          link(cell, here.piece[i], other_cell, there.piece[other]);
      }
    }
  }
  for (auto& pieces : result.neighbours)
    for (auto& neighbours : pieces) {
      std::sort(neighbours.begin(), neighbours.end());
      neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
    }
  return result;
}

}  // namespace altfem
