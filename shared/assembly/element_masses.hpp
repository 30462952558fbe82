#pragma once
// What the mass matrix, the lumped mass and the body-force loads need of a mass rule,
// per element and without density: the scalar mass matrix ∫ φ_a φ_b dV, the integrals
// ∫ φ_a dV and the volume. A method whose mass rules are large and used once (the
// FCM's unsimplified cut-cell mass rules, Longva et al. 2020 §6) reduces them cell by
// cell to this, instead of keeping their tabulation for the whole run.
#include <Eigen/Core>
#include <vector>

#include "shared/assembly/tabulated_elements.hpp"

namespace altfem {

struct ElementMasses {
  std::vector<Eigen::MatrixXd> matrices;   ///< per element, #basis × #basis: Σ_q w_q φ_a(x_q) φ_b(x_q)
  std::vector<Eigen::VectorXd> integrals;  ///< per element, #basis: Σ_q w_q φ_a(x_q)
  std::vector<double> volumes;             ///< per element: Σ_q w_q

  int size() const { return static_cast<int>(volumes.size()); }
  /// Appends the reduction of every element of `elements` (in parallel over elements); an
  /// element another rank holds (TabulatedElements::holds) gets empty entries and volume 0.
  void append(const TabulatedElements& elements);
};

/// The reduction of `elements`, one entry per element in order.
ElementMasses element_masses(const TabulatedElements& elements);

}  // namespace altfem
