#pragma once
// A cell's rule as bytes and back: the on-disk rule cache (rule_cache.cpp) and the ranks'
// exchange of the rules each computed (compute_cell_rules over several ranks) write the
// same fields.
#include "shared/cut_cells/cell_rules.hpp"
#include "shared/io/binary_cache.hpp"

namespace altfem {

/// Appends `cell` to `out`, its reduced rule included.
void write_cell_rule(BinaryWriter& out, const CellRule& cell);

/// Reads what write_cell_rule wrote into `cell`; false where it does not read back whole
/// and consistent.
bool read_cell_rule(BinaryReader& in, CellRule& cell);

}  // namespace altfem
