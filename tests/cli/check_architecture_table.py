"""docs/architecture.md's library table against the CMake targets: every library that
an `altfem_library(NAME ... DEPENDS ...)` call builds (shared/*, fcm, dg, polyhedral) has
a row, and the row's "depends on" column names exactly its altfem_* dependencies.
Usage: check_architecture_table.py SOURCE_DIR. Exit code 0 when they agree."""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1])
built = {}
for cmake in root.glob("**/CMakeLists.txt"):
    if "build" in cmake.relative_to(root).parts[0]:
        continue
    for name, arguments in re.findall(r"altfem_library\((\w+)([^)]*)\)", cmake.read_text()):
        built[name] = set(re.findall(r"altfem_(\w+)", arguments.split("DEPENDS", 1)[1])) if "DEPENDS" in arguments else set()

documented = {}
for line in (root / "docs/architecture.md").read_text().splitlines():
    row = re.match(r"\|\s*`(altfem_\w+)`\s*\|[^|]*\|([^|]*)\|", line)
    if row:
        names = {name.strip() for name in row.group(2).split(",")} - {"—", ""}
        documented[row.group(1)] = names

# Only dependencies on altfem's own libraries count (not altfem_suitesparse, an import).
built = {name: dependencies & {other[len("altfem_"):] for other in built} for name, dependencies in built.items()}
failures = [f"{name}: built but not in the table" for name in built if name not in documented]
failures += [f"{name}: in the table but not built" for name in documented if name not in built]
failures += [f"{name}: the table says {sorted(documented[name])}, CMake says {sorted(built[name])}"
             for name in built if name in documented and documented[name] != built[name]]
for failure in failures:
    print(failure)
sys.exit(1 if failures else 0)
