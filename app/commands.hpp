#pragma once
// The `altfem` subcommands (docs/conventions.md, "Command line and outputs"). Each returns the
// process exit code; errors are thrown as InputError / NumericalError and turned into
// exit codes 2 / 3 by main.
#include <filesystem>
#include <string>
#include <vector>

#include "shared/quadrature/simplify_quadrature.hpp"

namespace altfem::cli {

int info_command();
int check_command(const std::filesystem::path& scene_file, const std::string& method, bool json);
/// Options of `altfem mesh` (main.cpp documents each).
struct MeshCommandOptions {
  std::string method;
  /// dg/harmonic: "" (the mesh the method's block names), "convert" (the fem mesh cell by
  /// cell) or "slice" (the geometry sliced by the grid of the flags below)
  std::string source;
  int resolution = 16;            ///< --source slice: grid cells along the bounding box's longest side
  double sliver_fraction = 1e-3;  ///< --source slice: pieces below this fraction of a cell are merged
  int octree_levels = 0;          ///< --source slice: inside cells joined up to 2^levels grid cells per side
  std::filesystem::path output_directory;
  bool json = false;
};
int mesh_command(const std::filesystem::path& scene_file, const MeshCommandOptions& options);
/// `overrides` are the --set KEY=VALUE assignments (docs/scene-schema.md, "Overrides").
int run_command(const std::filesystem::path& scene_file, const std::string& method,
                const std::filesystem::path& output_directory, const std::vector<std::string>& overrides);

/// `quadrature monomials`: Longva et al. 2020, §4.6 for strengths 1..order.
int quadrature_monomials_command(const std::string& cell, int order, const std::string& simplifier, bool json);
/// `quadrature conditioning`: Longva et al. 2020, §5.4 (Fig. 5) for one cell type, with
/// stabilisation 0 and 1e-6 (the paper's remedies) and, for comparison, the face ghost
/// penalty with γ = ghost_penalty and no stabilisation.
int quadrature_conditioning_command(const std::string& cell, double ghost_penalty, bool json);
/// γ of the ghost-penalty rows unless --ghost-penalty says otherwise: measured on Fig. 5
/// and the FreeBall convergence test (tests/verify/fcm), 0.01 bounds κ at 2^-30 (Hex8
/// 1.1e4, Hex20 1.6e6, Tet10 1.4e5 unpreconditioned) while costing Hex20 1.45× its L2
/// error (0.1: κ about 5× lower on Hex8, the Hex20 error 6× higher; 0.001: the error
/// unchanged, κ about 8× higher).
inline constexpr double default_conditioning_ghost_penalty = 0.01;
/// `quadrature cell`: the rules of one background cell of a scene, as VTU points.
int quadrature_cell_command(const std::filesystem::path& scene_file, const std::string& cell_index,
                            const std::string& cell_type, const std::string& resolution, int order,
                            const std::string& simplifier, const std::filesystem::path& output, bool json);
/// "caratheodory", "nnls" or "lp" (--simplifier); InputError otherwise.
SimplificationMethod parse_simplification_method(const std::string& name);

}  // namespace altfem::cli
