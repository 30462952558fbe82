#include "shared/solve/huge_page_allocation.hpp"

#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace altfem {
namespace {
constexpr std::size_t huge_page_bytes = std::size_t{2} << 20;
}  // namespace

void* allocate_with_huge_pages(std::size_t bytes) {
  if (bytes < huge_page_threshold_bytes) return std::malloc(bytes);
  // Aligning the block to a huge page lets the kernel back all of it with huge
  // pages; posix_memalign memory is released by std::free like any other.
  void* block = nullptr;
  if (posix_memalign(&block, huge_page_bytes, bytes) != 0) return nullptr;
  const std::size_t rounded = (bytes + huge_page_bytes - 1) / huge_page_bytes * huge_page_bytes;
  madvise(block, rounded, MADV_HUGEPAGE);  // advice only: failure leaves ordinary pages
  return block;
}

void* allocate_zeroed_with_huge_pages(std::size_t count, std::size_t size) {
  if (size != 0 && count > std::numeric_limits<std::size_t>::max() / size) return nullptr;
  const std::size_t bytes = count * size;
  if (bytes < huge_page_threshold_bytes) return std::calloc(count, size);
  void* block = allocate_with_huge_pages(bytes);
  if (block != nullptr) std::memset(block, 0, bytes);
  return block;
}

void advise_huge_pages(void* block, std::size_t bytes) {
  if (bytes < huge_page_threshold_bytes) return;
  const auto first = reinterpret_cast<std::uintptr_t>(block);
  const std::uintptr_t start = (first + huge_page_bytes - 1) / huge_page_bytes * huge_page_bytes;
  const std::uintptr_t end = (first + bytes) / huge_page_bytes * huge_page_bytes;
  if (start < end) madvise(reinterpret_cast<void*>(start), end - start, MADV_HUGEPAGE);
}

}  // namespace altfem
