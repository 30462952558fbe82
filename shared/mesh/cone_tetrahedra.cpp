#include "shared/mesh/cone_tetrahedra.hpp"

#include <algorithm>

#include "shared/mesh/cut_tetrahedral_parts.hpp"

namespace altfem {

namespace {

// A fan triangle with twice its area, along the face's normal, under this fraction of the
// face's longest edge squared has none to a rounding: its nodes lie on one line.
constexpr double flat_triangle_fraction = 1e-6;

// A face's centroid sees an edge when their triangle turns the face's way by more than
// this fraction of its longest edge squared: a face that is not convex (the L a notch's
// corner leaves of a section has its centroid at its reflex corner) has one that turns back
// or has no area. Not the fan's threshold: a convex face with a short edge has a thin
// triangle there, whose tetrahedron about the centroid is sound.
constexpr double reflex_fraction = 1e-12;

// Whether (a, b, c) turns about `normal` by more than `fraction` of `longest`, a face's
// longest edge squared.
bool turns_with(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                const Eigen::Vector3d& normal, double longest, double fraction) {
  return (b - a).cross(c - a).dot(normal) > fraction * longest;
}

// Whether `point` of the face's plane lies in the triangle (a, b, c), which turns about
// `normal`, or on its edges.
bool in_triangle(const Eigen::Vector3d& point, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                 const Eigen::Vector3d& c, const Eigen::Vector3d& normal) {
  return (b - a).cross(point - a).dot(normal) >= 0 && (c - b).cross(point - b).dot(normal) >= 0 &&
         (a - c).cross(point - c).dot(normal) >= 0;
}

}  // namespace

ConeTetrahedra::ConeTetrahedra(const PolyhedralMesh& pieces, const std::vector<bool>& centred)
    : pieces_(pieces), fan_(static_cast<std::size_t>(pieces.face_count()), -1) {
  for (std::size_t face = 0; face < centred.size(); ++face)
    if (centred[face] && pieces.faces[face].size() > 3) split_about_centroid(static_cast<int>(face));
}

Eigen::Vector3d ConeTetrahedra::at(int node) const { return pieces_.nodes.row(node).transpose(); }

void ConeTetrahedra::split_about_centroid(int face) {
  const std::vector<int>& loop = pieces_.faces[face];
  const Eigen::Vector3d normal = face_area_vector(pieces_, loop).normalized();
  double longest = 0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < loop.size(); ++k) {
    longest = std::max(longest, (at(loop[(k + 1) % loop.size()]) - at(loop[k])).squaredNorm());
    centroid += at(loop[k]) / static_cast<double>(loop.size());
  }
  bool sees_every_edge = true;
  for (std::size_t k = 0; k < loop.size() && sees_every_edge; ++k)
    sees_every_edge =
        turns_with(centroid, at(loop[k]), at(loop[(k + 1) % loop.size()]), normal, longest, reflex_fraction);
  // A face the joins of a surface blade's pieces merged need not be convex (the L that a
  // notch's corner leaves of a section has its centroid at the reflex corner, whose
  // triangles about it are flat): its ears clipped instead.
  if (sees_every_edge || !clip_ears(face, true)) fan_[face] = add_centroid(loop) + 1;
}

bool ConeTetrahedra::clip_ears(int face, bool become_faces) {
  // The loop in an order no cut changes: from its lowest node by position, towards the
  // lesser of that node's two neighbours, so the fragments on either side of the face, and
  // a fragment split again later, clip the same ears.
  std::vector<int> left = pieces_.faces[face];
  const auto before = [&](int a, int b) { return tetrahedral_cut::comes_before(pieces_.nodes, a, b); };
  std::rotate(left.begin(), std::min_element(left.begin(), left.end(), before), left.end());
  const bool reversed = before(left.back(), left[1]);
  if (reversed) std::reverse(left.begin() + 1, left.end());
  const Eigen::Vector3d normal = face_area_vector(pieces_, left).normalized();
  double longest = 0;
  for (std::size_t k = 0; k < left.size(); ++k)
    longest = std::max(longest, (at(left[(k + 1) % left.size()]) - at(left[k])).squaredNorm());
  // Each ear a triangle that turns the face's way and holds no other node, the first one
  // found from the lowest node.
  std::vector<std::array<int, 3>> triangles;
  while (left.size() > 3) {
    const std::size_t n = left.size();
    std::size_t ear = n;
    for (std::size_t k = 0; k < n && ear == n; ++k) {
      const int a = left[(k + n - 1) % n], b = left[k], c = left[(k + 1) % n];
      if (!turns_with(at(a), at(b), at(c), normal, longest, flat_triangle_fraction)) continue;
      bool empty = true;
      for (const int other : left)
        if (other != a && other != b && other != c && in_triangle(at(other), at(a), at(b), at(c), normal))
          empty = false;
      if (empty) ear = k;
    }
    if (ear == n) return false;  // not a simple polygon to a rounding
    triangles.push_back({left[(ear + n - 1) % n], left[ear], left[(ear + 1) % n]});
    left.erase(left.begin() + static_cast<std::ptrdiff_t>(ear));
  }
  if (!turns_with(at(left[0]), at(left[1]), at(left[2]), normal, longest, flat_triangle_fraction)) return false;
  triangles.push_back({left[0], left[1], left[2]});
  if (reversed)  // as the face runs
    for (auto& triangle : triangles) std::swap(triangle[1], triangle[2]);
  fan_[face] = become_faces ? clipped_ : kept_clipped_;
  ears_[face] = std::move(triangles);
  return true;
}

int ConeTetrahedra::centre_of(int face) {
  if (fan_[face] < 0) {
    std::vector<int> loop = pieces_.faces[face];
    std::rotate(loop.begin(),
                std::min_element(loop.begin(), loop.end(),
                                 [&](int a, int b) { return tetrahedral_cut::comes_before(pieces_.nodes, a, b); }),
                loop.end());
    double longest = 0;
    for (std::size_t k = 0; k < loop.size(); ++k)
      longest = std::max(longest, (at(loop[(k + 1) % loop.size()]) - at(loop[k])).squaredNorm());
    // Signed against the face's own normal (Newell's, of the whole loop): a triangle of a
    // face a rounding from convex (nodes a step took on its plane within 1e-9) may turn
    // the other way, and its tetrahedron then is flat.
    const Eigen::Vector3d normal = face_area_vector(pieces_, loop).normalized();
    bool degenerate = false;
    for (std::size_t k = 1; k + 1 < loop.size() && !degenerate; ++k)
      degenerate = (at(loop[k]) - at(loop[0])).cross(at(loop[k + 1]) - at(loop[0])).dot(normal) <=
                   flat_triangle_fraction * longest;
    // Ears that fail (not a simple polygon to a rounding) fail whoever clips them: the
    // centroid at once.
    if (!degenerate) fan_[face] = 0;
    else if (!clip_ears(face, false)) fan_[face] = add_centroid(pieces_.faces[face]) + 1;
  }
  return is_clipped(face) ? -1 : fan_[face] - 1;
}

int ConeTetrahedra::add_centroid(const std::vector<int>& nodes) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const int node : nodes) sum += pieces_.nodes.row(node).transpose();
  added_.push_back(sum / static_cast<double>(nodes.size()));
  return static_cast<int>(pieces_.nodes.rows() + static_cast<Eigen::Index>(added_.size()) - 1);
}

Eigen::Vector3d ConeTetrahedra::position(int node) const {
  return node < pieces_.nodes.rows() ? Eigen::Vector3d(pieces_.nodes.row(node).transpose())
                                     : added_[static_cast<std::size_t>(node - pieces_.nodes.rows())];
}

void ConeTetrahedra::split(int piece, bool from_centroid, std::vector<Row>& rows, int& flat) {
  const Eigen::MatrixXd& nodes = pieces_.nodes;
  const auto before = [&](int a, int b) { return tetrahedral_cut::comes_before(nodes, a, b); };
  const std::vector<int>& faces = pieces_.cell_faces[piece];
  const std::vector<std::vector<int>> loops = tetrahedral_cut::outward_loops(pieces_, piece);
  int apex = loops[0][0];
  for (const auto& loop : loops) apex = std::min(apex, *std::min_element(loop.begin(), loop.end(), before), before);
  bool centred = false;
  for (const int face : faces) centred |= centre_of(face) >= 0 || is_clipped(face);
  if (!from_centroid && !centred) {
    // A face in a plane through the apex that does not hold it, exactly or to a rounding
    // (a face's triangles about its rounded centroid, the apex a node of that face), makes
    // the cone's tetrahedra over it flat: then the cone is from the centroid instead.
    const std::size_t first_row = rows.size();
    bool any_flat = false;
    for (std::size_t index = 0; index < loops.size() && !any_flat; ++index) {
      std::vector<int> loop = loops[index];
      if (std::find(loop.begin(), loop.end(), apex) != loop.end()) continue;
      std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end(), before), loop.end());
      for (std::size_t k = 1; k + 1 < loop.size() && !any_flat; ++k) {
        const Row row{apex, loop[0], loop[k], loop[k + 1]};
        any_flat = tetrahedral_cut::is_flat(nodes, row);
        rows.push_back(row);
      }
    }
    if (!any_flat) return;
    rows.resize(first_row);
  }
  std::vector<int> all;
  for (const auto& loop : loops) all.insert(all.end(), loop.begin(), loop.end());
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  const int centroid = add_centroid(all);
  const auto add = [&](int a, int b, int c) {
    if (tetrahedral_cut::is_flat(position(centroid), position(a), position(b), position(c))) ++flat;
    else rows.push_back({centroid, a, b, c});
  };
  for (std::size_t index = 0; index < faces.size(); ++index) {
    std::vector<int> loop = loops[index];
    if (const int centre = centre_of(faces[index]); centre >= 0) {
      for (std::size_t k = 0; k < loop.size(); ++k) add(centre, loop[k], loop[(k + 1) % loop.size()]);
      continue;
    }
    if (is_clipped(faces[index])) {  // its ears, as the face runs, reversed where the piece's loop is
      const bool reversed = pieces_.face_cells(faces[index], 0) != piece;
      for (const auto& [a, b, c] : ears_.at(faces[index])) reversed ? add(a, c, b) : add(a, b, c);
      continue;
    }
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end(), before), loop.end());
    for (std::size_t k = 1; k + 1 < loop.size(); ++k) add(loop[0], loop[k], loop[k + 1]);
  }
}

void ConeTetrahedra::set_faces_of(PolyhedralMesh& pieces) const {
  if (std::none_of(fan_.begin(), fan_.end(), [](int fan) { return fan > 0 || fan == clipped_; })) return;
  std::vector<std::vector<int>> loops;
  std::vector<std::array<int, 2>> cells;
  for (int face = 0; face < pieces.face_count(); ++face) {
    const std::array<int, 2> sides{pieces.face_cells(face, 0), pieces.face_cells(face, 1)};
    const std::vector<int>& loop = pieces.faces[face];
    if (fan_[face] == clipped_) {
      for (const auto& [a, b, c] : ears_.at(face)) {
        loops.push_back({a, b, c});
        cells.push_back(sides);
      }
      continue;
    }
    if (fan_[face] <= 0) {
      loops.push_back(loop);
      cells.push_back(sides);
      continue;
    }
    for (std::size_t k = 0; k < loop.size(); ++k) {
      loops.push_back({fan_[face] - 1, loop[k], loop[(k + 1) % loop.size()]});
      cells.push_back(sides);
    }
  }
  set_faces(pieces, std::move(loops), cells);
}

}  // namespace altfem
