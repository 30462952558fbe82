#pragma once
// What a method builds for one scene, and what the run driver needs from it: the
// discretization, output of its mesh, and the embedded surface every method deforms
// (docs/conventions.md, "Metrics": methods are compared on the same surface vertices).
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "shared/io/unstructured_grid.hpp"
#include "shared/mesh/surface_mesh.hpp"
#include "shared/scene/method_scene_block.hpp"
#include "shared/scene/scene.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/simulation/basis_embedding.hpp"
#include "shared/simulation/field_quadrature.hpp"
#include "shared/simulation/mesh_preview.hpp"
#include "shared/simulation/method_mesh.hpp"
#include "shared/simulation/prescribed_traction.hpp"
#include "shared/simulation/surface_lift.hpp"
#include "shared/solve/discretization.hpp"

namespace altfem {

class MethodInstance {
public:
  virtual ~MethodInstance() = default;

  virtual const Discretization& discretization() const = 0;
  /// Element counts by kind, e.g. {"tet10": 1234}.
  virtual nlohmann::json element_counts() const = 0;
  virtual long long quadrature_points() const = 0;
  /// Seconds spent generating quadrature (tabulation), part of set-up.
  virtual double quadrature_seconds() const = 0;
  /// The method's mesh at rest with the displacement u as point data "displacement".
  virtual UnstructuredGrid volume_grid(const Eigen::VectorXd& displacement) const = 0;
  /// The embedded surface at rest (the scene's surface, or the mesh boundary).
  virtual const SurfaceMesh& embedded_surface() const = 0;
  /// The basis of the method's elements at any point: what the embedded surface and the
  /// surface loads (surface_traction.hpp) are evaluated through.
  virtual const ElementBasisEvaluator& basis_evaluator() const = 0;
  /// The surface that surface loads act on: the boundary of the domain the method
  /// integrates (fem: its mesh's, lifted to the curved faces; fcm: its embedded
  /// tetrahedra's; dg, harmonic: their mesh's), so that a traction σ(u*)·n written with
  /// the surface's normals makes u* exact on that domain; the embedded surface by default.
  virtual const SurfaceMesh& load_surface() const { return embedded_surface(); }
  /// The curved surface the load surface's triangles stand for, when they only
  /// approximate the method's boundary (fem on a curved Lagrange mesh); empty when the
  /// triangles are the surface. Surface loads are integrated on it.
  virtual SurfaceLift surface_lift() const { return {}; }
  /// Displacement of every embedded surface vertex (#vertices × 3).
  virtual Eigen::MatrixXd embedded_displacement(const Eigen::VectorXd& displacement) const = 0;
  /// Once the embedding of the surface's vertices is built (a method builds it on first
  /// use: after an event, in the first surface frame): {"seconds": what it took,
  /// "vertices_relocated": the vertices located in the mesh}; null before.
  virtual nlohmann::json surface_embedding_report() const { return nullptr; }
  /// Called on the instance an event rebuilt, with the one before it (alive until this
  /// returns): lets the embedding of the surface keep what the event left alone.
  virtual void continue_embedding(const MethodInstance& /*previous*/) {}
  /// Called on the instance a cut rebuilt, before its surface is embedded, with the
  /// scene's common surface cut by the same blade: a method that deforms the common
  /// surface (not its mesh's own) deforms this one. The rebuild runs beside the surface's
  /// cut (Simulation::cut), so it was built with the surface from before.
  virtual void adopt_cut_surface(const SurfaceMesh& /*surface*/) {}
  /// The coefficients (#dofs) of a vector field in the method's basis: exact for affine
  /// fields, which every method's basis reproduces (initial velocities, the patch and
  /// rigid-motion tests of the conformance suite).
  virtual Eigen::VectorXd interpolate(const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& field) const = 0;
  /// The basis at the points of a volume rule over the method's domain, with their
  /// positions: the method's own stiffness rule for `added_strength` 0 (body-force loads),
  /// a rule of that much higher strength where the method can (field errors). nullopt
  /// when the method cannot tabulate its basis at points.
  virtual std::optional<FieldQuadrature> field_quadrature(int /*added_strength*/) const { return std::nullopt; }
  /// What the method was built on, for an event to hand back to its rebuild (the
  /// MethodDescription's); null for a method that cannot rebuild.
  virtual std::shared_ptr<const MethodMesh> mesh() const { return nullptr; }
  /// What in the method's settings may have caused a numerical failure of the run (exit 3):
  /// "; " and a clause the message ends with, naming the key that helps; empty for none.
  virtual std::string failure_hint() const { return ""; }
  /// Why this instance cannot be cut by a scene's `cut` event (one phrase); empty when
  /// it can. Asked before the run writes anything, so a refusal is bad input.
  virtual std::string cut_refusal() const { return "it does not cut yet (dg, harmonic and fcm do)"; }
  /// mesh() cut by the blade of the `cut` event in the rest configuration
  /// (docs/architecture.md, "Events"), for the rebuild; `facts` receives what the cut did
  /// (counts). Only where cut_refusal() is empty.
  virtual std::shared_ptr<const MethodMesh> cut_mesh(const SceneEvent& /*cut*/, nlohmann::json& /*facts*/) const {
    throw std::logic_error("this method cannot cut");
  }
  /// Why this instance cannot be refined by a scene's `refine` event of these options (one
  /// phrase); empty when it can. Asked before the run writes anything.
  virtual std::string refine_refusal(const RefineSpec& /*refine*/) const {
    return "it does not refine yet (dg, harmonic, and fem and fcm on hexahedral grids do)";
  }
  /// mesh() with the cells the `refine` event marks, for the displacement u (#dofs), split
  /// (docs/architecture.md, "Events"), for the rebuild; null when it marks none. The error
  /// indicator's boundary residuals take their tractions from `boundary`. `facts` receives
  /// what it did (counts). Only where refine_refusal() is empty.
  virtual std::shared_ptr<const MethodMesh> refine_mesh(const SceneEvent& /*refine*/,
                                                        const Eigen::VectorXd& /*displacement*/,
                                                        const PrescribedTraction& /*boundary*/,
                                                        nlohmann::json& /*facts*/) const {
    throw std::logic_error("this method cannot refine");
  }
  /// Fields of `previous` — an instance of the same method before an event, their
  /// coefficients the columns of `fields` (#dofs of previous × #fields: the displacement,
  /// the velocity) — as coefficients in this basis (#dofs × #fields; docs/architecture.md,
  /// "Events"): nodal bases evaluate the old fields at their nodes, and a node that did
  /// not move keeps its values bit for bit; DG restricts each parent polynomial to its
  /// children. The fields share one location of the new nodes or points in the old
  /// mesh. Only methods with a rebuild implement it.
  virtual Eigen::MatrixXd transfer(const MethodInstance& /*previous*/, const Eigen::MatrixXd& /*fields*/) const {
    throw std::logic_error("this method cannot transfer a field from an earlier discretization");
  }
  /// ∫ dV over the domain the method integrates (what events must conserve): by default
  /// the weights of field_quadrature(0); nullopt for a method without it.
  virtual std::optional<double> volume() const;
  /// Method-specific facts for summary.json (e.g. embedding distances).
  virtual nlohmann::json facts() const { return nlohmann::json::object(); }
  /// What the user should know about this discretization of the scene (one line each),
  /// printed by `run` and kept in summary.json's `warnings`.
  virtual std::vector<std::string> warnings() const { return {}; }
};

using MethodFactory = std::function<std::unique_ptr<MethodInstance>(const Scene&, const SceneGeometry&)>;
/// The method built on a mesh it is handed (MethodInstance::mesh(), changed or not by an
/// event) instead of the one it would make of the scene.
using MethodRebuilder =
    std::function<std::unique_ptr<MethodInstance>(const Scene&, const SceneGeometry&, const MethodMesh&)>;

/// The rebuild of a method whose constructor takes (scene, geometry, const Mesh* handed):
/// the handed MethodMesh read back as its Mesh.
template <class Method, class Mesh>
MethodRebuilder rebuild_on_handed_mesh(const char* method_name) {
  return [method_name](const Scene& scene, const SceneGeometry& geometry,
                       const MethodMesh& mesh) -> std::unique_ptr<MethodInstance> {
    return std::make_unique<Method>(scene, geometry, &method_mesh_as<Mesh>(mesh, method_name));
  };
}

/// The method's mesh as `altfem mesh` shows it (mesh_preview.hpp); throws InputError for
/// options the method does not have (a source it cannot build).
using MeshPreviewBuilder = std::function<MeshPreview(const Scene&, const SceneGeometry&, const MeshPreviewOptions&)>;

/// What a method registers (app/method_registry.cpp): its scene block, its factory,
/// one line for `altfem info`, its rebuild from a mesh (events that change the mesh) and
/// its mesh preview.
struct MethodDescription {
  MethodSceneBlock scene_block;
  MethodFactory factory;
  std::string_view summary;
  MethodRebuilder rebuild = {};
  MeshPreviewBuilder mesh_preview = {};
};

}  // namespace altfem
