#include "shared/cut_cells/tetrahedron_reductions.hpp"

namespace altfem {

void add_reduction(TetrahedronReduction& sum, const TetrahedronReduction& addend) {
  sum.clipped_volume += addend.clipped_volume;
  sum.points += addend.points;
  sum.taken += addend.taken;
  if (addend.products.products.size() == 0) return;
  if (sum.products.products.size() == 0) {
    sum.products = addend.products;
    return;
  }
  sum.products.products += addend.products.products;
  sum.products.integrals += addend.products.integrals;
  sum.products.weight_sum += addend.products.weight_sum;
}

TetrahedronReduction reduce_tetrahedra(const TetrahedronReductionRule& rule,
                                       std::span<const TetrahedronCorners> tetrahedra,
                                       const TetrahedronReductionMemory* previous, RememberedShares* remembered) {
  TetrahedronReduction sum;
  std::vector<TetrahedronCorners> one(1);
  for (const TetrahedronCorners& tetrahedron : tetrahedra) {
    CacheKeyHasher hasher = rule.cell_key;
    hasher.matrix(tetrahedron);
    const std::uint64_t key = hasher.value();
    std::shared_ptr<const TetrahedronReduction> share;
    if (previous)
      if (const auto found = previous->find(key); found != previous->end()) share = found->second;
    if (share) {
      add_reduction(sum, *share);
      ++sum.taken;
    } else {
      one[0] = tetrahedron;
      const IntersectionRule clip = intersection_rule(rule.cell, one, rule.order, rule.fan);
      auto computed = std::make_shared<TetrahedronReduction>();
      computed->clipped_volume = clip.clipped_volume;
      computed->points = clip.rule.points.rows();
      if (computed->points > 0) computed->products = reference_products(rule.cell.type(), clip.rule);
      add_reduction(sum, *computed);
      share = std::move(computed);
    }
    if (remembered) remembered->emplace_back(key, std::move(share));
  }
  return sum;
}

}  // namespace altfem
