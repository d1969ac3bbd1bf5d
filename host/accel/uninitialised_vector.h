// A vector whose resize leaves its new elements unwritten, for the arrays a
// build fills on several threads. A build's arrays are fresh memory, and the
// first write to each page costs a page fault (about 1.5 us a page on the
// development machine, about a quarter of a first BVH build of the 69k bunny;
// docs/accel.md, "Fewer fresh pages"). Sized by this vector, a page is first
// touched by the thread that fills it, and nothing writes it before.
#pragma once

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace prism {

// construct() without a value does nothing, not even the element's default
// member initialisers (Aabb's): the elements are implicit-lifetime types
// (trivially copyable aggregates), which the filling thread's first
// assignment gives their values. (C++20 words it so, P0593; the compilers
// treat C++17 code, which this is, the same way.) Read none before it is
// written.
template <typename T>
struct UninitialisedAllocator : std::allocator<T> {
  static_assert(std::is_trivially_copyable<T>::value && std::is_trivially_destructible<T>::value,
                "only plain records may be left unwritten");
  template <typename U>
  struct rebind {
    using other = UninitialisedAllocator<U>;
  };
  UninitialisedAllocator() = default;
  template <typename U>
  UninitialisedAllocator(const UninitialisedAllocator<U>&) noexcept {}
  template <typename U>
  void construct(U*) noexcept {}
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <typename T>
using UninitialisedVector = std::vector<T, UninitialisedAllocator<T>>;

}  // namespace prism
