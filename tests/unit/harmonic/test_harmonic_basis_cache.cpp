// The on-disk basis cache (polyhedral/harmonic_basis_cache.hpp): a second run reuses the
// file and gets bit-identical bases; other options or another mesh miss; a truncated or
// corrupted file is ignored, recomputed and rewritten; the harmonic method reports
// whether it wrote or reused its cache (facts: harmonic_basis_cache). The in-memory
// counterpart for events (polyhedral/harmonic_basis_memory.hpp): a rebuild after a cut
// fits only the cells the cut changed and keeps the others' bases and stiffness points bit
// for bit; and cells
// that are translates of one another share one fit.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <numeric>

#include "polyhedral/harmonic_basis_cache.hpp"
#include "polyhedral/harmonic_method.hpp"
#include "polyhedral/mesh_face_coordinates.hpp"
#include "shared/common/error.hpp"
#include "shared/mesh/cut_polyhedral_mesh.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "tests/unit/polyhedra.hpp"

namespace altfem::harmonic {
namespace {

std::filesystem::path fresh_directory(const std::string& name) {
  const auto directory = std::filesystem::path(ALTFEM_BINARY_DIR) / "test_output" / "unit_harmonic" / name;
  std::filesystem::remove_all(directory);
  return directory;
}

PolyhedralMesh hexahedra() {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 1.2, 0.8));
  return polyhedral_mesh_from_volume_mesh(structured_grid(box, {2, 2, 1}, ElementType::hex8));
}

// Every cell's nodes and basis, compared bit for bit (tolerance 0), or to `tolerance`
// relative to the largest entry (a recomputation: the fits' summation order may depend
// on the thread and buffer they ran in).
void expect_identical(const HarmonicElementBases& a, const HarmonicElementBases& b, double tolerance = 0) {
  const auto expect_equal = [tolerance](const Eigen::MatrixXd& x, const Eigen::MatrixXd& y) {
    ASSERT_EQ(x.rows(), y.rows());
    ASSERT_EQ(x.cols(), y.cols());
    if (tolerance == 0) EXPECT_EQ(x, y);
    else EXPECT_LE((x - y).cwiseAbs().maxCoeff(), tolerance * std::max(1.0, x.cwiseAbs().maxCoeff()));
  };
  ASSERT_EQ(a.cell_count(), b.cell_count());
  for (int cell = 0; cell < a.cell_count(); ++cell) {
    EXPECT_EQ(a.nodes(cell), b.nodes(cell));
    EXPECT_EQ(a.plain_type(cell), b.plain_type(cell));
    ASSERT_EQ(a.mfs_basis(cell) != nullptr, b.mfs_basis(cell) != nullptr);
    if (!a.mfs_basis(cell)) continue;
    const ElementHarmonicBasis &left = *a.mfs_basis(cell), &right = *b.mfs_basis(cell);
    if (tolerance == 0) {
      EXPECT_EQ(left.content_key(), right.content_key());
    }
    expect_equal(left.centres(), right.centres());
    expect_equal(left.boundary_integrals(), right.boundary_integrals());
    EXPECT_NEAR(left.boundary_residual(), right.boundary_residual(), tolerance);
    const Eigen::MatrixXd points = Eigen::MatrixXd::Random(5, 3);
    expect_equal(left.values(points), right.values(points));
  }
}

TEST(HarmonicBasisCache, SecondRunReusesIdenticalBasesAndBrokenFilesAreRewritten) {
  const auto directory = fresh_directory("basis_cache");
  const PolyhedralMesh mesh = hexahedra();
  const MfsOptions options;
  bool reused = true;
  const HarmonicElementBases computed =
      cached_harmonic_bases(mesh, HarmonicBasisKind::mfs, options, directory, &reused);
  EXPECT_FALSE(reused);
  expect_identical(computed, HarmonicElementBases(mesh, HarmonicBasisKind::mfs, options), 1e-10);
  const HarmonicElementBases read = cached_harmonic_bases(mesh, HarmonicBasisKind::mfs, options, directory, &reused);
  EXPECT_TRUE(reused);
  expect_identical(computed, read);

  MfsOptions other = options;
  other.edge_samples = options.edge_samples + 1;
  cached_harmonic_bases(mesh, HarmonicBasisKind::mfs, other, directory, &reused);
  EXPECT_FALSE(reused);  // other options: another key
  cached_harmonic_bases(mesh, HarmonicBasisKind::automatic, options, directory, &reused);
  EXPECT_FALSE(reused);  // closed-form cells: another key
  PolyhedralMesh moved = mesh;
  moved.nodes(0, 0) -= 1e-3;
  cached_harmonic_bases(moved, HarmonicBasisKind::mfs, options, directory, &reused);
  EXPECT_FALSE(reused);  // another mesh: another key

  const auto path =
      directory / cache_file_path({}, harmonic_bases_key(mesh, HarmonicBasisKind::mfs, options), ".harmonic");
  ASSERT_TRUE(std::filesystem::exists(path));
  const auto size = std::filesystem::file_size(path);
  std::filesystem::resize_file(path, size / 2);  // an interrupted writer without the atomic rename
  expect_identical(computed, cached_harmonic_bases(mesh, HarmonicBasisKind::mfs, options, directory, &reused), 1e-10);
  EXPECT_FALSE(reused);
  EXPECT_EQ(std::filesystem::file_size(path), size);  // rewritten whole
  {
    std::fstream file(path, std::ios::binary | std::ios::in | std::ios::out);
    file.seekp(3);
    file.put('#');  // the format's magic no longer matches
  }
  expect_identical(computed, cached_harmonic_bases(mesh, HarmonicBasisKind::mfs, options, directory, &reused), 1e-10);
  EXPECT_FALSE(reused);
  cached_harmonic_bases(mesh, HarmonicBasisKind::mfs, options, directory, &reused);
  EXPECT_TRUE(reused);
}

TEST(HarmonicBasisCache, TheMethodReportsWritingThenReusingItsCache) {
  const auto directory = fresh_directory("method_cache");
  Scene scene = load_scene(std::filesystem::path(ALTFEM_SOURCE_DIR) / "scenes/cantilever.json");
  scene.resolved["discretization"]["harmonic"] = {
      {"convert", {{"mesh", "grid"}, {"resolution", {4, 1, 1}}}}, {"basis", "mfs"}, {"cache", directory.string()}};
  const SceneGeometry geometry = load_scene_geometry(scene);
  const auto first = make_harmonic_method(scene, geometry);
  EXPECT_EQ(first->facts()["harmonic_basis_cache"], "written");
  const auto second = make_harmonic_method(scene, geometry);
  EXPECT_EQ(second->facts()["harmonic_basis_cache"], "reused");
  EXPECT_EQ(first->facts()["max_mfs_boundary_residual"], second->facts()["max_mfs_boundary_residual"]);
  EXPECT_EQ(first->discretization().dof_count(), second->discretization().dof_count());

  // A cache folder that cannot be created (a file is in the way): bad input naming the key.
  std::ofstream(directory / "file") << "in the way";
  scene.resolved["discretization"]["harmonic"]["cache"] = (directory / "file" / "cache").string();
  try {
    make_harmonic_method(scene, geometry);
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("/discretization/harmonic/cache"), std::string::npos) << error.what();
  }
}

TEST(HarmonicBasisMemory, ARebuildAfterACutFitsOnlyTheCellsItChanged) {
  const PolyhedralMesh mesh = hexahedra();  // 2 × 2 × 1 cells of [0, 2] × [0, 1.2] × [0, 0.8]
  const MfsOptions options;
  HarmonicBasisMemory memory(options);
  const HarmonicElementBases before(mesh, HarmonicBasisKind::mfs, options, nullptr, &memory);
  EXPECT_EQ(memory.size(), 1);  // the four cells are translates: one shape
  EXPECT_EQ(before.remembered_bases(), 0);
  // x = 0.5 crosses the two cells of x in [0, 1]; those of [1, 2] keep every node and face
  // (the crossings lie on edges inside [0, 1]).
  const PolyhedralCut cut =
      cut_polyhedral_mesh(mesh, CuttingPlane(Eigen::Vector3d(0.5, 0, 0), Eigen::Vector3d::UnitX()));
  ASSERT_EQ(cut.crossed_cells, 2);
  const HarmonicElementBases after(cut.mesh, HarmonicBasisKind::mfs, options, &memory);
  const HarmonicElementBases fresh(cut.mesh, HarmonicBasisKind::mfs, options);
  EXPECT_EQ(after.remembered_bases(), 2);
  // Every basis is the one a fresh fit gives, as functions (a fit of a cell numbered
  // otherwise lists its kernel centres in another order).
  const Eigen::MatrixXd samples = Eigen::MatrixXd::Random(5, 3);
  for (int cell = 0; cell < cut.mesh.cell_count(); ++cell) {
    ASSERT_EQ(after.nodes(cell), fresh.nodes(cell));
    const Eigen::MatrixXd difference = after.mfs_basis(cell)->values(samples) - fresh.mfs_basis(cell)->values(samples);
    EXPECT_LE(difference.cwiseAbs().maxCoeff(), 1e-10) << "cell " << cell;
  }
  // The local node of `parent` before the cut at the position of local node i of `cell`
  // after it (−1: none): the cut mesh numbers the nodes otherwise.
  const auto same_node_before = [&](int cell, int parent, size_t i) {
    const Eigen::RowVector3d x = cut.mesh.nodes.row(after.nodes(cell)[i]);
    for (size_t j = 0; j < before.nodes(parent).size(); ++j)
      if (mesh.nodes.row(before.nodes(parent)[j]) == x) return static_cast<int>(j);
    return -1;
  };
  // The kept bases are the build before's, bit for bit, node by node (matched by position).
  int kept = 0;
  const Eigen::MatrixXd points = Eigen::MatrixXd::Random(5, 3);
  for (int cell = 0; cell < cut.mesh.cell_count(); ++cell) {
    const int parent = cut.parent_cell[cell];
    if (mesh.cell_centroids(parent, 0) < 1) continue;
    ++kept;
    const Eigen::MatrixXd values = after.mfs_basis(cell)->values(points);
    const Eigen::MatrixXd values_before = before.mfs_basis(parent)->values(points);
    for (size_t i = 0; i < after.nodes(cell).size(); ++i) {
      const int same = same_node_before(cell, parent, i);
      ASSERT_GE(same, 0);
      EXPECT_EQ(values.col(static_cast<Eigen::Index>(i)), values_before.col(same));
      EXPECT_EQ(after.mfs_basis(cell)->boundary_integrals().row(static_cast<Eigen::Index>(i)),
                before.mfs_basis(parent)->boundary_integrals().row(same));
    }
  }
  EXPECT_EQ(kept, 2);
  // Other options fit every cell again.
  MfsOptions denser = options;
  ++denser.edge_samples;
  EXPECT_EQ(HarmonicElementBases(cut.mesh, HarmonicBasisKind::mfs, denser, &memory).remembered_bases(), 0);

  // The kept cells' stiffness points are copied from the build before (EarlierTabulation),
  // their nodes in the cut mesh's order, which lists them otherwise (faces, loops, node
  // numbers): the same values node by node, and integrals those of a tabulation afresh.
  const HarmonicQuadrature quadrature;
  const int strength = 4;
  const TabulatedElements table_before = before.tabulate(strength, quadrature);
  const EarlierTabulation earlier{&before, &table_before, strength};
  int copied = -1;
  const TabulatedElements taken = after.tabulate(strength, quadrature, {}, nullptr, nullptr, &earlier, &copied);
  const TabulatedElements again = after.tabulate(strength, quadrature);
  EXPECT_EQ(copied, 2);
  // Σ_q w_q ∇N_a(x_q) · ∇N_b(x_q): #nodes × #nodes.
  const auto gradient_products = [](const ElementView& view) {
    Eigen::MatrixXd products = Eigen::MatrixXd::Zero(view.basis_count(), view.basis_count());
    for (int q = 0; q < view.point_count(); ++q)
      products += view.weights[q] * view.gradients_at(q) * view.gradients_at(q).transpose();
    return products;
  };
  for (int cell = 0; cell < cut.mesh.cell_count(); ++cell) {
    const ElementView copy = taken[cell], fresh_view = again[cell];
    const Eigen::MatrixXd products = gradient_products(copy);
    EXPECT_LE((products - gradient_products(fresh_view)).norm(), 1e-12 * products.norm()) << "cell " << cell;
    const int parent = cut.parent_cell[cell];
    if (mesh.cell_centroids(parent, 0) < 1) continue;
    const ElementView kept_view = table_before[parent];
    ASSERT_EQ(copy.point_count(), kept_view.point_count());
    EXPECT_TRUE(std::equal(copy.weights.begin(), copy.weights.end(), kept_view.weights.begin()));
    for (size_t i = 0; i < after.nodes(cell).size(); ++i) {
      const int same = same_node_before(cell, parent, i);
      ASSERT_GE(same, 0);
      EXPECT_EQ(copy.values.col(static_cast<Eigen::Index>(i)), kept_view.values.col(same));
      for (int q = 0; q < copy.point_count(); ++q)
        EXPECT_EQ(copy.gradients_at(q).row(static_cast<Eigen::Index>(i)), kept_view.gradients_at(q).row(same));
    }
  }
  // At another strength nothing is copied.
  after.tabulate(strength + 1, quadrature, {}, nullptr, nullptr, &earlier, &copied);
  EXPECT_EQ(copied, 0);
}

// A mesh of `mesh` and its copy scaled by `factor` about the origin and moved by `offset`,
// side by side: a refinement's levels hold cells alike but for their size.
PolyhedralMesh with_scaled_copy(const PolyhedralMesh& mesh, double factor, const Eigen::Vector3d& offset) {
  PolyhedralMesh both = mesh;
  const auto nodes = static_cast<int>(mesh.nodes.rows());
  both.nodes.resize(2 * nodes, 3);
  both.nodes << mesh.nodes, (factor * mesh.nodes).rowwise() + offset.transpose();
  for (std::vector<int> face : mesh.faces) {
    for (int& node : face) node += nodes;
    both.faces.push_back(std::move(face));
  }
  both.face_cells.resize(2 * mesh.face_count(), 2);
  Eigen::MatrixXi copied = mesh.face_cells.array() + mesh.cell_count();
  copied.col(1) = (mesh.face_cells.col(1).array() < 0).select(-1, copied.col(1));
  both.face_cells << mesh.face_cells, copied;
  for (std::vector<int> cell : mesh.cell_faces) {
    for (int& face : cell) face += mesh.face_count();
    both.cell_faces.push_back(std::move(cell));
  }
  both.cell_kinds.insert(both.cell_kinds.end(), mesh.cell_kinds.begin(), mesh.cell_kinds.end());
  compute_polyhedral_geometry(both);
  return both;
}

// Each cell's basis against the fit its own cell gets on the mesh's shared face
// coordinates, at random points of its bounding box: to round-off where a cell took
// another's fit, moved.
void expect_every_basis_its_own_fit(const PolyhedralMesh& mesh, const HarmonicElementBases& bases,
                                    const MfsOptions& options) {
  std::vector<int> every(mesh.cell_count());
  std::iota(every.begin(), every.end(), 0);
  const auto faces = mesh_face_coordinates(mesh, every, options);
  for (int cell = 0; cell < mesh.cell_count(); ++cell) {
    const ElementHarmonicBasis own = cell_harmonic_basis(mesh, cell, faces, options);
    const Polyhedron polyhedron = cell_polyhedron(mesh, cell);
    const Eigen::Vector3d low = polyhedron.vertices.colwise().minCoeff(),
                          high = polyhedron.vertices.colwise().maxCoeff();
    const Eigen::ArrayXXd unit = (Eigen::ArrayXXd::Random(20, 3) + 1) / 2;
    const Eigen::MatrixXd points =
        (unit.rowwise() * (high - low).transpose().array()).rowwise() + low.transpose().array();
    const Eigen::MatrixXd difference = bases.mfs_basis(cell)->values(points) - own.values(points);
    EXPECT_LE(difference.cwiseAbs().maxCoeff(), 1e-10) << "cell " << cell;
    const double scale = own.boundary_integrals().cwiseAbs().maxCoeff();
    EXPECT_LE((bases.mfs_basis(cell)->boundary_integrals() - own.boundary_integrals()).cwiseAbs().maxCoeff(),
              1e-12 * scale)
        << "cell " << cell;
  }
}

// Cells that are translates of one another, and list their faces alike, take one fit,
// moved (cell_shape_key): a plane through a 4 × 4 grid cuts its crossed cells alike. Each
// moved basis is the fit its own cell gets on the mesh's shared face coordinates, to
// round-off, node by node, so it still shares its faces' data with its neighbours.
TEST(HarmonicElementBases, TranslatesOfACellShareItsFit) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 2, 0.5));
  const PolyhedralMesh grid = polyhedral_mesh_from_volume_mesh(structured_grid(box, {4, 4, 1}, ElementType::hex8));
  const PolyhedralCut cut =
      cut_polyhedral_mesh(grid, CuttingPlane(Eigen::Vector3d(0.8, 0, 0), Eigen::Vector3d(1, 0, 0)));
  ASSERT_EQ(cut.crossed_cells, 4);
  const MfsOptions options;
  const HarmonicElementBases bases(cut.mesh, HarmonicBasisKind::mfs, options);
  EXPECT_GT(bases.moved_bases(), cut.mesh.cell_count() / 2);
  expect_every_basis_its_own_fit(cut.mesh, bases, options);
}

// A cell half the size of another, or twice, is not its translate: the two may share a fit
// only scaled. A refinement's levels make such cells (a hanging node on a face at every
// level), and a basis moved without its scale would be that of a cell of another size.
TEST(HarmonicElementBases, ScaledCopiesOfACellShareItsFitScaled) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 1, 1));
  const PolyhedralMesh grid = polyhedral_mesh_from_volume_mesh(structured_grid(box, {2, 1, 1}, ElementType::hex8));
  const PolyhedralCut cut =
      cut_polyhedral_mesh(grid, CuttingPlane(Eigen::Vector3d(0.3, 0, 0), Eigen::Vector3d(1, 0, 0)));
  const MfsOptions options;
  for (double factor : {0.5, 2.0, 3.0}) {
    const PolyhedralMesh mesh = with_scaled_copy(cut.mesh, factor, Eigen::Vector3d(10, 0, 0));
    const HarmonicElementBases bases(mesh, HarmonicBasisKind::mfs, options);
    // A power of two scales exactly: the copy takes the original's fits; 3 does not.
    EXPECT_EQ(bases.moved_bases(), factor == 3.0 ? 0 : cut.mesh.cell_count()) << "factor " << factor;
    expect_every_basis_its_own_fit(mesh, bases, options);
  }
}

// What an embedded point's holder is keyed by (HarmonicBasisEvaluator::element_key): the
// hash of the basis's bytes, made once for a fitted, moved, reordered or read-back basis.
TEST(ElementHarmonicBasis, ContentKeyIsTheHashOfItsBytes) {
  const ElementHarmonicBasis fitted(test::box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()), MfsOptions{});
  std::vector<int> order(static_cast<size_t>(fitted.node_count()));
  std::iota(order.rbegin(), order.rend(), 0);
  const ElementHarmonicBasis moved = fitted.moved(Eigen::Vector3d::Zero(), Eigen::Vector3d(3, 0, 0), 2.0);
  const ElementHarmonicBasis reordered = fitted.reordered(order);
  BinaryWriter bytes("basis");
  fitted.write(bytes);
  BinaryReader reader(bytes.bytes(), "basis");
  const std::optional<ElementHarmonicBasis> read = ElementHarmonicBasis::read(reader);
  ASSERT_TRUE(read);
  // write's bytes after the magic and its NUL.
  const auto hash_of_bytes = [](const ElementHarmonicBasis& basis) {
    BinaryWriter data("");
    basis.write(data);
    CacheKeyHasher hasher;
    hasher.bytes(data.bytes().data() + 1, data.bytes().size() - 1);
    return hasher.value();
  };
  for (const ElementHarmonicBasis* basis : {&fitted, &moved, &reordered, &*read})
    EXPECT_EQ(basis->content_key(), hash_of_bytes(*basis));
  EXPECT_EQ(read->content_key(), fitted.content_key());
  EXPECT_NE(moved.content_key(), fitted.content_key());
  EXPECT_NE(reordered.content_key(), fitted.content_key());
  std::vector<int> identity(order.size());
  std::iota(identity.begin(), identity.end(), 0);
  EXPECT_EQ(reordered.reordered(order).content_key(), fitted.content_key());  // the order is its own inverse
  EXPECT_EQ(fitted.reordered(identity).content_key(), fitted.content_key());
}

}  // namespace
}  // namespace altfem::harmonic
