// The shipped cantilever scene (scenes/cantilever.json: 1 × 0.1 × 0.1 m, E = 1e9 Pa,
// ν = 0.3, clamped at x = 0, its own weight) with dg of degree 1, 2, 3 on the default
// 20 × 2 × 2 hexahedra, against Timoshenko's tip deflection (1.4868e-3 m, see
// tests/verify/fem/test_cantilever.cpp) and a fine fem run (Hex20 [40, 4, 4]) of the
// same scene. The clamp is imposed weakly (Kaufmann et al. 2009 §4.2), and strongly
// (dg/strong_conditions.hpp). Prints the table; k = 2 and 3 are checked to 2% of the fem
// reference when weak; strong, the clamp holds the whole polynomial trace at zero and
// the 2 × 2 cells across the section are stiffer at the wall (k = 2 −2.4%, k = 3 −0.4%),
// checked to 3% and 1%. k = 1 locks on these cells (−57%) and recovers under refinement,
// checked on [40, 4, 4] and [80, 8, 8] below.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "dg/dg_method.hpp"
#include "shared/fem/method/fem_method.hpp"
#include "tests/support/static_solve.hpp"

namespace altfem::dg {
namespace {

struct TipResult {
  int dofs;
  double deflection;  ///< −(mean z-displacement of the embedded surface vertices at x = 1)
};

TipResult tip_deflection(const MethodFactory& factory, const std::vector<std::string>& assignments) {
  const test::StaticSurface surface =
      test::static_surface(std::filesystem::path(ALTFEM_SOURCE_DIR) / "scenes/cantilever.json", factory, assignments);
  return {surface.dofs, -test::mean_on_plane(surface, 0, 1.0, 2, 1e-9)};
}

TEST(DgCantilever, TipDeflectionAgreesWithTimoshenkoAndFineFem) {
  constexpr double timoshenko = 1.4868e-3;
  const TipResult reference =
      tip_deflection(make_fem_method, {"/discretization/fem/element=hex20", "/discretization/fem/resolution=[40,4,4]"});
  std::printf("  %-29s %7s %12s %10s %10s\n", "method", "DOFs", "tip (m)", "vs fem", "vs Timo.");
  std::printf("  %-29s %7d %12.5e %9.2f%% %9.2f%%\n", "fem Hex20 [40,4,4]", reference.dofs, reference.deflection, 0.0,
              100 * (reference.deflection - timoshenko) / timoshenko);
  std::vector<double> excess_stiffness;  // k = 1, weak: (w − w_h) / w_h on [20,2,2], [40,4,4], [80,8,8]
  for (const std::string conditions : {"weak", "strong"})
    for (int degree : {1, 2, 3}) {
      const TipResult dg = tip_deflection(make_dg_method, {"/discretization/dg/degree=" + std::to_string(degree),
                                                           "/discretization/dg/conditions=\"" + conditions + "\""});
      const double relative = (dg.deflection - reference.deflection) / reference.deflection;
      const std::string label = "dg k=" + std::to_string(degree) + " [20,2,2] " + conditions;
      std::printf("  %-29s %7d %12.5e %9.2f%% %9.2f%%\n", label.c_str(), dg.dofs, dg.deflection, 100 * relative,
                  100 * (dg.deflection - timoshenko) / timoshenko);
      const double bound = conditions == "weak" ? 0.02 : degree == 2 ? 0.03 : 0.01;
      if (degree >= 2) {
        EXPECT_LT(std::abs(relative), bound) << "degree " << degree << ", " << conditions;
      } else if (conditions == "weak") {
        excess_stiffness.push_back((reference.deflection - dg.deflection) / dg.deflection);
      }
    }
  // Linear monomials lock in bending: bending of curvature κ needs the product x z in u_x,
  // which a complete linear field in a cell of size h misses by a parasitic strain ∝ κ h,
  // whose energy against the bending energy ∝ κ² t² (t the thickness) makes the discrete
  // beam stiffer by a factor 1 + c (h/t)². So the tip deflection recovers under refinement
  // with its excess stiffness (w − w_h) / w_h falling like h²: measured 1.33, 0.416, 0.115
  // on the three grids (rates 1.67, 1.85, towards 2), the deflection error 57%, 29%, 10%.
  for (const char* grid : {"[40,4,4]", "[80,8,8]"}) {
    const TipResult linear = tip_deflection(
        make_dg_method, {"/discretization/dg/degree=1", std::string("/discretization/dg/resolution=") + grid});
    std::printf("  %-29s %7d %12.5e %9.2f%% %9.2f%%\n", (std::string("dg k=1 ") + grid + " weak").c_str(), linear.dofs,
                linear.deflection, 100 * (linear.deflection - reference.deflection) / reference.deflection,
                100 * (linear.deflection - timoshenko) / timoshenko);
    excess_stiffness.push_back((reference.deflection - linear.deflection) / linear.deflection);
  }
  ASSERT_EQ(excess_stiffness.size(), 3u);
  EXPECT_GT(excess_stiffness[0], excess_stiffness[1]);
  EXPECT_GT(excess_stiffness[1], excess_stiffness[2]);
  EXPECT_GT(excess_stiffness[2], 0.0) << "a locking field is stiffer, never softer";
  EXPECT_NEAR(std::log2(excess_stiffness[1] / excess_stiffness[2]), 2.0, 0.3);
}

}  // namespace
}  // namespace altfem::dg
