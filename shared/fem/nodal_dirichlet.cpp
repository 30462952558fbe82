#include "shared/fem/nodal_dirichlet.hpp"

#include <Eigen/Geometry>
#include <bit>
#include <map>
#include <memory>

#include "shared/common/error.hpp"

namespace altfem {

DirichletDofs nodal_dirichlet(const Eigen::MatrixXd& nodes, const std::vector<DirichletCondition>& conditions,
                              const std::string& scene_file, std::string_view mesh_name,
                              const NodeRegionFilter& also_requires) {
  Eigen::AlignedBox3d bounds;
  for (Eigen::Index node = 0; node < nodes.rows(); ++node) bounds.extend(nodes.row(node).transpose());
  const double tolerance = region_tolerance(bounds);
  std::map<int, ConstraintHolders> holders_of_dof;  // the last selecting condition prescribes
  for (size_t c = 0; c < conditions.size(); ++c) {
    int selected = 0;
    for (Eigen::Index node = 0; node < nodes.rows(); ++node) {
      if (!conditions[c].region.contains(nodes.row(node).transpose(), tolerance)) continue;
      if (also_requires && !also_requires(static_cast<int>(node), conditions[c].region, tolerance)) continue;
      ++selected;
      for (int k = 0; k < 3; ++k)
        if (conditions[c].components[k]) {
          ConstraintHolders& holders = holders_of_dof[3 * static_cast<int>(node) + k];
          holders.conditions |= condition_bit(static_cast<int>(c));
          holders.prescribing = condition_bit(static_cast<int>(c));
        }
    }
    if (selected == 0)
      throw InputError(input_message(scene_file, conditions[c].pointer + "/region",
                                     "selects no node of " + std::string(mesh_name) + " (" +
                                         std::to_string(nodes.rows()) + " nodes); enlarge the region"));
  }

  // What the prescribed values need, shared by the returned function.
  struct Selection {
    std::vector<Eigen::Vector3d> positions;  // per constrained DOF: its node's rest position
    std::vector<int> components;             // per constrained DOF: 0, 1 or 2
    std::vector<const DirichletCondition*> conditions;
    std::vector<DirichletCondition> owned;  // a copy: the scene may not outlive the run
  };
  auto selection = std::make_shared<Selection>();
  selection->owned = conditions;
  DirichletDofs result;
  for (auto [dof, holders] : holders_of_dof) {
    result.dofs.push_back(dof);
    result.holders.push_back(holders);
    selection->positions.push_back(nodes.row(dof / 3).transpose());
    selection->components.push_back(dof % 3);
    selection->conditions.push_back(&selection->owned[std::countr_zero(holders.prescribing)]);
  }
  result.prescribed = [selection](double time) {
    Eigen::VectorXd values(static_cast<Eigen::Index>(selection->positions.size()));
    for (size_t i = 0; i < selection->positions.size(); ++i)
      values[static_cast<Eigen::Index>(i)] =
          selection->conditions[i]->motion.displacement(selection->positions[i], time)[selection->components[i]];
    return values;
  };
  return result;
}

}  // namespace altfem
