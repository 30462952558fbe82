// OpenBLAS's generic kernels on a CPU that has AVX2 or AVX-512 are replaced by the right
// ones (blas_core_type.hpp); a core with such kernels, or a CPU without AVX2, is left alone.
#include "shared/solve/blas_core_type.hpp"

#include <gtest/gtest.h>

namespace altfem {
namespace {

TEST(BlasCoreType, AGenericCoreOnAnAvxCpuGetsTheWidestKernels) {
  EXPECT_EQ(better_openblas_core("Prescott", true, true), "SkylakeX");  // issue #35's Xeon
  EXPECT_EQ(better_openblas_core("Prescott", true, false), "Haswell");
  EXPECT_EQ(better_openblas_core("Nehalem", true, false), "Haswell");
  EXPECT_EQ(better_openblas_core("Sandybridge", true, true), "SkylakeX");
}

TEST(BlasCoreType, ARightChoiceOrAnOldCpuIsLeftAlone) {
  for (const char* core : {"Haswell", "SkylakeX", "Zen", "COOPERLAKE", "SapphireRapids", "Excavator"})
    EXPECT_EQ(better_openblas_core(core, true, true), "") << core;
  EXPECT_EQ(better_openblas_core("Prescott", false, false), "");
  EXPECT_EQ(better_openblas_core("", true, true), "");  // not OpenBLAS
}

}  // namespace
}  // namespace altfem
