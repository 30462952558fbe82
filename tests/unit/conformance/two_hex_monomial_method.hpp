#pragma once
// A test-only method built from the shared parts (issue #14): it shows that a basis
// that is neither Lagrange nor conforming runs the whole path — load vector, sparsity
// with face couplings, face terms, weak conditions, embedding, output — and it passes
// the conformance suite like every shipped method.
//
// The scene geometry's bounding box is split at mid-x into two hexahedra. Each carries
// the degree-1 monomials 1, (x−c)/h, (y−c)/h, (z−c)/h about its centre c (h: its
// largest side): 4 functions, 12 DOFs. The halves are coupled across the middle face
// by a jump penalty η_f/2 ∫|[[u]]|² (the Babuška–Zlámal flux, Kaufmann et al. 2009
// eq. (19)) with η_f = η·E·area·(1/vol⁻ + 1/vol⁺) (eq. (20)), and each Dirichlet
// condition is imposed weakly by the same penalty on the box faces its region holds.
#include <memory>

#include "shared/simulation/method_instance.hpp"

namespace altfem::test {

std::unique_ptr<MethodInstance> make_two_hex_monomial_method(const Scene& scene, const SceneGeometry& geometry);

}  // namespace altfem::test
