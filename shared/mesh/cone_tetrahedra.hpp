#pragma once
// The tetrahedra of the convex pieces of a cut (cut_tetrahedral_mesh.hpp): a cone from one
// point of a piece over the triangles of its faces. Two pieces that share a face must
// split it alike, so how a face is split depends on the face alone:
//   - fanned from its lowest node (by position: an order no cut changes), as every face
//     was before — unless a triangle of that fan has no area to a rounding, or turns
//     against the face (nodes in the middle of an edge: a plane crossing faces that lie in
//     one plane puts them along their common line; a surface blade's steps on the faces of
//     the fragments they leave whole, or take nodes on their planes within 1e-9);
//   - then into its ears (triangles of its own nodes, each turning the face's way and
//     holding no other node, clipped in an order no cut changes), the face staying one
//     polygon in the fragments, so a later cut crosses it as one face, not each triangle;
//   - else (not a simple polygon to a rounding), and for a surface blade's changed faces
//     (`centred`), about its centroid, a new node that the face's pieces share, and the
//     face becomes those triangles in the fragments (a later cut fans each as itself); or,
//     for such a face its centroid does not see every edge of (not convex), its ears, which
//     become its faces too.
// Split about its centroid, a face with nodes in the middle of its edges became triangles
// with an edge to each node, and a later blade nearly parallel to an earlier one (a pencil
// sharpened 200 times) crossed most of them and made each a few: the faces of a piece grew
// about 1.4-fold a cut, to 75,000 after 55 cuts.
// The cone is from the piece's lowest node over the faces that do not hold it, as before,
// unless a face was split about its centroid or into ears, or a tetrahedron of that cone
// is flat (a face in a plane through that node, exactly or to a rounding: a face's
// triangles about its rounded centroid, the node on that face); then from the piece's
// centroid, a new node strictly inside it. Either way each face is split as itself alone
// decides.
#include <Eigen/Core>
#include <array>
#include <map>
#include <vector>

#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem {

class ConeTetrahedra {
public:
  using Row = std::array<int, 4>;

  /// `centred` (optional, per face): faces of more than three nodes to split about their
  /// centroid whatever their fan (a surface blade's changed faces, whose nodes a step took
  /// on its plane within 1e-9 fan into slivers of thin triangles).
  explicit ConeTetrahedra(const PolyhedralMesh& pieces, const std::vector<bool>& centred = {});

  /// Appends the tetrahedra of `piece` to `rows` (each positively oriented; flat ones left
  /// out and counted in `flat`); from its centroid with `from_centroid`.
  void split(int piece, bool from_centroid, std::vector<Row>& rows, int& flat);

  /// The new nodes (#nodes of the pieces + their place here): centroids of faces and pieces.
  const std::vector<Eigen::Vector3d>& added() const { return added_; }

  /// `pieces` (the mesh given, now to be changed) with each face split about its centroid
  /// as those triangles.
  void set_faces_of(PolyhedralMesh& pieces) const;

private:
  // Per face: −1 undecided, 0 fanned from its lowest node, clipped_ or kept_clipped_ split
  // into its ears (ears_; the triangles become faces of the fragments, or the face stays
  // one), else its centroid's node + 1.
  int centre_of(int face);
  // Decides `face`'s split about its centroid, or its ears where the centroid does not see
  // every edge.
  void split_about_centroid(int face);
  // Splits `face` into its ears, unless it is not a simple polygon to a rounding (false).
  bool clip_ears(int face, bool become_faces);
  bool is_clipped(int face) const { return fan_[face] == clipped_ || fan_[face] == kept_clipped_; }
  Eigen::Vector3d at(int node) const;
  int add_centroid(const std::vector<int>& nodes);
  Eigen::Vector3d position(int node) const;

  const PolyhedralMesh& pieces_;
  static constexpr int clipped_ = -2, kept_clipped_ = -3;
  std::vector<int> fan_;
  std::map<int, std::vector<std::array<int, 3>>> ears_;  // per clipped face, its triangles as it runs
  std::vector<Eigen::Vector3d> added_;
};

}  // namespace altfem
