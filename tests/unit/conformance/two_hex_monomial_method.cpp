#include "tests/unit/conformance/two_hex_monomial_method.hpp"

#include <array>

#include "shared/assembly/face_assembler.hpp"
#include "shared/assembly/jump_penalty_kernel.hpp"
#include "shared/assembly/tabulated_discretization.hpp"
#include "shared/common/error.hpp"
#include "shared/quadrature/reference_rules.hpp"
#include "shared/simulation/basis_embedding.hpp"

namespace altfem::test {

namespace {

constexpr int monomials = 4;    // 1, x, y, z
constexpr double penalty = 20;  // η of Kaufmann et al. 2009 eq. (20), relative to E

// One hexahedron and its monomials.
struct Hexahedron {
  Eigen::AlignedBox3d box;
  double size() const { return box.sizes().maxCoeff(); }
  double volume() const { return box.volume(); }
  /// φ_a(x), a = 0..3.
  Eigen::Vector4d values(const Eigen::Vector3d& x) const {
    Eigen::Vector4d v;
    v << 1.0, (x - box.center()) / size();
    return v;
  }
  /// ∇φ_a (4 × 3): constant.
  Eigen::Matrix<double, 4, 3> gradients() const {
    Eigen::Matrix<double, 4, 3> g = Eigen::Matrix<double, 4, 3>::Zero();
    g.bottomRows<3>() = Eigen::Matrix3d::Identity() / size();
    return g;
  }
};

// A face of a hexahedron: axis d, at its min (side 0) or max (side 1) coordinate.
struct BoxFace {
  int axis, side;
  Eigen::Vector3d normal() const { return (side == 0 ? -1.0 : 1.0) * Eigen::Vector3d::Unit(axis); }
};

// Points and weights of a strength-3 rule on a face of `box` (#points × 3, #points).
std::pair<Eigen::MatrixXd, Eigen::VectorXd> face_rule(const Eigen::AlignedBox3d& box, BoxFace face) {
  const QuadratureRule rule = quad_rule(3);
  const int u = (face.axis + 1) % 3, v = (face.axis + 2) % 3;
  const Eigen::Vector3d half = box.sizes() / 2;
  Eigen::MatrixXd points(rule.weights.size(), 3);
  for (Eigen::Index q = 0; q < points.rows(); ++q) {
    Eigen::Vector3d x = box.center();
    x[face.axis] = face.side == 0 ? box.min()[face.axis] : box.max()[face.axis];
    x[u] += half[u] * rule.points(q, 0);
    x[v] += half[v] * rule.points(q, 1);
    points.row(q) = x.transpose();
  }
  return {points, rule.weights * half[u] * half[v]};
}

class TwoHexMonomialMethod final : public MethodInstance, private ElementBasisEvaluator {
public:
  TwoHexMonomialMethod(const Scene& scene, const SceneGeometry& geometry)
      : material_(make_material(*material_model_from_name(scene.material.model), scene.material.youngs_modulus,
                                scene.material.poisson_ratio, scene.material.density)) {
    const Eigen::AlignedBox3d& bounds = geometry.bounds;
    const double middle = bounds.center().x();
    hexahedra_[0].box = Eigen::AlignedBox3d(bounds.min(), Eigen::Vector3d(middle, bounds.max().y(), bounds.max().z()));
    hexahedra_[1].box = Eigen::AlignedBox3d(Eigen::Vector3d(middle, bounds.min().y(), bounds.min().z()), bounds.max());

    DiscretizationParts parts;
    tabulate_volumes(parts.elements);
    parts.materials = {material_.get()};
    const double youngs_modulus = scene.material.youngs_modulus;
    add_face(0, {0, 1}, 1, youngs_modulus);  // the middle face, minus side: hexahedron 0
    for (const DirichletCondition& condition : scene.dirichlet) add_weak_condition(scene, condition, youngs_modulus);
    parts.terms.push_back(std::make_unique<FaceAssembler<JumpPenaltyKernel>>(faces_, JumpPenaltyKernel(penalties_)));
    parts.conditions_weakly = true;
    parts.explicit_mass = ExplicitMassKind::block_per_element;  // no basis function is shared
    parts.external_force = [this](double time) { return weak_condition_load(time); };
    discretization_ = std::make_unique<TabulatedDiscretization>(std::move(parts));

    surface_ = geometry.surface ? *geometry.surface : box_surface(bounds);
    embedding_ = std::make_unique<BasisEmbedding>(static_cast<const ElementBasisEvaluator&>(*this), surface_.vertices);
  }

  const Discretization& discretization() const override { return *discretization_; }
  nlohmann::json element_counts() const override { return {{"monomial_hexahedron", 2}}; }
  long long quadrature_points() const override { return discretization_->elements().point_count(); }
  double quadrature_seconds() const override { return 0; }
  const SurfaceMesh& embedded_surface() const override { return surface_; }
  const ElementBasisEvaluator& basis_evaluator() const override { return *this; }
  Eigen::MatrixXd embedded_displacement(const Eigen::VectorXd& u) const override { return embedding_->displacement(u); }

  Eigen::VectorXd interpolate(const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& field) const override {
    // An affine f has f(x) = f(c)·1 + Σ_d h (f(c + e_d) − f(c)) (x_d − c_d)/h.
    Eigen::VectorXd coefficients(3 * monomials * 2);
    for (int e = 0; e < 2; ++e) {
      const Eigen::Vector3d centre = hexahedra_[e].box.center(), at_centre = field(centre);
      coefficients.segment<3>(3 * monomials * e) = at_centre;
      for (int d = 0; d < 3; ++d)
        coefficients.segment<3>(3 * (monomials * e + 1 + d)) =
            hexahedra_[e].size() * (field(centre + Eigen::Vector3d::Unit(d)) - at_centre);
    }
    return coefficients;
  }

  // The volume output: each hexahedron with its own copy of its corners (a
  // discontinuous field), so there are 16 points for 24 DOFs.
  UnstructuredGrid volume_grid(const Eigen::VectorXd& u) const override {
    UnstructuredGrid grid;
    grid.points.resize(16, 3);
    Eigen::MatrixXd displacement(16, 3);
    Eigen::MatrixXi cells(2, 8);
    for (int e = 0; e < 2; ++e)
      for (int corner = 0; corner < 8; ++corner) {
        // VTK's hexahedron order: the bottom face counter-clockwise, then the top.
        const int bits[8] = {0, 1, 3, 2, 4, 5, 7, 6};
        const Eigen::Vector3d x = hexahedra_[e].box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(bits[corner]));
        const int point = 8 * e + corner;
        grid.points.row(point) = x.transpose();
        displacement.row(point) = evaluate(e, x, u).transpose();
        cells(e, corner) = point;
      }
    grid.add_cells(ElementType::hex8, cells);
    grid.point_data.emplace_back("displacement", displacement);
    return grid;
  }

private:
  // ElementBasisEvaluator: the embedding's view of the two hexahedra.
  int element_count() const override { return 2; }
  Eigen::AlignedBox3d element_bounds(int e) const override { return hexahedra_[e].box; }
  bool evaluate_inside(int e, const Eigen::Vector3d& x, std::vector<int>& basis,
                       std::vector<double>& values) const override {
    const double slack = 1e-9 * hexahedra_[e].size();
    if (hexahedra_[e].box.exteriorDistance(x) > slack) return false;
    fill(e, x, basis, values);
    return true;
  }
  double evaluate_nearest(const Eigen::Vector3d& x, std::vector<int>& basis,
                          std::vector<double>& values) const override {
    const int e = hexahedra_[0].box.exteriorDistance(x) <= hexahedra_[1].box.exteriorDistance(x) ? 0 : 1;
    fill(e, x, basis, values);
    return hexahedra_[e].box.exteriorDistance(x);
  }
  BoundaryPointRule boundary_rule() const override { return BoundaryPointRule::average; }

  void fill(int e, const Eigen::Vector3d& x, std::vector<int>& basis, std::vector<double>& values) const {
    const Eigen::Vector4d phi = hexahedra_[e].values(x);
    basis.resize(monomials);
    values.resize(monomials);
    for (int a = 0; a < monomials; ++a) {
      basis[a] = monomials * e + a;
      values[a] = phi[a];
    }
  }
  Eigen::Vector3d evaluate(int e, const Eigen::Vector3d& x, const Eigen::VectorXd& u) const {
    const Eigen::Vector4d phi = hexahedra_[e].values(x);
    Eigen::Vector3d value = Eigen::Vector3d::Zero();
    for (int a = 0; a < monomials; ++a) value += phi[a] * u.segment<3>(3 * (monomials * e + a));
    return value;
  }

  void tabulate_volumes(TabulatedElements& elements) const {
    const QuadratureRule rule = hex_rule(2);
    for (int e = 0; e < 2; ++e) {
      const Hexahedron& hexahedron = hexahedra_[e];
      const Eigen::Vector3d half = hexahedron.box.sizes() / 2;
      const auto points = rule.weights.size();
      Eigen::VectorXd weights = rule.weights * half.prod();
      Eigen::MatrixXd values(points, monomials), gradients(points * monomials, 3);
      for (Eigen::Index q = 0; q < points; ++q) {
        const Eigen::Vector3d x = hexahedron.box.center() + half.cwiseProduct(rule.points.row(q).transpose());
        values.row(q) = hexahedron.values(x).transpose();
        gradients.middleRows(q * monomials, monomials) = hexahedron.gradients();
      }
      const std::array<int, monomials> basis{monomials * e, monomials * e + 1, monomials * e + 2, monomials * e + 3};
      elements.add(basis, std::span<const double>(weights.data(), weights.size()), values, gradients);
    }
  }

  // Adds face `face` of hexahedron `minus`, coupled to hexahedron `plus` (-1: boundary).
  void add_face(int minus, BoxFace face, int plus, double youngs_modulus) {
    const auto [points, weights] = face_rule(hexahedra_[minus].box, face);
    const Eigen::Index count = points.rows();
    const int sides = plus < 0 ? 1 : 2;
    std::vector<int> basis;
    for (int s = 0; s < sides; ++s)
      for (int a = 0; a < monomials; ++a) basis.push_back(monomials * (s == 0 ? minus : plus) + a);
    const Eigen::Index n = static_cast<Eigen::Index>(basis.size());
    Eigen::MatrixXd normals = face.normal().transpose().replicate(count, 1);
    Eigen::MatrixXd values_minus = Eigen::MatrixXd::Zero(count, n), values_plus = values_minus;
    Eigen::MatrixXd gradients_minus = Eigen::MatrixXd::Zero(count * n, 3), gradients_plus = gradients_minus;
    for (Eigen::Index q = 0; q < count; ++q) {
      values_minus.block(q, 0, 1, monomials) = hexahedra_[minus].values(points.row(q).transpose()).transpose();
      gradients_minus.middleRows(q * n, monomials) = hexahedra_[minus].gradients();
      if (plus < 0) continue;
      values_plus.block(q, monomials, 1, monomials) = hexahedra_[plus].values(points.row(q).transpose()).transpose();
      gradients_plus.middleRows(q * n + monomials, monomials) = hexahedra_[plus].gradients();
    }
    faces_.add(basis, std::span<const double>(weights.data(), weights.size()), normals, values_minus, values_plus,
               gradients_minus, gradients_plus, minus, plus);
    const double area = weights.sum();
    double inverse_volumes = 1.0 / hexahedra_[minus].volume();
    if (plus >= 0) inverse_volumes += 1.0 / hexahedra_[plus].volume();
    penalties_.push_back(penalty * youngs_modulus * area * inverse_volumes);
  }

  // The outer faces of both hexahedra that the condition's region holds (all corners inside).
  void add_weak_condition(const Scene& scene, const DirichletCondition& condition, double youngs_modulus) {
    if (!(condition.components[0] && condition.components[1] && condition.components[2]))
      throw InputError(input_message(scene.file.string(), condition.pointer,
                                     "the two-hexahedra test method imposes all three components"));
    const double tolerance = 1e-9 * (hexahedra_[0].box.sizes() + hexahedra_[1].box.sizes()).norm();
    const size_t before = weak_faces_.size();
    for (int e = 0; e < 2; ++e)
      for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
          if (axis == 0 && side == 1 - e) continue;  // the middle face
          const auto [points, weights] = face_rule(hexahedra_[e].box, {axis, side});
          bool inside = true;
          for (Eigen::Index q = 0; q < points.rows() && inside; ++q)
            inside = condition.region.contains(points.row(q).transpose(), tolerance);
          if (!inside) continue;
          weak_faces_.push_back({faces_.size(), e, {axis, side}, condition.motion});
          add_face(e, {axis, side}, -1, youngs_modulus);
        }
    if (weak_faces_.size() == before)
      throw InputError(input_message(scene.file.string(), condition.pointer + "/region",
                                     "holds no whole face of the two hexahedra"));
  }

  // η_f ∫_f g(x, t)·φ_a dA for each weakly imposed face: the data part of the penalty.
  Eigen::VectorXd weak_condition_load(double time) const {
    Eigen::VectorXd load = Eigen::VectorXd::Zero(3 * monomials * 2);
    for (const WeakFace& weak : weak_faces_) {
      const auto [points, weights] = face_rule(hexahedra_[weak.element].box, weak.face);
      const double eta = penalties_[weak.face_index];
      for (Eigen::Index q = 0; q < points.rows(); ++q) {
        const Eigen::Vector3d x = points.row(q).transpose();
        const Eigen::Vector3d g = weak.motion.displacement(x, time);
        const Eigen::Vector4d phi = hexahedra_[weak.element].values(x);
        for (int a = 0; a < monomials; ++a)
          load.segment<3>(3 * (monomials * weak.element + a)) += eta * weights[q] * phi[a] * g;
      }
    }
    return load;
  }
  static SurfaceMesh box_surface(const Eigen::AlignedBox3d& box) {
    SurfaceMesh surface;
    surface.vertices.resize(8, 3);
    for (int corner = 0; corner < 8; ++corner)
      surface.vertices.row(corner) = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner)).transpose();
    // Corner bits: x = 1, y = 2, z = 4; outward triangles of the six faces.
    surface.triangles.resize(12, 3);
    surface.triangles << 0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3,
        5, 3, 7, 5;
    return surface;
  }

  struct WeakFace {
    int face_index, element;
    BoxFace face;
    Motion motion;  // a copy: the scene need not outlive the method
  };

  std::unique_ptr<Material> material_;
  std::vector<double> penalties_;  // η_f per face of faces_
  std::array<Hexahedron, 2> hexahedra_;
  TabulatedFaces faces_;
  std::vector<WeakFace> weak_faces_;
  std::unique_ptr<TabulatedDiscretization> discretization_;
  SurfaceMesh surface_;
  std::unique_ptr<BasisEmbedding> embedding_;
};

}  // namespace

std::unique_ptr<MethodInstance> make_two_hex_monomial_method(const Scene& scene, const SceneGeometry& geometry) {
  return std::make_unique<TwoHexMonomialMethod>(scene, geometry);
}

}  // namespace altfem::test
