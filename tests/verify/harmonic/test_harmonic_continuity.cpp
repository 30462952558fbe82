// The C0 mismatch of the harmonic bases across the faces shared by two MFS cells of a
// sliced mesh (Martin et al. 2008 §5: "about 2-3% with 5 samples per edge", shrinking
// with more): the relative L2 difference of the two cells' traces of every shared node's
// function, over every interior face between two cut cells of the bunny sliced at 8³.
// The face functions are fitted once per mesh face and shared (mesh_face_coordinates),
// so the boundary data agree exactly and what is left is each cell's 3D fit error; the
// column "own faces" (at the default samples) fits each cell on its own copy of its faces' functions instead (as
// before sharing: the same polygon, but kernel centres kept in the order of each cell's
// loop, so slightly different functions).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "polyhedral/harmonic_element_bases.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"

namespace altfem::harmonic {
namespace {

struct Mismatch {
  double relative = 0;  // √(Σ ∫(N_left − N_right)² / Σ ∫ N_left²) over faces and their nodes
  int faces = 0;
};

// basis(cell): the MFS basis of a cell (nullptr for a plain one), its functions in the
// order of bases.nodes(cell).
template <typename BasisOf>
Mismatch shared_face_mismatch(const PolyhedralMesh& mesh, const HarmonicElementBases& bases, const BasisOf& basis) {
  double difference = 0, norm = 0;
  int faces = 0;
  for (int face = 0; face < mesh.face_count(); ++face) {
    if (mesh.is_boundary_face(face)) continue;
    const int left = mesh.face_cells(face, 0), right = mesh.face_cells(face, 1);
    if (!basis(left) || !basis(right)) continue;
    const std::vector<int>& loop = mesh.faces[face];
    const PolyhedronRule rule = polygon_rule(mesh.nodes(loop, Eigen::all), 4);
    const Eigen::MatrixXd a = basis(left)->values(rule.points);   // #points × #left nodes
    const Eigen::MatrixXd b = basis(right)->values(rule.points);  // #points × #right nodes
    const auto column = [&](int cell, int node) {
      const std::vector<int>& nodes = bases.nodes(cell);
      return static_cast<Eigen::Index>(std::find(nodes.begin(), nodes.end(), node) - nodes.begin());
    };
    for (int node : loop) {
      const Eigen::VectorXd trace = a.col(column(left, node)), other = b.col(column(right, node));
      difference += rule.weights.dot((trace - other).cwiseAbs2());
      norm += rule.weights.dot(trace.cwiseAbs2());
    }
    ++faces;
  }
  return {std::sqrt(difference / norm), faces};
}

TEST(HarmonicContinuity, MismatchAcrossSharedFacesOfCutCellsShrinksWithSamples) {
  const SurfaceMesh bunny = read_surface(std::string(ALTFEM_SOURCE_DIR) + "/data/surface/bunny_npm.off");
  SlicingOptions slicing;
  slicing.resolution = 8;
  const PolyhedralMesh mesh = slice_into_polyhedra(bunny, slicing).mesh;
  std::printf("[ C0       ] bunny sliced at 8^3, faces between two cut cells\n");
  std::printf("[ C0       ] samples/edge   faces   rel. L2 mismatch   own faces   max boundary RMS misfit\n");
  std::map<int, double> mismatch;
  for (int samples : {3, 4, 5, 6}) {
    MfsOptions options;
    options.edge_samples = samples;
    const HarmonicElementBases bases(mesh, HarmonicBasisKind::automatic, options);
    const Mismatch shared = shared_face_mismatch(mesh, bases, [&](int cell) { return bases.mfs_basis(cell); });
    mismatch[samples] = shared.relative;
    ASSERT_GT(shared.faces, 0);
    if (samples != MfsOptions{}.edge_samples) {
      std::printf("[ C0       ] %12d  %6d   %16.3e   %9s   %23.3e\n", samples, shared.faces, shared.relative, "",
                  bases.max_boundary_residual());
      continue;
    }
    // At the default samples, also each cell fitted on its own copy of its faces' functions.
    std::vector<std::optional<ElementHarmonicBasis>> own(static_cast<size_t>(mesh.cell_count()));
#pragma omp parallel for schedule(dynamic, 4)
    for (int cell = 0; cell < mesh.cell_count(); ++cell)
      if (bases.mfs_basis(cell)) own[cell].emplace(cell_polyhedron(mesh, cell), options);
    const Mismatch separate =
        shared_face_mismatch(mesh, bases, [&](int cell) { return own[cell] ? &*own[cell] : nullptr; });
    std::printf("[ C0       ] %12d  %6d   %16.3e   %9.3e   %23.3e\n", samples, shared.faces, shared.relative,
                separate.relative, bases.max_boundary_residual());
    // Cells fitting their own copy drop kernel centres in the order of their own loop
    // (the neighbour's is reversed), so their face functions differ slightly; shared
    // ones are the same function on both sides.
    EXPECT_LT(shared.relative, separate.relative);
  }
  // Cut cells of a coarse slicing have kinked, sliver-like faces: their mismatch is well
  // above the paper's 2-3% (its cells are hexahedron-like); it must shrink with samples.
  EXPECT_LT(mismatch[4], mismatch[3]);
  EXPECT_LT(mismatch[5], mismatch[4]);
  EXPECT_LT(mismatch[6], mismatch[5]);
}

// Hexahedron-like cells, the paper's (§5: "about 2-3% with 5 samples per edge"): a 4³ grid
// with MFS bases on every cell, as boxes (rectangular faces: their exact bilinear
// coordinates, so only the 3D fits differ) and sheared into parallelepipeds (parallelogram
// faces, fitted by 2D MFS). Measured at 3/4/5/6 samples: boxes 2.2e-4 / 3.0e-5 / 7.1e-6 /
// 1.7e-6, parallelepipeds 0.24 / 0.12 / 0.064 / 0.039% — below the paper's figure; checked
// below 1% at the default.
TEST(HarmonicContinuity, MismatchAcrossFacesOfHexahedronLikeCells) {
  const VolumeMesh grid = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()),
                                          {4, 4, 4}, ElementType::hex8);
  Eigen::Matrix3d shear = Eigen::Matrix3d::Identity();
  shear(0, 1) = 0.4;
  shear(1, 2) = 0.3;
  std::printf("[ C0       ] 4^3 hexahedra, MFS on every cell\n");
  std::printf("[ C0       ] cells            samples/edge   faces   rel. L2 mismatch\n");
  for (const bool sheared : {false, true}) {
    PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(grid);
    if (sheared) {
      VolumeMesh moved = grid;
      moved.nodes = (moved.nodes * shear.transpose()).eval();
      mesh = polyhedral_mesh_from_volume_mesh(moved);
    }
    std::map<int, double> mismatch;
    for (int samples : {3, 4, 5, 6}) {
      MfsOptions options;
      options.edge_samples = samples;
      const HarmonicElementBases bases(mesh, HarmonicBasisKind::mfs, options);
      const Mismatch shared = shared_face_mismatch(mesh, bases, [&](int cell) { return bases.mfs_basis(cell); });
      mismatch[samples] = shared.relative;
      std::printf("[ C0       ] %-16s %12d  %6d   %16.3e\n", sheared ? "parallelepipeds" : "boxes", samples,
                  shared.faces, shared.relative);
    }
    EXPECT_LT(mismatch[MfsOptions{}.edge_samples], 0.01) << (sheared ? "parallelepipeds" : "boxes");
    EXPECT_LT(mismatch[6], mismatch[3]) << (sheared ? "parallelepipeds" : "boxes");
  }
}

}  // namespace
}  // namespace altfem::harmonic
