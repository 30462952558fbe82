#pragma once
#include <Eigen/Core>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "shared/scene/scene.hpp"
#include "shared/solve/dirichlet_dofs.hpp"

namespace altfem {

/// Strong Dirichlet conditions on the nodes of a Lagrange basis (fem, and fcm on its
/// background nodes, Longva et al. 2020 §6): the DOFs of the nodes each condition's
/// region selects (its components only), prescribed by its motion at the node's rest
/// position. A DOF selected by several conditions follows the last one, as in the
/// scene's order. nodes: #nodes × 3 rest positions (basis function i is node i).
/// Throws InputError naming the condition when its region selects no node of
/// `mesh_name` (e.g. "the fem mesh").
///
/// `also_requires` (when given) narrows each region's choice: a node the region contains
/// is selected only if also_requires(node, region, tolerance) holds (fcm's
/// topology-aware cells: a node's copy whose material does not reach the region).
using NodeRegionFilter = std::function<bool(int node, const RegionSelector& region, double tolerance)>;
DirichletDofs nodal_dirichlet(const Eigen::MatrixXd& nodes, const std::vector<DirichletCondition>& conditions,
                              const std::string& scene_file, std::string_view mesh_name,
                              const NodeRegionFilter& also_requires = {});

}  // namespace altfem
