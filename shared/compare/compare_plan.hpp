#pragma once
// What `altfem compare` runs: methods × the Cartesian product of the sweeps (or the union
// of several groups' products), plus a reference run (docs/scene-schema.md, "Compare"). Each configuration is an
// `altfem run` with `--set` overrides, so it is reproducible by hand.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "shared/scene/scene_override.hpp"

namespace altfem {

/// One swept key: a JSON pointer (leading '/') and the values it takes.
struct Sweep {
  std::string pointer;
  std::vector<nlohmann::json> values;
};

/// The reference run: a method and its overrides; nullopt in ComparePlan means
/// "the successful run with the most DOFs".
struct ReferenceSpec {
  std::string method;
  std::vector<SceneOverride> overrides;
};

/// Sweeps run as the Cartesian product of their values.
using SweepGroup = std::vector<Sweep>;

struct ComparePlan {
  std::vector<std::string> methods;
  /// The union of the groups' products: e.g. uniform resolutions in one group and adaptive
  /// refinement cycles in another, without running every resolution × every cycle count.
  std::vector<SweepGroup> sweeps;
  std::optional<ReferenceSpec> reference;
  /// The RMS error of the report's equal-accuracy table (nullopt: the report's default).
  std::optional<double> error;
};

struct Configuration {
  std::string method;
  std::vector<SceneOverride> overrides;  ///< in sweep order
  bool is_reference = false;
  /// Per override, its value named by the leaves that tell it from the sweep's other values
  /// ("cycles=4") when its JSON is long; "" (or missing) shows the value whole.
  std::vector<std::string> value_labels;
  /// "fem element=tet4 resolution=[10,1,1] events(cycles=4)": the method and the last token of
  /// each override with its value or, for a long one, its value label.
  std::string label() const;
};

/// Splits at `separator` outside brackets, braces and double quotes, so JSON values
/// with commas stay whole: "[1,2],[3,4]" → {"[1,2]", "[3,4]"}.
std::vector<std::string> split_top_level(std::string_view text, char separator);
/// "KEY=V1,V2,..." (each V as in SceneOverride). Throws InputError naming --sweep.
Sweep parse_sweep(std::string_view text);
/// "METHOD" or "METHOD:KEY=VALUE,KEY=VALUE". Throws InputError naming --reference.
ReferenceSpec parse_reference(std::string_view text);
/// The plan of a resolved scene's `compare` block (null or absent: every method, no sweep).
ComparePlan plan_from_scene(const nlohmann::json& compare_block, const std::vector<std::string>& available_methods);

/// Every method × every combination of each group's sweep values (the first sweep varies
/// slowest; the groups in order), then the reference. A configuration two groups both make
/// is listed twice: compare runs each resolved scene once (run_hash). A sweep pointer under /discretization/<m>/
/// applies to method m only, so other methods do not run once per value of a key they ignore.
std::vector<Configuration> expand_configurations(const ComparePlan& plan);

}  // namespace altfem
