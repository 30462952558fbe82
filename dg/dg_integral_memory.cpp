#include "dg/dg_integral_memory.hpp"

namespace altfem::dg {

namespace {

bool same_material(const DgMaterial& a, const DgMaterial& b) {
  return a.lambda == b.lambda && a.mu == b.mu && a.density == b.density && a.penalty == b.penalty &&
         a.tangential_fraction == b.tangential_fraction;
}

}  // namespace

bool DgIntegralMemory::integrates_as(const DgSettings& other_settings,
                                     const std::vector<DgMaterial>& other_materials) const {
  const DgSettings& a = settings;
  const DgSettings& b = other_settings;
  // rule_simplification is left out: only the tabulated paths read it, never a matrix here;
  // share_stiffness too: it says where K is summed, not what a cell's or face's matrix is.
  if (a.degree != b.degree || a.flux != b.flux || a.boundary_penalty_factor != b.boundary_penalty_factor ||
      a.scaling != b.scaling || !a.reuse_similar_cells || !b.reuse_similar_cells ||
      !same_material({a.lambda, a.mu, a.density, a.penalty, a.tangential_fraction},
                     {b.lambda, b.mu, b.density, b.penalty, b.tangential_fraction}) ||
      materials.size() != other_materials.size())
    return false;
  for (size_t m = 0; m < materials.size(); ++m)
    if (!same_material(materials[m], other_materials[m])) return false;
  return true;
}

}  // namespace altfem::dg
