#pragma once
// What a method is built on, so that an event can hand it back (changed by a cut or a
// refinement, or not at all) and the method rebuilds on it instead of meshing the scene
// again (docs/architecture.md, "Events"). Each method decides what that is (fem: its
// elements; fcm: its background cells and embedded tetrahedra; dg and harmonic: the
// polyhedral mesh with the surfaces it deforms and loads), and only it reads it back.
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

namespace altfem {

class MethodMesh {
public:
  virtual ~MethodMesh() = default;
  /// Of the time the event took to make it, what went into elements ahead of the rebuild
  /// (harmonic fits a cut's new cells to check them, and the rebuild takes those fits): an
  /// event record counts it as integration, not geometry.
  double integration_seconds = 0;
};

/// A method's mesh of type T as a MethodMesh.
template <class T>
class MeshOf final : public MethodMesh {
public:
  explicit MeshOf(T value) : value_(std::move(value)) {}
  const T& value() const { return value_; }

private:
  T value_;
};

/// The T a method's own mesh() handed back holds; std::invalid_argument when it holds another.
template <class T>
const T& method_mesh_as(const MethodMesh& mesh, const char* method) {
  const auto* held = dynamic_cast<const MeshOf<T>*>(&mesh);
  if (!held) throw std::invalid_argument(std::string(method) + ": the handed mesh is not this method's");
  return held->value();
}

}  // namespace altfem
