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
                                       const TetrahedronReductionMemory* previous,
                                       std::vector<std::pair<std::uint64_t, TetrahedronReduction>>* remembered) {
  TetrahedronReduction sum;
  std::vector<TetrahedronCorners> one(1);
  for (const TetrahedronCorners& tetrahedron : tetrahedra) {
    CacheKeyHasher hasher = rule.cell_key;
    hasher.matrix(tetrahedron);
    const std::uint64_t key = hasher.value();
    const TetrahedronReduction* share = nullptr;
    TetrahedronReduction computed;
    if (previous)
      if (const auto found = previous->find(key); found != previous->end()) share = &found->second;
    if (!share) {
      one[0] = tetrahedron;
      const IntersectionRule clip = intersection_rule(rule.cell, one, rule.order, rule.fan);
      computed.clipped_volume = clip.clipped_volume;
      computed.points = clip.rule.points.rows();
      if (computed.points > 0) computed.products = reference_products(rule.cell.type(), clip.rule);
      share = &computed;
    }
    add_reduction(sum, *share);
    if (share != &computed) ++sum.taken;
    if (remembered) {
      remembered->emplace_back(key, *share);
      remembered->back().second.taken = 0;
    }
  }
  return sum;
}

}  // namespace altfem
