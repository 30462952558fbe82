// `altfem quadrature conditioning`: the experiment of Longva et al. 2020, §5.4 (Fig. 5),
// one row per smallest volume fraction, with and without quadrature stabilisation, and
// with the face ghost penalty instead (no stabilisation: no added points).
#include <cstdio>
#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "fcm/conditioning_experiment.hpp"
#include "shared/common/error.hpp"

namespace altfem::cli {

namespace {

struct Remedy {
  double stabilization, ghost_penalty;
};

}  // namespace

int quadrature_conditioning_command(const std::string& cell_name, double ghost_penalty, bool json) {
  const auto cell = element_type_from_name(cell_name);
  if (!cell || *cell == ElementType::tet20 || *cell == ElementType::hex27)
    throw InputError(
        input_message("command line", "--cell", "expected tet4, tet10, hex8 or hex20, got '" + cell_name + "'"));
  // The paper's fractions 2^-k (Fig. 5).
  const std::vector<int> exponents{0, 1, 2, 3, 4, 8, 12, 16, 24, 30};
  nlohmann::json rows = nlohmann::json::array();
  for (const Remedy remedy : {Remedy{0.0, 0.0}, Remedy{1e-6, 0.0}, Remedy{0.0, ghost_penalty}}) {
    if (!json)
      std::printf(
          "%s, stabilisation %g, ghost penalty %g: kappa(SA) and PCG iterations to 1e-8\n"
          "%12s %11s %11s %11s %6s %6s %6s\n",
          cell_name.c_str(), remedy.stabilization, remedy.ghost_penalty, "fraction", "none", "Jacobi", "Schwarz",
          "none", "Jacobi", "Schwarz");
    for (const fcm::ConditioningRow& row :
         fcm::conditioning_experiment(*cell, exponents, remedy.stabilization, remedy.ghost_penalty)) {
      if (json) {
        rows.push_back({{"cell", cell_name},
                        {"stabilization", remedy.stabilization},
                        {"ghost_penalty", remedy.ghost_penalty},
                        {"volume_fraction", row.volume_fraction},
                        {"condition_number", {{"none", row.none}, {"jacobi", row.jacobi}, {"schwarz", row.schwarz}}},
                        {"pcg_iterations",
                         {{"none", row.none_iterations},
                          {"jacobi", row.jacobi_iterations},
                          {"schwarz", row.schwarz_iterations}}}});
      } else {
        std::printf("%12.3e %11.3e %11.3e %11.3e %6d %6d %6d\n", row.volume_fraction, row.none, row.jacobi, row.schwarz,
                    row.none_iterations, row.jacobi_iterations, row.schwarz_iterations);
      }
    }
  }
  if (json) std::printf("%s\n", rows.dump(2).c_str());
  return exit_ok;
}

}  // namespace altfem::cli
