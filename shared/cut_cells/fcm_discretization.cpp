#include "shared/cut_cells/fcm_discretization.hpp"

#include <utility>

#include "shared/common/error.hpp"
#include "shared/cut_cells/kept_hanging_nodes.hpp"
#include "shared/element/geometry_map.hpp"
#include "shared/element/reference_element.hpp"
#include "shared/fem/constrain_lagrange_elements.hpp"
#include "shared/fem/first_order_space.hpp"
#include "shared/fem/lagrange_element_masses.hpp"
#include "shared/fem/nodal_dirichlet.hpp"
#include "shared/fem/tabulate_lagrange.hpp"
#include "shared/quadrature/reference_rules.hpp"
#include "shared/solve/additive_schwarz_preconditioner.hpp"

namespace altfem {

namespace {

QuadratureRule standard_rule(ElementType type, int strength) {
  return reference_element(type).shape() == ElementShape::tetrahedron ? tet_rule(strength) : hex_rule(strength);
}

// `rule` followed by the standard rule with its weights scaled by `factor` (§5.3).
QuadratureRule stabilized(const QuadratureRule& rule, const QuadratureRule& standard, double factor) {
  QuadratureRule result;
  result.strength = rule.strength;
  result.points.resize(rule.points.rows() + standard.points.rows(), 3);
  result.points << rule.points, standard.points;
  result.weights.resize(rule.weights.size() + standard.weights.size());
  result.weights << rule.weights, factor * standard.weights;
  return result;
}

// Cut-cell rules of the kept cells (kept-cell index → rule), stabilised if asked; the
// rules are moved out of `cells` (mass rules run to thousands of points per cell). The
// stabilised copies are made in parallel, the map filled by moves after. With `mesh` (the
// kept cells) and their `reductions`, a kept cell with a reduction whose nodes are affine
// gets no rule: its masses are the reduction times det J (lagrange_element_masses), which
// never reads it.
LagrangeCellRules kept_rules(std::vector<CellQuadrature>& cells, const std::vector<int>& kept, ElementType type,
                             int strength, double stabilization, const VolumeMesh* mesh = nullptr,
                             const std::unordered_map<int, ReferenceProducts>* reductions = nullptr) {
  LagrangeCellRules rules{standard_rule(type, strength), {}, {}};
  const auto count = static_cast<int>(kept.size());
  std::vector<QuadratureRule> own(count);
  std::vector<char> has_rule(count, 0);
  const ReferenceElement& element = reference_element(type);
#pragma omp parallel
  {
    Eigen::MatrixXd nodes(element.node_count(), 3);
#pragma omp for schedule(dynamic, 16)
    for (int k = 0; k < count; ++k) {
      CellQuadrature& cell = cells[kept[k]];
      if (!cell.rule) continue;
      if (mesh && reductions && reductions->contains(k)) {
        for (Eigen::Index a = 0; a < nodes.rows(); ++a) nodes.row(a) = mesh->nodes.row(mesh->cells(k, a));
        if (affine_jacobian(element, nodes)) continue;
      }
      own[k] = stabilization > 0 ? stabilized(*cell.rule, rules.standard, stabilization) : std::move(*cell.rule);
      has_rule[k] = 1;
    }
  }
  for (int k = 0; k < count; ++k)
    if (has_rule[k]) rules.custom.emplace(k, std::move(own[k]));
  return rules;
}

// The kept cut cells' mass rules reduced (kept-cell index → reduction, where the rules
// came with one), stabilised as kept_rules stabilises their rules: plus the standard
// rule's reduction times `stabilization`.
std::unordered_map<int, ReferenceProducts> kept_reductions(std::vector<CellQuadrature>& cells,
                                                           const std::vector<int>& kept, ElementType type, int strength,
                                                           double stabilization) {
  const ReferenceProducts standard = reference_products(type, standard_rule(type, strength));
  std::unordered_map<int, ReferenceProducts> reductions;
  for (size_t k = 0; k < kept.size(); ++k) {
    std::optional<ReferenceProducts>& reduced = cells[kept[k]].reduced;
    if (!reduced) continue;
    if (stabilization > 0) {
      reduced->products += stabilization * standard.products;
      reduced->integrals += stabilization * standard.integrals;
      reduced->weight_sum += stabilization * standard.weight_sum;
    }
    reductions.emplace(static_cast<int>(k), std::move(*reduced));
  }
  return reductions;
}

}  // namespace

FcmDiscretization build_fcm_discretization(const VolumeMesh& background, const CellQuadratureSource& quadrature,
                                           const Material& material, const std::vector<DirichletCondition>& dirichlet,
                                           const FcmOptions& options, const std::string& scene_file) {
  return build_fcm_discretization(background, quadrature, {&material},
                                  std::vector<int>(static_cast<size_t>(background.cells.rows()), 0), dirichlet, options,
                                  scene_file);
}

FcmDiscretization build_fcm_discretization(const VolumeMesh& background, const CellQuadratureSource& quadrature,
                                           std::vector<const Material*> materials,
                                           const std::vector<int>& background_materials,
                                           const std::vector<DirichletCondition>& dirichlet, const FcmOptions& options,
                                           const std::string& scene_file, const NodeRegionFilter& dirichlet_nodes,
                                           const BackgroundHangingNodes& hanging) {
  std::vector<CellQuadrature> stiffness_cells = quadrature(options.quadrature_strength, RulePurpose::stiffness);
  std::vector<CellQuadrature> mass_cells = quadrature(options.mass_quadrature_strength, RulePurpose::mass);

  // Classify the cells and keep those with enough material.
  FcmDiscretization fcm;
  std::vector<int> kept;
  for (size_t cell = 0; cell < stiffness_cells.size(); ++cell) {
    const double fraction = stiffness_cells[cell].volume_fraction;
    if (fraction <= 0) {
      ++fcm.counts.outside;
    } else if (fraction < options.discard_fraction) {
      ++fcm.counts.discarded;
    } else {
      kept.push_back(static_cast<int>(cell));
      fraction >= 1 ? ++fcm.counts.inside : ++fcm.counts.cut;
      fcm.volume_fractions.push_back(fraction);
    }
  }
  if (kept.empty())
    throw InputError(
        input_message(scene_file, "/geometry", "no background cell holds material (check the grid's extent)"));
  fcm.background_cells = kept;

  // The kept cells with their nodes renumbered in order of first use.
  fcm.mesh.element_type = background.element_type;
  fcm.mesh.cells.resize(static_cast<Eigen::Index>(kept.size()), background.cells.cols());
  std::vector<int> node_of(static_cast<size_t>(background.nodes.rows()), -1);
  std::vector<int> used_nodes;
  for (size_t k = 0; k < kept.size(); ++k)
    for (Eigen::Index a = 0; a < background.cells.cols(); ++a) {
      const int node = background.cells(kept[k], a);
      if (node_of[node] < 0) {
        node_of[node] = static_cast<int>(used_nodes.size());
        used_nodes.push_back(node);
      }
      fcm.mesh.cells(static_cast<Eigen::Index>(k), a) = node_of[node];
    }
  fcm.constraints.free_nodes = static_cast<int>(used_nodes.size());
  if (hanging.sources && !hanging.sources->empty()) {
    std::vector<int> grid_node(used_nodes.size());
    for (size_t i = 0; i < used_nodes.size(); ++i)
      grid_node[i] = hanging.grid_node.empty() ? used_nodes[i] : hanging.grid_node[used_nodes[i]];
    std::vector<int> cell_leaf;
    for (const int cell : kept) cell_leaf.push_back(hanging.grid_cell.empty() ? cell : hanging.grid_cell[cell]);
    KeptHangingNodes kept_hanging =
        kept_hanging_nodes(grid_node, hanging.grid_free_nodes, *hanging.sources, fcm.mesh.cells, cell_leaf);
    std::vector<int> renumbered(used_nodes.size());
    for (size_t i = 0; i < used_nodes.size(); ++i) renumbered[kept_hanging.new_index[i]] = used_nodes[i];
    used_nodes = std::move(renumbered);
    fcm.mesh.cells = fcm.mesh.cells.unaryExpr([&](int node) { return kept_hanging.new_index[node]; }).eval();
    fcm.constraints = std::move(kept_hanging.constraints);
  }
  fcm.mesh.nodes.resize(static_cast<Eigen::Index>(used_nodes.size()), 3);
  for (size_t i = 0; i < used_nodes.size(); ++i)
    fcm.mesh.nodes.row(static_cast<Eigen::Index>(i)) = background.nodes.row(used_nodes[i]);
  const bool constrained = !fcm.constraints.empty();

  std::vector<int> kept_materials;
  for (int cell : kept) kept_materials.push_back(background_materials[cell]);
  const bool stabilize_stiffness = options.stabilized == StabilizedMatrices::mass_and_stiffness;
  const bool stabilize_mass = options.stabilized != StabilizedMatrices::none;
  DiscretizationParts parts;
  LagrangeCellRules stiffness_rules =
      kept_rules(stiffness_cells, kept, background.element_type, options.quadrature_strength,
                 stabilize_stiffness ? options.stabilization : 0.0);
  stiffness_rules.materials = kept_materials;
  // Each rank tabulates only its cells (the discretization is built below, while fcm.mesh
  // and fcm.constraints live).
  parts.tabulate = lagrange_tabulator(fcm.mesh, std::move(stiffness_rules), &fcm.constraints);
  // The mass rules are large (a high strength, never simplified) and serve only the
  // masses (Longva et al. 2020 §6): reduced to element masses, never tabulated.
  const double mass_stabilization = stabilize_mass ? options.stabilization : 0.0;
  const std::unordered_map<int, ReferenceProducts> mass_reductions =
      kept_reductions(mass_cells, kept, background.element_type, options.mass_quadrature_strength, mass_stabilization);
  parts.element_masses =
      lagrange_element_masses(fcm.mesh,
                              kept_rules(mass_cells, kept, background.element_type, options.mass_quadrature_strength,
                                         mass_stabilization, &fcm.mesh, &mass_reductions),
                              mass_reductions);
  if (constrained)
    parts.element_masses = constrain_element_masses(*parts.element_masses, fcm.mesh.cells, fcm.constraints);
  if (options.ghost_penalty > 0) {
    // Listed here, tabulated by the term once it knows its faces: over several ranks the
    // faces this rank owns (during the discretization's construction, below).
    const NodeConstraints* hanging_nodes = constrained ? &fcm.constraints : nullptr;
    fcm.ghost = std::make_unique<GhostPenaltyFaces>(ghost_penalty_faces(
        fcm.mesh, fcm.volume_fractions, [](int) { return false; }, hanging_nodes));
    parts.terms.push_back(ghost_penalty_term(
        *fcm.ghost, fcm.mesh.element_type, kept_materials, materials, options.ghost_penalty,
        [&mesh = fcm.mesh, &fractions = fcm.volume_fractions, hanging_nodes](const TabulatedHere& here) {
          return std::move(ghost_penalty_faces(mesh, fractions, here, hanging_nodes).faces);
        }));
  }
  parts.materials = std::move(materials);
  NodeRegionFilter kept_dirichlet_nodes;
  if (dirichlet_nodes)
    kept_dirichlet_nodes = [&](int node, const RegionSelector& region, double tolerance) {
      return dirichlet_nodes(used_nodes[node], region, tolerance);
    };
  parts.dirichlet = nodal_dirichlet(fcm.mesh.nodes.topRows(fcm.constraints.free_nodes), dirichlet, scene_file,
                                    "the kept background cells", kept_dirichlet_nodes);

  // §5.2: one Schwarz block per small cut cell: the DOFs of its basis functions (after the
  // hanging nodes' substitution), from the cells' listing without their points.
  const TabulatedElements listing = parts.tabulate([](int) { return false; }, nullptr);
  std::vector<std::vector<int>> blocks;
  for (size_t k = 0; k < kept.size(); ++k) {
    if (fcm.volume_fractions[k] >= options.schwarz_fraction) continue;
    std::vector<int> block;
    for (const int function : listing[static_cast<int>(k)].basis)
      for (int i = 0; i < 3; ++i) block.push_back(3 * function + i);
    blocks.push_back(std::move(block));
  }
  fcm.schwarz_blocks = static_cast<int>(blocks.size());
  const double epsilon = options.schwarz_epsilon;
  parts.preconditioner = [blocks, epsilon] { return std::make_unique<AdditiveSchwarzPreconditioner>(blocks, epsilon); };
  parts.coarse_space = first_order_space(fcm.mesh, &fcm.constraints);
  fcm.discretization = std::make_unique<TabulatedDiscretization>(std::move(parts));
  return fcm;
}

}  // namespace altfem
