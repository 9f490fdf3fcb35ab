// A std::vector whose resize leaves new elements of trivial types uninitialized (default
// initialization) instead of zeroing them: for scratch arrays that are written in full after
// every resize, so that growing them again each frame costs nothing. Not part of the API.
#pragma once

#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace shadelab::detail {

template <class T>
struct DefaultInitAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  DefaultInitAllocator() = default;
  template <class U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}

  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;  // default-initialized: indeterminate for trivial U
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

/// A vector for scratch data written in full after each resize.
template <class T>
using ScratchVector = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace shadelab::detail
