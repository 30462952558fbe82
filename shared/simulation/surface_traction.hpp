#pragma once
// Surface loads of a scene (`loads.traction`, docs/scene-schema.md "Loads"): dead
// tractions and pressures on the surface a method deforms, integrated against any
// method's basis through its ElementBasisEvaluator, so fem, fcm, dg and harmonic share
// one implementation.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
#include <string>

#include "shared/mesh/surface_mesh.hpp"
#include "shared/scene/scene.hpp"
#include "shared/simulation/basis_embedding.hpp"
#include "shared/simulation/surface_lift.hpp"

namespace altfem {

class MethodInstance;

/// Quadrature points on a surface and the force each carries, F_q = w_q t(x_q) with w_q
/// its area weight.
struct SurfaceForcePoints {
  Eigen::MatrixXd points;  ///< #points × 3
  Eigen::MatrixXd forces;  ///< #points × 3 [N]
};

/// The force points of one surface load at full load (factor 1): every triangle of
/// `surface` whose centroid `load.region` holds (within `tolerance`), integrated with a
/// triangle rule of strength 6 — exact for every polynomial basis of altfem restricted
/// to a plane (Hex27's triquadratic functions reach degree 6). A triangle that crosses
/// the evaluator's cells is split along them when their bounding boxes tile it (the
/// axis-aligned cells of fcm's grid), so that each piece meets one polynomial. With a
/// `lift`, each selected triangle is integrated on the curved surface it stands for
/// instead (points, area and, for a pressure, normals from the lift; no splitting: a
/// lifted triangle is a face of one cell) with a rule of strength 10, exact for a
/// pressure on a curved Hex27 face. Throws InputError
/// "file: <load.pointer>/region: ..." when no triangle is selected.
SurfaceForcePoints surface_force_points(const SurfaceMesh& surface, const SurfaceTraction& load,
                                        const ElementBasisEvaluator& evaluator, double tolerance,
                                        const std::string& file, const SurfaceLift& lift = {});

/// The load vectors of surface loads, integrated once, scaled by their ramps at a time.
class SurfaceTractionLoad {
public:
  /// One load vector (#dofs) per entry of `loads`, on `surface` (lifted by `lift`) in
  /// `evaluator`'s basis.
  SurfaceTractionLoad(const std::vector<SurfaceTraction>& loads, const SurfaceMesh& surface,
                      const ElementBasisEvaluator& evaluator, int dof_count, double tolerance, const std::string& file,
                      const SurfaceLift& lift = {});
  /// Σ_i factor_i(t) f_i (#dofs), f_(i,3a+k) = Σ_T ∫_T t_k φ_a dA.
  Eigen::VectorXd operator()(double time) const;

private:
  std::vector<SurfaceTraction> loads_;
  Eigen::MatrixXd vectors_;  // #dofs × #loads
};

/// The scene's surface loads on a method, as a load vector at a time; empty when the
/// scene has none. Region tolerance: the scene's (region_tolerance of the geometry's bounds).
std::function<Eigen::VectorXd(double)> surface_traction_load(const Scene& scene,
                                                             const Eigen::AlignedBox3d& geometry_bounds,
                                                             const MethodInstance& method);

}  // namespace altfem
