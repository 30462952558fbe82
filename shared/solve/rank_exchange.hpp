#pragma once
// Work divided among the ranks, its results on every rank (docs/scaling.md): each rank
// computes the items i with i mod count() = index() — ranks::computes_item — and
// exchange_items gives every rank the others'. harmonic's MFS fits, fcm's cell rules and
// pieces are shared out so.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "shared/io/binary_cache.hpp"
#include "shared/solve/process_ranks.hpp"

namespace altfem::ranks {

/// Whether this rank computes item `item` of a list shared out among the ranks.
inline bool computes_item(std::size_t item) {
  return item % static_cast<std::size_t>(count()) == static_cast<std::size_t>(index());
}

/// Over several ranks, every rank's items of `item_count` on every rank: `write(out, i)`
/// appends item i, which this rank computed, to a BinaryWriter; `read(in, i)` reads
/// another rank's item i back, false where it does not (a std::logic_error then). Every
/// rank calls it alike; on one rank it does nothing.
template <typename Write, typename Read>
void exchange_items(std::size_t item_count, std::string_view what, Write&& write, Read&& read) {
  if (!distributed()) return;
  BinaryWriter mine(what);
  for (std::size_t item = static_cast<std::size_t>(index()); item < item_count;
       item += static_cast<std::size_t>(count())) {
    mine.put<std::int64_t>(static_cast<std::int64_t>(item));
    write(mine, item);
  }
  const std::vector<std::string> all = gather(mine.bytes());
  for (int rank = 0; rank < count(); ++rank) {
    if (rank == index()) continue;
    BinaryReader theirs(all[static_cast<std::size_t>(rank)], what);
    while (const std::optional<std::int64_t> item = theirs.get<std::int64_t>())
      if (*item < 0 || static_cast<std::size_t>(*item) >= item_count || !read(theirs, static_cast<std::size_t>(*item)))
        throw std::logic_error(std::string(what) + ": a rank's items did not read back");
  }
}

}  // namespace altfem::ranks
