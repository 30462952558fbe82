// The on-disk rule cache (shared/cut_cells/rule_cache.hpp): a second run reuses the file and gets
// identical rules; other options miss; a truncated file (an interrupted writer without
// the atomic rename) is recomputed, not trusted; named tetrahedra per cell key apart. A
// cell's rule with its reduction (what ranks exchange) reads back bit for bit.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>

#include "shared/cut_cells/cell_rule_bytes.hpp"
#include "shared/cut_cells/rule_cache.hpp"
#include "shared/mesh/structured_grid.hpp"

namespace altfem::fcm {
namespace {

TEST(RuleCache, SecondRunReusesIdenticalRulesAndTruncatedFilesAreRecomputed) {
  const auto directory = std::filesystem::temp_directory_path() / "altfem_rule_cache_test";
  std::filesystem::remove_all(directory);
  const VolumeMesh background = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()),
                                                Eigen::Vector3i(2, 2, 2), ElementType::hex20);
  VolumeMesh embedded =
      structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Constant(0.1), Eigen::Vector3d(0.8, 0.7, 0.9)),
                      Eigen::Vector3i(2, 2, 2), ElementType::tet4);
  const CellRuleOptions options{3};
  bool reused = true;
  const CellRules first = cached_cell_rules(background, embedded, options, directory, &reused);
  EXPECT_FALSE(reused);
  const CellRules second = cached_cell_rules(background, embedded, options, directory, &reused);
  EXPECT_TRUE(reused);
  ASSERT_EQ(first.cells.size(), second.cells.size());
  EXPECT_EQ(first.final_points, second.final_points);
  EXPECT_EQ(first.cut_cells, second.cut_cells);
  for (std::size_t c = 0; c < first.cells.size(); ++c) {
    EXPECT_EQ(first.cells[c].rule.points, second.cells[c].rule.points);
    EXPECT_EQ(first.cells[c].rule.weights, second.cells[c].rule.weights);
  }

  cached_cell_rules(background, embedded, CellRuleOptions{4}, directory, &reused);
  EXPECT_FALSE(reused);  // another order: another key
  embedded.nodes(0, 0) += 1e-3;
  cached_cell_rules(background, embedded, options, directory, &reused);
  EXPECT_FALSE(reused);  // moved geometry: another key
  embedded.nodes(0, 0) -= 1e-3;
  // Cells that clip named tetrahedra (pieces of topology-aware cells): another key, and
  // the cached rules are those of the named tetrahedra (none: every cell outside).
  const std::vector<std::vector<int>> no_tetrahedra(static_cast<std::size_t>(background.cells.rows()));
  const CellRules pieces = cached_cell_rules(background, embedded, options, directory, &reused, &no_tetrahedra);
  EXPECT_FALSE(reused);
  EXPECT_EQ(pieces.final_points, 0);
  cached_cell_rules(background, embedded, options, directory, &reused, &no_tetrahedra);
  EXPECT_TRUE(reused);

  char name[32];
  std::snprintf(name, sizeof name, "%016llx.rules",
                static_cast<unsigned long long>(cell_rules_key(background, embedded, options)));
  const auto path = directory / name;
  std::filesystem::resize_file(path, std::filesystem::file_size(path) / 2);
  const CellRules recomputed = cached_cell_rules(background, embedded, options, directory, &reused);
  EXPECT_FALSE(reused);
  EXPECT_EQ(recomputed.final_points, first.final_points);
  std::filesystem::remove_all(directory);
}

TEST(CellRuleBytes, ACutCellsReducedRuleReadsBackBitForBitAndATruncatedOneFails) {
  const VolumeMesh background = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()),
                                                Eigen::Vector3i(2, 2, 2), ElementType::hex20);
  const VolumeMesh embedded =
      structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Constant(0.1), Eigen::Vector3d(0.8, 0.7, 0.9)),
                      Eigen::Vector3i(2, 2, 2), ElementType::tet4);
  CellRuleOptions options{6};
  options.simplify = false;
  options.reduce = true;
  const CellRules rules = compute_cell_rules(background, embedded, options);
  ASSERT_GT(rules.cut_cells, 0);
  BinaryWriter out("test");
  for (const CellRule& cell : rules.cells) write_cell_rule(out, cell);
  BinaryReader in(out.bytes(), "test");
  for (const CellRule& cell : rules.cells) {
    CellRule back;
    ASSERT_TRUE(read_cell_rule(in, back));
    EXPECT_EQ(back.kind, cell.kind);
    EXPECT_EQ(back.clipped_volume, cell.clipped_volume);
    EXPECT_EQ(back.rule.points, cell.rule.points);
    EXPECT_EQ(back.rule.weights, cell.rule.weights);
    ASSERT_EQ(back.reduced.has_value(), cell.reduced.has_value());
    if (!cell.reduced) continue;
    EXPECT_EQ(back.reduced->products, cell.reduced->products);
    EXPECT_EQ(back.reduced->integrals, cell.reduced->integrals);
    EXPECT_EQ(back.reduced->weight_sum, cell.reduced->weight_sum);
  }
  EXPECT_TRUE(in.at_end());
  const std::string half = out.bytes().substr(0, out.bytes().size() / 2);
  BinaryReader truncated(half, "test");
  bool whole = true;
  for (std::size_t c = 0; c < rules.cells.size() && whole; ++c) {
    CellRule back;
    whole = read_cell_rule(truncated, back);
  }
  EXPECT_FALSE(whole);
}

}  // namespace
}  // namespace altfem::fcm
