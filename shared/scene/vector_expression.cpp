// muParser behind VectorExpression (vector_expression.hpp). A muParser parser reads its
// variables through pointers it was given, so one parser cannot serve two threads at
// once: each evaluation borrows a parser set (three parsers bound to their own x, y, z,
// t) from a pool, and returns it; the pool grows to the number of threads that ever
// evaluate at the same time.
#include "shared/scene/vector_expression.hpp"

#include <muParser.h>

#include <cmath>
#include <mutex>
#include <sstream>
#include <vector>

#include "shared/common/error.hpp"

namespace altfem {

namespace {

// Three parsers bound to this object's own variables (so it must not move). The normal
// is defined only for surface expressions, so nx in a body force is a parse error.
struct ParserSet {
  double x = 0, y = 0, z = 0, t = 0;
  double nx = 0, ny = 0, nz = 0;
  std::array<mu::Parser, 3> parsers;

  ParserSet(const std::array<std::string, 3>& components, const ExpressionConstants& constants,
            ExpressionVariables variables) {
    for (int i = 0; i < 3; ++i) {
      mu::Parser& parser = parsers[i];
      parser.DefineVar("x", &x);
      parser.DefineVar("y", &y);
      parser.DefineVar("z", &z);
      parser.DefineVar("t", &t);
      if (variables == ExpressionVariables::surface) {
        parser.DefineVar("nx", &nx);
        parser.DefineVar("ny", &ny);
        parser.DefineVar("nz", &nz);
      }
      parser.DefineConst("pi", 3.14159265358979323846);
      for (const auto& [name, value] : constants) parser.DefineConst(name, value);
      parser.SetExpr(components[i]);
    }
  }
  Eigen::Vector3d evaluate(const Eigen::Vector3d& position, double time) {
    x = position.x(), y = position.y(), z = position.z(), t = time;
    return {parsers[0].Eval(), parsers[1].Eval(), parsers[2].Eval()};
  }
};

// muParser's message with its 0-based "position N" as a 1-based character, plus the text.
std::string parse_message(const mu::Parser::exception_type& error, const std::string& text) {
  std::string message = error.GetMsg();
  while (!message.empty() && (message.back() == '.' || message.back() == ' ')) message.pop_back();
  if (!message.empty()) message[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(message[0])));
  const std::string position = "found at position " + std::to_string(error.GetPos());
  if (const auto at = message.find(position); at != std::string::npos)
    message.replace(at, position.size(), "at character " + std::to_string(error.GetPos() + 1));
  else if (const auto plain = message.find(" at position "); plain != std::string::npos) message.erase(plain);
  return "cannot parse the expression \"" + text + "\": " + message;
}

}  // namespace

struct VectorExpression::Shared {
  std::array<std::string, 3> components;
  ExpressionConstants constants;
  ExpressionVariables variables = ExpressionVariables::position_and_time;
  std::string pointer;
  bool time_dependent = false;
  std::mutex mutex;
  std::vector<std::unique_ptr<ParserSet>> idle;

  // A parser set for the caller's exclusive use until it is given back.
  std::unique_ptr<ParserSet> borrow() {
    {
      const std::lock_guard lock(mutex);
      if (!idle.empty()) {
        std::unique_ptr<ParserSet> set = std::move(idle.back());
        idle.pop_back();
        return set;
      }
    }
    return std::make_unique<ParserSet>(components, constants, variables);
  }
  void give_back(std::unique_ptr<ParserSet> set) {
    const std::lock_guard lock(mutex);
    idle.push_back(std::move(set));
  }
  [[noreturn]] void not_finite(const Eigen::Vector3d& position, double time, const Eigen::Vector3d& value) const {
    std::ostringstream message;
    message << pointer << ": the expression is not finite at x = (" << position.x() << ", " << position.y() << ", "
            << position.z() << "), t = " << time << ": (" << value.x() << ", " << value.y() << ", " << value.z() << ")";
    throw NumericalError(message.str());
  }
};

VectorExpression::VectorExpression(const std::array<std::string, 3>& components, const ExpressionConstants& constants,
                                   const std::string& file, const std::string& pointer, ExpressionVariables variables)
    : shared_(std::make_shared<Shared>()) {
  shared_->components = components;
  shared_->constants = constants;
  shared_->variables = variables;
  shared_->pointer = pointer;
  auto set = std::make_unique<ParserSet>(components, constants, variables);
  for (int i = 0; i < 3; ++i) {
    mu::Parser& parser = set->parsers[i];
    const std::string component_pointer = pointer + "/" + std::to_string(i);
    try {
      parser.Eval();  // muParser parses the whole text at the first evaluation
      if (parser.GetNumResults() != 1)
        throw InputError(input_message(file, component_pointer,
                                       "expected one value, got " + std::to_string(parser.GetNumResults()) +
                                           " (comma-separated) in \"" + components[i] + "\""));
      shared_->time_dependent = shared_->time_dependent || parser.GetUsedVar().count("t") > 0;
    } catch (const mu::Parser::exception_type& error) {
      throw InputError(input_message(file, component_pointer, parse_message(error, components[i])));
    }
  }
  shared_->idle.push_back(std::move(set));
}

Eigen::Vector3d VectorExpression::operator()(const Eigen::Vector3d& x, double t) const {
  std::unique_ptr<ParserSet> set = shared_->borrow();
  const Eigen::Vector3d value = set->evaluate(x, t);
  shared_->give_back(std::move(set));
  if (!value.allFinite()) shared_->not_finite(x, t, value);
  return value;
}

Eigen::MatrixXd VectorExpression::evaluate(const Eigen::MatrixXd& points, double t) const {
  return evaluate_at(points, nullptr, t);
}

Eigen::MatrixXd VectorExpression::evaluate(const Eigen::MatrixXd& points, const Eigen::MatrixXd& normals,
                                           double t) const {
  return evaluate_at(points, &normals, t);
}

Eigen::MatrixXd VectorExpression::evaluate_at(const Eigen::MatrixXd& points, const Eigen::MatrixXd* normals,
                                              double t) const {
  Eigen::MatrixXd values(points.rows(), 3);
  std::unique_ptr<ParserSet> set = shared_->borrow();
  for (Eigen::Index p = 0; p < points.rows(); ++p) {
    if (normals) set->nx = (*normals)(p, 0), set->ny = (*normals)(p, 1), set->nz = (*normals)(p, 2);
    values.row(p) = set->evaluate(points.row(p).transpose(), t);
  }
  shared_->give_back(std::move(set));
  for (Eigen::Index p = 0; p < points.rows(); ++p)
    if (!values.row(p).allFinite()) shared_->not_finite(points.row(p).transpose(), t, values.row(p).transpose());
  return values;
}

bool VectorExpression::depends_on_time() const { return shared_->time_dependent; }

const std::string& VectorExpression::pointer() const { return shared_->pointer; }

}  // namespace altfem
