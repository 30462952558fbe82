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
};

struct SurfaceError {
  double rms = 0;  ///< sqrt(mean_i |x_i − x_ref,i|²) / diagonal
  double max = 0;  ///< max_i |x_i − x_ref,i| / diagonal
};

/// Reads the points and the "displacement" point data of a VTU written by write_vtu
/// (appended raw data, UInt64 headers, Float64 values). Throws InputError naming the
/// file if it is not such a file.
SurfaceFrame read_surface_frame(const std::filesystem::path& file);

/// Error of `deformed` [n × 3] against `reference_deformed` [n × 3], relative to the
/// bounding-box diagonal of the reference's rest positions `reference_rest` [n × 3].
/// Throws InputError when the vertex counts differ (not the same embedded surface).
SurfaceError surface_error(const Eigen::MatrixX3d& deformed, const Eigen::MatrixX3d& reference_deformed,
                           const Eigen::MatrixX3d& reference_rest);

}  // namespace altfem
