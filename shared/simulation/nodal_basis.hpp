#pragma once
// What every method with a nodal basis (basis function i is node i: fem, harmonic, the
// FCM's background nodes) does the same way in its MethodInstance.
#include <Eigen/Core>
#include <functional>
#include <nlohmann/json.hpp>

#include "shared/io/unstructured_grid.hpp"
#include "shared/mesh/surface_mesh.hpp"
#include "shared/simulation/basis_embedding.hpp"
#include "shared/simulation/field_quadrature.hpp"

namespace altfem {

/// The coefficients (3 × #nodes) of a vector field in a nodal basis: its values at the
/// nodes (#nodes × 3).
Eigen::VectorXd interpolate_at_nodes(const Eigen::MatrixXd& nodes,
                                     const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& field);

/// Fields of a nodal basis before an event (its nodes `previous_nodes`, #old nodes × 3,
/// evaluated through `previous`; coefficients the columns of `fields`, 3·#old nodes ×
/// #fields) in the nodal basis of `nodes` (#nodes × 3; the result 3·#nodes × #fields): a
/// node at its old index and position, or at the position of exactly one old node, takes
/// that node's values bit for bit, any other the old fields at its position
/// (docs/architecture.md, "Events").
Eigen::MatrixXd transfer_to_nodes(const Eigen::MatrixXd& nodes, const Eigen::MatrixXd& previous_nodes,
                                  const ElementBasisEvaluator& previous, const Eigen::MatrixXd& fields);

/// Adds the point data "displacement" (#points × 3) of nodal coefficients u (3 × #points).
void add_nodal_displacement(UnstructuredGrid& grid, const Eigen::VectorXd& displacement);

/// A method's field quadrature from tabulated elements of a nodal basis (nodes:
/// #nodes × 3), the points placed by nodal_quadrature_points.
FieldQuadrature nodal_field_quadrature(std::shared_ptr<const TabulatedElements> elements, const Eigen::MatrixXd& nodes,
                                       int strength);

}  // namespace altfem
