#pragma once
// One output time of a run, in memory: what run_simulation writes as volume_NNNNNN.vtu
// and surface_NNNNNN.vtu, handed to an observer as well (the Python module's
// `altfem.run` keeps every frame; docs/python.md).
#include <Eigen/Core>
#include <functional>

#include "shared/io/unstructured_grid.hpp"

namespace altfem {

struct RunFrame {
  double time = 0;  ///< the state's time (s); a static run's load factor
  /// The method's mesh at rest with point data "displacement" (#points × 3) and, where its
  /// elements are the cells, cell data "cauchy_stress" (#cells × 9, σ row by row) and
  /// "von_mises" (#cells × 1); no cells when the scene's output.volume is false.
  UnstructuredGrid volume;
  Eigen::MatrixXd surface_vertices;      ///< the embedded surface at rest, #vertices × 3 (empty: output.surface false)
  Eigen::MatrixXi surface_triangles;     ///< #triangles × 3 vertex ids
  Eigen::MatrixXd surface_displacement;  ///< #vertices × 3
};

/// Called once per frame, after its files are written.
using FrameObserver = std::function<void(RunFrame&&)>;

}  // namespace altfem
