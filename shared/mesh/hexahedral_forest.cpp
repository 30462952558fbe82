#include "shared/mesh/hexahedral_forest.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include "shared/element/reference_element.hpp"

namespace altfem {

namespace {

constexpr int units = forest_units_per_cell;

// A lattice point as one 64-bit key: each coordinate below 2^21 (grid_forest's limit).
std::uint64_t lattice_key(const Eigen::Vector3i& point) {
  return static_cast<std::uint64_t>(point.x()) | static_cast<std::uint64_t>(point.y()) << 21 |
         static_cast<std::uint64_t>(point.z()) << 42;
}

// Which leaf holds a point, by its level and lower corner: one hash lookup per level in use.
class LeafLocator {
public:
  explicit LeafLocator(const HexahedralForest& forest) : extent_(2 * units * forest.resolution) {
    for (int leaf = 0; leaf < forest.leaf_count(); ++leaf) {
      const int level = forest.levels[leaf];
      if (level >= static_cast<int>(leaves_.size())) leaves_.resize(level + 1);
      leaves_[level].emplace(lattice_key(forest.origins[leaf]), leaf);
    }
  }
  // The leaf whose interior holds the point at `doubled` (lattice coordinates × 2, so that a
  // point half a unit off a node is integral); -1 outside the grid.
  int locate(const Eigen::Vector3i& doubled) const {
    if ((doubled.array() < 0).any() || (doubled.array() >= extent_.array()).any()) return -1;
    for (int level = 0; level < static_cast<int>(leaves_.size()); ++level) {
      const int edge = HexahedralForest::edge_units(level);
      const Eigen::Vector3i origin = (doubled.array() / (2 * edge)) * edge;
      const auto found = leaves_[level].find(lattice_key(origin));
      if (found != leaves_[level].end()) return found->second;
    }
    return -1;
  }

private:
  Eigen::Vector3i extent_;
  std::vector<std::unordered_map<std::uint64_t, int>> leaves_;  // per level: corner → leaf
};

// The 18 directions to a leaf's face and edge neighbours.
std::vector<Eigen::Vector3i> face_and_edge_directions() {
  std::vector<Eigen::Vector3i> directions;
  for (int z = -1; z <= 1; ++z)
    for (int y = -1; y <= 1; ++y)
      for (int x = -1; x <= 1; ++x) {
        const int nonzero = (x != 0) + (y != 0) + (z != 0);
        if (nonzero == 1 || nonzero == 2) directions.emplace_back(x, y, z);
      }
  return directions;
}

// Each leaf replaced by its eighths where `split` says so.
HexahedralForest split_leaves(const HexahedralForest& forest, const std::vector<char>& split) {
  HexahedralForest result{forest.box, forest.resolution, forest.type, {}, {}};
  for (int leaf = 0; leaf < forest.leaf_count(); ++leaf) {
    if (!split[leaf]) {
      result.origins.push_back(forest.origins[leaf]);
      result.levels.push_back(forest.levels[leaf]);
      continue;
    }
    if (forest.levels[leaf] >= max_forest_level)
      throw std::invalid_argument("refine_forest: leaf " + std::to_string(leaf) + " is at the deepest level, " +
                                  std::to_string(max_forest_level));
    const int half = HexahedralForest::edge_units(forest.levels[leaf] + 1);
    for (int z = 0; z < 2; ++z)
      for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
          result.origins.push_back(forest.origins[leaf] + half * Eigen::Vector3i(x, y, z));
          result.levels.push_back(forest.levels[leaf] + 1);
        }
  }
  return result;
}

}  // namespace

Eigen::Vector3d HexahedralForest::position(const Eigen::Vector3i& lattice) const {
  Eigen::Vector3d point;
  // As structured_grid places its planes, min + size · i / n, so that grid nodes agree bit for bit.
  for (int axis = 0; axis < 3; ++axis)
    point[axis] = box.min()[axis] + box.sizes()[axis] * (static_cast<double>(lattice[axis]) / units) / resolution[axis];
  return point;
}

HexahedralForest grid_forest(const Eigen::AlignedBox3d& box, const Eigen::Vector3i& resolution, ElementType type) {
  if (type != ElementType::hex8 && type != ElementType::hex20 && type != ElementType::hex27)
    throw std::invalid_argument("grid_forest: the cells must be hex8, hex20 or hex27");
  if ((resolution.array() < 1).any() || (resolution.array() > 1000).any())
    throw std::invalid_argument("grid_forest: the resolution must be 1 to 1000 cells per axis");
  if (!((box.sizes().array() > 0).all())) throw std::invalid_argument("grid_forest: the box is empty");
  HexahedralForest forest{box, resolution, type, {}, {}};
  for (int k = 0; k < resolution.z(); ++k)
    for (int j = 0; j < resolution.y(); ++j)
      for (int i = 0; i < resolution.x(); ++i) {
        forest.origins.push_back(units * Eigen::Vector3i(i, j, k));
        forest.levels.push_back(0);
      }
  return forest;
}

void keep_leaves(HexahedralForest& forest, const std::vector<bool>& keep) {
  if (keep.size() != forest.levels.size()) throw std::invalid_argument("keep_leaves: a flag per leaf");
  std::size_t kept = 0;
  for (std::size_t leaf = 0; leaf < keep.size(); ++leaf)
    if (keep[leaf]) {
      forest.origins[kept] = forest.origins[leaf];
      forest.levels[kept] = forest.levels[leaf];
      ++kept;
    }
  forest.origins.resize(kept);
  forest.levels.resize(kept);
}

HexahedralForest refine_forest(const HexahedralForest& forest, const std::vector<int>& marked, int* balancing_splits) {
  std::vector<char> split(static_cast<std::size_t>(forest.leaf_count()), 0);
  for (const int leaf : marked) split.at(leaf) = 1;
  HexahedralForest result = split_leaves(forest, split);
  const std::vector<Eigen::Vector3i> directions = face_and_edge_directions();
  int added = 0;
  for (;;) {
    // A leaf F of level f sees, just past each face and edge, a leaf that must be of level
    // f − 1 or finer; a coarser one is split, and the check repeats on the result.
    const LeafLocator locator(result);
    std::vector<char> coarse(static_cast<std::size_t>(result.leaf_count()), 0);
    int found = 0;
    for (int leaf = 0; leaf < result.leaf_count(); ++leaf) {
      if (result.levels[leaf] < 2) continue;
      const int edge = HexahedralForest::edge_units(result.levels[leaf]);
      const Eigen::Vector3i doubled_centre = 2 * result.origins[leaf] + Eigen::Vector3i::Constant(edge);
      for (const Eigen::Vector3i& direction : directions) {
        const int neighbour = locator.locate(doubled_centre + (edge + 1) * direction);
        if (neighbour >= 0 && result.levels[neighbour] < result.levels[leaf] - 1 && !coarse[neighbour]) {
          coarse[neighbour] = 1;
          ++found;
        }
      }
    }
    if (found == 0) break;
    added += found;
    result = split_leaves(result, coarse);
  }
  if (balancing_splits) *balancing_splits = added;
  return result;
}

ConstrainedHexahedralMesh forest_mesh(const HexahedralForest& forest) {
  const ReferenceElement& reference = reference_element(forest.type);
  const int per_cell = reference.node_count();
  // Which of the 3 × 3 × 3 points {−1, 0, 1}³ of the reference cube are nodes of the type.
  std::array<bool, 27> is_node{};
  std::vector<Eigen::Vector3i> steps(per_cell);  // a node's offset in half edges (0, 1, 2)
  for (int a = 0; a < per_cell; ++a) {
    steps[a] = (reference.nodes().row(a).transpose().array() + 1).round().cast<int>();
    is_node[steps[a].x() + 3 * steps[a].y() + 9 * steps[a].z()] = true;
  }

  // Nodes by lattice position, numbered as first met.
  std::unordered_map<std::uint64_t, int> node_at;
  std::vector<Eigen::Vector3i> lattice;
  Eigen::MatrixXi cells(forest.leaf_count(), per_cell);
  for (int leaf = 0; leaf < forest.leaf_count(); ++leaf) {
    const int half = HexahedralForest::edge_units(forest.levels[leaf]) / 2;
    for (int a = 0; a < per_cell; ++a) {
      const Eigen::Vector3i point = forest.origins[leaf] + half * steps[a];
      const auto [entry, inserted] = node_at.try_emplace(lattice_key(point), static_cast<int>(lattice.size()));
      if (inserted) lattice.push_back(point);
      cells(leaf, a) = entry->second;
    }
  }

  // A node is hanging when a leaf touching it (in one of its 8 octants) does not have it as
  // a node; the coarsest such leaf's interpolation at it gives its values. Every such leaf
  // is kept too, coarsest first, for a method that keeps only some leaves (sources).
  const LeafLocator locator(forest);
  const int node_count = static_cast<int>(lattice.size());
  DirectConstraints direct(node_count);  // masters, possibly hanging
  std::vector<std::vector<HangingNodeSource>> candidates(node_count);
  std::vector<char> hanging(node_count, 0);
  std::vector<int> lacking;
  Eigen::VectorXd values(per_cell);
  for (int node = 0; node < node_count; ++node) {
    lacking.clear();
    for (int octant = 0; octant < 8; ++octant) {
      const Eigen::Vector3i sign(octant & 1 ? 1 : -1, octant & 2 ? 1 : -1, octant & 4 ? 1 : -1);
      const int leaf = locator.locate(2 * lattice[node] + sign);
      if (leaf < 0 || std::find(lacking.begin(), lacking.end(), leaf) != lacking.end()) continue;
      const int half = HexahedralForest::edge_units(forest.levels[leaf]) / 2;
      const Eigen::Vector3i offset = lattice[node] - forest.origins[leaf];
      const bool on_half_edges = offset.x() % half == 0 && offset.y() % half == 0 && offset.z() % half == 0;
      const Eigen::Vector3i step = offset / half;
      if (!on_half_edges || !is_node[step.x() + 3 * step.y() + 9 * step.z()]) lacking.push_back(leaf);
    }
    if (lacking.empty()) continue;
    hanging[node] = 1;
    std::stable_sort(lacking.begin(), lacking.end(), [&](int a, int b) { return forest.levels[a] < forest.levels[b]; });
    for (const int leaf : lacking) {
      const int edge = HexahedralForest::edge_units(forest.levels[leaf]);
      const Eigen::Vector3d xi = (2.0 * (lattice[node] - forest.origins[leaf]).cast<double>() / edge).array() - 1.0;
      reference.evaluate(xi, values);
      HangingNodeSource& source = candidates[node].emplace_back();
      source.leaf = leaf;
      for (int a = 0; a < per_cell; ++a)
        if (std::abs(values[a]) > 1e-12) {
          source.masters.push_back(cells(leaf, a));
          source.weights.push_back(values[a]);
        }
    }
    const HangingNodeSource& coarsest = candidates[node].front();
    for (std::size_t k = 0; k < coarsest.masters.size(); ++k)
      direct[node].emplace_back(coarsest.masters[k], coarsest.weights[k]);
  }

  // Free nodes first, in the order met, then the hanging ones, their chains substituted.
  std::vector<int> number;
  ConstrainedHexahedralMesh result;
  result.constraints = resolve_constraints(direct, number);
  for (int node = 0; node < node_count; ++node) {
    if (!hanging[node]) continue;
    for (HangingNodeSource& source : candidates[node])
      for (int& master : source.masters) master = number[master];
    result.sources.push_back(std::move(candidates[node]));
  }
  result.mesh.element_type = forest.type;
  result.mesh.nodes.resize(node_count, 3);
  for (int node = 0; node < node_count; ++node) result.mesh.nodes.row(number[node]) = forest.position(lattice[node]);
  result.mesh.cells = cells.unaryExpr([&](int node) { return number[node]; });
  return result;
}

std::vector<ForestFace> forest_interior_faces(const HexahedralForest& forest) {
  const LeafLocator locator(forest);
  const Eigen::Array3d grid_cell = forest.box.sizes().array() / forest.resolution.cast<double>().array();
  std::vector<ForestFace> faces;
  for (int leaf = 0; leaf < forest.leaf_count(); ++leaf) {
    const int edge = HexahedralForest::edge_units(forest.levels[leaf]);
    const Eigen::Vector3i doubled_centre = 2 * forest.origins[leaf] + Eigen::Vector3i::Constant(edge);
    const Eigen::Array3d sides = grid_cell * (static_cast<double>(edge) / units);
    for (int axis = 0; axis < 3; ++axis)
      for (const int side : {-1, 1}) {
        const int neighbour = locator.locate(doubled_centre + side * (edge + 1) * Eigen::Vector3i::Unit(axis));
        if (neighbour < 0) continue;
        const int level = forest.levels[leaf], other = forest.levels[neighbour];
        // Each face once: from the finer leaf, or the lower index of two at one level.
        if (other > level || (other == level && neighbour < leaf)) continue;
        faces.push_back({leaf, neighbour, sides.prod() / sides[axis], axis, side});
      }
  }
  return faces;
}

std::vector<CellFaceContact> forest_face_contacts(const std::vector<ForestFace>& faces) {
  // hexahedron_faces' index of the face on the lower (−) and upper (+) side of each axis.
  constexpr std::array<std::array<int, 2>, 3> face_on{{{5, 3}, {2, 4}, {0, 1}}};
  std::vector<CellFaceContact> contacts;
  contacts.reserve(faces.size());
  for (const ForestFace& face : faces)
    contacts.push_back({face.first, face_on[face.axis][face.side > 0 ? 1 : 0], face.second,
                        face_on[face.axis][face.side > 0 ? 0 : 1]});
  return contacts;
}

BoundarySurface forest_boundary_surface(const HexahedralForest& forest, const VolumeMesh& mesh) {
  const BoundarySurface all = boundary_surface(mesh);
  const LeafLocator locator(forest);
  const Eigen::Array3d units_per_length =
      (forest.resolution.cast<double>() * units).array() / forest.box.sizes().array();
  // A triangle with a leaf on both sides (a coarse face and the finer ones on it, which
  // boundary_surface cannot match) is interior: half a lattice unit either way from its
  // centroid, across the grid plane it lies in, are points of leaves.
  const auto interior = [&](const Eigen::Index triangle) {
    Eigen::Matrix3d lattice;  // rows: the corners in lattice units
    for (int c = 0; c < 3; ++c)
      lattice.row(c) = ((all.surface.vertices.row(all.surface.triangles(triangle, c)).transpose().array() -
                         forest.box.min().array()) *
                        units_per_length)
                           .transpose();
    const Eigen::Vector3d centroid = lattice.colwise().mean().transpose();
    int axis = -1;
    for (int a = 0; a < 3; ++a)
      if (lattice.col(a).maxCoeff() - lattice.col(a).minCoeff() < 1e-6) axis = a;
    if (axis < 0) return false;
    Eigen::Vector3i doubled;
    for (int a = 0; a < 3; ++a)
      doubled[a] = static_cast<int>(a == axis ? std::lround(2 * centroid[a]) : std::floor(2 * centroid[a]));
    for (const int side : {-1, 1}) {
      Eigen::Vector3i probe = doubled;
      probe[axis] += side;
      if (locator.locate(probe) < 0) return false;
    }
    return true;
  };
  BoundarySurface kept;
  std::vector<int> vertex_of(all.mesh_nodes.size(), -1);
  std::vector<Eigen::RowVector3i> triangles;
  for (Eigen::Index t = 0; t < all.surface.triangles.rows(); ++t) {
    if (interior(t)) continue;
    Eigen::RowVector3i triangle;
    for (int c = 0; c < 3; ++c) {
      int& vertex = vertex_of[all.surface.triangles(t, c)];
      if (vertex < 0) {
        vertex = static_cast<int>(kept.mesh_nodes.size());
        kept.mesh_nodes.push_back(all.mesh_nodes[all.surface.triangles(t, c)]);
      }
      triangle[c] = vertex;
    }
    triangles.push_back(triangle);
    kept.cells.push_back(all.cells[t]);
  }
  kept.surface.vertices.resize(static_cast<Eigen::Index>(kept.mesh_nodes.size()), 3);
  for (std::size_t v = 0; v < kept.mesh_nodes.size(); ++v)
    kept.surface.vertices.row(static_cast<Eigen::Index>(v)) = mesh.nodes.row(kept.mesh_nodes[v]);
  kept.surface.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    kept.surface.triangles.row(static_cast<Eigen::Index>(t)) = triangles[t];
  return kept;
}

}  // namespace altfem
