// Storage laid out like an array view, for the generated adjoint of a kernel
// whose work arrays (outputs a later loop reads) are views: dpgen cannot make
// a view of the user's class over memory of its own, so the adjoint keeps
// the recomputed values and the adjoints of such an output in ViewBuffers.
//
// A ViewBuffer borrows a view of the same shape and bounds (the output's
// seed, which the signature rule gives that type) only for its layout:
// element (i, j, ...) lives at data[&like(i, j, ...) - lowest], where lowest
// is the lowest element address the kernel reaches (`cover` sees each
// element the kernel stores or reads before `allocate`). The borrowed
// view's elements are never read or written through it; its operator() only
// says where an element sits.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace dpgen {

template <class View, class T> class ViewBuffer {
public:
  /// `like` must outlive the buffer (the generated adjoint's parameter).
  explicit ViewBuffer(const View& like) : like_(&const_cast<View&>(like)) {}

  /// Element (i...) is one the kernel reaches: the buffer covers it.
  template <class... I> void cover(I... i) {
    const T* a = address(i...);
    if (!lowest_ || std::less<const T*>()(a, lowest_))
      lowest_ = a;
    if (!highest_ || std::less<const T*>()(highest_, a))
      highest_ = a;
  }
  /// Covers what `other` covers (the adjoints of an output beside its values).
  void cover_as(const ViewBuffer& other) {
    lowest_ = other.lowest_;
    highest_ = other.highest_;
  }
  /// Storage for the covered elements, each set to `fill`.
  void allocate(T fill) {
    data_.assign(lowest_ ? static_cast<std::size_t>(highest_ - lowest_) + 1 : 0, fill);
  }

  /// The element (i...): one that `cover` saw. (Generated code writes every
  /// view access as a call, a(k, j, i).)
  template <class... I> T& operator()(I... i) const {
    return const_cast<T&>(data_[static_cast<std::size_t>(address(i...) - lowest_)]);
  }

  /// The view it is laid out like (the generated adjoint reads the output's
  /// shape through it: `flux.cols()` of the kernel is `flux_adj.view().cols()`).
  const View& view() const { return *like_; }

private:
  template <class... I> const T* address(I... i) const { return &(*like_)(i...); }

  View* like_;
  const T* lowest_ = nullptr;
  const T* highest_ = nullptr;
  std::vector<T> data_;
};

} // namespace dpgen
