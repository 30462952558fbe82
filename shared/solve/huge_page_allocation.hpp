#pragma once
// malloc-compatible allocation backed by 2 MiB transparent huge pages.
//
// Why: a sparse Cholesky factor is written once per factorisation into freshly
// allocated memory. With 4 KiB pages every first touch is a page fault, and on
// the virtual machines we measured (issue #9) those faults and the zeroing behind
// them took half of CHOLMOD's factorisation time of a 27,783-DOF Tet10 cube
// (1.0 s → 0.43 s with huge pages in a one-off comparison; `perf record` of
// bench_factorisation showed page-fault handling and memset above the BLAS kernels). Huge pages cut the
// faults 512-fold. The kernel's policy must allow them on request
// (/sys/kernel/mm/transparent_hugepage/enabled = madvise or always); otherwise
// this is plain malloc.
#include <cstddef>

namespace altfem {

/// Blocks of at least this many bytes get huge pages; smaller ones come from malloc.
inline constexpr std::size_t huge_page_threshold_bytes = std::size_t{4} << 20;

/// Like std::malloc(bytes); release with std::free (std::realloc also works).
void* allocate_with_huge_pages(std::size_t bytes);
/// Like std::calloc(count, size); release with std::free.
void* allocate_zeroed_with_huge_pages(std::size_t count, std::size_t size);

/// Asks for huge pages behind the whole 2 MiB pages inside an allocated block that is not
/// touched yet (memory another allocator owns, such as Eigen's sparse storage), so that
/// its first touch faults once per huge page. Blocks below huge_page_threshold_bytes are
/// left alone; advice only.
void advise_huge_pages(void* block, std::size_t bytes);

}  // namespace altfem
