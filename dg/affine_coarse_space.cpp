#include "dg/affine_coarse_space.hpp"

namespace altfem::dg {

CoarseSpace affine_coarse_space(const DgLinearSystem& system) {
  CoarseSpace space;
  if (!system.constrained_dofs().empty() || system.cell_count() == 0) return space;
  constexpr int affine = 4;  // 1, x, y, z
  bool higher = false;
  for (int cell = 0; cell < system.cell_count(); ++cell)
    higher |= system.offset(cell + 1) - system.offset(cell) > affine;
  if (!higher) return space;
  std::vector<Eigen::Triplet<double>> entries;
  for (int cell = 0; cell < system.cell_count(); ++cell)
    for (int function = 0; function < affine; ++function) {
      const int fine = system.offset(cell) + function;
      entries.emplace_back(fine, static_cast<int>(space.fine_function.size()), 1.0);
      space.fine_function.push_back(fine);
    }
  space.prolongation.resize(system.offset(system.cell_count()), static_cast<Eigen::Index>(space.fine_function.size()));
  space.prolongation.setFromTriplets(entries.begin(), entries.end());
  return space;
}

}  // namespace altfem::dg
