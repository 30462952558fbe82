#pragma once
// The surface error of docs/conventions.md, "Metrics": every method deforms the same
// embedded surface vertices, compared vertex by vertex with the reference run.
#include <Eigen/Core>
#include <filesystem>

namespace altfem {

/// The embedded surface of a run's last frame, as `altfem run` writes it (surface_NNNNNN.vtu).
struct SurfaceFrame {
  Eigen::MatrixX3d deformed;      ///< [vertices × 3] deformed positions (the VTU points)
  Eigen::MatrixX3d displacement;  ///< [vertices × 3] the "displacement" point data
  Eigen::MatrixXi triangles;      ///< [triangles × 3] vertex rows
};

struct SurfaceError {
  double rms = 0;  ///< sqrt(mean_i |x_i − x_ref,i|²) / diagonal
  double max = 0;  ///< max_i |x_i − x_ref,i| / diagonal
  /// sqrt(mean_i |x_i − x_ref,i|²) / sqrt(mean_i |u_ref,i|²): relative to the solution, so
  /// that a body that barely moves does not look accurate (docs/conventions.md, "Metrics").
  /// Infinite when the reference does not move.
  double relative_rms = 0;
};

/// Reads the points and the "displacement" point data of a VTU written by write_vtu
/// (appended raw data, UInt64 headers, Float64 values). Throws InputError naming the
/// file if it is not such a file.
SurfaceFrame read_surface_frame(const std::filesystem::path& file);

/// The reference's deformed positions at the rest points `rest_points` [m × 3] of another
/// run whose embedded surface differs (a shape geometry meshed per run): each point's
/// closest point on the reference's rest surface, deformed by the reference displacement
/// interpolated linearly on that triangle. Exact for a point on the reference surface when
/// the reference displacement is linear on its triangles.
Eigen::MatrixX3d reference_at(const SurfaceFrame& reference, const Eigen::MatrixX3d& rest_points);

/// The bounding-box diagonal of a frame's rest positions (deformed − displacement).
double rest_diagonal(const SurfaceFrame& frame);

/// Error of `deformed` [n × 3] against `reference_deformed` [n × 3], relative to `diagonal`
/// and to the RMS of `reference_displacement` [n × 3]. Throws InputError when the vertex
/// counts differ.
SurfaceError surface_error(const Eigen::MatrixX3d& deformed, const Eigen::MatrixX3d& reference_deformed,
                           const Eigen::MatrixX3d& reference_displacement, double diagonal);

/// A run's error against the reference: vertex by vertex on the same embedded surface,
/// else (a different surface) against reference_at its rest vertices. Relative to the
/// reference's rest_diagonal.
SurfaceError surface_error(const SurfaceFrame& run, const SurfaceFrame& reference);

}  // namespace altfem
