// The papers' Fig. 8: a bar refined where its stress is high, the element counts they report.
//   - Kaufmann et al. 2009 §9.3, Fig. 8: "A bar (36 hex-elements) is dynamically refined
//     during bending. 1-to-8 subdivision results in 274 elements, whereas 1-to-2 refinement
//     yields 77 elements" — the same threshold for both, which the paper does not give.
//     `scenes/refine_bar.json` (9 × 2 × 2 hexahedra, clamped, bending under its weight) takes
//     one threshold, 5 kPa, and one refinement: 1→8 and 1→2 must both land within ±20% of
//     the paper's counts, with dg (the paper's method) and harmonic. One number fixes both
//     counts, so the second is a prediction, not a fit.
//   - Martin et al. 2008 §8, Fig. 8 and Table 1: a bar of 40 hexahedra (99 nodes) held at
//     both ends, refined 1→2 while it bends (88 elements after) and 1→8 while it twists
//     (719). `scenes/refine_bending_bar.json` and `scenes/refine_twisting_bar.json`
//     (10 × 2 × 2, refined every 5 steps) must land within ±20%, harmonic (their method).
//     Their thresholds are not in the paper either; each scene has its own.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/method_registry.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/run_simulation.hpp"

namespace altfem {
namespace {

struct FigureCase {
  std::string scene, method, split;
  int paper_count;  // the elements after refinement the paper reports
};

void PrintTo(const FigureCase& test, std::ostream* out) {
  *out << test.scene << " " << test.method << " " << test.split;
}

class RefineFigure8 : public ::testing::TestWithParam<FigureCase> {};

TEST_P(RefineFigure8, EndsWithinTwentyPercentOfThePapersElementCount) {
  const FigureCase& test = GetParam();
  const Scene scene = load_scene(std::filesystem::path(ALTFEM_SOURCE_DIR) / "scenes" / (test.scene + ".json"),
                                 {parse_scene_override("events/0/refine/split=\"" + test.split + "\""),
                                  parse_scene_override("output/volume=false")});
  const std::filesystem::path output = std::filesystem::path(ALTFEM_BINARY_DIR) /
                                       ("verify_refine_figure8_" + test.scene + "_" + test.method + "_" + test.split);
  std::filesystem::remove_all(output);
  const nlohmann::json summary =
      run_simulation(scene, load_scene_geometry(scene), test.method, cli::find_method(test.method), output, 0.0);
  ASSERT_EQ(summary["status"], "ok");
  const nlohmann::json& events = summary["events"];
  ASSERT_FALSE(events.empty());
  const int cells = events.back()["facts"]["cells"].get<int>();
  EXPECT_GE(cells, 0.8 * test.paper_count);
  EXPECT_LE(cells, 1.2 * test.paper_count);
  for (const nlohmann::json& event : events)  // a refinement keeps the body whole
    EXPECT_LE(std::abs(event["conserved"]["volume_change"].get<double>()), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(PapersBars, RefineFigure8,
                         ::testing::Values(FigureCase{"refine_bar", "dg", "1to8", 274},
                                           FigureCase{"refine_bar", "dg", "1to2", 77},
                                           FigureCase{"refine_bar", "harmonic", "1to8", 274},
                                           FigureCase{"refine_bar", "harmonic", "1to2", 77},
                                           FigureCase{"refine_bending_bar", "harmonic", "1to2", 88},
                                           FigureCase{"refine_twisting_bar", "harmonic", "1to8", 719}),
                         [](const auto& info) {
                           return info.param.scene + "_" + info.param.method + "_" + info.param.split.substr(3);
                         });

}  // namespace
}  // namespace altfem
