#pragma once
// The material of dg's unit tests: Lamé parameters λ = 2, μ = 1.5, distinct so that a
// term with λ and μ exchanged fails its check.
namespace altfem::dg {

inline constexpr double lambda = 2.0, mu = 1.5;

}  // namespace altfem::dg
