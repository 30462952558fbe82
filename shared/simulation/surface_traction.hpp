#pragma once
// Surface loads of a scene (`loads.traction`, docs/scene-schema.md "Loads"): dead
// tractions and pressures on the surface a method deforms, integrated against any
// method's basis through its ElementBasisEvaluator, so fem, fcm, dg and harmonic share
// one implementation.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
#include <memory>
#include <string>

#include "shared/mesh/surface_mesh.hpp"
#include "shared/scene/scene.hpp"
#include "shared/simulation/basis_embedding.hpp"
#include "shared/simulation/surface_lift.hpp"

namespace altfem {

class MethodInstance;

/// Quadrature points on a surface: where, with which outward unit normal and area weight
/// a surface load acts.
struct SurfacePoints {
  Eigen::MatrixXd points;   ///< #points × 3
  Eigen::MatrixXd normals;  ///< #points × 3, outward unit normals
  Eigen::VectorXd weights;  ///< #points [m²]
};

/// The quadrature points of one surface load: every triangle of `surface` whose centroid
/// `load.region` holds (within `tolerance`), integrated with a triangle rule of strength
/// 6 — exact for every polynomial basis of altfem restricted to a plane (Hex27's
/// triquadratic functions reach degree 6). A triangle that crosses the evaluator's cells
/// is split along them when their bounding boxes tile it (the axis-aligned cells of fcm's
/// grid), so that each piece meets one polynomial. With a `lift`, each selected triangle
/// is integrated on the curved surface it stands for instead (points, area and normals
/// from the lift; no splitting: a lifted triangle is a face of one cell) with a rule of
/// strength 10, exact for a pressure on a curved Hex27 face. Throws InputError
/// "file: <load.pointer>/region: ..." when no triangle is selected.
SurfacePoints surface_load_points(const SurfaceMesh& surface, const SurfaceTraction& load,
                                  const ElementBasisEvaluator& evaluator, double tolerance, const std::string& file,
                                  const SurfaceLift& lift = {});

/// The force F_q = w_q t(x_q, n_q, time) each point carries at full load (factor 1)
/// (#points × 3 [N]): the traction vector, the traction field, or −pressure n_q.
Eigen::MatrixXd surface_forces(const SurfaceTraction& load, const SurfacePoints& points, double time);

/// The load vectors of surface loads, scaled by their ramps at a time: integrated once,
/// except traction fields that depend on t, which are integrated again at each time on
/// the points found once.
class SurfaceTractionLoad {
public:
  /// One load per entry of `loads`, on `surface` (lifted by `lift`) in `evaluator`'s basis.
  SurfaceTractionLoad(const std::vector<SurfaceTraction>& loads, const SurfaceMesh& surface,
                      const ElementBasisEvaluator& evaluator, int dof_count, double tolerance, const std::string& file,
                      const SurfaceLift& lift = {});
  /// Σ_i factor_i(t) f_i(t) (#dofs), f_(i,3a+k) = Σ_T ∫_T t_k φ_a dA.
  Eigen::VectorXd operator()(double time) const;

private:
  struct TimeDependentLoad {
    int load;  ///< index into loads_
    SurfacePoints points;
    std::shared_ptr<const BasisEmbedding> embedding;
  };
  std::vector<SurfaceTraction> loads_;
  Eigen::MatrixXd vectors_;  // #dofs × #loads; zero columns for the time-dependent loads
  std::vector<TimeDependentLoad> time_dependent_;
};

/// The scene's surface loads on a method, as a load vector at a time; empty when the
/// scene has none. Region tolerance: the scene's (region_tolerance of the geometry's bounds).
std::function<Eigen::VectorXd(double)> surface_traction_load(const Scene& scene,
                                                             const Eigen::AlignedBox3d& geometry_bounds,
                                                             const MethodInstance& method);

}  // namespace altfem
