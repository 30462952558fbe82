#pragma once
// A closed, manifold, outward-oriented triangle surface, and its reader.
#include <Eigen/Core>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "shared/mesh/cutting_plane.hpp"

namespace altfem {

struct SurfaceCutRecord;

struct SurfaceMesh {
  Eigen::MatrixXd vertices;   ///< #vertices × 3
  Eigen::MatrixXi triangles;  ///< #triangles × 3, counter-clockwise seen from outside
  /// Empty, or #vertices × 3: where each vertex reads the field it moves with, relative to
  /// its position. A cut (cut_surface) sets it on the vertices of its cut, a hair inside
  /// the material they bound, so that the two copies of a point of the cut each move with
  /// their own side rather than whichever piece a point on the blade is found in.
  Eigen::MatrixXd embedding_offsets;
  /// Empty, or one per triangle: 1 on the triangles of a piece that a cut found intersecting
  /// itself (cut_surface), so that later cuts leave it whole without testing it again.
  std::vector<char> self_intersecting;
  /// Set by cut_surface: a surface and the blades that cut it into this one. A piece a
  /// finite blade notched has its two caps on one another, which corefinement cannot cut:
  /// a later blade that meets it cuts that surface again, with those blades and its own.
  std::shared_ptr<const SurfaceCutRecord> cut_record;
};

struct SurfaceCutRecord {
  SurfaceMesh before;
  std::vector<CuttingPlane> blades;
};

/// Where each vertex is embedded in a method's basis: its position plus its offset.
inline Eigen::MatrixXd embedding_points(const SurfaceMesh& surface) {
  if (surface.embedding_offsets.size() == 0) return surface.vertices;
  return surface.vertices + surface.embedding_offsets;
}

/// Reads OFF, OBJ, STL or PLY through CGAL and checks, in this order: the file exists
/// and is not empty; (OFF) header counts, finite coordinates and indices, with line
/// numbers; finite coordinates; a polygon mesh — else an orientable one (orientation
/// fixed with a warning) or a non-manifold error; closed; polygons triangulated; no
/// degenerate faces; no self-intersections; outward orientation (an inward surface is
/// flipped with a warning). Warnings ("path: what", one line each) are appended to
/// `warnings` if given. Throws InputError "path: what". Without `closed` (a blade's surface)
/// the surface may have boundary edges, and its orientation is the file's.
SurfaceMesh read_surface(const std::filesystem::path& path, std::vector<std::string>* warnings = nullptr,
                         bool closed = true);

/// Enclosed volume by the divergence theorem (positive for outward orientation).
double surface_volume(const SurfaceMesh& surface);

}  // namespace altfem
