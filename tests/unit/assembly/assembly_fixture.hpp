#pragma once
// Small distorted meshes, tabulated, with a material and a random displacement: what
// the assembly tests differentiate, project and compare across thread counts.
#include <memory>
#include <random>

#include "shared/assembly/elastic_assembler.hpp"
#include "shared/fem/tabulate_lagrange.hpp"
#include "shared/material/material.hpp"
#include "tests/unit/fem/test_meshes.hpp"

namespace altfem::test {

struct AssemblyProblem {
  VolumeMesh mesh;
  TabulatedElements elements;
  std::unique_ptr<Material> material;
  std::unique_ptr<ElasticAssembler> assembler;  // refers to elements and material
  double cell_size;

  AssemblyProblem(ElementType type, const Eigen::Vector3i& resolution, MaterialModel model, double density = 1000)
      : mesh(distorted_grid(unit_cube(), resolution, type, 0.15, 17)),
        elements(tabulate_lagrange(mesh, 2 * element_degree(type))),
        material(make_material(model, 1e4, 0.35, density)),
        assembler(std::make_unique<ElasticAssembler>(elements, std::vector<const Material*>{material.get()})),
        cell_size(1.0 / resolution.maxCoeff()) {}

  /// u = (G − I) X + noise: a homogeneous deformation G plus per-DOF noise of
  /// `noise` × the cell size, so that F differs from point to point.
  Eigen::VectorXd displacement(const Eigen::Matrix3d& G, double noise, unsigned seed) const {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Eigen::VectorXd u = nodal_values(
        mesh, [&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return (G - Eigen::Matrix3d::Identity()) * x; });
    for (Eigen::Index i = 0; i < u.size(); ++i) u[i] += noise * cell_size * uniform(random);
    return u;
  }
};

/// Central differences of an assembler's energy (→ gradient) and gradient (→ Hessian)
/// at u, one unknown at a time: #dofs and #dofs × #dofs.
struct FiniteDifferences {
  Eigen::VectorXd gradient;
  Eigen::MatrixXd hessian;
};

inline FiniteDifferences central_differences(const ElasticAssembler& assembler, const Eigen::VectorXd& u, double step) {
  FiniteDifferences differences{Eigen::VectorXd(u.size()), Eigen::MatrixXd(u.size(), u.size())};
  Eigen::VectorXd shifted = u, plus, minus;
  for (Eigen::Index i = 0; i < u.size(); ++i) {
    shifted[i] = u[i] + step;
    const double energy_plus = assembler.energy(shifted);
    assembler.gradient(shifted, plus);
    shifted[i] = u[i] - step;
    const double energy_minus = assembler.energy(shifted);
    assembler.gradient(shifted, minus);
    shifted[i] = u[i];
    differences.gradient[i] = (energy_plus - energy_minus) / (2 * step);
    differences.hessian.col(i) = (plus - minus) / (2 * step);
  }
  return differences;
}

/// A moderate stretch with shear: well inside every model's domain (det G ≈ 1.1).
inline Eigen::Matrix3d moderate_deformation() {
  Eigen::Matrix3d G;
  G << 1.1, 0.05, -0.03, 0.02, 0.95, 0.04, -0.05, 0.03, 1.05;
  return G;
}

}  // namespace altfem::test
