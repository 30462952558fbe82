// A cut event (docs/scene-schema.md, "Events"; Kaufmann et al. 2009 §9.4, Martin et al.
// 2008 §8) with every method: dg, harmonic, fcm (Longva et al. 2020's cells, the blade
// cutting the embedded tetrahedra) and fem (the same cells on its own elements: the
// virtual node algorithm, Molino et al. 2004):
//   - A bar held at both ends and cut through its middle, along the faces between its
//     cells, is two cantilevers: its static solution's elastic energy and ∫ρ u_z dV are
//     exactly twice those of the half bar meshed alone (the pieces separate, and nothing
//     of the cut couples them).
//   - A cut through cells of a swinging cantilever splits exactly the crossed cells,
//     conserves volume and mass to round-off (fcm: up to the α-weighted fictitious parts
//     of its new cut cells, exactly predicted), and dg's transfer (each piece keeps its
//     parent's polynomial) and fcm's (each node copy its node's values) conserve momentum;
//     the run goes on.
//   - A second cut along the faces through the first cut's blade keeps apart the node
//     copies the first made (they share positions): harmonic's transfer follows each
//     node's sources, so nothing moves and the energy does not jump.
//   - A cut along cell faces keeps fem's, fcm's and harmonic's kinetic plus elastic energy
//     to round-off (their transfers copy the field and no cell's rule changes).
//   - After a cut an affine displacement's strain energy is exact (the patch test's
//     consistency on the cut mesh).
//   - The piece cut off falls freely: nothing holds it and its internal forces sum to
//     zero, so each backward-Euler step adds exactly m g dt to its momentum.
//   - A finite blade notching the bar from below (the side in tension) half-way up, along
//     cell faces or through cells, makes it sag more than the whole bar and less than the
//     bar cut through, and conserves the volume; swept up through the bar it ends as the
//     two cantilevers, each of its cuts opening the surface further; a second notch
//     softens it further and opens the surface too.
//   - dg and harmonic merge a piece of 10⁻⁹ of its cell, so PCG converges where it does
//     not without.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "app/method_registry.hpp"
#include "shared/common/error.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/simulation.hpp"
#include "tests/verify/events/element_count.hpp"
#include "tests/verify/events/piece_momentum.hpp"
#include "tests/verify/events/static_answer.hpp"

namespace altfem {
namespace {

const std::filesystem::path scenes = std::filesystem::path(ALTFEM_SOURCE_DIR) / "tests/verify/events/scenes";

// The piece beyond the plane x = `blade`.
PieceMomentum momentum_beyond(const Simulation& simulation, double blade, double density) {
  return momentum_beyond(simulation, Eigen::Vector3d(blade, 0, 0), Eigen::Vector3d::UnitX(), density);
}

// The fcm scenes' stabilisation α (the default of /discretization/fcm/stabilization).
constexpr double fcm_stabilization = 1e-6;

// What a cut of the 1 × 0.1 × 0.1 m bar must conserve: the volume of material, and its
// mass and momentum — exactly for dg (each piece keeps its parent's polynomial), fcm and
// fem (each node copy keeps its node's values), to the transfer's accuracy for harmonic. fcm
// adds α × the whole cell's rule to every cut cell (Longva et al. 2020 §5.3), so each
// cell a cut newly makes a cut cell (`new_cut_cells`, of 0.001 m³) adds exactly
// α ρ 0.001 m³ to the discrete mass, and at most about as much to the momentum.
void expect_conserved(const EventRecord& record, const std::string& method, int new_cut_cells) {
  EXPECT_LE(std::abs(record.conserved["volume_change"].get<double>()), 1e-12);
  const double mass_jump = method == "fcm" ? fcm_stabilization * new_cut_cells * 0.001 / 0.01 : 0.0;
  EXPECT_NEAR(record.conserved["mass_change"].get<double>(), mass_jump, 1e-12 + 1e-5 * mass_jump);
  if (method != "harmonic") {
    EXPECT_LE(std::abs(record.conserved["momentum_change"].get<double>()), std::max(1e-12, 2 * mass_jump));
  }
}

class Cut : public ::testing::TestWithParam<std::string> {};

TEST_P(Cut, AlongCellFacesTheBarHeldAtBothEndsIsTwoCantilevers) {
  const StaticAnswer cut = solve_static(scenes / "bar_held_at_both_ends.json", GetParam());
  const StaticAnswer half = solve_static(scenes / "half_bar.json", GetParam());
  ASSERT_LT(half.vertical_mass, 0.0);  // it sags
  EXPECT_NEAR(cut.vertical_mass, 2 * half.vertical_mass, 1e-10 * std::abs(half.vertical_mass));
  EXPECT_NEAR(cut.energy, 2 * half.energy, 1e-10 * half.energy);
}

// The bar held at both ends sags under its weight, its bottom in tension at midspan; a
// notch from the bottom half-way up (a polygon blade over z ≤ `top`) at x = `x` softens
// it (its ligament is a hinge: the bar sags about half as much as the two cantilevers
// the bar cut through becomes), but it still carries its load across: it sags more
// than the whole bar and less than the bar cut through. At x = 0.5 the blade lies along the faces of the cells (2 × 2
// across the section for every method); at x = 0.55 it ends inside the upper cells, which
// are split into pieces that stay joined.
// A notch over the bottom half of the section swept up through the bar (in two load
// steps: cuts at 0, 1/3, 2/3 and 1 covering z ≤ 0.05, 0.083, 0.117, 0.15) ends cut
// through: the two cantilevers, as a plane cut gives them. Its second cut deepens a notch
// in the surface (solve_static checks that it opens it).
TEST_P(Cut, ASweptBladeThatEndsThroughTheBarGivesTwoCantilevers) {
  const StaticAnswer swept = solve_static(
      scenes / "bar_held_at_both_ends.json", GetParam(),
      {parse_scene_override("time/load_steps=2"),
       parse_scene_override("events=[{\"time\": 0, \"cut\": {\"polygon\": [[0.5, -1, -1], [0.5, 1, -1], "
                            "[0.5, 1, 0.05], [0.5, -1, 0.05]], \"sweep\": {\"to_time\": 1, \"translation\": "
                            "[0, 0, 0.1], \"substeps\": 3}}}]")});
  const StaticAnswer half = solve_static(scenes / "half_bar.json", GetParam());
  EXPECT_NEAR(swept.vertical_mass, 2 * half.vertical_mass, 1e-10 * std::abs(half.vertical_mass));
  EXPECT_NEAR(swept.energy, 2 * half.energy, 1e-10 * half.energy);
}

TEST_P(Cut, APartialNotchSoftensTheBarButDoesNotSeparateIt) {
  const std::string method = GetParam();
  const std::string resolution = method == "harmonic" ? "discretization/harmonic/convert/resolution=[10,2,2]"
                                                      : "discretization/" + method + "/resolution=[10,2,2]";
  for (const auto& [x, top] : {std::pair{0.5, 0.05}, std::pair{0.55, 0.07}}) {
    SCOPED_TRACE(::testing::Message() << "blade at x = " << x);
    const std::string at = std::to_string(x), up = std::to_string(top);
    const auto solve = [&](const std::string& events) {
      return solve_static(scenes / "bar_held_at_both_ends.json", method,
                          {parse_scene_override(resolution), parse_scene_override("events=" + events)});
    };
    const StaticAnswer whole = solve("[]");
    const StaticAnswer notched = solve("[{\"time\": 0, \"cut\": {\"polygon\": [[" + at + ", -1, -1], [" + at +
                                       ", 1, -1], [" + at + ", 1, " + up + "], [" + at + ", -1, " + up + "]]}}]");
    const StaticAnswer cut =
        solve("[{\"time\": 0, \"cut\": {\"plane\": {\"point\": [" + at + ", 0, 0], \"normal\": [1, 0, 0]}}}]");
    ASSERT_LT(whole.vertical_mass, 0.0);
    EXPECT_LT(notched.vertical_mass, 1.01 * whole.vertical_mass);  // sags at least 1% more
    EXPECT_GT(notched.vertical_mass, 0.99 * cut.vertical_mass);    // and at least 1% less than cut through
    EXPECT_GT(notched.energy, whole.energy);
    EXPECT_LT(notched.energy, cut.energy);
  }
}

// A second notch (at x = 0.7, the first at 0.3, both from below half-way up) softens the
// bar further, and opens the surface too: the bar before the first notch cut again with
// both blades (solve_static checks that no piece is left whole).
TEST_P(Cut, ASecondNotchSoftensTheBarFurtherAndOpensTheSurface) {
  const std::string method = GetParam();
  const std::string resolution = method == "harmonic" ? "discretization/harmonic/convert/resolution=[10,2,2]"
                                                      : "discretization/" + method + "/resolution=[10,2,2]";
  const auto notch = [](const std::string& x) {
    return "{\"time\": 0, \"cut\": {\"polygon\": [[" + x + ", -1, -1], [" + x + ", 1, -1], [" + x + ", 1, 0.05], [" +
           x + ", -1, 0.05]]}}";
  };
  const auto solve = [&](const std::string& events) {
    return solve_static(scenes / "bar_held_at_both_ends.json", method,
                        {parse_scene_override(resolution), parse_scene_override("events=" + events)});
  };
  const StaticAnswer one = solve("[" + notch("0.3") + "]");
  const StaticAnswer two = solve("[" + notch("0.3") + ", " + notch("0.7") + "]");
  ASSERT_LT(one.vertical_mass, 0.0);
  EXPECT_LT(two.vertical_mass, 1.001 * one.vertical_mass);
  EXPECT_GT(two.energy, 1.001 * one.energy);
}

TEST_P(Cut, ThroughCellsItSplitsTheCrossedOnesAndConservesVolumeAndMass) {
  const Scene scene = load_scene(scenes / "cantilever_cut.json");
  const SceneGeometry geometry = load_scene_geometry(scene);
  const MethodDescription& method = cli::find_method(GetParam());
  Simulation simulation(scene, geometry, GetParam(), method.factory, method.rebuild);
  const int cells_before = element_count(simulation.method());
  for (int step = 0; step < 5; ++step) simulation.integrator().step(simulation.state());
  const EventRecord record = simulation.apply(scene.events.at(0));

  if (GetParam() == "fcm" || GetParam() == "fem") {
    // The blade cuts the embedded tetrahedra (fem: its elements' own); of the 10 cells,
    // [0.5, 0.6] holds two pieces of material after it, each a cell with its own copies of
    // the cell's nodes (fem: the virtual node algorithm).
    EXPECT_GT(record.facts["crossed_fragments"].get<int>(), 0);
    EXPECT_EQ(record.facts["flat_tetrahedra"], 0);
    EXPECT_EQ(simulation.method().facts()["cells"]["split"], 1);
    EXPECT_EQ(element_count(simulation.method()), cells_before + 1);
    // fcm integrates again only the cells whose tetrahedra the blade changed: [0.5, 0.6] at
    // least, and not every cell (a tetrahedron spans at most two).
    if (GetParam() == "fcm") {
      EXPECT_GE(simulation.method().facts()["reused_cell_rules"].get<int>(), cells_before - 3);
      EXPECT_LE(simulation.method().facts()["reused_cell_rules"].get<int>(), cells_before - 1);
    }
  } else {
    // The plane x = 0.55 crosses one slab of cells: 1 × 1 for dg's grid, 2 × 2 for harmonic's.
    const int crossed = GetParam() == "dg" ? 1 : 4;
    EXPECT_EQ(record.facts["crossed_cells"], crossed);
    EXPECT_EQ(record.facts["separated_faces"], 0);
    EXPECT_EQ(record.facts["cells"], cells_before + crossed);
    EXPECT_EQ(element_count(simulation.method()), cells_before + crossed);
    if (GetParam() == "dg") {
      // dg integrates again only what the cut touched: the crossed cube's two pieces (each
      // 0.05 wide, translates: one class) and the two faces joining them to the bar. The
      // cube's class, its faces' and the clamp's come from the build before
      // (dg/dg_integral_memory.hpp).
      const nlohmann::json similar = simulation.method().facts()["similar_cells"];
      EXPECT_EQ(similar["cell_classes"], 2);
      EXPECT_EQ(similar["remembered_cell_classes"], 1);
      EXPECT_EQ(similar["face_classes"], 4);
      EXPECT_EQ(similar["remembered_face_classes"], 2);
    }
  }
  expect_conserved(record, GetParam(), 2);
  EXPECT_GT(record.dofs_after, record.dofs_before);
  // Free fall of the piece beyond the blade: 0.45 of the bar's 1 × 0.1 × 0.1 m at 1000 kg/m³
  // (fcm: and some of the two pieces' α-weighted points of the cell's rule, < α ρ 0.001 m³).
  const double g = -9.81, dt = scene.time.dt;
  PieceMomentum before = momentum_beyond(simulation, 0.55, 1000);
  EXPECT_NEAR(before.mass, 4.5, GetParam() == "fcm" ? fcm_stabilization * 1000 * 0.001 : 1e-10);
  for (int step = 0; step < 5; ++step) {
    simulation.integrator().step(simulation.state());
    const PieceMomentum after = momentum_beyond(simulation, 0.55, 1000);
    EXPECT_NEAR(after.momentum_z - before.momentum_z, before.mass * g * dt, 1e-6 * before.mass * std::abs(g) * dt)
        << "step " << step;
    before = after;
  }
}

// The cantilever cut at x = 0.55 at 0.02 s, then at 0.04 s by the plane through `point`
// normal to `normal` (JSON arrays).
Scene cantilever_cut_twice(const std::string& point, const std::string& normal) {
  return load_scene(scenes / "cantilever_cut.json",
                    {parse_scene_override("events=[{\"time\": 0.02, \"cut\": {\"plane\": {\"point\": [0.55, 0, 0], "
                                          "\"normal\": [1, 0, 0]}}}, {\"time\": 0.04, \"cut\": {\"plane\": "
                                          "{\"point\": " +
                                          point + ", \"normal\": " + normal + "}}}]")});
}

TEST_P(Cut, ASecondCutThroughTheFirstsBladeKeepsItsCopiesApart) {
  const Scene scene = cantilever_cut_twice("[0, 0.05, 0]", "[0, 1, 0]");
  const SceneGeometry geometry = load_scene_geometry(scene);
  const MethodDescription& method = cli::find_method(GetParam());
  Simulation simulation(scene, geometry, GetParam(), method.factory, method.rebuild);
  for (int step = 0; step < 5; ++step) simulation.integrator().step(simulation.state());
  simulation.apply(scene.events.at(0));
  for (int step = 0; step < 5; ++step) simulation.integrator().step(simulation.state());  // the pieces move apart
  const EventRecord second = simulation.apply(scene.events.at(1));
  // fcm: 9 whole cells become two cut pieces each, and [0.5, 0.6]'s two pieces four.
  expect_conserved(second, GetParam(), 20);
  if (GetParam() == "harmonic") {  // y = 0.05 is a plane of its grid's faces: nothing is interpolated
    EXPECT_EQ(second.facts["crossed_cells"], 0);
    // Nor fitted again: the first cut's 8 pieces (MFS cells) keep their bases, every other
    // cell its trilinear one (polyhedral/harmonic_basis_memory.hpp).
    EXPECT_EQ(simulation.method().element_counts()["mfs_polyhedron"], 8);
    EXPECT_EQ(simulation.method().facts()["remembered_mfs_bases"], 8);
    EXPECT_LE(std::abs(second.conserved["energy_jump_relative"].get<double>()), 1e-12);
    EXPECT_LE(std::abs(second.conserved["momentum_change"].get<double>()), 1e-12);
  } else if (GetParam() == "dg") {  // it crosses every dg cell; each piece keeps its parent's polynomial
    EXPECT_EQ(second.facts["crossed_cells"], 11);
  } else {  // it splits the material of every fcm and fem cell; each copy keeps its node's values
    EXPECT_EQ(simulation.method().facts()["cells"]["split"], 10);
  }
}

// A cut along the faces between cells (x = 0.5, a plane of every method's grid) of the
// swinging cantilever crosses no cell: fem's, fcm's and harmonic's node copies carry the
// field as it was and every cell keeps its rule, so the kinetic plus elastic energy stays
// as it was to round-off (the exact transfers' bound; through cells the cut cells' new
// rules integrate the same field a little differently: 6e-8 and 2e-7 of it for fem and fcm
// at x = 0.55). dg's pieces keep their polynomials too, but its energy loses the interior
// penalty's terms on the faces that become boundary, so it is not bounded here.
TEST_P(Cut, AlongCellFacesTheExactTransfersKeepTheEnergy) {
  if (GetParam() == "dg") GTEST_SKIP() << "dg's energy loses the blade's faces' interior-penalty terms";
  const Scene scene = load_scene(scenes / "cantilever_cut.json",
                                 {parse_scene_override("events=[{\"time\": 0.02, \"cut\": {\"plane\": {\"point\": "
                                                       "[0.5, 0, 0], \"normal\": [1, 0, 0]}}}]")});
  const SceneGeometry geometry = load_scene_geometry(scene);
  const MethodDescription& method = cli::find_method(GetParam());
  Simulation simulation(scene, geometry, GetParam(), method.factory, method.rebuild);
  for (int step = 0; step < 5; ++step) simulation.integrator().step(simulation.state());
  const EventRecord record = simulation.apply(scene.events.at(0));
  EXPECT_GT(record.dofs_after, record.dofs_before);  // the nodes on the blade copied
  EXPECT_GT(record.conserved["energy_before_j"].get<double>(), 0);
  EXPECT_LE(std::abs(record.conserved["energy_jump_relative"].get<double>()), 1e-13);
}

// After a cut every method still passes the patch test's consistency: it reproduces an
// affine displacement, and integrates its constant strain energy density exactly over
// the material (the cut cells' rules integrate constants; the pieces and node copies
// carry the field). fcm adds α × the energy density over its two cut cells (§5.3);
// harmonic's cut pieces reproduce affine fields to the MFS fit (~1e-9 of a cell).
// A rebuild integrates again only what the event changed (Kaufmann et al. 2009 §9.4,
// Martin et al. 2008 §8): after the cut at x = 0.55, a second at x = 0.25 crosses one
// slab of cells, and every other cell keeps what it was integrated or fitted with.
TEST_P(Cut, ASecondCutElsewhereIntegratesOnlyTheCellsItCrosses) {
  const Scene scene = cantilever_cut_twice("[0.25, 0, 0]", "[1, 0, 0]");
  const SceneGeometry geometry = load_scene_geometry(scene);
  const MethodDescription& method = cli::find_method(GetParam());
  Simulation simulation(scene, geometry, GetParam(), method.factory, method.rebuild);
  simulation.apply(scene.events.at(0));
  const int cells_before = element_count(simulation.method());
  const EventRecord second = simulation.apply(scene.events.at(1));
  expect_conserved(second, GetParam(), 2);
  const nlohmann::json facts = simulation.method().facts();
  if (GetParam() == "dg") {
    // Its pieces, 0.05 wide, are translates of the first cut's, and so are the faces that
    // join them to the bar: every class is the build before's.
    EXPECT_EQ(facts["similar_cells"]["remembered_cell_classes"], facts["similar_cells"]["cell_classes"]);
    EXPECT_EQ(facts["similar_cells"]["remembered_face_classes"], facts["similar_cells"]["face_classes"]);
  } else if (GetParam() == "harmonic") {
    // The first cut's 8 pieces keep their MFS bases, and the second's 8, translates of
    // theirs, take their fits: no cell is fitted again (only shapes new to the run are).
    EXPECT_EQ(simulation.method().element_counts()["mfs_polyhedron"], 16);
    EXPECT_EQ(facts["remembered_mfs_bases"], 16);
    // The first's 8 also keep their stiffness points (the second's are new cells).
    EXPECT_EQ(facts["copied_mfs_tabulations"], 8);
  } else {
    // Every cell but [0.2, 0.3], whose tetrahedra the blade cut (fcm: a tetrahedron
    // spans at most two cells), takes its rules from the build before.
    EXPECT_GE(facts["reused_cell_rules"].get<int>(), cells_before - (GetParam() == "fcm" ? 3 : 1));
    EXPECT_LE(facts["reused_cell_rules"].get<int>(), cells_before - 1);
  }
}

TEST_P(Cut, AfterACutAnAffineFieldHasItsExactStrainEnergy) {
  const Scene scene = load_scene(scenes / "cantilever_cut.json");
  const SceneGeometry geometry = load_scene_geometry(scene);
  const MethodDescription& method = cli::find_method(GetParam());
  Simulation simulation(scene, geometry, GetParam(), method.factory, method.rebuild);
  simulation.apply(scene.events.at(0));
  // Zero on the clamp x = 0, so that dg's weak condition there adds nothing.
  Eigen::Matrix3d gradient = Eigen::Matrix3d::Zero();
  gradient.col(0) << 1e-3, 3e-4, -2e-4;
  const Eigen::VectorXd u =
      simulation.method().interpolate([&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return gradient * x; });
  const Eigen::Matrix3d strain = 0.5 * (gradient + gradient.transpose());
  const double E = 1e8, nu = 0.3, lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double density = 0.5 * lambda * strain.trace() * strain.trace() + mu * strain.squaredNorm();
  const double volume = 0.01 + (GetParam() == "fcm" ? fcm_stabilization * 2 * 0.001 : 0.0);
  const double tolerance = GetParam() == "harmonic" ? 1e-6 : 1e-10;
  EXPECT_NEAR(simulation.method().discretization().energy(u), density * volume, tolerance * density * volume);
}

// A blade 10⁻¹⁰ m short of the faces at x = 0.6 leaves pieces of 10⁻⁹ of their cells:
// unmerged, PCG (dg's block Jacobi, harmonic's Jacobi) does not converge in 10,000
// iterations; merged into the cells beyond (the default merge fraction 10⁻³), the pieces
// are gone and the bar is the two cantilevers of a cut along the faces, to the slab's
// 10⁻⁹ of a cell (dg; harmonic to its MFS fit).
TEST(CutMerge, APieceOfABillionthOfItsCellIsMergedAndPcgConverges) {
  for (const std::string method : {"dg", "harmonic"}) {
    SCOPED_TRACE(method);
    const auto cut_at = [&](const std::string& x, const std::string& merge_fraction) {
      return solve_static(
          scenes / "bar_held_at_both_ends.json", method,
          {parse_scene_override("solver/linear=\"pcg\""),
           parse_scene_override("events=[{\"time\": 0, \"cut\": {\"plane\": {\"point\": [" + x +
                                ", 0, 0], \"normal\": [1, 0, 0]}, \"merge_fraction\": " + merge_fraction + "}}]")});
    };
    EXPECT_THROW(cut_at("0.5999999999", "0"), NumericalError);
    const StaticAnswer merged = cut_at("0.5999999999", "0.001");
    const StaticAnswer along_faces = cut_at("0.6", "0.001");
    // harmonic: the merged cell gets an MFS basis where the box had its exact trilinear
    // one (trilinear functions are harmonic), equal to the MFS fit.
    const double tolerance = method == "harmonic" ? 1e-4 : 1e-7;
    EXPECT_NEAR(merged.vertical_mass, along_faces.vertical_mass, tolerance * std::abs(along_faces.vertical_mass));
    EXPECT_NEAR(merged.energy, along_faces.energy, tolerance * along_faces.energy);
  }
}

// harmonic checks each new cell's MFS fit before it becomes an element
// (polyhedral/cut_piece_fits.hpp): with `cut_piece_residual` below any fit's misfit, the
// blade's 8 pieces (through the slab x in [0.5, 0.6] of the 10 × 2 × 2 grid) are each
// refused and merged into a neighbour, counted, the volume kept; the merged cells lie on
// their own side of the blade, so the bar is still the two cantilevers of the cut with
// every piece kept, to the two meshes' difference (3e-5 of the energy; asserted to 1e-3),
// where the uncut bar's energy is 2.3 times less.
TEST(CutMerge, HarmonicMergesThePiecesWhoseFitItRefuses) {
  const auto cut_with = [](const std::string& residual, nlohmann::json& facts) {
    const Scene scene = load_scene(
        scenes / "bar_held_at_both_ends.json",
        {parse_scene_override("discretization/harmonic/cut_piece_residual=" + residual),
         parse_scene_override(
             "events=[{\"time\": 0, \"cut\": {\"plane\": {\"point\": [0.55, 0, 0], \"normal\": [1, 0, 0]}}}]")});
    const SceneGeometry geometry = load_scene_geometry(scene);
    const MethodDescription& method = cli::find_method("harmonic");
    Simulation simulation(scene, geometry, "harmonic", method.factory, method.rebuild);
    const EventRecord record = simulation.apply(scene.events.at(0));
    facts = record.facts;
    EXPECT_LE(std::abs(record.conserved["volume_change"].get<double>()), 1e-12 * 0.01);
  };
  nlohmann::json refused, kept;
  cut_with("1e-9", refused);
  cut_with("1e-2", kept);
  EXPECT_EQ(refused["refused_cells"], 8);
  EXPECT_EQ(refused["merged_pieces"], 8);
  EXPECT_EQ(refused["cells"], kept["cells"].get<int>() - 8);
  EXPECT_EQ(kept["refused_cells"], 0);
  const auto energy_of = [](const std::string& residual) {
    return solve_static(scenes / "bar_held_at_both_ends.json", "harmonic",
                        {parse_scene_override("discretization/harmonic/cut_piece_residual=" + residual),
                         parse_scene_override("events=[{\"time\": 0, \"cut\": {\"plane\": {\"point\": [0.55, "
                                              "0, 0], \"normal\": [1, 0, 0]}}}]")})
        .energy;
  };
  const double merged = energy_of("1e-9"), with_pieces = energy_of("1e-2");
  const double whole =
      solve_static(scenes / "bar_held_at_both_ends.json", "harmonic", {parse_scene_override("events=[]")}).energy;
  std::printf("energy: pieces merged %.6e J, kept %.6e J, the bar uncut %.6e J\n", merged, with_pieces, whole);
  EXPECT_NEAR(merged, with_pieces, 1e-3 * with_pieces);
  EXPECT_GT(merged, 2 * whole);
}

// A piece of a tenth of its cell (x in [0.59, 0.6]) merged with the cell beyond its other
// face (merge_fraction 0.2), a cell of another parent: dg projects the moving bar's field
// on the merged cell piece by piece, each with its parent's polynomial, so its momentum
// is kept to round-off. By a rule over the whole merged cell, which straddles the two
// parents' jump, it changed by 1.7e-6.
TEST(CutMerge, APieceMergedIntoACellOfAnotherParentKeepsTheMomentum) {
  const Scene scene =
      load_scene(scenes / "cantilever_cut.json",
                 {parse_scene_override("events=[{\"time\": 0.02, \"cut\": {\"plane\": {\"point\": [0.59, 0, 0], "
                                       "\"normal\": [1, 0, 0]}, \"merge_fraction\": 0.2}}]")});
  const SceneGeometry geometry = load_scene_geometry(scene);
  const MethodDescription& method = cli::find_method("dg");
  Simulation simulation(scene, geometry, "dg", method.factory, method.rebuild);
  for (int step = 0; step < 5; ++step) simulation.integrator().step(simulation.state());
  const EventRecord record = simulation.apply(scene.events.at(0));
  EXPECT_EQ(record.facts["merged_pieces"], 1);
  EXPECT_LE(record.conserved["momentum_change"].get<double>(), 1e-13);
  EXPECT_LE(record.conserved["mass_change"].get<double>(), 1e-13);
}

INSTANTIATE_TEST_SUITE_P(CuttingMethods, Cut, ::testing::Values("dg", "harmonic", "fcm", "fem"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace altfem
