#include "dg/tabulated_dg.hpp"

#include <algorithm>
#include <numeric>

#include "dg/lifted_gradients.hpp"
#include "shared/assembly/face_assembler.hpp"
#include "shared/assembly/jump_penalty_kernel.hpp"
#include "shared/assembly/tabulated_here.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"

namespace altfem::dg {

namespace {

std::vector<int> cell_functions(const DgLinearSystem& system, int cell) {
  std::vector<int> functions(system.basis(cell).size());
  std::iota(functions.begin(), functions.end(), system.offset(cell));
  return functions;
}

// values (#points × n) and gradients ((#points·n) × 3) of cell's basis at rule points,
// in columns [column, column + n).
void tabulate_basis(const MonomialBasis& basis, const Eigen::MatrixXd& points, Eigen::Index column,
                    Eigen::MatrixXd& values, Eigen::MatrixXd& gradients) {
  const Eigen::Index n = basis.size(), width = values.cols();
  Eigen::VectorXd phi;
  Eigen::MatrixXd grad;
  for (Eigen::Index q = 0; q < points.rows(); ++q) {
    basis.evaluate(points.row(q).transpose(), phi, grad);
    values.block(q, column, 1, n) = phi.transpose();
    gradients.block(q * width + column, 0, n, 3) = grad;
  }
}

// Whether `face` carries a term: interior, or with a weakly imposed Dirichlet condition.
bool carries_term(const DgFace& face) { return face.plus >= 0 || (face.condition >= 0 && !face.strong); }

// The faces that carry a term, those `here` holds (every one when it is empty) tabulated and
// the others listed (TabulatedFaces::add_held_elsewhere), each in parallel and then appended
// in face order.
TabulatedFaces tabulate_faces(const DgLinearSystem& system, int strength, const TabulatedHere& here) {
  std::vector<int> term_faces;
  for (int f = 0; f < static_cast<int>(system.faces().size()); ++f)
    if (carries_term(system.faces()[f])) term_faces.push_back(f);
  const auto count = static_cast<int>(term_faces.size());
  const std::vector<char> held = tabulated_here(here, count);
  struct Tabulation {
    std::vector<int> functions;
    PolyhedronRule rule;
    Eigen::MatrixXd values_minus, values_plus, gradients_minus, gradients_plus;
  };
  std::vector<Tabulation> tabulations(static_cast<size_t>(count));
#pragma omp parallel for schedule(dynamic, 16)
  for (int t = 0; t < count; ++t) {
    const DgFace& face = system.faces()[term_faces[t]];
    Tabulation& tabulation = tabulations[t];
    tabulation.functions = cell_functions(system, face.minus);
    const auto minus_count = static_cast<Eigen::Index>(tabulation.functions.size());
    if (face.plus >= 0)
      for (int a : cell_functions(system, face.plus)) tabulation.functions.push_back(a);
    if (!held[t]) continue;
    tabulation.rule = polygon_rule(face.polygon, strength);
    const Eigen::Index points = tabulation.rule.weights.size();
    const auto n = static_cast<Eigen::Index>(tabulation.functions.size());
    tabulation.values_minus = Eigen::MatrixXd::Zero(points, n), tabulation.values_plus = tabulation.values_minus;
    tabulation.gradients_minus = Eigen::MatrixXd::Zero(points * n, 3);
    tabulation.gradients_plus = tabulation.gradients_minus;
    tabulate_basis(system.basis(face.minus), tabulation.rule.points, 0, tabulation.values_minus,
                   tabulation.gradients_minus);
    if (face.plus >= 0)
      tabulate_basis(system.basis(face.plus), tabulation.rule.points, minus_count, tabulation.values_plus,
                     tabulation.gradients_plus);
  }
  TabulatedFaces faces;
  for (int t = 0; t < count; ++t) {
    const DgFace& face = system.faces()[term_faces[t]];
    Tabulation& tabulation = tabulations[t];
    if (!held[t]) {
      faces.add_held_elsewhere(tabulation.functions, face.minus, face.plus);
      continue;
    }
    const Eigen::Index points = tabulation.rule.weights.size();
    const Eigen::MatrixXd normals = face.normal.transpose().replicate(points, 1);
    faces.add(tabulation.functions, std::span<const double>(tabulation.rule.weights.data(), points), normals,
              tabulation.values_minus, tabulation.values_plus, tabulation.gradients_minus, tabulation.gradients_plus,
              face.minus, face.plus);
    tabulation = Tabulation{};  // freed as it is packed
  }
  return faces;
}

// The penalty tensors P T P of the faces that carry a term (JumpPenalty, P the components a
// condition prescribes), in tabulate_faces' order.
std::vector<Eigen::Matrix3d> face_penalties(const DgLinearSystem& system) {
  std::vector<Eigen::Matrix3d> penalties;
  for (const DgFace& face : system.faces()) {
    if (!carries_term(face)) continue;
    const Eigen::Matrix3d mask =
        Eigen::Vector3d(face.components[0], face.components[1], face.components[2]).asDiagonal();
    penalties.push_back(mask * system.face_penalty(face).tensor(face.normal) * mask);
  }
  return penalties;
}

// Whether the lifted gradient carries Dirichlet data: a face holding a weak condition
// (lift_cell's lifting weight 1).
bool system_has_weak_dirichlet_faces(const DgLinearSystem& system) {
  return std::any_of(system.faces().begin(), system.faces().end(),
                     [](const DgFace& face) { return face.plus < 0 && face.condition >= 0 && !face.strong; });
}

}  // namespace

TabulatedElements tabulate_dg_cells(const DgLinearSystem& system, int strength, Eigen::MatrixXd* points,
                                    const TabulatedHere& here, const TabulatedElements* listed) {
  // Each cell's rule (a polyhedron's, simplified) and tabulation in parallel, then
  // appended in cell order.
  const int cells = system.cell_count();
  std::vector<PolyhedronRule> rules(static_cast<size_t>(cells));
  std::vector<Eigen::MatrixXd> values(static_cast<size_t>(cells)), gradients(static_cast<size_t>(cells));
  const std::vector<char> held = tabulated_here(here, cells);
#pragma omp parallel for schedule(dynamic, 8)
  for (int cell = 0; cell < cells; ++cell) {
    if (!held[cell] && listed) continue;  // its point count is listed
    rules[cell] = system.cell_rule(cell, strength);
    if (!held[cell]) continue;
    const Eigen::Index count = rules[cell].weights.size(), n = system.basis(cell).size();
    values[cell].resize(count, n);
    gradients[cell].resize(count * n, 3);
    tabulate_basis(system.basis(cell), rules[cell].points, 0, values[cell], gradients[cell]);
  }
  TabulatedElements elements;
  long long point_total = 0, basis_total = 0, value_total = 0;
  for (int cell = 0; cell < cells; ++cell) {
    point_total += rules[cell].weights.size();
    basis_total += system.basis(cell).size();
    value_total += values[cell].size();
  }
  elements.reserve(cells, basis_total, point_total, value_total);
  for (int cell = 0; cell < cells; ++cell) {
    const PolyhedronRule& rule = rules[cell];
    if (!held[cell])
      elements.add_held_elsewhere(cell_functions(system, cell),
                                  listed ? listed->whole_point_count(cell) : static_cast<int>(rule.weights.size()),
                                  system.material_id(cell));
    else
      elements.add(cell_functions(system, cell), std::span<const double>(rule.weights.data(), rule.weights.size()),
                   values[cell], gradients[cell], system.material_id(cell));
  }
  if (points) {
    points->resize(elements.point_count(), 3);
    Eigen::Index row = 0;
    for (const PolyhedronRule& rule : rules)
      points->middleRows(row, rule.points.rows()) = rule.points, row += rule.points.rows();
  }
  return elements;
}

TabulatedDg make_tabulated_dg(const DgLinearSystem& system, std::vector<const Material*> materials,
                              std::function<Eigen::VectorXd(double)> external_force,
                              PreconditionerFactory preconditioner, ConditionTrajectory data, DirichletDofs strong,
                              CoarseSpace coarse_space) {
  const int strength = 2 * system.basis(0).degree();
  DiscretizationParts parts;
  TabulatedDg result;
  const bool interior_penalty = system.flux() == Flux::interior_penalty;
  // Over several ranks each tabulates (and lifts) only its cells: the discretization calls
  // these while it is built, below.
  if (interior_penalty) {
    result.lifted_data = std::make_unique<LiftedDirichletData>();
    parts.tabulate = [&system, strength, lifted_data = result.lifted_data.get()](const TabulatedHere& here,
                                                                                 const TabulatedElements* listed) {
      LiftedDgCells lifted = tabulate_lifted_dg_cells(system, strength, here, listed);
      *lifted_data = std::move(lifted.dirichlet);
      return std::move(lifted.elements);
    };
    // The data's shift (zero where no cell of this rank has a Dirichlet face).
    if (data && system_has_weak_dirichlet_faces(system))
      parts.deformation_shifts = [lifted_data = result.lifted_data.get(), data = std::move(data)](
                                     double time, std::span<double> shifts) {
        lifted_data->shifts([&](int condition, const Eigen::Vector3d& x) { return data(condition, x, time); }, shifts);
      };
  } else {
    parts.tabulate = [&system, strength](const TabulatedHere& here, const TabulatedElements* listed) {
      return tabulate_dg_cells(system, strength, nullptr, here, listed);
    };
  }
  parts.materials = std::move(materials);
  // The faces are tabulated by their term once it knows which it assembles: over several
  // ranks the faces this rank owns (while the discretization is built, below).
  parts.terms.push_back(std::make_unique<FaceAssembler<JumpPenaltyKernel>>(
      [&system, strength](const TabulatedHere& here) { return tabulate_faces(system, strength, here); },
      [&system](const TabulatedFaces&) { return JumpPenaltyKernel(face_penalties(system)); }));
  parts.conditions_weakly = strong.dofs.empty();
  parts.dirichlet = std::move(strong);
  parts.explicit_mass = ExplicitMassKind::block_per_element;  // no function is shared by two cells
  // A lifted cell lists its neighbours' functions too (with zero values): the blocks are the cells'.
  if (interior_penalty)
    for (int cell = 0; cell < system.cell_count(); ++cell) {
      parts.mass_blocks.emplace_back();
      for (int dof = 3 * system.offset(cell); dof < 3 * system.offset(cell + 1); ++dof)
        parts.mass_blocks.back().push_back(dof);
    }
  parts.external_force = std::move(external_force);
  parts.preconditioner = std::move(preconditioner);
  parts.coarse_space = std::move(coarse_space);
  result.discretization = std::make_unique<TabulatedDiscretization>(std::move(parts));
  return result;
}

}  // namespace altfem::dg
