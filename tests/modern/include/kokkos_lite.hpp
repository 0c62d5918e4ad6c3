// kokkos_lite.hpp: a small, faithful stand-in for the parts of Kokkos that a
// stencil kernel touches (Kokkos is not a Debian package), host backend
// semantics: View<DataType> with the data-type syntax (View<double**>,
// View<const double***>), LayoutRight (the last index fastest), unmanaged
// views over a user pointer, View<T> -> View<const T> conversion,
// RangePolicy, MDRangePolicy<Rank<N>> (with an optional work tag), and
// parallel_for with an optional label, a lambda or a functor. An MDRange is
// the loop nest with the first index outermost; a work tag is passed as an
// unnamed first argument of the functor's operator().
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#define KOKKOS_LAMBDA [=]
#define KOKKOS_CLASS_LAMBDA [ =, *this ]
#define KOKKOS_INLINE_FUNCTION inline
#define KOKKOS_FUNCTION
#define KOKKOS_FORCEINLINE_FUNCTION inline

namespace Kokkos {

struct LayoutRight {};
struct HostSpace {};

namespace Impl {
template <class T> struct DataTypeTraits {
  using value_type = T;
  static constexpr int rank = 0;
};
template <class T> struct DataTypeTraits<T*> {
  using value_type = typename DataTypeTraits<T>::value_type;
  static constexpr int rank = DataTypeTraits<T>::rank + 1;
};
} // namespace Impl

template <class DataType, class... Properties> class View {
public:
  using traits = Impl::DataTypeTraits<DataType>;
  using value_type = typename traits::value_type;
  using const_value_type = const std::remove_const_t<value_type>;
  using non_const_value_type = std::remove_const_t<value_type>;
  using pointer_type = value_type*;
  using reference_type = value_type&;
  using array_layout = LayoutRight;
  static constexpr unsigned rank = traits::rank;

  View() = default;

  /// Managed view: allocates n0 x n1 x n2 zero-initialized elements.
  explicit View(const std::string& label, std::size_t n0, std::size_t n1 = 0, std::size_t n2 = 0)
      : label_(label) {
    set_extents(n0, n1, n2);
    auto store =
        std::make_shared<std::vector<non_const_value_type>>(span(), non_const_value_type(0));
    owner_ = store;
    ptr_ = store->data();
  }

  /// Unmanaged view of user memory.
  View(pointer_type ptr, std::size_t n0, std::size_t n1 = 0, std::size_t n2 = 0) : ptr_(ptr) {
    set_extents(n0, n1, n2);
  }

  /// View<double**> -> View<const double**>.
  template <class D2, class... P2,
            typename = std::enable_if_t<std::is_same<typename Impl::DataTypeTraits<D2>::value_type,
                                                     non_const_value_type>::value &&
                                        std::is_const<value_type>::value &&
                                        Impl::DataTypeTraits<D2>::rank == rank>>
  View(const View<D2, P2...>& rhs) : ptr_(rhs.data()), label_(rhs.label()), owner_(rhs.owner()) {
    for (unsigned r = 0; r < 3; ++r) {
      extent_[r] = rhs.extent(r);
      stride_[r] = rhs.stride(r);
    }
  }

  KOKKOS_INLINE_FUNCTION reference_type operator()(const std::int64_t i0) const { return ptr_[i0]; }
  KOKKOS_INLINE_FUNCTION reference_type operator()(const std::int64_t i0,
                                                   const std::int64_t i1) const {
    return ptr_[i0 * stride_[0] + i1];
  }
  KOKKOS_INLINE_FUNCTION reference_type operator()(const std::int64_t i0, const std::int64_t i1,
                                                   const std::int64_t i2) const {
    return ptr_[i0 * stride_[0] + i1 * stride_[1] + i2];
  }
  KOKKOS_INLINE_FUNCTION reference_type operator[](const std::int64_t i0) const { return ptr_[i0]; }

  KOKKOS_INLINE_FUNCTION std::size_t extent(unsigned r) const { return r < 3 ? extent_[r] : 1; }
  KOKKOS_INLINE_FUNCTION int extent_int(unsigned r) const { return int(extent(r)); }
  KOKKOS_INLINE_FUNCTION std::size_t stride(unsigned r) const { return r < 3 ? stride_[r] : 1; }
  KOKKOS_INLINE_FUNCTION std::size_t size() const { return span(); }
  KOKKOS_INLINE_FUNCTION pointer_type data() const { return ptr_; }
  const std::string& label() const { return label_; }
  const std::shared_ptr<void>& owner() const { return owner_; }

private:
  void set_extents(std::size_t n0, std::size_t n1, std::size_t n2) {
    extent_[0] = n0;
    extent_[1] = rank > 1 ? n1 : 1;
    extent_[2] = rank > 2 ? n2 : 1;
    stride_[2] = 1;
    stride_[1] = extent_[2];
    stride_[0] = extent_[1] * extent_[2];
  }
  std::size_t span() const { return extent_[0] * extent_[1] * extent_[2]; }

  pointer_type ptr_ = nullptr;
  std::size_t extent_[3] = {0, 1, 1};
  std::size_t stride_[3] = {1, 1, 1};
  std::string label_;
  std::shared_ptr<void> owner_;
};

template <unsigned N> struct Rank { static constexpr unsigned rank = N; };

template <class T, std::size_t N> using Array = std::array<T, N>;

namespace Impl {
template <class T> struct is_rank : std::false_type {};
template <unsigned N> struct is_rank<Rank<N>> : std::true_type {};
template <class T> struct is_index_type : std::false_type {};

// The work tag of a policy: its template argument that is not a Rank.
template <class... P> struct WorkTagOf { using type = void; };
template <class P0, class... P> struct WorkTagOf<P0, P...> {
  using type = std::conditional_t<is_rank<P0>::value, typename WorkTagOf<P...>::type, P0>;
};
template <class... P> struct RankOf { static constexpr unsigned value = 0; };
template <class P0, class... P> struct RankOf<P0, P...> {
  static constexpr unsigned value = RankOf<P...>::value;
};
template <unsigned N, class... P> struct RankOf<Rank<N>, P...> {
  static constexpr unsigned value = N;
};

template <class Tag, class F, class... I>
KOKKOS_FORCEINLINE_FUNCTION void invoke(const F& f, I... i) {
  if constexpr (std::is_void<Tag>::value)
    f(i...);
  else
    f(Tag{}, i...);
}
} // namespace Impl

template <class... Properties> class RangePolicy {
public:
  using work_tag = typename Impl::WorkTagOf<Properties...>::type;
  using index_type = std::int64_t;
  RangePolicy(index_type begin, index_type end) : begin_(begin), end_(end) {}
  index_type begin() const { return begin_; }
  index_type end() const { return end_; }

private:
  index_type begin_, end_;
};

template <class... Properties> class MDRangePolicy {
public:
  using work_tag = typename Impl::WorkTagOf<Properties...>::type;
  static constexpr unsigned rank = Impl::RankOf<Properties...>::value;
  static_assert(rank >= 2 && rank <= 3, "MDRangePolicy: Rank<2> or Rank<3>");
  using index_type = std::int64_t;
  using point_type = Kokkos::Array<index_type, rank>;
  MDRangePolicy(const point_type& lower, const point_type& upper) : lower_(lower), upper_(upper) {}
  const point_type& lower() const { return lower_; }
  const point_type& upper() const { return upper_; }

private:
  point_type lower_, upper_;
};

template <class... P, class F> void parallel_for(const RangePolicy<P...>& policy, const F& f) {
  using Tag = typename RangePolicy<P...>::work_tag;
  for (std::int64_t i = policy.begin(); i < policy.end(); ++i)
    Impl::invoke<Tag>(f, i);
}

template <class... P, class F> void parallel_for(const MDRangePolicy<P...>& policy, const F& f) {
  using Policy = MDRangePolicy<P...>;
  using Tag = typename Policy::work_tag;
  const auto& lo = policy.lower();
  const auto& hi = policy.upper();
  if constexpr (Policy::rank == 2) {
    for (std::int64_t i0 = lo[0]; i0 < hi[0]; ++i0)
      for (std::int64_t i1 = lo[1]; i1 < hi[1]; ++i1)
        Impl::invoke<Tag>(f, i0, i1);
  } else {
    for (std::int64_t i0 = lo[0]; i0 < hi[0]; ++i0)
      for (std::int64_t i1 = lo[1]; i1 < hi[1]; ++i1)
        for (std::int64_t i2 = lo[2]; i2 < hi[2]; ++i2)
          Impl::invoke<Tag>(f, i0, i1, i2);
  }
}

/// parallel_for(n, f): the range [0, n).
template <class I, class F, typename = std::enable_if_t<std::is_integral<I>::value>>
void parallel_for(const I n, const F& f) {
  for (I i = 0; i < n; ++i)
    f(i);
}

template <class Policy, class F>
void parallel_for(const std::string& /*label*/, const Policy& policy, const F& f) {
  parallel_for(policy, f);
}

inline void fence() {}

} // namespace Kokkos
