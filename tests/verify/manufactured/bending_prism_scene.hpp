#pragma once
// The harmonic method's manufactured problem on a sliced curved shape (issue 19), shared
// by verify_manufactured's convergence study and verify_harmonic_quadrature's rule table:
// a 48-sided prism of radius 1/2 and height 2 (a cylinder whose side facets are exactly
// vertical) in pure bending (Timoshenko & Goodier, §103):
// u* = (−κ/2 (z² + ν(x² − y²)), −κνxy, κxz) has σ = Eκx e_z⊗e_z, no body force and no
// traction on the sides, so u* on the two end faces is the whole problem.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

namespace altfem::test {

// The prism's closed, outward surface as OFF in `folder`: `sides` vertical rectangles (two
// triangles each) and two triangle fans closing the ends at z = 0 and z = height.
inline std::filesystem::path write_prism(const std::filesystem::path& folder, int sides, double radius, double height) {
  std::filesystem::create_directories(folder);
  const std::filesystem::path file = folder / "bending_prism.off";
  std::ofstream out(file);
  out.precision(17);
  out << "OFF\n" << 2 * sides + 2 << " " << 4 * sides << " 0\n";
  for (int level = 0; level < 2; ++level)
    for (int i = 0; i < sides; ++i) {
      const double angle = 2 * std::numbers::pi * i / sides;
      out << radius * std::cos(angle) << " " << radius * std::sin(angle) << " " << level * height << "\n";
    }
  const int bottom_centre = 2 * sides, top_centre = 2 * sides + 1;
  out << "0 0 0\n0 0 " << height << "\n";
  for (int i = 0; i < sides; ++i) {
    const int next = (i + 1) % sides;
    out << "3 " << i << " " << next << " " << sides + next << "\n";
    out << "3 " << i << " " << sides + next << " " << sides + i << "\n";
    out << "3 " << bottom_centre << " " << next << " " << i << "\n";
    out << "3 " << top_centre << " " << sides + i << " " << sides + next << "\n";
  }
  return file;
}

/// The scene file (written to `folder`, with its surface): harmonic on mesh `slice`.
inline std::filesystem::path write_bending_scene(const std::filesystem::path& folder) {
  const std::filesystem::path surface = write_prism(folder, 48, 0.5, 2.0);
  const std::filesystem::path file = folder / "bending_prism.json";
  const std::string field =
      R"json("motion": { "kind": "field", "displacement": ["-kappa/2*(z^2 + nu*(x^2 - y^2))", "-kappa*nu*x*y", "kappa*x*z"] })json";
  std::ofstream(file) << R"json({
  "name": "bending_prism",
  "geometry": { "surface": ")json"
                      << surface.string() << R"json(" },
  "material": { "model": "linear", "youngs_modulus": 26, "poisson_ratio": 0.3, "density": 1 },
  "constants": { "kappa": 0.01, "nu": 0.3 },
  "boundary_conditions": [
    { "type": "dirichlet", "region": { "half_space": { "point": [0, 0, 0], "normal": [0, 0, 1] } }, )json"
                      << field << R"json( },
    { "type": "dirichlet", "region": { "half_space": { "point": [0, 0, 2], "normal": [0, 0, -1] } }, )json"
                      << field << R"json( }
  ],
  "exact_displacement": ["-kappa/2*(z^2 + nu*(x^2 - y^2))", "-kappa*nu*x*y", "kappa*x*z"],
  "solver": { "tolerance": 1e-10 },
  "discretization": { "harmonic": { "mesh": "slice" } },
  "output": { "volume": false, "surface": false }
})json";
  return file;
}

}  // namespace altfem::test
