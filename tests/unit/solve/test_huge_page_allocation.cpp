#include "shared/solve/huge_page_allocation.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
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

// The kernel's THP policy ("always [madvise] never"); empty when unknown.
std::string huge_page_policy() {
  std::ifstream policy_file("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string policy;
  std::getline(policy_file, policy);
  return policy;
}

// KiB of huge pages backing the mappings that overlap [block, block + bytes)
// (AnonHugePages in /proc/self/smaps).
long huge_page_kib(const void* block, std::size_t bytes) {
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
  return huge_kib;
}

// The point of the allocator: where the kernel grants huge pages on request, a
// touched large block is backed by them.
TEST(HugePageAllocation, KernelBacksLargeBlocksWithHugePages) {
  const std::string policy = huge_page_policy();
  if (policy.find("[never]") != std::string::npos || policy.empty())
    GTEST_SKIP() << "transparent huge pages are disabled on this machine";
  const std::size_t bytes = std::size_t{16} << 20;
  auto* block = static_cast<char*>(allocate_with_huge_pages(bytes));
  ASSERT_NE(block, nullptr);
  std::memset(block, 1, bytes);
  const long huge_kib = huge_page_kib(block, bytes);
  std::free(block);
  EXPECT_GE(huge_kib, 2048) << "no huge page backs a touched 16 MiB block (policy: " << policy << ")";
}

// Advice on memory another allocator owns (DG's sparse K): its whole huge pages inside
// the block are backed by huge pages once touched.
TEST(HugePageAllocation, AdvisedMallocBlocksGetHugePages) {
  const std::string policy = huge_page_policy();
  if (policy.find("[never]") != std::string::npos || policy.empty())
    GTEST_SKIP() << "transparent huge pages are disabled on this machine";
  const std::size_t bytes = std::size_t{16} << 20;
  auto* block = static_cast<char*>(std::malloc(bytes));  // not aligned to a huge page
  ASSERT_NE(block, nullptr);
  advise_huge_pages(block, bytes);
  std::memset(block, 1, bytes);
  const long huge_kib = huge_page_kib(block, bytes);
  EXPECT_EQ(block[bytes - 1], 1);
  std::free(block);
  EXPECT_GE(huge_kib, 2048) << "no huge page backs an advised 16 MiB block (policy: " << policy << ")";
  advise_huge_pages(nullptr, 100);  // below the threshold: nothing to do
}

}  // namespace
}  // namespace altfem
