#pragma once
/// An allocator whose value-less construction default-initialises: a `std::vector<double>` with it
/// grows by `resize` without writing zeros first.
///
/// Design note: a fracture's corner values (mesh_attributes.h) are written once, in runs, straight
/// into the fragment's array (CornerProvenance::resolve); with the standard allocator each run would
/// first be zeroed by `resize` and then overwritten, one more pass over the largest array a fracture
/// writes. Only construction without arguments changes: copies, `assign`, `insert` and
/// `resize(n, value)` behave as with std::allocator, and `resize(n)` leaves the new values
/// indeterminate, so code that grows such a vector writes every new value before reading it.

#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace shatter {

/// std::allocator<T>, except that construct(p) default-initialises (no zeroing for arithmetic T).
template <class T>
class DefaultInitAllocator : public std::allocator<T> {
 public:
  using std::allocator<T>::allocator;
  DefaultInitAllocator() noexcept = default;
  template <class U>
  DefaultInitAllocator(const DefaultInitAllocator<U>& /*other*/) noexcept {}  // NOLINT: implicit, as std::allocator's
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };

  /// Default-initialises `*p` (leaves an arithmetic value indeterminate).
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  /// Constructs `*p` from `args`, as std::allocator does.
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

/// Every DefaultInitAllocator is interchangeable with every other (stateless).
template <class T, class U>
bool operator==(const DefaultInitAllocator<T>& /*a*/, const DefaultInitAllocator<U>& /*b*/) noexcept {
  return true;
}

}  // namespace shatter
