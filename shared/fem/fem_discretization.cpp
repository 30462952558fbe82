#include "shared/fem/fem_discretization.hpp"

#include <map>

#include "shared/common/error.hpp"
#include "shared/fem/tabulate_lagrange.hpp"

namespace altfem {

FemDiscretization::FemDiscretization(VolumeMesh mesh, const Material& material,
                                     const std::vector<DirichletCondition>& dirichlet, int quadrature_strength,
                                     const std::string& scene_file)
    : mesh_(std::move(mesh)), elements_(tabulate_lagrange(mesh_, quadrature_strength)), dirichlet_(dirichlet) {
  assembler_ = std::make_unique<ElasticAssembler>(elements_, std::vector<const Material*>{&material});
  assembler_->mass_matrix(mass_);
  lumped_mass_ = assembler_->lumped_mass();

  // A DOF selected by several conditions follows the last one, as in the scene's order.
  Eigen::AlignedBox3d bounds;
  for (Eigen::Index node = 0; node < mesh_.nodes.rows(); ++node) bounds.extend(mesh_.nodes.row(node).transpose());
  const double tolerance = region_tolerance(bounds);
  std::map<int, int> condition_of_dof;
  for (size_t c = 0; c < dirichlet_.size(); ++c) {
    int selected = 0;
    for (Eigen::Index node = 0; node < mesh_.nodes.rows(); ++node) {
      if (!dirichlet_[c].region.contains(mesh_.nodes.row(node).transpose(), tolerance)) continue;
      ++selected;
      for (int k = 0; k < 3; ++k)
        if (dirichlet_[c].components[k]) condition_of_dof[3 * static_cast<int>(node) + k] = static_cast<int>(c);
    }
    if (selected == 0)
      throw InputError(input_message(scene_file, dirichlet_[c].pointer + "/region",
                                    "selects no node of the fem mesh (" + std::to_string(mesh_.nodes.rows()) +
                                        " nodes); enlarge the region"));
  }
  for (auto [dof, condition] : condition_of_dof) {
    constrained_.push_back(dof);
    constrained_condition_.push_back(condition);
  }
}

Eigen::VectorXd FemDiscretization::prescribed_displacement(double time) const {
  Eigen::VectorXd values(static_cast<Eigen::Index>(constrained_.size()));
  for (size_t i = 0; i < constrained_.size(); ++i) {
    const int node = constrained_[i] / 3;
    const Eigen::Vector3d displacement =
        dirichlet_[constrained_condition_[i]].motion.displacement(mesh_.nodes.row(node).transpose(), time);
    values[static_cast<Eigen::Index>(i)] = displacement[constrained_[i] % 3];
  }
  return values;
}

Eigen::Vector3d FemDiscretization::centre_of_mass() const {
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  double mass = 0;
  for (Eigen::Index node = 0; node < mesh_.nodes.rows(); ++node) {
    moment += lumped_mass_[3 * node] * mesh_.nodes.row(node).transpose();
    mass += lumped_mass_[3 * node];
  }
  return moment / mass;
}

}  // namespace altfem
