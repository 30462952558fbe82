#pragma once
// The levels below the vertex coarse space (dg/vertex_coarse_space.hpp) of DG's multilevel
// preconditioner: Cartesian background grids of spacings 2h, 4h, 8h, … over the mesh's
// bounding box, each prolongated to the level above — the mesh's vertices, then the next finer
// grid — by trilinear interpolation of its nodes' values. The grids share the box's lowest
// corner as origin, so from the second grid on each is nested in the one above and the
// interpolation is the standard geometric-multigrid one; the vertices of a grid-aligned mesh of
// spacing h (the 10³ cube of bench_dg_table1) are nested in the first grid too.
//
// Why a background grid and not the mesh's own coarsening: sliced and polyhedral meshes have no
// hierarchy, and a grid needs none — only the vertex positions. Trilinear interpolation
// reproduces affine fields, so every level keeps the rigid motions and the constant strains the
// coarse levels must carry (the same reason the vertex space fits affine functions).
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <vector>

#include "dg/vertex_coarse_space.hpp"

namespace altfem::dg {

/// The prolongations of the grid levels, finest first: element l is 3 · #nodes(level l) ×
/// 3 · #nodes(level l + 1), level 0 being the points; column 3n + i is the unit value of
/// component i at node n, as in the vertex space's prolongation. Each grid keeps only the
/// nodes that some point of the level above interpolates from. Grids are added, the spacing
/// doubling from `finest_spacing`, until one has at most `coarsest_nodes` nodes or stops
/// shrinking; none when the points are already that few.
/// points: #points × 3 (the vertex space's vertices); finest_spacing > 0.
std::vector<Eigen::SparseMatrix<double>> grid_coarse_levels(const Eigen::MatrixXd& points, double finest_spacing,
                                                            int coarsest_nodes);

/// At most this many nodes on the coarsest grid, factorised by CHOLMOD: on the 10³ grid of
/// bench_dg_table1 its 6³ nodes (648 unknowns, ~140 nonzeros a row) take about 3 ms with the
/// analysis; a 64-node limit (one more level) saved that and cost more in the iterations.
inline constexpr int coarsest_grid_nodes = 512;

/// The grid levels below `space` (the vertex coarse space of `mesh`, whose cells are
/// `system`'s): its vertices as points, the finest spacing twice the median cell size ∛vol(K)
/// (2h on a grid of cubes of edge h), at most coarsest_grid_nodes on the coarsest grid.
std::vector<Eigen::SparseMatrix<double>> grid_coarse_levels(const PolyhedralMesh& mesh, const DgLinearSystem& system,
                                                            const VertexCoarseSpace& space);

}  // namespace altfem::dg
