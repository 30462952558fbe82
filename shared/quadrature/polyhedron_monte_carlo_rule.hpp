#pragma once
// Monte Carlo integration over a polyhedron (Martin et al. 2008, §6, the alternative to
// bounding-box subdivision): `count` points uniform in the polyhedron's axis-aligned
// bounding box, those inside it (generalised winding number > ½) kept, each weighted
// vol(box) / count. Unbiased; the error of an integral falls as O(1/√count) (its standard
// deviation vol(box) · sd(f·1_P) / √count), with no exactness for any polynomial.
#include <cstdint>

#include "shared/geometry/polyhedron.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"

namespace altfem {

/// The rule above, from std::mt19937_64(seed), so a run is reproducible. points:
/// #inside × 3; weights all vol(box) / count. Throws std::invalid_argument for a
/// polyhedron without faces or count < 1.
PolyhedronRule polyhedron_monte_carlo_rule(const Polyhedron& polyhedron, int count, std::uint64_t seed);

}  // namespace altfem
