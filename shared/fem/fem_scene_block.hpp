#pragma once
// The `fem` block of a scene (docs/scene-schema.md, "fem"): its rules, the defaults
// that depend on the geometry, and the plain options the fem method reads.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "shared/element/element_type.hpp"
#include "shared/scene/method_scene_block.hpp"

namespace altfem {

enum class FemMeshKind { grid, tetrahedralize, file };
inline constexpr std::array<std::string_view, 3> fem_mesh_names{"grid", "tetrahedralize", "file"};

struct FemSpec {
  ElementType element = ElementType::tet10;  ///< a mesh file's own element by default
  FemMeshKind mesh = FemMeshKind::tetrahedralize;
  Eigen::Vector3i resolution = Eigen::Vector3i::Constant(4);  ///< grid only
  /// tetrahedralize only; nullopt (a surface geometry) means the loaded surface's
  /// bounding-box diagonal / 15 — see fem_max_cell_size.
  std::optional<double> max_cell_size;
  int quadrature_order = 4;
  bool curved = false;
  /// After a cut: α of the cut elements' pieces, each integrated also over its whole
  /// element with weights × α (fcm's quadrature stabilisation, Longva et al. 2020 §5.3);
  /// 0: every piece exact, however small.
  double cut_stabilization = 0;
  /// The block these options come from, for messages (e.g. max_cell_size's key).
  std::string pointer = "/discretization/fem";
};

const MethodSceneBlock& fem_scene_block();

/// The resolved /discretization/fem of `scene` as options. Throws InputError for a bad block.
FemSpec fem_spec(const Scene& scene);
/// The options of a block already resolved by fem_scene_block() (rule and complete), e.g.
/// the volume mesh the harmonic method converts (discretization.harmonic.convert).
FemSpec fem_spec_from_block(const nlohmann::json& fem);

/// max_cell_size, or the default diagonal / 15 of the loaded geometry's bounds.
double fem_max_cell_size(const FemSpec& fem, const Eigen::AlignedBox3d& geometry_bounds);

}  // namespace altfem
