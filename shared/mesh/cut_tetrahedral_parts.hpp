#pragma once
// The parts of cut_tetrahedral_mesh that its planar cut (cut_tetrahedral_mesh.cpp), a
// surface blade's (cut_tetrahedral_mesh_by_surface.cpp) and the pieces' cones
// (cone_tetrahedra.cpp) share. Only those include it.
#include <Eigen/Core>
#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "shared/mesh/cut_tetrahedral_mesh.hpp"

namespace altfem::tetrahedral_cut {

using TetrahedronRow = std::array<int, 4>;

TetrahedronRow row_of(const VolumeMesh& mesh, int cell);
VolumeMesh tetrahedra_of_rows(const Eigen::MatrixXd& nodes, const std::vector<TetrahedronRow>& rows);

/// Not positively oriented (exact predicate), or a sliver by its rounded volume (under
/// 1e-14 of its longest edge cubed).
bool is_flat(const Eigen::MatrixXd& nodes, const TetrahedronRow& row);
/// The same for the tetrahedron of these corners.
bool is_flat(const Eigen::Vector3d& origin, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
             const Eigen::Vector3d& c);

/// Node a before node b by position (lexicographic coordinates; equal positions by index):
/// an order no cut changes, since nodes never move and a copy sits where its node does, so
/// a face fanned from its first node is fanned alike before and after any later cut.
bool comes_before(const Eigen::MatrixXd& nodes, int a, int b);

/// The cell's node loops, each counter-clockwise seen from outside it.
std::vector<std::vector<int>> outward_loops(const PolyhedralMesh& mesh, int cell);

/// The input's fragments that hold a tetrahedron that is not flat, as the polyhedral mesh
/// the blade cuts: per kept fragment its input index and non-flat tetrahedra, and per
/// node of that mesh its input node.
struct CutInput {
  std::optional<PolyhedralMesh> built;        ///< when not the input's own fragments, whole
  const PolyhedralMesh* fragments = nullptr;  ///< the input's, when it keeps every one
  std::vector<int> fragment;                  ///< per cell of mesh()
  std::vector<std::vector<int>> tetrahedra;   ///< per cell of mesh()
  std::vector<int> input_node;                ///< per node of mesh(); empty: the same numbers

  const PolyhedralMesh& mesh() const { return built ? *built : *fragments; }
  int input_node_of(int node) const { return input_node.empty() ? node : input_node[node]; }
};
CutInput cut_input(const FragmentedTetrahedra& input, int& flat);

/// Per node of `mesh`, whether a face holds it: a node none holds lies inside a fragment,
/// a cone's apex (cone_tetrahedra.hpp), which no cut duplicates.
std::vector<bool> on_a_face(const PolyhedralMesh& mesh);

/// The input tetrahedra of a piece the blade did not cross, each corner taken as the copy
/// of its node that the piece holds (`copied`: per node of `pieces`, the input node it is
/// or copies, −1 for none), a corner `inside` a fragment (per input node) as itself; false
/// when a corner has none (then the piece is split afresh). `copy_of`: scratch, reused.
bool carry_tetrahedra(const PolyhedralMesh& pieces, int piece, const std::vector<int>& copied,
                      const std::vector<bool>& inside, const VolumeMesh& input, const std::vector<int>& tetrahedra,
                      std::vector<TetrahedronRow>& rows, std::vector<std::pair<int, int>>& copy_of);

/// Per input node, whether it is a cone's apex inside a fragment (a tetrahedron's corner no
/// face of `fragments` holds).
std::vector<bool> inside_fragments(const FragmentedTetrahedra& input, const CutInput& fragments);

/// `fragments` with `added` appended to its nodes, and the tetrahedra `rows` on them, as
/// the output's.
void set_result(FragmentedTetrahedra& output, PolyhedralMesh fragments, const std::vector<Eigen::Vector3d>& added,
                const std::vector<TetrahedronRow>& rows);

}  // namespace altfem::tetrahedral_cut
