#include "shared/fem/method/cut_fem_method.hpp"

#include "shared/fem/fem_scene_block.hpp"
#include "shared/mesh/boundary_surface.hpp"
#include "shared/mesh/convex_cell.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/tetrahedra_of_hexahedra.hpp"
#include "shared/simulation/embedded_surface.hpp"
#include "shared/simulation/nodal_basis.hpp"

namespace altfem {

namespace {

// Exact and conservative: every piece kept however small (a cut loses no material), the
// stiffness and mass rules of fem's own strength, and by default no fictitious domain to
// stabilise (an element's rule covers only its piece); `cut_stabilization` gives tiny
// pieces fcm's remedy at the price of α × the element's mass and stiffness.
CutCellSettings fem_cut_cell_settings(const Scene& scene) {
  const FemSpec fem = fem_spec(scene);
  CutCellSettings settings;
  settings.options.quadrature_strength = fem.quadrature_order;
  settings.options.mass_quadrature_strength = fem.quadrature_order;
  settings.options.discard_fraction = 0;
  settings.options.stabilization = fem.cut_stabilization;
  return settings;
}

class CutFemMethod final : public EmbeddedSurfaceMethod {
public:
  CutFemMethod(const Scene& scene, const SceneGeometry& geometry, const FemMesh& mesh)
      : materials_(scene),
        elements_(mesh.elements),
        failure_hint_(fem_cut_failure_hint(fem_spec(scene).cut_stabilization)) {
    cells_ = std::make_unique<EmbeddedCutCells>(mesh.elements, *mesh.material, fem_cut_cell_settings(scene), materials_,
                                                scene.dirichlet, scene.file.string(),
                                                CutCellRebuild{nullptr, mesh.rules, nullptr, false});
    // The surface every method deforms, else (a volume mesh file) the material's own
    // boundary, open along the cut. Surface loads act on the boundary of the material, the
    // cut tetrahedra's (the blade's faces included, unloaded by tractions given on the
    // original boundary's regions).
    surface_.load_surface = boundary_surface(cells_->embedded().mesh()).surface;
    surface_.surface = geometry.common_surface() ? *geometry.common_surface() : surface_.load_surface;
    surface_.common = geometry.common_surface() != nullptr;
    surface_.evaluator = cells_->basis_evaluator();
  }

  const Discretization& discretization() const override { return *cells_->discretization().discretization; }
  nlohmann::json element_counts() const override {
    return {{std::string(element_name(elements_.element_type)), cells_->discretization().mesh.cells.rows()}};
  }
  long long quadrature_points() const override {
    return cells_->discretization().discretization->elements().whole_point_count();
  }
  double quadrature_seconds() const override { return cells_->seconds(); }
  std::string failure_hint() const override { return failure_hint_; }
  UnstructuredGrid volume_grid(const Eigen::VectorXd& displacement) const override {
    return cells_->volume_grid(displacement);
  }
  Eigen::VectorXd interpolate(const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& field) const override {
    return interpolate_at_nodes(cells_->discretization().mesh.nodes, field);
  }
  std::vector<std::string> warnings() const override { return cells_->warnings(); }
  nlohmann::json facts() const override {
    nlohmann::json facts = surface_.facts();
    facts.update(cells_->facts());
    return facts;
  }
  std::shared_ptr<const MethodMesh> mesh() const override {
    return std::make_shared<MeshOf<FemMesh>>(FemMesh{
        elements_, EmbeddedTetrahedra{cells_->embedded().material, {}}, std::nullopt, {}, cells_->rule_memory()});
  }
  std::optional<double> volume() const override { return cells_->material_volume(); }
  std::string cut_refusal() const override { return cells_->cut_refusal(); }
  std::shared_ptr<const MethodMesh> cut_mesh(const SceneEvent& cut, nlohmann::json& facts) const override {
    return std::make_shared<MeshOf<FemMesh>>(
        FemMesh{elements_, cells_->cut(cut.blade, facts), std::nullopt, {}, cells_->rule_memory()});
  }
  /// From fem before its first cut, each node copy takes its node's values; from a cut
  /// fem, the values of the copy its material came from (EmbeddedCutCells::transfer).
  Eigen::MatrixXd transfer(const MethodInstance& previous, const Eigen::MatrixXd& fields) const override {
    if (const auto* cut = dynamic_cast<const CutFemMethod*>(&previous))
      return cells_->transfer(*cut->cells_, previous.basis_evaluator(), fields);
    return cells_->transfer_from_background(fields);
  }
  std::optional<FieldQuadrature> field_quadrature(int /*added_strength*/) const override {
    return nodal_field_quadrature(borrowed(cells_->discretization().discretization->elements()),
                                  cells_->discretization().mesh.nodes, cells_->quadrature_strength());
  }

private:
  SceneMaterials materials_;
  VolumeMesh elements_;
  std::unique_ptr<EmbeddedCutCells> cells_;
  std::string failure_hint_;
};

}  // namespace

FragmentedTetrahedra element_material(const VolumeMesh& elements) {
  if (element_shape(elements.element_type) != ElementShape::hexahedron)
    return {VolumeMesh{ElementType::tet4, elements.nodes, elements.cells.leftCols(4)}};
  PolyhedralMesh cells = polyhedral_mesh_from_volume_mesh(elements);
  for (int cell = 0; cell < cells.cell_count(); ++cell)
    if (!is_convex_cell(cells, cell, cell_node_set(cells, cell))) return {tetrahedra_of_hexahedra(elements)};
  return convex_cells_as_fragments(std::move(cells));
}

std::string fem_cut_refusal(ElementType type) {
  return type == ElementType::tet20 ? "it cuts tet4, tet10, hex8, hex20 and hex27 elements (the cut-cell rules' cells)"
                                    : "";
}

std::string fem_cut_failure_hint(double cut_stabilization) {
  if (cut_stabilization > 0) return "";
  return "; a cut may have left a piece of an element too small for its functions' mass and stiffness to stay "
         "positive: discretization.fem.cut_stabilization (e.g. 1e-6) keeps them so, at that fraction of the cut "
         "elements' mass";
}

std::unique_ptr<MethodInstance> make_cut_fem_method(const Scene& scene, const SceneGeometry& geometry,
                                                    const FemMesh& mesh) {
  return std::make_unique<CutFemMethod>(scene, geometry, mesh);
}

}  // namespace altfem
