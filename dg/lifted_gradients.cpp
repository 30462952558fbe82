#include "dg/lifted_gradients.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <exception>
#include <stdexcept>
#include <string>

#include "shared/assembly/tabulated_here.hpp"
#include "shared/common/eigen_decompositions.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"

namespace altfem::dg {

namespace {

// One cell's tabulation, built in parallel and appended in cell order.
struct LiftedCell {
  std::vector<int> functions;
  Eigen::VectorXd weights;
  Eigen::MatrixXd values;               // #points × #functions
  Eigen::MatrixXd gradients;            // (#points·#functions) × 3
  LiftedDirichletData::Cell dirichlet;  // no face points when the cell has no Dirichlet face
};

// The faces each cell bounds (indices into system.faces()), in face order.
std::vector<std::vector<int>> faces_of_cells(const DgLinearSystem& system) {
  std::vector<std::vector<int>> cell_faces(static_cast<size_t>(system.cell_count()));
  for (int f = 0; f < static_cast<int>(system.faces().size()); ++f) {
    const DgFace& face = system.faces()[f];
    cell_faces[face.minus].push_back(f);
    if (face.plus >= 0) cell_faces[face.plus].push_back(f);
  }
  return cell_faces;
}

// α_f of the lifting (header): ½ interior, 1 Dirichlet, 0 free.
double lifting_weight(const DgFace& face) {
  if (face.plus >= 0) return 0.5;
  return face.condition >= 0 && !face.strong ? 1.0 : 0.0;  // a strong face carries no flux term
}

// A lifted cell's functions: its own, then each face neighbour's once, in face order;
// `first` receives (neighbour, its first column) when given.
std::vector<int> lifted_functions(const DgLinearSystem& system, int cell, const std::vector<int>& faces,
                                  std::vector<std::pair<int, int>>* first = nullptr) {
  std::vector<int> functions;
  for (int a = 0; a < system.basis(cell).size(); ++a) functions.push_back(system.offset(cell) + a);
  std::vector<int> neighbours;
  for (int f : faces) {
    const DgFace& face = system.faces()[f];
    if (face.plus < 0) continue;
    const int neighbour = face.minus == cell ? face.plus : face.minus;
    if (std::find(neighbours.begin(), neighbours.end(), neighbour) != neighbours.end()) continue;
    neighbours.push_back(neighbour);
    if (first) first->emplace_back(neighbour, static_cast<int>(functions.size()));
    for (int a = 0; a < system.basis(neighbour).size(); ++a) functions.push_back(system.offset(neighbour) + a);
  }
  return functions;
}

LiftedCell lift_cell(const DgLinearSystem& system, int cell, const std::vector<int>& faces, int strength) {
  const MonomialBasis& basis = system.basis(cell);
  const int own = basis.size();
  LiftedCell lifted;
  std::vector<std::pair<int, int>> first;  // (neighbour, its first column)
  lifted.functions = lifted_functions(system, cell, faces, &first);
  const int n = static_cast<int>(lifted.functions.size());

  // The lifting's right-hand sides: b(m, 3a + j) = Σ_f α_f ∫_f φ_m j_a n_K,j dA with the
  // jump j_a = φ_a on K's own functions and −φ_a on the neighbour's across f.
  Eigen::MatrixXd right_hand_sides = Eigen::MatrixXd::Zero(own, 3 * n);
  // The data's right-hand sides, one column per Dirichlet face point p: α_f w_p φ_m(x_p).
  std::vector<Eigen::VectorXd> data_columns;
  std::vector<Eigen::Vector3d> data_points, data_normals;
  Eigen::VectorXd phi, neighbour_phi;
  Eigen::MatrixXd gradients, neighbour_gradients;
  for (int f : faces) {
    const DgFace& face = system.faces()[f];
    const double alpha = lifting_weight(face);
    if (alpha == 0) continue;
    const Eigen::Vector3d normal = face.minus == cell ? face.normal : Eigen::Vector3d(-face.normal);
    int neighbour = -1, column = 0;
    if (face.plus >= 0) {
      neighbour = face.minus == cell ? face.plus : face.minus;
      column =
          std::find_if(first.begin(), first.end(), [&](const auto& entry) { return entry.first == neighbour; })->second;
    }
    const PolyhedronRule rule = polygon_rule(face.polygon, 2 * basis.degree());
    for (Eigen::Index p = 0; p < rule.weights.size(); ++p) {
      const Eigen::Vector3d x = rule.points.row(p).transpose();
      basis.evaluate(x, phi, gradients);
      const Eigen::VectorXd scaled = alpha * rule.weights[p] * phi;  // α w φ_m
      for (int a = 0; a < own; ++a)
        for (int j = 0; j < 3; ++j) right_hand_sides.col(3 * a + j) += (phi[a] * normal[j]) * scaled;
      if (face.plus < 0) {
        data_columns.push_back(scaled);
        data_points.push_back(x);
        data_normals.push_back(normal);
        lifted.dirichlet.conditions.push_back(face.condition);
      }
      if (neighbour < 0) continue;
      system.basis(neighbour).evaluate(x, neighbour_phi, neighbour_gradients);
      for (Eigen::Index a = 0; a < neighbour_phi.size(); ++a)
        for (int j = 0; j < 3; ++j)
          right_hand_sides.col(3 * (column + a) + j) -= (neighbour_phi[a] * normal[j]) * scaled;
    }
  }

  const PolyhedronRule rule = system.cell_rule(cell, strength);
  const Eigen::Index points = rule.weights.size();
  Eigen::MatrixXd own_values(points, own);
  std::vector<Eigen::MatrixXd> own_gradients(static_cast<size_t>(points));
  Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(own, own);
  for (Eigen::Index q = 0; q < points; ++q) {
    basis.evaluate(rule.points.row(q).transpose(), phi, own_gradients[q]);
    own_values.row(q) = phi.transpose();
    mass.noalias() += rule.weights[q] * phi * phi.transpose();
  }
  // The lifting's coefficients c(m, 3a + j): r_a,j = Σ_m c(m, 3a + j) φ_m, from
  // Σ_m' ∫_K φ_m φ_m' c(m', ·) = b(m, ·) (the mass of K's monomials: rule strength ≥ 2k).
  const Eigen::LLT<Eigen::MatrixXd> mass_factor(mass);
  const Eigen::MatrixXd lifting_at_points =
      own_values * mass_factor.solve(right_hand_sides);  // #points × 3n: r_a,j(x_q)
  if (!data_columns.empty()) {
    const auto count = static_cast<Eigen::Index>(data_columns.size());
    Eigen::MatrixXd columns(own, count);
    lifted.dirichlet.face_points.resize(count, 3);
    lifted.dirichlet.normals.resize(count, 3);
    for (Eigen::Index p = 0; p < count; ++p) {
      columns.col(p) = data_columns[p];
      lifted.dirichlet.face_points.row(p) = data_points[p].transpose();
      lifted.dirichlet.normals.row(p) = data_normals[p].transpose();
    }
    lifted.dirichlet.coefficients = own_values * mass_factor.solve(columns);
  }

  lifted.weights = rule.weights;
  lifted.values = Eigen::MatrixXd::Zero(points, n);
  lifted.values.leftCols(own) = own_values;
  lifted.gradients.resize(points * n, 3);
  for (Eigen::Index q = 0; q < points; ++q) {
    for (int a = 0; a < n; ++a) lifted.gradients.row(q * n + a) = -lifting_at_points.block(q, 3 * a, 1, 3);
    lifted.gradients.middleRows(q * n, own) += own_gradients[q];
  }
  return lifted;
}

}  // namespace

void LiftedDirichletData::shifts(const ConditionData& data, std::span<double> shifts) const {
  std::fill(shifts.begin(), shifts.end(), 0.0);
  for (const Cell& cell : cells_) {
    Eigen::MatrixXd data_at_points(cell.face_points.rows(), 3);
    for (Eigen::Index p = 0; p < data_at_points.rows(); ++p)
      data_at_points.row(p) = data(cell.conditions[p], cell.face_points.row(p).transpose()).transpose();
    for (Eigen::Index q = 0; q < cell.coefficients.rows(); ++q) {
      Eigen::Map<Eigen::Matrix3d> shift(shifts.data() + 9 * (cell.first_point + q));
      for (Eigen::Index p = 0; p < data_at_points.rows(); ++p)
        shift.noalias() += cell.coefficients(q, p) * data_at_points.row(p).transpose() * cell.normals.row(p);
    }
  }
}

LiftedDgCells tabulate_lifted_dg_cells(const DgLinearSystem& system, int strength, const TabulatedHere& here,
                                       const TabulatedElements* listed) {
  const std::vector<std::vector<int>> cell_faces = faces_of_cells(system);
  for (size_t f = 0; f < system.faces().size(); ++f) {
    const DgFace& face = system.faces()[f];
    if (face.plus < 0 && face.condition >= 0 && !(face.components[0] && face.components[1] && face.components[2]))
      throw std::invalid_argument("tabulate_lifted_dg_cells: Dirichlet face " + std::to_string(f) +
                                  " prescribes some components only, which the lifted gradient cannot carry");
  }
  std::vector<LiftedCell> cells(static_cast<size_t>(system.cell_count()));
  const std::vector<char> held = tabulated_here(here, system.cell_count());
  // A cell's lifting costs a few face and volume rules and one small solve: parallel over cells.
  std::exception_ptr failure;  // an exception must not leave the OpenMP region
#pragma omp parallel for schedule(dynamic, 16)
  for (int cell = 0; cell < system.cell_count(); ++cell) {
    try {
      if (held[cell]) {
        cells[cell] = lift_cell(system, cell, cell_faces[cell], strength);
      } else {  // another rank's: its functions and how many points its rule has
        cells[cell].functions = lifted_functions(system, cell, cell_faces[cell]);
        cells[cell].weights.resize(listed ? listed->whole_point_count(cell)
                                          : system.cell_rule(cell, strength).weights.size());
      }
    } catch (...) {
#pragma omp critical(altfem_lift_cells)
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  LiftedDgCells result;
  for (int cell = 0; cell < system.cell_count(); ++cell) {
    LiftedCell& lifted = cells[cell];
    if (!held[cell]) {
      result.elements.add_held_elsewhere(lifted.functions, static_cast<int>(lifted.weights.size()),
                                         system.material_id(cell));
      continue;
    }
    if (lifted.dirichlet.face_points.rows() > 0) {
      lifted.dirichlet.first_point = result.elements.whole_point_count();
      result.dirichlet.add(std::move(lifted.dirichlet));
    }
    result.elements.add(lifted.functions, std::span<const double>(lifted.weights.data(), lifted.weights.size()),
                        lifted.values, lifted.gradients, system.material_id(cell));
  }
  return result;
}

}  // namespace altfem::dg
