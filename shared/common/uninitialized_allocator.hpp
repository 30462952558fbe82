#pragma once
// An allocator for arrays that are written whole after they are sized (a tabulation's
// weights, values and gradients, TabulatedElements::lay_out): resizing them does not
// zero memory, so their first touch is the write, by the threads that write it.
#include <memory>
#include <new>
#include <utility>

namespace altfem {

/// std::allocator whose value-less construction leaves a double unwritten, so resizing a
/// tabulation's arrays does not zero memory its tabulator writes anyway.
template <class T>
struct UninitializedAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <class U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* pointer) noexcept {
    ::new (static_cast<void*>(pointer)) U;
  }
  template <class U, class... Arguments>
  void construct(U* pointer, Arguments&&... arguments) {
    ::new (static_cast<void*>(pointer)) U(std::forward<Arguments>(arguments)...);
  }
};

}  // namespace altfem
