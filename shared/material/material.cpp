#include "shared/material/material.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <string>

#include "shared/common/error.hpp"
#include "shared/material/corotated_linear.hpp"
#include "shared/material/linear_elastic.hpp"
#include "shared/material/neo_hookean.hpp"
#include "shared/material/st_venant_kirchhoff.hpp"
#include "shared/material/stable_neo_hookean.hpp"

namespace altfem {

std::string_view material_model_name(MaterialModel model) {
  switch (model) {
    case MaterialModel::linear: return "linear";
    case MaterialModel::corotated_linear: return "corotated_linear";
    case MaterialModel::st_venant_kirchhoff: return "st_venant_kirchhoff";
    case MaterialModel::neo_hookean: return "neo_hookean";
    case MaterialModel::stable_neo_hookean: return "stable_neo_hookean";
  }
  return "unknown";
}

std::optional<MaterialModel> material_model_from_name(std::string_view name) {
  for (MaterialModel model : all_material_models) {
    if (material_model_name(model) == name) return model;
  }
  return std::nullopt;
}

Material::Material(MaterialModel model, LameParameters lame, double density)
    : model_(model), lame_(lame), density_(density) {}

double Material::infinite_unless_finite(double energy) {
  return std::isfinite(energy) ? energy : std::numeric_limits<double>::infinity();
}

void Material::infinite_unless_finite(Eigen::Matrix3d& P) {
  if (!P.allFinite()) P.setConstant(std::numeric_limits<double>::infinity());
}

void Material::infinite_unless_finite(Eigen::Matrix3d& P, Matrix9d& dPdF) {
  if (!P.allFinite() || !dPdF.allFinite()) {
    P.setConstant(std::numeric_limits<double>::infinity());
    dPdF.setConstant(std::numeric_limits<double>::infinity());
  }
}

std::unique_ptr<Material> make_material(MaterialModel model, double youngs_modulus, double poisson_ratio,
                                        double density) {
  const LameParameters lame = lame_parameters(youngs_modulus, poisson_ratio);
  // Zero is allowed: a static problem needs no mass.
  if (!(std::isfinite(density) && density >= 0.0)) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, density);
    throw InputError("material: density: expected a finite number >= 0, got " + std::string(buffer, result.ptr));
  }
  switch (model) {
    case MaterialModel::linear: return std::make_unique<LinearElastic>(lame, density);
    case MaterialModel::corotated_linear: return std::make_unique<CorotatedLinear>(lame, density);
    case MaterialModel::st_venant_kirchhoff: return std::make_unique<StVenantKirchhoff>(lame, density);
    case MaterialModel::neo_hookean: return std::make_unique<NeoHookean>(lame, density);
    case MaterialModel::stable_neo_hookean: return std::make_unique<StableNeoHookean>(lame, density);
  }
  throw std::logic_error("make_material: unhandled MaterialModel");
}

}  // namespace altfem
