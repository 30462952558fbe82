// `altfem quadrature monomials`: the experiment of Longva et al. 2020, §4.6 (Fig. 4),
// one row per strength 1..m.
#include <cstdio>
#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "fcm/monomial_experiment.hpp"
#include "shared/common/error.hpp"

namespace altfem::cli {

namespace {

nlohmann::json accuracy_json(const fcm::RuleAccuracy& accuracy) {
  return {{"points", accuracy.points},
          {"max_relative_error", accuracy.max_relative_error},
          {"median_relative_error", accuracy.median_relative_error},
          {"min_weight", accuracy.min_weight},
          {"inside", accuracy.inside}};
}

}  // namespace

int quadrature_monomials_command(const std::string& cell_name, int order, const std::string& method_name, bool json) {
  const auto cell = element_type_from_name(cell_name);
  if (!cell || *cell == ElementType::tet20) {
    throw InputError(
        input_message("command line", "--cell", "expected hex8, hex20, hex27, tet4 or tet10, got '" + cell_name + "'"));
  }
  if (order < 1 || order > 20) {
    throw InputError(input_message("command line", "--order", "expected 1..20, got " + std::to_string(order)));
  }
  const SimplificationMethod method = parse_simplification_method(method_name);
  nlohmann::json rows = nlohmann::json::array();
  if (!json) {
    std::printf("%-6s %2s %4s %8s %8s %10s %10s %10s %10s %10s %6s %9s %9s\n", "cell", "m", "M", "initial", "final",
                "init max", "init med", "simp max", "simp med", "min w", "inside", "gen s", "simp s");
  }
  for (int m = 1; m <= order; ++m) {
    const fcm::MonomialExperiment e = fcm::run_monomial_experiment(*cell, m, method);
    if (json) {
      rows.push_back(
          {{"cell", cell_name},
           {"order", m},
           {"basis_size", e.basis_size},
           {"method", std::string(simplification_method_name(method))},
           {"initial", accuracy_json(e.initial)},
           {"simplified", accuracy_json(e.simplified)},
           {"residual", e.residual},
           {"simplification_failed", e.simplification_failed},
           {"timings_s", {{"generation", e.generation_seconds}, {"simplification", e.simplification_seconds}}}});
    } else {
      std::printf("%-6s %2d %4d %8lld %8lld %10.2e %10.2e %10.2e %10.2e %10.2e %6s %9.2e %9.2e%s\n", cell_name.c_str(),
                  m, e.basis_size, static_cast<long long>(e.initial.points),
                  static_cast<long long>(e.simplified.points), e.initial.max_relative_error,
                  e.initial.median_relative_error, e.simplified.max_relative_error, e.simplified.median_relative_error,
                  e.simplified.min_weight, e.initial.inside && e.simplified.inside ? "yes" : "no", e.generation_seconds,
                  e.simplification_seconds, e.simplification_failed ? "  (simplification failed: kept)" : "");
    }
  }
  if (json) std::printf("%s\n", rows.dump(2).c_str());
  return exit_ok;
}

SimplificationMethod parse_simplification_method(const std::string& name) {
  if (name == "lp") return SimplificationMethod::linear_program;
  if (name == "nnls") return SimplificationMethod::nonnegative_least_squares;
  if (name == "caratheodory") return SimplificationMethod::caratheodory;
  throw InputError(
      input_message("command line", "--simplifier", "expected caratheodory, nnls or lp, got '" + name + "'"));
}

}  // namespace altfem::cli
