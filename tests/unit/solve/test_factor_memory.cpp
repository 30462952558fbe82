// A factor that does not fit is refused before it is computed, with the sizes and the
// scene key to change (factor_memory.hpp).
#include "shared/solve/factor_memory.hpp"

#include <gtest/gtest.h>

#include "shared/common/error.hpp"

namespace altfem {
namespace {

TEST(FactorMemory, AFactorLargerThanTheAvailableMemoryIsRefusedWithTheKeyToChange) {
  try {
    require_factor_fits(1e9, 8e9, 4e9);
    FAIL() << "expected NumericalError";
  } catch (const NumericalError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("8.0 GB (1e+09 entries)"), std::string::npos) << message;
    EXPECT_NE(message.find("the 4.0 GB of memory available"), std::string::npos) << message;
    EXPECT_NE(message.find("solver.linear"), std::string::npos) << message;
  }
}

TEST(FactorMemory, AFactorThatFitsOrAnUnknownMemoryPasses) {
  EXPECT_NO_THROW(require_factor_fits(1e9, 8e9, 8e9));
  EXPECT_NO_THROW(require_factor_fits(1e9, 8e9, 0));  // /proc/meminfo unreadable
}

TEST(FactorMemory, ReadsTheAvailableMemory) { EXPECT_GT(available_memory_bytes(), 0); }

}  // namespace
}  // namespace altfem
