#include "shared/cut_cells/ghost_penalty_faces.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <string>
#include <utility>

#include "shared/assembly/face_assembler.hpp"
#include "shared/assembly/ghost_penalty_kernel.hpp"
#include "shared/assembly/parallel_loops.hpp"
#include "shared/assembly/tabulated_here.hpp"
#include "shared/common/error.hpp"
#include "shared/element/element_faces.hpp"
#include "shared/element/geometry_map.hpp"
#include "shared/fem/constrain_lagrange_elements.hpp"
#include "shared/mesh/face_neighbours.hpp"
#include "shared/quadrature/reference_rules.hpp"

namespace altfem {

namespace {

struct CellFace {
  int cell, face;
};

// A point of the face rule in the minus cell's reference coordinates with the
// derivatives of that parametrisation: triangles affinely from the unit triangle,
// quadrilaterals bilinearly from [-1, 1]² (corners in cyclic order).
struct FacePoint {
  Eigen::Vector3d xi, d_xi_ds, d_xi_dt;
};
FacePoint face_point(const std::vector<Eigen::Vector3d>& corners, double s, double t) {
  if (corners.size() == 3)
    return {corners[0] + s * (corners[1] - corners[0]) + t * (corners[2] - corners[0]), corners[1] - corners[0],
            corners[2] - corners[0]};
  const std::array<double, 4> value{(1 - s) * (1 - t) / 4, (1 + s) * (1 - t) / 4, (1 + s) * (1 + t) / 4,
                                    (1 - s) * (1 + t) / 4};
  const std::array<double, 4> d_s{-(1 - t) / 4, (1 - t) / 4, (1 + t) / 4, -(1 + t) / 4};
  const std::array<double, 4> d_t{-(1 - s) / 4, -(1 + s) / 4, (1 + s) / 4, (1 - s) / 4};
  FacePoint point{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  for (int c = 0; c < 4; ++c) {
    point.xi += value[c] * corners[c];
    point.d_xi_ds += d_s[c] * corners[c];
    point.d_xi_dt += d_t[c] * corners[c];
  }
  return point;
}

Eigen::MatrixXd cell_nodes(const VolumeMesh& mesh, int cell) {
  Eigen::MatrixXd nodes(mesh.cells.cols(), 3);
  for (Eigen::Index a = 0; a < mesh.cells.cols(); ++a) nodes.row(a) = mesh.nodes.row(mesh.cells(cell, a));
  return nodes;
}

// The corners of a cell's local face in its reference coordinates, in cyclic order.
std::vector<Eigen::Vector3d> reference_face_corners(const ReferenceElement& element, int face) {
  std::vector<Eigen::Vector3d> corners;
  const ElementShape shape = element.shape();
  for (int c = 0; c < face_corner_count(shape); ++c)
    corners.push_back(element.nodes().row(element_faces(shape)[face][c]).transpose());
  return corners;
}

// The coarser cell whose face holds all of `cell`'s face `face`, or −1: on a refined grid
// a finer cell's face lies within a coarser neighbour's, which no matching of corner nodes
// finds. A finer face shares a corner (a node) with the coarser face it lies on, so the
// candidates are the cells holding one of its nodes; the one found holds a point just
// across the face's centre and every corner of the face. A coarser face has no such cell
// (its corners lie in several finer cells), so each pair is found once, from its finer side.
int coarser_cell_across(const VolumeMesh& mesh, const ReferenceElement& element,
                        const std::vector<std::vector<int>>& cells_of_node, int cell, int face) {
  const Eigen::MatrixXd nodes = cell_nodes(mesh, cell);
  const std::vector<Eigen::Vector3d> corners = reference_face_corners(element, face);
  const FacePoint centre =
      face_point(corners, corners.size() == 3 ? 1.0 / 3 : 0.0, corners.size() == 3 ? 1.0 / 3 : 0.0);
  const Eigen::Matrix3d jacobian = map_jacobian(element, nodes, centre.xi);
  Eigen::Vector3d normal = (jacobian * centre.d_xi_ds).cross(jacobian * centre.d_xi_dt).normalized();
  const Eigen::Vector3d x = map_to_physical(element, nodes, centre.xi);
  const Eigen::Vector3d cell_centre = nodes.colwise().mean().transpose();
  if (normal.dot(x - cell_centre) < 0) normal = -normal;
  const Eigen::Vector3d probe = x + 1e-6 * (x - cell_centre).norm() * normal;

  std::vector<int> candidates;
  for (const int local : element_faces(element.shape())[face])
    for (const int other : cells_of_node[mesh.cells(cell, local)])
      if (other != cell) candidates.push_back(other);
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  for (const int other : candidates) {
    const Eigen::MatrixXd other_nodes = cell_nodes(mesh, other);
    const InverseMapResult across = map_to_reference(element, other_nodes, probe);
    if (!across.converged || !element.contains(across.xi, 0)) continue;
    const bool holds_face = std::all_of(corners.begin(), corners.end(), [&](const Eigen::Vector3d& corner) {
      const InverseMapResult located = map_to_reference(element, other_nodes, map_to_physical(element, nodes, corner));
      return located.converged && element.contains(located.xi, 1e-8);
    });
    if (holds_face) return other;
  }
  return -1;
}

// The interior faces of the mesh: both (cell, local face) pairs of each shared face, in
// the order of their second sides; with `hanging` nodes (a refined grid), then each finer
// face on a coarser cell's face as (finer cell and face, coarser cell), in cell order.
std::vector<std::array<CellFace, 2>> interior_faces(const VolumeMesh& mesh, bool hanging) {
  const auto face_count = static_cast<int>(element_faces(element_shape(mesh.element_type)).size());
  const std::vector<FaceNeighbour> neighbours = face_neighbours(mesh);
  std::vector<std::array<CellFace, 2>> pairs;
  for (int cell = 0; cell < static_cast<int>(mesh.cells.rows()); ++cell)
    for (int f = 0; f < face_count; ++f) {
      const FaceNeighbour across = neighbours[static_cast<std::size_t>(cell) * face_count + f];
      if (across.cell >= 0 && std::pair(across.cell, across.face) < std::pair(cell, f))
        pairs.push_back({CellFace{across.cell, across.face}, CellFace{cell, f}});
    }
  if (!hanging) return pairs;

  std::vector<std::vector<int>> cells_of_node(static_cast<size_t>(mesh.nodes.rows()));
  for (int cell = 0; cell < static_cast<int>(mesh.cells.rows()); ++cell)
    for (Eigen::Index a = 0; a < mesh.cells.cols(); ++a) cells_of_node[mesh.cells(cell, a)].push_back(cell);
  const ReferenceElement& element = reference_element(mesh.element_type);
  std::vector<int> coarser(neighbours.size(), -1);
#pragma omp parallel for schedule(dynamic, 64)
  for (int entry = 0; entry < static_cast<int>(neighbours.size()); ++entry)
    if (neighbours[entry].cell < 0)
      coarser[entry] = coarser_cell_across(mesh, element, cells_of_node, entry / face_count, entry % face_count);
  for (int entry = 0; entry < static_cast<int>(neighbours.size()); ++entry)
    if (coarser[entry] >= 0)
      pairs.push_back({CellFace{entry / face_count, entry % face_count}, CellFace{coarser[entry], -1}});
  return pairs;
}

// Physical values, gradients (#nodes × 3) and Hessians (#nodes × 9) of one cell's
// basis at reference point ξ. With J_mi = ∂x_m/∂ξ_i and g_a = ∇ₓφ_a:
//   ∇_ξφ_a = Jᵀ g_a,   ∇_ξ²φ_a = Jᵀ Hₓφ_a J + Σ_m g_am ∇_ξ²x_m,
// hence Hₓφ_a = J^{-T} (∇_ξ²φ_a − Σ_m g_am ∇_ξ²x_m) J^{-1} (the last term vanishes for
// the affine maps of structured grids).
// One side's basis at a point, with the work arrays it is computed in: made once per face,
// so that its points allocate nothing.
struct SideDerivatives {
  explicit SideDerivatives(int n)
      : values(n), gradients(n, 3), hessians(n, 9), reference_gradients(n, 3), reference_hessians(n, 9) {}
  Eigen::VectorXd values;
  Eigen::MatrixXd gradients, hessians;
  Eigen::MatrixXd reference_gradients, reference_hessians;
};
void side_derivatives(const ReferenceElement& element, const Eigen::MatrixXd& nodes, const Eigen::Vector3d& xi,
                      SideDerivatives& side) {
  const int n = element.node_count();
  element.evaluate(xi, side.values);
  element.evaluate_gradients(xi, side.reference_gradients);
  element.evaluate_hessians(xi, side.reference_hessians);
  const Eigen::Matrix3d jacobian = nodes.transpose() * side.reference_gradients;
  const Eigen::Matrix3d inverse = jacobian.inverse();
  side.gradients.noalias() = side.reference_gradients * inverse;
  std::array<Eigen::Matrix3d, 3> map_hessians;  // ∇_ξ²x_m
  for (int m = 0; m < 3; ++m) {
    const Eigen::Matrix<double, 1, 9> flat = nodes.col(m).transpose() * side.reference_hessians;
    for (int c = 0; c < 9; ++c) map_hessians[m](c / 3, c % 3) = flat[c];
  }
  for (int a = 0; a < n; ++a) {
    Eigen::Matrix3d reference;
    for (int c = 0; c < 9; ++c) reference(c / 3, c % 3) = side.reference_hessians(a, c);
    for (int m = 0; m < 3; ++m) reference -= side.gradients(a, m) * map_hessians[m];
    const Eigen::Matrix3d physical = inverse.transpose() * reference * inverse;
    for (int c = 0; c < 9; ++c) side.hessians(a, c) = physical(c / 3, c % 3);
  }
}

// One face's tabulation, as TabulatedFaces::add takes it.
struct FaceTabulation {
  std::vector<int> basis;
  std::vector<double> weights;
  Eigen::MatrixXd normals, values_minus, values_plus, gradients_minus, gradients_plus, hessians_minus, hessians_plus;
};

// A face's functions with every hanging node replaced by its masters (substitute_hanging,
// as a cell's tabulation does): values N S and each point's gradients and Hessians Sᵀ G —
// the traces of the constrained space's basis functions. A face listed only (held
// elsewhere) has its basis list substituted alone.
void substitute_hanging_nodes(FaceTabulation& face, const NodeConstraints& constraints) {
  if (!any_hanging(face.basis, constraints)) return;
  std::vector<int> basis;
  Eigen::MatrixXd substitution;  // #nodes × #basis
  substitute_hanging(face.basis, constraints, basis, substitution);
  face.basis = std::move(basis);
  if (face.weights.empty()) return;
  const Eigen::Index n = substitution.rows(), m = substitution.cols(), points = face.values_minus.rows();
  face.values_minus = face.values_minus * substitution;
  face.values_plus = face.values_plus * substitution;
  const auto per_point = [&](Eigen::MatrixXd& rows) {  // (#points·n) × c → (#points·m) × c, point-major
    if (rows.rows() == 0) return;
    Eigen::MatrixXd combined(points * m, rows.cols());
    for (Eigen::Index q = 0; q < points; ++q)
      combined.middleRows(q * m, m) = substitution.transpose() * rows.middleRows(q * n, n);
    rows = std::move(combined);
  };
  per_point(face.gradients_minus), per_point(face.gradients_plus);
  per_point(face.hessians_minus), per_point(face.hessians_plus);
}

}  // namespace

GhostPenaltyFaces ghost_penalty_faces(const VolumeMesh& mesh, const std::vector<double>& volume_fractions,
                                      const TabulatedHere& here, const NodeConstraints* constraints) {
  const bool hanging = constraints && !constraints->empty();
  const ReferenceElement& element = reference_element(mesh.element_type);
  const ElementShape shape = element.shape();
  const int degree = element.degree();
  const QuadratureRule rule = shape == ElementShape::tetrahedron ? triangle_rule(2 * degree) : quad_rule(2 * degree);
  const auto points = static_cast<int>(rule.weights.size());
  const int n_cell = element.node_count();
  const int corner_count = face_corner_count(shape);

  std::vector<std::array<CellFace, 2>> pairs = interior_faces(mesh, hanging);
  std::erase_if(pairs, [&](const std::array<CellFace, 2>& pair) {
    return volume_fractions[pair[0].cell] >= 1 && volume_fractions[pair[1].cell] >= 1;
  });
  const auto face_count = static_cast<int>(pairs.size());
  const std::vector<char> held = tabulated_here(here, face_count);
  std::vector<FaceTabulation> tabulations(static_cast<size_t>(face_count));
  std::vector<double> sizes(static_cast<size_t>(face_count));
  parallel::FirstFailure failure;
#pragma omp parallel for schedule(dynamic, 16)
  for (int f = 0; f < face_count; ++f) {
    const auto& [minus, plus] = pairs[f];
    const Eigen::MatrixXd minus_nodes = cell_nodes(mesh, minus.cell), plus_nodes = cell_nodes(mesh, plus.cell);
    FaceTabulation& face = tabulations[f];

    // The face's functions: the minus cell's nodes, then the plus cell's others.
    std::vector<int>& basis = face.basis;
    for (int a = 0; a < n_cell; ++a) basis.push_back(mesh.cells(minus.cell, a));
    std::vector<int> plus_local(static_cast<size_t>(n_cell));
    for (int a = 0; a < n_cell; ++a) {
      const int node = mesh.cells(plus.cell, a);
      const auto found = std::find(basis.begin(), basis.end(), node);
      plus_local[a] = static_cast<int>(found - basis.begin());
      if (found == basis.end()) basis.push_back(node);
    }
    const auto n = static_cast<Eigen::Index>(basis.size());

    std::vector<Eigen::Vector3d> corners;
    double size = 0;
    for (int c = 0; c < corner_count; ++c) {
      const int corner = element_faces(shape)[minus.face][c];
      corners.push_back(element.nodes().row(corner).transpose());
      const int next = element_faces(shape)[minus.face][(c + 1) % corner_count];
      size = std::max(size, (minus_nodes.row(corner) - minus_nodes.row(next)).norm());
    }
    sizes[f] = size;
    if (!held[f]) continue;
    const Eigen::Vector3d centre_offset = plus_nodes.colwise().mean() - minus_nodes.colwise().mean();

    face.weights.resize(static_cast<size_t>(points));
    face.normals.resize(points, 3);
    face.values_minus = Eigen::MatrixXd::Zero(points, n), face.values_plus = Eigen::MatrixXd::Zero(points, n);
    face.gradients_minus = Eigen::MatrixXd::Zero(points * n, 3), face.gradients_plus = face.gradients_minus;
    face.hessians_minus = Eigen::MatrixXd::Zero(degree < 2 ? 0 : points * n, 9),
    face.hessians_plus = face.hessians_minus;
    SideDerivatives from_minus(n_cell), from_plus(n_cell);
    for (int q = 0; q < points; ++q) {
      const FacePoint point = face_point(corners, rule.points(q, 0), rule.points(q, 1));
      const Eigen::Vector3d x = map_to_physical(element, minus_nodes, point.xi);
      const Eigen::Matrix3d jacobian = map_jacobian(element, minus_nodes, point.xi);
      const Eigen::Vector3d cross = (jacobian * point.d_xi_ds).cross(jacobian * point.d_xi_dt);
      face.weights[q] = rule.weights[q] * cross.norm();
      const Eigen::Vector3d normal = cross.normalized();
      face.normals.row(q) = (normal.dot(centre_offset) >= 0 ? normal : -normal).transpose();

      const InverseMapResult located = map_to_reference(element, plus_nodes, x);
      if (!located.converged || !element.contains(located.xi, 1e-8)) {
        failure.record(f);
        break;
      }
      side_derivatives(element, minus_nodes, point.xi, from_minus);
      side_derivatives(element, plus_nodes, located.xi, from_plus);
      for (int a = 0; a < n_cell; ++a) {
        const int b = plus_local[a];
        face.values_minus(q, a) = from_minus.values[a];
        face.values_plus(q, b) = from_plus.values[a];
        face.gradients_minus.row(q * n + a) = from_minus.gradients.row(a);
        face.gradients_plus.row(q * n + b) = from_plus.gradients.row(a);
        if (degree < 2) continue;  // first derivatives suffice (GhostPenaltyKernel sums k = 1..p)
        face.hessians_minus.row(q * n + a) = from_minus.hessians.row(a);
        face.hessians_plus.row(q * n + b) = from_plus.hessians.row(a);
      }
    }
  }
  if (failure.item() >= 0) {
    const auto& [minus, plus] = pairs[failure.item()];
    throw NumericalError("ghost penalty: a point of the face between cells " + std::to_string(minus.cell) + " and " +
                         std::to_string(plus.cell) + " is not in the cell across the face");
  }

  GhostPenaltyFaces result;
  result.sizes = std::move(sizes);
  for (int f = 0; f < face_count; ++f) {
    FaceTabulation& face = tabulations[f];
    if (hanging) substitute_hanging_nodes(face, *constraints);
    if (!held[f]) result.faces.add_held_elsewhere(face.basis, pairs[f][0].cell, pairs[f][1].cell);
    else
      result.faces.add(face.basis, face.weights, face.normals, face.values_minus, face.values_plus,
                       face.gradients_minus, face.gradients_plus, pairs[f][0].cell, pairs[f][1].cell,
                       face.hessians_minus, face.hessians_plus);
    face = FaceTabulation{};  // freed as it is packed
  }
  return result;
}

std::unique_ptr<EnergyTerm> ghost_penalty_term(const GhostPenaltyFaces& faces, ElementType type,
                                               const std::vector<int>& cell_materials,
                                               const std::vector<const Material*>& materials, double gamma,
                                               FaceTabulator tabulate) {
  const auto modulus = [&](int cell) {
    const LameParameters lame = materials[cell_materials[cell]]->lame();
    return lame.lambda + 2 * lame.mu;
  };
  std::vector<double> penalties;
  for (int f = 0; f < faces.faces.size(); ++f)
    penalties.push_back(gamma * 0.5 * (modulus(faces.faces[f].minus) + modulus(faces.faces[f].plus)));
  const int degree = element_degree(type);
  if (tabulate)
    return std::make_unique<FaceAssembler<GhostPenaltyKernel>>(std::move(tabulate), [&](const TabulatedFaces& listed) {
      return GhostPenaltyKernel(listed, std::move(penalties), faces.sizes, degree);
    });
  return std::make_unique<FaceAssembler<GhostPenaltyKernel>>(
      faces.faces, GhostPenaltyKernel(faces.faces, std::move(penalties), faces.sizes, degree));
}

}  // namespace altfem
