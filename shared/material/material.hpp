#pragma once
// Hyperelastic material models: strain-energy density ψ(F) per unit reference
// volume, first Piola–Kirchhoff stress P = ∂ψ/∂F and its tangent ∂P/∂F.
//
// Called by the assembly kernel at every quadrature point, so every model is
// closed form on fixed-size Eigen types and never allocates.
//
// Contract for every finite F (the assembler relies on it):
//   - energy(F) is finite, or +infinity where the model is undefined (Neo-Hookean
//     at det F ≤ 0) or where the result overflows double;
//   - P and dP/dF are either entirely finite or entirely +infinity (same cases);
//   - nothing is ever NaN.
#include <Eigen/Core>
#include <array>
#include <memory>
#include <optional>
#include <string_view>

#include "shared/material/lame_parameters.hpp"

namespace altfem {

/// 9 × 9 tangent: dPdF(i + 3j, k + 3l) = ∂P_ij / ∂F_kl, i.e. the derivative of
/// the column-major vec(P) (Eigen's storage order) with respect to vec(F).
using Matrix9d = Eigen::Matrix<double, 9, 9>;

enum class MaterialModel { linear, corotated_linear, st_venant_kirchhoff, neo_hookean, stable_neo_hookean };

inline constexpr std::array<MaterialModel, 5> all_material_models = {
    MaterialModel::linear, MaterialModel::corotated_linear, MaterialModel::st_venant_kirchhoff,
    MaterialModel::neo_hookean, MaterialModel::stable_neo_hookean};

/// "linear", "corotated_linear", "st_venant_kirchhoff", "neo_hookean", "stable_neo_hookean"
/// (the scene file's material.model values).
std::string_view material_model_name(MaterialModel model);
/// The inverse of material_model_name; nullopt for an unknown name.
std::optional<MaterialModel> material_model_from_name(std::string_view name);
/// Whether the model stays well posed through element inversion: Neo-Hookean's energy
/// grows without bound as J → 0⁺, Stable Neo-Hookean's is smooth through J ≤ 0. The
/// others (linear, corotated_linear, St. Venant–Kirchhoff) have no barrier: crushed past
/// 100 % strain, an element can invert and Newton stalls at the energy's kink.
constexpr bool resists_inversion(MaterialModel model) {
  return model == MaterialModel::neo_hookean || model == MaterialModel::stable_neo_hookean;
}

class Material {
public:
  virtual ~Material() = default;

  /// A model is written in the displacement gradient G = ∂u/∂X (F = I + G), which the
  /// assembler computes: forming I + G rounds away G's digits below ε, a relative error
  /// ε / |G| in the strain (a 1 µm cube under gravity has |G| ~ 1e-11: 1e-5, more than
  /// Newton's tolerance), so the models work from G (corotated_linear alone forms F).
  /// ψ(I + G) [J/m³], zero at G = 0.
  virtual double energy_at(const Eigen::Matrix3d& G) const = 0;
  /// P = ∂ψ/∂F at F = I + G (3 × 3).
  virtual Eigen::Matrix3d pk1_at(const Eigen::Matrix3d& G) const = 0;
  /// P (3 × 3) and dPdF (9 × 9, symmetric, see Matrix9d) together, sharing work.
  virtual void pk1_and_tangent_at(const Eigen::Matrix3d& G, Eigen::Matrix3d& P, Matrix9d& dPdF) const = 0;
  /// The same three of the deformation gradient F (G = F − I is exact where F's entries
  /// are near those of I), for callers that hold F.
  double energy(const Eigen::Matrix3d& F) const { return energy_at(F - Eigen::Matrix3d::Identity()); }
  Eigen::Matrix3d pk1(const Eigen::Matrix3d& F) const { return pk1_at(F - Eigen::Matrix3d::Identity()); }
  void pk1_and_tangent(const Eigen::Matrix3d& F, Eigen::Matrix3d& P, Matrix9d& dPdF) const {
    pk1_and_tangent_at(F - Eigen::Matrix3d::Identity(), P, dPdF);
  }
  /// True when dP/dF does not depend on F (only the linear model): the stiffness
  /// matrix can be assembled and factorised once.
  virtual bool is_linear() const { return false; }

  MaterialModel model() const { return model_; }
  /// The small-strain Lamé parameters from (E, ν); a model may use others
  /// internally (stable Neo-Hookean reparametrises them to match these).
  LameParameters lame() const { return lame_; }
  /// Mass density [kg/m³].
  double density() const { return density_; }

protected:
  Material(MaterialModel model, LameParameters lame, double density);

  /// The contract above: a non-finite energy becomes +infinity, a P or dP/dF
  /// with any non-finite entry becomes entirely +infinity.
  static double infinite_unless_finite(double energy);
  static void infinite_unless_finite(Eigen::Matrix3d& P);
  static void infinite_unless_finite(Eigen::Matrix3d& P, Matrix9d& dPdF);

private:
  MaterialModel model_;
  LameParameters lame_;
  double density_;
};

/// The model with Lamé parameters from (E [Pa], ν); throws InputError for E ≤ 0,
/// ν outside (−1, 1/2) or a negative or non-finite density.
std::unique_ptr<Material> make_material(MaterialModel model, double youngs_modulus, double poisson_ratio,
                                        double density);

}  // namespace altfem
