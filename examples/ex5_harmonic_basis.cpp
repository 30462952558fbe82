// Example 5: the harmonic basis of one non-convex polyhedral element
// (Martin et al. 2008, §4–5, Fig. 2), written to VTU.
//
//   build/bin/ex5_harmonic_basis [OUTPUT.vtu]     (default: ex5_harmonic_basis.vtu here)
//
// A polyhedral element has no reference element and no Lagrange basis. Martin et al.
// build one node function N_i per vertex i that is HARMONIC inside the element (ΔN_i = 0)
// and on the boundary equals a 2D harmonic coordinate of the face: 1 at vertex i, 0 at
// the others, linear along edges. By the maximum principle 0 ≤ N_i ≤ 1, and since
// constants and linear fields are harmonic, Σ_i N_i = 1 and Σ_i N_i x_i = x exactly.
// altfem approximates each N_i by the method of fundamental solutions (eq. (11)):
//   N_i(x) = Σ_j w_ij / ‖x − k_j‖ + a_i·x + a_i0,  kernel centres k_j outside the element,
// fitted in the least-squares sense to the boundary data at collocation points (eq. (14)).
// The element here is an L-shaped prism — non-convex, with non-convex top and bottom —
// where no barycentric or trilinear construction applies.
#include <algorithm>
#include <cstdio>

#include "polyhedral/element_harmonic_basis.hpp"
#include "shared/io/vtu_writer.hpp"
#include "shared/mesh/structured_grid.hpp"

using namespace altfem;

// The prism of height 0.7 over the L = [0,2]×[0,1] ∪ [0,1]×[0,2]: bottom vertices 0–5
// along the outline (counter-clockwise seen from above), top vertices 6–11 above them.
Polyhedron l_shaped_prism() {
  const double outline[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  Polyhedron prism;
  prism.vertices.resize(12, 3);
  for (int k = 0; k < 6; ++k) {
    prism.vertices.row(k) << outline[k][0], outline[k][1], 0.0;
    prism.vertices.row(k + 6) << outline[k][0], outline[k][1], 0.7;
  }
  // Faces counter-clockwise seen from outside: the bottom reversed, the top as is, and
  // one quadrilateral per outline edge.
  prism.faces = {{5, 4, 3, 2, 1, 0}, {6, 7, 8, 9, 10, 11}};
  for (int k = 0; k < 6; ++k) prism.faces.push_back({k, (k + 1) % 6, (k + 1) % 6 + 6, k + 6});
  return prism;
}

int main(int argc, char** argv) {
  const char* output = argc > 1 ? argv[1] : "ex5_harmonic_basis.vtu";
  const Polyhedron element = l_shaped_prism();
  const harmonic::ElementHarmonicBasis basis(element, {});
  std::printf("L-shaped prism: %d nodes, %lld kernel centres, boundary fit RMS %.2e\n", basis.node_count(),
              static_cast<long long>(basis.centres().rows()), basis.boundary_residual());

  // 1. Kronecker property N_i(x_j) = δ_ij at the vertices: as good as the boundary fit.
  //    Along the re-entrant edge (vertices 3 and 9, interior angle 3π/2) the exact N_i
  //    behave like r^(2/3): their gradient is singular, and the smooth MFS fit is worst
  //    there; at the other ten vertices the error is that of the fit elsewhere.
  const Eigen::MatrixXd at_vertices = basis.values(element.vertices);  // #nodes × #nodes
  const Eigen::VectorXd kronecker_errors =
      (at_vertices - Eigen::MatrixXd::Identity(basis.node_count(), basis.node_count())).cwiseAbs().rowwise().maxCoeff();
  double kronecker_error = 0, reentrant_kronecker_error = 0;
  for (int j = 0; j < basis.node_count(); ++j) {
    double& worst = j % 6 == 3 ? reentrant_kronecker_error : kronecker_error;
    worst = std::max(worst, kronecker_errors[j]);
  }

  // 2. A sampling grid of the element: the cells of a 16 × 16 × 6 grid of its bounding box
  //    whose centre lies inside (winding number 1); the L's edges fall on grid lines, so
  //    the kept cells fill the element exactly. Unused grid nodes are dropped.
  const VolumeMesh box =
      structured_grid({Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 2, 0.7)}, {16, 16, 6}, ElementType::hex8);
  std::vector<int> kept_cells, node_number(box.nodes.rows(), -1);
  int node_count = 0;
  for (Eigen::Index cell = 0; cell < box.cells.rows(); ++cell) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int a = 0; a < 8; ++a) centre += box.nodes.row(box.cells(cell, a)).transpose() / 8;
    if (harmonic::winding_number(element, centre) < 0.5) continue;
    kept_cells.push_back(static_cast<int>(cell));
    for (int a = 0; a < 8; ++a)
      if (node_number[box.cells(cell, a)] < 0) node_number[box.cells(cell, a)] = node_count++;
  }
  VolumeMesh samples{ElementType::hex8, Eigen::MatrixXd(node_count, 3),
                     Eigen::MatrixXi(static_cast<Eigen::Index>(kept_cells.size()), 8)};
  for (Eigen::Index node = 0; node < box.nodes.rows(); ++node)
    if (node_number[node] >= 0) samples.nodes.row(node_number[node]) = box.nodes.row(node);
  for (size_t k = 0; k < kept_cells.size(); ++k)
    for (int a = 0; a < 8; ++a)
      samples.cells(static_cast<Eigen::Index>(k), a) = node_number[box.cells(kept_cells[k], a)];

  // 3. Partition of unity, linear reproduction and the maximum principle on the samples.
  const Eigen::MatrixXd values = basis.values(samples.nodes);  // #samples × #nodes
  const double unity_error = (values.rowwise().sum().array() - 1.0).abs().maxCoeff();
  const double linear_error = (values * element.vertices - samples.nodes).cwiseAbs().maxCoeff();
  const double lowest = values.minCoeff(), highest = values.maxCoeff();
  std::printf("%lld sample points in %lld cells (volume %.3f, the element's 2.100)\n",
              static_cast<long long>(samples.nodes.rows()), static_cast<long long>(samples.cells.rows()),
              samples.cells.rows() * (2.0 / 16) * (2.0 / 16) * (0.7 / 6));
  std::printf("max |N_i(x_j) - delta_ij| at the vertices   %.2e (re-entrant edge: %.2e)\n", kronecker_error,
              reentrant_kronecker_error);
  std::printf("max |sum_i N_i - 1|                        %.2e\n", unity_error);
  std::printf("max |sum_i N_i x_i - x|                    %.2e\n", linear_error);
  std::printf("range of the N_i over the samples          [%.4f, %.4f]\n", lowest, highest);

  // 4. The VTU: the sampling cells with every N_i and their sum as point data. Node 3 is
  //    the re-entrant corner (1, 1, 0), whose function bends around the notch.
  UnstructuredGrid grid = grid_from_volume_mesh(samples);
  for (int i = 0; i < basis.node_count(); ++i) grid.point_data.emplace_back("N_" + std::to_string(i), values.col(i));
  grid.point_data.emplace_back("sum", values.rowwise().sum());
  write_vtu(output, grid);
  std::printf("wrote %s (point data N_0 ... N_11 and their sum; N_3 is the re-entrant corner's)\n", output);

  // Partition of unity and linear reproduction hold to round-off by construction; the
  // rest is the MFS fit's accuracy with the default sampling (MfsOptions: 4 samples per
  // edge, picked for the solutions' accuracy against time). Its spacing comes from the
  // element's surface area, 1.24x coarser here than the mean edge length it came from
  // before (which made cut cells with many short edges 50x slower). Measured at 4 samples:
  // δ_ij missed by 3.0e-2 at the other vertices and 0.19 on the re-entrant edge, the N_i
  // within [−0.030, 1.011]; at 5: 7.9e-3, 0.13 (10 samples per edge: 0.075).
  const bool ok = unity_error < 1e-10 && linear_error < 1e-10 && kronecker_error < 4e-2 &&
                  reentrant_kronecker_error < 0.2 && lowest > -4e-2 && highest < 1 + 4e-2;
  std::printf(
      "\n%s: partition of unity and linear reproduction to 1e-10; N_i(x_j) = delta_ij to 4e-2\n"
      "(0.2 on the re-entrant edge); 0 <= N_i <= 1 to 4e-2\n",
      ok ? "verified" : "NOT verified");
  return ok ? 0 : 1;
}
