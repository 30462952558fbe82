// Kaufmann et al. 2009 §9.6, Figs. 11 and 12: the condition number κ(K) of the DG
// stiffness (IP, Dirichlet data imposed weakly on one boundary face so that K is SPD;
// κ = λ_max/λ_min by a dense eigensolver).
//  Fig. 11: κ grows with the ratio of the largest to the smallest element volume. Here a
//  tetrahedron split into a small inner tetrahedron (scaled by s about the centroid) and
//  the four convex frusta between its faces and the outer ones (five elements; the
//  paper's mesh has nine), s = ½ → 10⁻⁶: the volume ratio sweeps seventeen decades, κ
//  grows as its cube root once the small element dominates. Graded slabs (thin cells,
//  not shape-regular) for comparison: κ grows as the ratio squared.
//  Fig. 12: a single non-convex element whose middle section thins to ε keeps κ bounded:
//  two unit cubes joined by a neck of width ε and height 1 (a prism over a dumbbell
//  profile), ε = 10⁻¹ → 10⁻⁶; a Tet4 fem mesh of the same dumbbell (its neck's cells ε
//  wide) is compared: its κ grows like ε⁻².
// Prints the tables.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>

#include "dg/dg_linear_system.hpp"
#include "dg/polyhedral_mesh_faces.hpp"
#include "shared/common/eigen_decompositions.hpp"
#include "shared/fem/lagrange_discretization.hpp"
#include "shared/material/material.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"
#include "shared/mesh/structured_grid.hpp"

namespace altfem::dg {
namespace {

using FaceLoops = std::vector<std::vector<int>>;  // one cell: its faces, counter-clockwise seen from outside

// The PolyhedralMesh of hand-built cells over `nodes` (#nodes × 3): a face given by two
// cells (the same nodes, opposite orientations) becomes one interior face.
PolyhedralMesh mesh_of_cells(const Eigen::MatrixXd& nodes, const std::vector<FaceLoops>& cells) {
  PolyhedralMesh mesh;
  mesh.nodes = nodes;
  std::map<std::vector<int>, int> face_of_nodes;
  std::vector<std::array<int, 2>> face_cells;
  for (size_t c = 0; c < cells.size(); ++c) {
    mesh.cell_faces.emplace_back();
    for (const auto& loop : cells[c]) {
      std::vector<int> key = loop;
      std::sort(key.begin(), key.end());
      const auto [found, inserted] = face_of_nodes.try_emplace(key, mesh.face_count());
      if (inserted) {
        mesh.faces.push_back(loop);
        face_cells.push_back({static_cast<int>(c), -1});
      } else {
        face_cells[found->second][1] = static_cast<int>(c);
      }
      mesh.cell_faces.back().push_back(found->second);
    }
    // Only the VTU output reads the kind: hand-built cells are tetrahedra or "cut" pieces.
    mesh.cell_kinds.push_back(cells[c].size() == 4 ? PolyhedralCellKind::tetrahedron : PolyhedralCellKind::cut);
  }
  mesh.face_cells.resize(mesh.face_count(), 2);
  for (int f = 0; f < mesh.face_count(); ++f) mesh.face_cells.row(f) << face_cells[f][0], face_cells[f][1];
  compute_polyhedral_geometry(mesh);
  return mesh;
}

// `loop` ordered counter-clockwise seen from outside a convex cell with this interior point.
std::vector<int> outward(std::vector<int> loop, const Eigen::MatrixXd& nodes, const Eigen::Vector3d& inside) {
  const Eigen::Vector3d a = nodes.row(loop[0]), b = nodes.row(loop[1]), c = nodes.row(loop[2]);
  if ((b - a).cross(c - a).dot(a - inside) < 0) std::reverse(loop.begin(), loop.end());
  return loop;
}

struct Conditioning {
  double condition_number;
  double smallest_eigenvalue;
};

// κ(K) of IP of degree k (E = 1, ν = 0.3, Kaufmann's η = 20 E doubled until K is
// definite, as the method does) with the boundary faces `is_dirichlet` selects (by
// centroid) held weakly.
Conditioning stiffness_conditioning(const PolyhedralMesh& mesh, int degree,
                                    const std::function<bool(const Eigen::Vector3d&)>& is_dirichlet) {
  std::vector<DgFace> faces = mesh_faces(mesh);
  for (int f = 0; f < mesh.face_count(); ++f)
    if (mesh.is_boundary_face(f) && is_dirichlet(mesh.face_centroids.row(f).transpose())) faces[f].condition = 0;
  const LameParameters lame = lame_parameters(1.0, 0.3);
  DgSettings settings{degree, Flux::interior_penalty, 20.0, lame.lambda, lame.mu};
  for (int doubling = 0; doubling < 20; ++doubling, settings.penalty *= 2) {
    const DgLinearSystem system(mesh_cells(mesh), faces, settings);
    const Eigen::VectorXd eigenvalues =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(system.stiffness()), Eigen::EigenvaluesOnly)
            .eigenvalues();
    if (eigenvalues.minCoeff() > 0) return {eigenvalues.maxCoeff() / eigenvalues.minCoeff(), eigenvalues.minCoeff()};
  }
  return {INFINITY, 0};
}

// A regular tetrahedron (edge 1) with an inner tetrahedron scaled by `scale` about the
// centroid; the four frusta between the faces opposite the same vertex.
PolyhedralMesh tetrahedron_with_inner_tetrahedron(double scale) {
  Eigen::MatrixXd nodes(8, 3);
  nodes.topRows(4) << 0, 0, 0, 1, 0, 0, 0.5, std::sqrt(3.0) / 2, 0, 0.5, std::sqrt(3.0) / 6, std::sqrt(2.0 / 3.0);
  const Eigen::RowVector3d centre = nodes.topRows(4).colwise().mean();
  for (int v = 0; v < 4; ++v) nodes.row(4 + v) = centre + scale * (nodes.row(v) - centre);
  std::vector<FaceLoops> cells;
  FaceLoops inner;
  for (int opposite = 0; opposite < 4; ++opposite) {
    std::vector<int> face;
    for (int v = 0; v < 4; ++v)
      if (v != opposite) face.push_back(4 + v);
    inner.push_back(outward(face, nodes, centre.transpose()));
  }
  cells.push_back(inner);
  for (int opposite = 0; opposite < 4; ++opposite) {
    std::vector<int> corners;  // the three vertices of the outer face
    for (int v = 0; v < 4; ++v)
      if (v != opposite) corners.push_back(v);
    Eigen::Vector3d inside = Eigen::Vector3d::Zero();  // the frustum's vertex mean
    for (int v : corners) inside += (nodes.row(v) + nodes.row(4 + v)).transpose() / 6;
    FaceLoops frustum{outward(corners, nodes, inside),
                      outward({4 + corners[0], 4 + corners[1], 4 + corners[2]}, nodes, inside)};
    for (int e = 0; e < 3; ++e) {
      const int a = corners[e], b = corners[(e + 1) % 3];
      frustum.push_back(outward({a, b, 4 + b, 4 + a}, nodes, inside));
    }
    cells.push_back(frustum);
  }
  return mesh_of_cells(nodes, cells);
}

// One cell: the prism y ∈ [0, 1] over the dumbbell profile in the (x, z) plane — the unit
// squares z ∈ [0, 1] and z ∈ [2, 3] joined by the neck |x − ½| ≤ ε/2, z ∈ [1, 2].
PolyhedralMesh dumbbell(double neck) {
  const double left = 0.5 - neck / 2, right = 0.5 + neck / 2;
  // Counter-clockwise in (x, z): its y = 0 copy then has the outward normal −y (e_x × e_z = −e_y).
  const std::vector<Eigen::Vector2d> profile{{0, 0}, {1, 0}, {1, 1}, {right, 1}, {right, 2}, {1, 2},
                                             {1, 3}, {0, 3}, {0, 2}, {left, 2},  {left, 1},  {0, 1}};
  const int n = static_cast<int>(profile.size());
  Eigen::MatrixXd nodes(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    nodes.row(i) << profile[i].x(), 0, profile[i].y();
    nodes.row(n + i) << profile[i].x(), 1, profile[i].y();
  }
  FaceLoops cell(2);
  for (int i = 0; i < n; ++i) {
    cell[0].push_back(i);
    cell[1].push_back(2 * n - 1 - i);
    const int next = (i + 1) % n;
    cell.push_back({i, n + i, n + next, next});
  }
  return mesh_of_cells(nodes, {cell});
}

// A row of unit-square slabs along x with the widths `widths` (y, z ∈ [0, 1]).
PolyhedralMesh graded_row(const std::vector<double>& widths) {
  const int n = static_cast<int>(widths.size());
  Eigen::MatrixXd nodes(4 * (n + 1), 3);
  double x = 0;
  for (int i = 0; i <= n; ++i) {
    for (int corner = 0; corner < 4; ++corner) nodes.row(4 * i + corner) << x, corner & 1, corner >> 1;
    if (i < n) x += widths[i];
  }
  std::vector<FaceLoops> cells;
  for (int i = 0; i < n; ++i) {
    const int a = 4 * i, b = 4 * (i + 1);  // the corners (y, z) = (0,0), (1,0), (0,1), (1,1) at x_i and x_i+1
    const Eigen::Vector3d inside = nodes.middleRows(a, 8).colwise().mean().transpose();
    cells.push_back({outward({a, a + 1, a + 3, a + 2}, nodes, inside), outward({b, b + 1, b + 3, b + 2}, nodes, inside),
                     outward({a, a + 1, b + 1, b}, nodes, inside), outward({a + 2, a + 3, b + 3, b + 2}, nodes, inside),
                     outward({a, a + 2, b + 2, b}, nodes, inside),
                     outward({a + 1, a + 3, b + 3, b + 1}, nodes, inside)});
  }
  return mesh_of_cells(nodes, cells);
}

// log κ / log(volume ratio) between two rows.
double slope(double kappa_0, double ratio_0, double kappa_1, double ratio_1) {
  return std::log(kappa_1 / kappa_0) / std::log(ratio_1 / ratio_0);
}

TEST(DgConditioningFigure11, ConditionNumberGrowsWithTheVolumeRatio) {
  // The monomials are scaled by each element's diameter, so every entry of the small
  // element's rows scales like its size s: κ stays at the large elements' value (their
  // penalty against their softest elastic mode) until the small element's modes, ∝ s,
  // fall below that softest mode; from then on κ ∝ 1/s = (volume ratio)^⅓.
  std::printf("  %8s %12s %12s %12s\n", "scale", "vol. ratio", "kappa k=1", "kappa k=2");
  std::array<double, 2> previous{0, 0}, first_kappa{0, 0};
  double first_ratio = 0, ratio = 0;
  for (double scale : {0.5, 0.2, 0.1, 0.05, 0.02, 0.01, 1e-3, 1e-4, 1e-5, 1e-6}) {
    const PolyhedralMesh mesh = tetrahedron_with_inner_tetrahedron(scale);
    ASSERT_NEAR(mesh.cell_volumes.sum(), std::sqrt(2.0) / 12, 1e-12);
    ratio = mesh.cell_volumes.maxCoeff() / mesh.cell_volumes.minCoeff();
    std::array<double, 2> kappa{};
    for (int degree : {1, 2})
      kappa[degree - 1] =
          stiffness_conditioning(mesh, degree, [](const Eigen::Vector3d& x) { return x.z() < 1e-12; }).condition_number;
    std::printf("  %8.0e %12.3e %12.3e %12.3e\n", scale, ratio, kappa[0], kappa[1]);
    if (scale > 1e-3) continue;  // the plateau
    if (first_ratio == 0) first_ratio = ratio, first_kappa = kappa;
    for (int k = 0; k < 2; ++k) {
      EXPECT_GT(kappa[k], previous[k]) << "k = " << k + 1 << ", scale " << scale;
      previous[k] = kappa[k];
    }
  }
  for (int k = 0; k < 2; ++k) {
    const double measured = slope(first_kappa[k], first_ratio, previous[k], ratio);
    std::printf("  k = %d: kappa ~ (volume ratio)^%.3f from scale 1e-3 to 1e-6\n", k + 1, measured);
    EXPECT_NEAR(measured, 1.0 / 3, 0.03) << "k = " << k + 1;
  }
}

TEST(DgConditioningFigure11, GradedSlabsGrowWithTheVolumeRatioSquared) {
  // Four slabs of widths 1, 1/r, 1/r², 1/r³ (volume ratio r³): the thin slabs' diameter
  // stays ~√2, so their x-monomials shrink with the width as well and κ grows faster, as
  // (volume ratio)² for k = 1.
  std::printf("  %12s %12s\n", "vol. ratio", "kappa k=1");
  double previous = 0, first_kappa = 0, kappa = 0;
  for (double ratio : {1.0, 1e1, 1e2, 1e3, 1e4}) {
    const double r = std::cbrt(ratio);
    const PolyhedralMesh mesh = graded_row({1, 1 / r, 1 / (r * r), 1 / ratio});
    ASSERT_NEAR(mesh.cell_volumes.maxCoeff() / mesh.cell_volumes.minCoeff(), ratio, 1e-9 * ratio);
    kappa = stiffness_conditioning(mesh, 1, [](const Eigen::Vector3d& x) { return x.x() < 1e-12; }).condition_number;
    std::printf("  %12.3e %12.3e\n", ratio, kappa);
    EXPECT_GT(kappa, previous) << "volume ratio " << ratio;
    previous = kappa;
    if (ratio == 1e2) first_kappa = kappa;
  }
  const double measured = slope(first_kappa, 1e2, kappa, 1e4);
  std::printf("  kappa ~ (volume ratio)^%.3f from 1e2 to 1e4\n", measured);
  EXPECT_NEAR(measured, 2.0, 0.1);
}

TEST(DgConditioningFigure12, AThinningNeckKeepsTheConditionNumberBounded) {
  std::printf("  %8s %12s %12s %12s\n", "neck", "volume", "kappa k=1", "kappa k=2");
  std::array<double, 2> smallest{INFINITY, INFINITY}, largest{0, 0};
  for (double neck : {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6}) {
    const PolyhedralMesh mesh = dumbbell(neck);
    ASSERT_NEAR(mesh.cell_volumes[0], 2 + neck, 1e-12);
    std::array<double, 2> kappa{};
    for (int degree : {1, 2})
      kappa[degree - 1] =
          stiffness_conditioning(mesh, degree, [](const Eigen::Vector3d& x) { return x.z() < 1e-12; }).condition_number;
    std::printf("  %8.0e %12.6f %12.4e %12.4e\n", neck, mesh.cell_volumes[0], kappa[0], kappa[1]);
    for (int k = 0; k < 2; ++k) {
      smallest[k] = std::min(smallest[k], kappa[k]);
      largest[k] = std::max(largest[k], kappa[k]);
    }
  }
  for (int k = 0; k < 2; ++k) EXPECT_LT(largest[k], 1.2 * smallest[k]) << "k = " << k + 1;
}

// The exact Tet4 mesh of the dumbbell: the rectilinear grid through the planes of its
// three boxes, Kuhn-split, without the cells beside the neck (and the nodes only they use).
VolumeMesh dumbbell_tetrahedra(double neck) {
  const double left = 0.5 - neck / 2, right = 0.5 + neck / 2;
  const VolumeMesh grid = rectilinear_grid({{{0, left, right, 1}, {0, 1}, {0, 1, 2, 3}}}, ElementType::tet4);
  std::vector<int> new_index(grid.nodes.rows(), -1);
  std::vector<int> kept_nodes;
  std::vector<Eigen::RowVector4i> cells;
  for (Eigen::Index c = 0; c < grid.cells.rows(); ++c) {
    Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
    for (int v = 0; v < 4; ++v) centroid += grid.nodes.row(grid.cells(c, v)) / 4;
    if (centroid.z() > 1 && centroid.z() < 2 && (centroid.x() < left || centroid.x() > right)) continue;
    Eigen::RowVector4i cell;
    for (int v = 0; v < 4; ++v) {
      int& index = new_index[grid.cells(c, v)];
      if (index < 0) index = static_cast<int>(kept_nodes.size()), kept_nodes.push_back(grid.cells(c, v));
      cell[v] = index;
    }
    cells.push_back(cell);
  }
  VolumeMesh mesh;
  mesh.nodes.resize(static_cast<Eigen::Index>(kept_nodes.size()), 3);
  for (size_t n = 0; n < kept_nodes.size(); ++n) mesh.nodes.row(n) = grid.nodes.row(kept_nodes[n]);
  mesh.cells.resize(static_cast<Eigen::Index>(cells.size()), 4);
  for (size_t c = 0; c < cells.size(); ++c) mesh.cells.row(c) = cells[c];
  return mesh;
}

TEST(DgConditioningFigure12, Tet4FemOfTheSameNeckIsNot) {
  // The same dumbbell as Tet4 fem sees it (dumbbell_tetrahedra: the neck's column of cells
  // is ε wide), E = 1, ν = 0.3, the nodes at z = 0 held: κ of K on the free nodes.
  const auto material = make_material(MaterialModel::linear, 1.0, 0.3, 1.0);
  std::printf("  %8s %8s %12s\n", "neck", "tets", "kappa Tet4");
  double widest = 0, kappa = 0;
  for (double neck : {1e-1, 1e-2, 1e-3, 1e-4}) {
    const VolumeMesh mesh = dumbbell_tetrahedra(neck);
    const auto discretization = make_lagrange_discretization(mesh, *material, {}, 2);
    Eigen::SparseMatrix<double> stiffness = discretization->hessian_pattern();
    discretization->hessian(Eigen::VectorXd::Zero(discretization->dof_count()), stiffness, false);
    std::vector<int> free;
    for (int dof = 0; dof < discretization->dof_count(); ++dof)
      if (mesh.nodes(dof / 3, 2) > 0) free.push_back(dof);
    const Eigen::MatrixXd dense(stiffness);
    const Eigen::VectorXd eigenvalues =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dense(free, free), Eigen::EigenvaluesOnly).eigenvalues();
    ASSERT_GT(eigenvalues.minCoeff(), 0);
    kappa = eigenvalues.maxCoeff() / eigenvalues.minCoeff();
    if (widest == 0) widest = kappa;
    std::printf("  %8.0e %8lld %12.4e\n", neck, static_cast<long long>(mesh.cells.rows()), kappa);
  }
  // Three decades thinner: κ grows like ε⁻², six decades (the single DG element's stays
  // within 20%, above).
  EXPECT_GT(kappa, 1e5 * widest);
}

}  // namespace
}  // namespace altfem::dg
