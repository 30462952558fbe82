// Surface input through CGAL's polygon-soup I/O and Polygon Mesh Processing checks,
// in the order that gives one clear message per defect (docs/environment.md, "CGAL 5.5"):
// CGAL's read_polygon_mesh would only return false, or silently repair.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <cmath>
#include <iterator>
#include <set>
#include <vector>

#include "shared/common/error.hpp"
#include "shared/mesh/off_check.hpp"
#include "shared/mesh/surface_mesh.hpp"
#include "shared/mesh/text_file.hpp"

namespace altfem {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Polygon = std::vector<std::size_t>;

class SurfaceReader {
public:
  SurfaceReader(const std::filesystem::path& path, std::vector<std::string>* warnings, bool closed)
      : path_(path), name_(path.string()), warnings_(warnings), closed_(closed) {}

  SurfaceMesh read() {
    const std::string extension = lowercase_extension(path_);
    if (extension != ".off" && extension != ".obj" && extension != ".stl" && extension != ".ply")
      fail("unknown surface format '" + extension + "', expected .off, .obj, .stl or .ply");
    check_input_file(path_);
    if (extension == ".off") check_off_text(read_text_file(path_), name_);
    if (!CGAL::IO::read_polygon_soup(name_, points_, polygons_))
      fail("CGAL could not read the file as " + extension.substr(1) + " (malformed, truncated or non-numeric data)");
    check_soup();
    Mesh mesh = to_mesh();
    check_mesh(mesh);
    return to_surface(mesh);
  }

private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(input_message(name_, "", what)); }
  void warn(const std::string& what) const {
    if (warnings_) warnings_->push_back(input_message(name_, "", what));
  }

  void check_soup() {
    if (polygons_.empty()) fail("the file has no faces");
    for (std::size_t vertex = 0; vertex < points_.size(); ++vertex) {
      const Point& p = points_[vertex];
      if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
        fail("vertex " + std::to_string(vertex) + " has a non-finite coordinate");
    }
    for (std::size_t face = 0; face < polygons_.size(); ++face) {
      const Polygon& polygon = polygons_[face];
      if (polygon.size() < 3) fail("face " + std::to_string(face) + " has fewer than 3 vertices");
      for (const std::size_t vertex : polygon)
        if (vertex >= points_.size())
          fail("face " + std::to_string(face) + " refers to vertex " + std::to_string(vertex) + ", but the file has " +
               std::to_string(points_.size()) + " vertices");
      if (std::set<std::size_t>(polygon.begin(), polygon.end()).size() != polygon.size())
        fail("face " + std::to_string(face) + " is degenerate (it repeats a vertex)");
    }
    // Points no face uses carry no geometry; keeping them would leave isolated vertices.
    PMP::remove_isolated_points_in_polygon_soup(points_, polygons_);
  }

  Mesh to_mesh() {
    if (!PMP::is_polygon_soup_a_polygon_mesh(polygons_)) {
      if (!PMP::orient_polygon_soup(points_, polygons_))
        fail(
            "the surface is not manifold (an edge shared by more than two faces, or a vertex joining separate "
            "sheets)");
      warn("face orientations were inconsistent and have been made consistent");
    }
    Mesh mesh;
    PMP::polygon_soup_to_polygon_mesh(points_, polygons_, mesh);
    return mesh;
  }

  void check_mesh(Mesh& mesh) const {
    std::size_t border_edges = 0;
    for (const auto halfedge : mesh.halfedges())
      if (mesh.is_border(halfedge)) ++border_edges;
    if (closed_ && (border_edges > 0 || !CGAL::is_closed(mesh)))
      fail("the surface is not closed (" + std::to_string(border_edges) + " boundary edges)");
    if (!PMP::triangulate_faces(mesh)) fail("a polygonal face could not be triangulated");
    for (const auto face : mesh.faces())
      if (PMP::is_degenerate_triangle_face(face, mesh))
        fail("face " + std::to_string(face.idx()) + " is degenerate (zero area)");
    if (PMP::does_self_intersect(mesh)) {
      std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
      PMP::self_intersections(mesh, std::back_inserter(pairs));
      fail("the surface intersects itself (" + std::to_string(pairs.size()) + " pairs of faces, e.g. faces " +
           std::to_string(pairs.front().first.idx()) + " and " + std::to_string(pairs.front().second.idx()) + ")");
    }
    if (closed_ && !PMP::is_outward_oriented(mesh)) {
      PMP::reverse_face_orientations(mesh);
      warn("the surface was oriented inward; its faces have been flipped");
    }
  }

  static SurfaceMesh to_surface(const Mesh& mesh) {
    SurfaceMesh surface;
    surface.vertices.resize(mesh.number_of_vertices(), 3);
    for (const auto vertex : mesh.vertices()) {
      const Point& p = mesh.point(vertex);
      surface.vertices.row(vertex.idx()) << p.x(), p.y(), p.z();
    }
    surface.triangles.resize(mesh.number_of_faces(), 3);
    for (const auto face : mesh.faces()) {
      int corner = 0;
      for (const auto vertex : CGAL::vertices_around_face(mesh.halfedge(face), mesh))
        surface.triangles(face.idx(), corner++) = static_cast<int>(vertex.idx());
    }
    return surface;
  }

  std::filesystem::path path_;
  std::string name_;
  std::vector<std::string>* warnings_;
  bool closed_;  ///< a body's surface (closed, outward), not a blade's (open or closed)
  std::vector<Point> points_;
  std::vector<Polygon> polygons_;
};

}  // namespace

SurfaceMesh read_surface(const std::filesystem::path& path, std::vector<std::string>* warnings, bool closed) {
  try {
    return SurfaceReader(path, warnings, closed).read();
  } catch (const CGAL::Failure_exception& failure) {
    // CGAL's messages span several lines; the first names the violated condition.
    std::string what = failure.what();
    what = what.substr(0, what.find('\n'));
    throw InputError(input_message(path.string(), "", "CGAL rejected the surface: " + what));
  }
}

}  // namespace altfem
