#include "shared/solve/huge_page_allocation.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

namespace altfem {
namespace {

TEST(HugePageAllocation, SmallBlocksAreOrdinaryMallocMemory) {
  void* block = allocate_with_huge_pages(100);
  ASSERT_NE(block, nullptr);
  std::memset(block, 1, 100);
  block = std::realloc(block, 200);  // malloc-compatible: CHOLMOD reallocates with std::realloc
  ASSERT_NE(block, nullptr);
  EXPECT_EQ(static_cast<unsigned char*>(block)[99], 1);
  std::free(block);
}

TEST(HugePageAllocation, LargeBlocksAreAlignedToHugePages) {
  const std::size_t bytes = huge_page_threshold_bytes + 12345;
  void* block = allocate_with_huge_pages(bytes);
  ASSERT_NE(block, nullptr);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(block) % (std::size_t{2} << 20), 0u);
  std::memset(block, 7, bytes);
  EXPECT_EQ(static_cast<unsigned char*>(block)[bytes - 1], 7);
  std::free(block);
}

TEST(HugePageAllocation, ZeroedBlocksAreZero) {
  for (std::size_t count : {std::size_t{10}, huge_page_threshold_bytes / 8 + 3}) {
    auto* values = static_cast<double*>(allocate_zeroed_with_huge_pages(count, sizeof(double)));
    ASSERT_NE(values, nullptr);
    for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(values[i], 0.0) << i;
    std::free(values);
  }
}

TEST(HugePageAllocation, OverflowingSizeIsRefused) {
  EXPECT_EQ(allocate_zeroed_with_huge_pages(std::numeric_limits<std::size_t>::max() / 2, 4), nullptr);
}

// The point of the allocator: where the kernel grants huge pages on request, a
// touched large block is backed by them (AnonHugePages in /proc/self/smaps).
TEST(HugePageAllocation, KernelBacksLargeBlocksWithHugePages) {
  std::ifstream policy_file("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string policy;
  std::getline(policy_file, policy);
  if (policy.find("[never]") != std::string::npos || policy.empty())
    GTEST_SKIP() << "transparent huge pages are disabled on this machine";
  const std::size_t bytes = std::size_t{16} << 20;
  auto* block = static_cast<char*>(allocate_with_huge_pages(bytes));
  ASSERT_NE(block, nullptr);
  std::memset(block, 1, bytes);
  const auto start = reinterpret_cast<std::uintptr_t>(block);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  long huge_kib = 0;
  while (std::getline(smaps, line)) {
    std::uintptr_t from = 0, to = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> from >> dash >> to && dash == '-') {
      inside = from < start + bytes && start < to;
      continue;
    }
    long kib = 0;
    if (inside && std::sscanf(line.c_str(), "AnonHugePages: %ld kB", &kib) == 1) huge_kib += kib;
  }
  std::free(block);
  EXPECT_GE(huge_kib, 2048) << "no huge page backs a touched 16 MiB block (policy: " << policy << ")";
}

}  // namespace
}  // namespace altfem
