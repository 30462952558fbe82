#pragma once
// A vector field of the scene given as three expressions of x, y, z (the reference
// position X, m) and t (s), e.g. ["0.01*sin(pi*x)", "0", "-t*y"] (docs/scene-schema.md,
// "Expressions"); a surface field (a traction) may also use nx, ny, nz, the outward unit
// normal of the surface there. Parsed once, when the scene is loaded, by muParser (the parser of
// deal.II's FunctionParser); evaluated at quadrature points and nodes, from any number
// of threads at once.
#include <Eigen/Core>
#include <array>
#include <map>
#include <memory>
#include <string>

namespace altfem {

/// Named numbers the expressions may use besides x, y, z, t, pi and muParser's own
/// constants (_pi, _e): the scene's `constants`.
using ExpressionConstants = std::map<std::string, double>;

/// The variables an expression may use: x, y, z, t everywhere; nx, ny, nz on surfaces.
enum class ExpressionVariables { position_and_time, surface };

class VectorExpression {
public:
  /// An empty expression (absent from the scene): has_value() is false.
  VectorExpression() = default;
  /// Parses the three components. Throws InputError naming `file` and `pointer/i`
  /// (e.g. "scene.json: /loads/body_force/1: unexpected token "yy" at character 3 of
  /// "x*yy"") when a component does not parse or gives more than one value.
  VectorExpression(const std::array<std::string, 3>& components, const ExpressionConstants& constants,
                   const std::string& file, const std::string& pointer,
                   ExpressionVariables variables = ExpressionVariables::position_and_time);

  bool has_value() const { return shared_ != nullptr; }
  /// The value at rest position x and time t. Thread-safe: each call borrows a parser of
  /// its own from a pool (muParser keeps its variables inside the parser).
  Eigen::Vector3d operator()(const Eigen::Vector3d& x, double t) const;
  /// The values at many points (#points × 3 → #points × 3), with one borrowed parser:
  /// what quadrature loops call. Thread-safe like operator().
  Eigen::MatrixXd evaluate(const Eigen::MatrixXd& points, double t) const;
  /// A surface expression's values at points (#points × 3) with their outward unit
  /// normals (#points × 3), → #points × 3. Thread-safe like operator().
  Eigen::MatrixXd evaluate(const Eigen::MatrixXd& points, const Eigen::MatrixXd& normals, double t) const;
  /// Whether any component uses t (a constant-in-time load is integrated once).
  bool depends_on_time() const;
  /// The JSON pointer the expression came from, for messages.
  const std::string& pointer() const;

private:
  struct Shared;
  Eigen::MatrixXd evaluate_at(const Eigen::MatrixXd& points, const Eigen::MatrixXd* normals, double t) const;
  std::shared_ptr<Shared> shared_;
};

}  // namespace altfem
