#include "shared/cut_cells/region_cut_check.hpp"

namespace altfem {

std::vector<std::string> conditions_cutting_cells(const VolumeMesh& cells,
                                                  const std::vector<DirichletCondition>& dirichlet) {
  std::vector<std::string> warnings;
  for (const DirichletCondition& condition : dirichlet) {
    int cut = 0;
    for (Eigen::Index c = 0; c < cells.cells.rows(); ++c) {
      Eigen::AlignedBox3d box;
      for (Eigen::Index a = 0; a < cells.cells.cols(); ++a) box.extend(cells.nodes.row(cells.cells(c, a)).transpose());
      int inside = 0, samples = 0;
      for (int i = 1; i <= 3; ++i)
        for (int j = 1; j <= 3; ++j)
          for (int k = 1; k <= 3; ++k, ++samples) {
            const Eigen::Vector3d fraction(i / 4.0, j / 4.0, k / 4.0);
            inside += condition.region.contains(box.min() + fraction.cwiseProduct(box.sizes()), 0.0);
          }
      cut += inside > 0 && inside < samples;
    }
    if (cut > 0)
      warnings.push_back(condition.pointer + ": the region's boundary passes through " + std::to_string(cut) +
                         " background cells, so the condition also holds their nodes outside the material "
                         "(fcm imposes conditions on background nodes, Longva et al. 2020 §6); put the region's "
                         "boundary on a grid plane");
  }
  return warnings;
}

}  // namespace altfem
