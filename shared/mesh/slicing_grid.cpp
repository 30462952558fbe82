#include "shared/mesh/slicing_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace altfem {

SlicingGrid SlicingGrid::covering(const Eigen::Vector3d& lower, const Eigen::Vector3d& upper, double cell_size,
                                  double margin_cells) {
  SlicingGrid grid;
  grid.cell_size = cell_size;
  grid.origin = lower.array() - margin_cells * cell_size;
  for (int axis = 0; axis < 3; ++axis) {
    const double extent = upper(axis) - lower(axis) + 2 * margin_cells * cell_size;
    int& count = grid.cells(axis);
    count = std::max(1, static_cast<int>(std::ceil(extent / cell_size - 1e-9)));
    // The last plane must not fall short of the object by a rounding.
    while (grid.origin(axis) + count * cell_size < upper(axis)) ++count;
    grid.planes[axis].resize(grid.cells(axis) + 1);
    for (int i = 0; i <= grid.cells(axis); ++i) grid.planes[axis][i] = grid.origin(axis) + i * cell_size;
  }
  return grid;
}

int SlicingGrid::slab(int axis, double value) const {
  const auto& p = planes[axis];
  const int above = static_cast<int>(std::upper_bound(p.begin(), p.end(), value) - p.begin());
  return std::clamp(above - 1, 0, cells(axis) - 1);
}

std::size_t NodeRegistry::Hash::operator()(const std::array<std::uint64_t, 3>& key) const {
  std::size_t hash = 1469598103934665603ull;
  for (std::uint64_t word : key) hash = (hash ^ word) * 1099511628211ull ^ (word >> 29);
  return hash;
}

int NodeRegistry::node(const Eigen::Vector3d& point) {
  std::array<std::uint64_t, 3> key;
  for (int axis = 0; axis < 3; ++axis) {
    const double value = point(axis) + 0.0;  // -0 and +0 are one coordinate
    std::memcpy(&key[axis], &value, sizeof value);
  }
  auto [it, inserted] = index_.emplace(key, static_cast<int>(points_.size()));
  if (inserted) points_.push_back(point);
  return it->second;
}

namespace {

using Polygon = std::vector<Eigen::Vector3d>;

bool lexicographically_less(const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
  return std::lexicographical_compare(p.data(), p.data() + 3, q.data(), q.data() + 3);
}

// A coordinate within this fraction of a cell of a grid plane is put on the plane: a vertex
// a few ulps off a plane, or a crossing that lies on a grid line in exact arithmetic but
// was rounded off it, would otherwise give crossings that round onto each other along
// different paths and tangle the topology. Moves the surface by at most 1e-12 cells.
constexpr double snap_fraction = 1e-12;

void snap_to_planes(Eigen::Vector3d& point, const SlicingGrid& grid) {
  for (int axis = 0; axis < 3; ++axis) {
    double& value = point(axis);
    const int slab = grid.slab(axis, value);
    for (int plane = slab; plane <= slab + 1; ++plane)
      if (std::abs(value - grid.planes[axis][plane]) <= snap_fraction * grid.cell_size)
        value = grid.planes[axis][plane];
  }
}

/// Where the segment pq meets the plane x_axis = value (the endpoints on opposite sides,
/// "on" counting as above). Computed from the lexicographically smaller endpoint so both
/// polygons sharing the edge get the same bits; the plane coordinate is set exactly.
Eigen::Vector3d plane_crossing(Eigen::Vector3d p, Eigen::Vector3d q, int axis, double value, const SlicingGrid& grid) {
  if (p(axis) == value) return p;
  if (q(axis) == value) return q;
  if (lexicographically_less(q, p)) std::swap(p, q);
  const double t = (value - p(axis)) / (q(axis) - p(axis));
  Eigen::Vector3d crossing = p + t * (q - p);
  crossing(axis) = value;
  snap_to_planes(crossing, grid);
  return crossing;
}

void drop_repeated_vertices(Polygon& polygon) {
  polygon.erase(std::unique(polygon.begin(), polygon.end()), polygon.end());
  while (polygon.size() > 1 && polygon.front() == polygon.back()) polygon.pop_back();
}

/// Sutherland–Hodgman: the parts of `polygon` below and above (or on) the plane.
void split_polygon(const Polygon& polygon, int axis, double value, const SlicingGrid& grid, Polygon& below,
                   Polygon& above) {
  below.clear();
  above.clear();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector3d& p = polygon[i];
    const Eigen::Vector3d& q = polygon[(i + 1) % polygon.size()];
    const bool p_below = p(axis) < value, q_below = q(axis) < value;
    (p_below ? below : above).push_back(p);
    if (p_below != q_below) {
      const Eigen::Vector3d crossing = plane_crossing(p, q, axis, value, grid);
      below.push_back(crossing);
      above.push_back(crossing);
    }
  }
  drop_repeated_vertices(below);
  drop_repeated_vertices(above);
}

struct CellPolygon {
  Polygon polygon;
  Eigen::Vector3i cell;
};

/// Whether every vertex lies in one grid plane of the polygon's cell along some axis.
bool lies_in_grid_plane(const CellPolygon& piece, const SlicingGrid& grid) {
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const double plane = grid.planes[axis][piece.cell(axis) + side];
      if (std::all_of(piece.polygon.begin(), piece.polygon.end(),
                      [&](const Eigen::Vector3d& p) { return p(axis) == plane; }))
        return true;
    }
  return false;
}

}  // namespace

SurfacePieces split_surface_by_grid(const SurfaceMesh& surface, const SlicingGrid& grid, NodeRegistry& nodes) {
  std::vector<Eigen::Vector3d> vertices(static_cast<std::size_t>(surface.vertices.rows()));
  for (Eigen::Index v = 0; v < surface.vertices.rows(); ++v) {
    vertices[v] = surface.vertices.row(v).transpose();
    snap_to_planes(vertices[v], grid);
  }
  SurfacePieces pieces;
  std::vector<CellPolygon> current, next;
  Polygon below, above;
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t) {
    current.assign(1, CellPolygon{{}, Eigen::Vector3i::Zero()});
    for (int corner = 0; corner < 3; ++corner) current[0].polygon.push_back(vertices[surface.triangles(t, corner)]);
    for (int axis = 0; axis < 3; ++axis) {
      next.clear();
      for (CellPolygon& piece : current) {
        double lowest = piece.polygon[0](axis), highest = lowest;
        for (const auto& p : piece.polygon) lowest = std::min(lowest, p(axis)), highest = std::max(highest, p(axis));
        const int first = grid.slab(axis, lowest), last = grid.slab(axis, highest);
        for (int slab = first; slab < last; ++slab) {
          split_polygon(piece.polygon, axis, grid.planes[axis][slab + 1], grid, below, above);
          if (below.size() >= 3) {
            next.push_back({below, piece.cell});
            next.back().cell(axis) = slab;
          }
          piece.polygon.swap(above);
          if (piece.polygon.size() < 3) break;
        }
        if (piece.polygon.size() >= 3) {
          piece.cell(axis) = last;
          next.push_back(std::move(piece));
        }
      }
      current.swap(next);
    }
    for (const CellPolygon& piece : current) {
      if (lies_in_grid_plane(piece, grid)) continue;
      std::vector<int> loop;
      loop.reserve(piece.polygon.size());
      for (const auto& p : piece.polygon) loop.push_back(nodes.node(p));
      pieces.polygons.push_back(std::move(loop));
      pieces.cells.push_back(grid.cell_index(piece.cell));
    }
  }
  return pieces;
}

}  // namespace altfem
