#pragma once
// Test shapes for intersection quadrature, each given twice: as a tetrahedral mesh (what
// is clipped) and as a closed polyhedron (whose exact moments polyhedron_moments gives).
#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "shared/geometry/clip_convex.hpp"
#include "shared/geometry/polyhedron.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem::fcm::testing {

struct EmbeddedShape {
  std::string name;
  VolumeMesh tetrahedra;  ///< Tet4
  Polyhedron boundary;
};

/// A tetrahedron (0,0,0),(a,0,0),(0,a,0),(0,0,a); a box [0,a]³; the non-convex L-prism
/// of the boxes [0,2a]×[0,a]×[0,a] and [0,a]×[a,2a]×[0,a]. All touch the planes x = 0,
/// y = 0, z = 0 with faces, and the coordinate axes with edges and vertices.
std::vector<EmbeddedShape> corner_shapes(double a);

/// The shape moved by x ↦ map(x) (an orientation-preserving affine map).
EmbeddedShape mapped(const EmbeddedShape& shape, const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& map);

/// The tetrahedra of a Tet4 mesh as corner matrices.
std::vector<TetrahedronCorners> corner_matrices(const VolumeMesh& mesh);

}  // namespace altfem::fcm::testing
