// mdspan_lite.hpp: a C++17 stand-in for std::mdspan (C++23), written the way
// the reference implementation (kokkos/mdspan) is in C++17 mode: extents with
// static or dynamic extents, layout_right / layout_left mappings computing the
// offset recursively over the rank, a default_accessor, and the C++17
// call operator mdspan(i, j, k) (the reference implementation's
// MDSPAN_USE_PAREN_OPERATOR). Namespace stdex, as in many codes that alias it.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

namespace stdex {

inline constexpr std::size_t dynamic_extent = std::size_t(-1);

template <class IndexType, std::size_t... Exts> class extents {
public:
  using index_type = IndexType;
  using rank_type = std::size_t;
  static constexpr rank_type rank() noexcept { return sizeof...(Exts); }
  static constexpr rank_type rank_dynamic() noexcept {
    return ((Exts == dynamic_extent ? 1 : 0) + ... + 0);
  }
  static constexpr std::size_t static_extent(rank_type r) noexcept {
    constexpr std::size_t e[] = {Exts..., 0};
    return e[r];
  }

  constexpr extents() noexcept : ext_{} {}
  /// One value per dynamic extent, or one per extent.
  template <class... I,
            typename = std::enable_if_t<(std::is_convertible<I, IndexType>::value && ...)>>
  constexpr explicit extents(I... e) noexcept : ext_{} {
    const IndexType given[] = {IndexType(e)..., IndexType(0)};
    rank_type d = 0;
    for (rank_type r = 0; r < rank(); ++r) {
      if (static_extent(r) == dynamic_extent)
        ext_[r] = given[sizeof...(I) == rank() ? r : d++];
      else
        ext_[r] = IndexType(static_extent(r));
    }
  }
  constexpr index_type extent(rank_type r) const noexcept { return ext_[r]; }

private:
  std::array<IndexType, sizeof...(Exts)> ext_;
};

namespace detail {
template <class IndexType, class Seq> struct make_dextents;
template <class IndexType, std::size_t... Is>
struct make_dextents<IndexType, std::index_sequence<Is...>> {
  using type = extents<IndexType, ((void)Is, dynamic_extent)...>;
};
} // namespace detail

template <class IndexType, std::size_t Rank>
using dextents = typename detail::make_dextents<IndexType, std::make_index_sequence<Rank>>::type;

/// Row-major: the last index is contiguous.
struct layout_right {
  template <class Extents> class mapping {
  public:
    using extents_type = Extents;
    using index_type = typename Extents::index_type;
    constexpr mapping() noexcept = default;
    constexpr mapping(const Extents& e) noexcept : ext_(e) {}
    constexpr const extents_type& extents() const noexcept { return ext_; }

    template <class... Indices> constexpr index_type operator()(Indices... idxs) const noexcept {
      return compute_offset(std::integral_constant<std::size_t, 0>(), index_type(0),
                            static_cast<index_type>(idxs)...);
    }
    constexpr index_type required_span_size() const noexcept {
      index_type s = 1;
      for (std::size_t r = 0; r < Extents::rank(); ++r)
        s *= ext_.extent(r);
      return s;
    }

  private:
    template <std::size_t R>
    constexpr index_type compute_offset(std::integral_constant<std::size_t, R>,
                                        index_type offset) const noexcept {
      return offset;
    }
    template <std::size_t R, class... Rest>
    constexpr index_type compute_offset(std::integral_constant<std::size_t, R>, index_type offset,
                                        index_type i, Rest... rest) const noexcept {
      return compute_offset(std::integral_constant<std::size_t, R + 1>(),
                            offset * ext_.extent(R) + i, rest...);
    }
    Extents ext_;
  };
};

/// Column-major (Fortran): the first index is contiguous.
struct layout_left {
  template <class Extents> class mapping {
  public:
    using extents_type = Extents;
    using index_type = typename Extents::index_type;
    constexpr mapping() noexcept = default;
    constexpr mapping(const Extents& e) noexcept : ext_(e) {}
    constexpr const extents_type& extents() const noexcept { return ext_; }

    template <class... Indices> constexpr index_type operator()(Indices... idxs) const noexcept {
      const index_type idx[] = {static_cast<index_type>(idxs)...};
      index_type offset = 0, stride = 1;
      for (std::size_t r = 0; r < Extents::rank(); ++r) {
        offset += idx[r] * stride;
        stride *= ext_.extent(r);
      }
      return offset;
    }
    constexpr index_type required_span_size() const noexcept {
      index_type s = 1;
      for (std::size_t r = 0; r < Extents::rank(); ++r)
        s *= ext_.extent(r);
      return s;
    }

  private:
    Extents ext_;
  };
};

template <class ElementType> struct default_accessor {
  using element_type = ElementType;
  using reference = ElementType&;
  using data_handle_type = ElementType*;
  constexpr default_accessor() noexcept = default;
  template <class Other,
            typename = std::enable_if_t<std::is_convertible<Other (*)[], ElementType (*)[]>::value>>
  constexpr default_accessor(default_accessor<Other>) noexcept {}
  constexpr reference access(data_handle_type p, std::size_t i) const noexcept { return p[i]; }
};

template <class ElementType, class Extents, class LayoutPolicy = layout_right,
          class AccessorPolicy = default_accessor<ElementType>>
class mdspan {
public:
  using element_type = ElementType;
  using value_type = std::remove_cv_t<ElementType>;
  using extents_type = Extents;
  using layout_type = LayoutPolicy;
  using mapping_type = typename LayoutPolicy::template mapping<Extents>;
  using accessor_type = AccessorPolicy;
  using reference = typename AccessorPolicy::reference;
  using data_handle_type = typename AccessorPolicy::data_handle_type;
  using index_type = typename Extents::index_type;

  constexpr mdspan() = default;
  template <class... I,
            typename = std::enable_if_t<(std::is_convertible<I, index_type>::value && ...)>>
  constexpr explicit mdspan(data_handle_type p, I... exts)
      : ptr_(p), map_(Extents(static_cast<index_type>(exts)...)), acc_() {}
  constexpr mdspan(data_handle_type p, const mapping_type& m) : ptr_(p), map_(m), acc_() {}

  /// mdspan<double, E> -> mdspan<const double, E>.
  template <class OtherElement, class OtherAccessor,
            typename =
                std::enable_if_t<std::is_convertible<OtherElement (*)[], ElementType (*)[]>::value>>
  constexpr mdspan(const mdspan<OtherElement, Extents, LayoutPolicy, OtherAccessor>& other)
      : ptr_(other.data_handle()), map_(other.mapping()), acc_() {}

  template <class... Indices> constexpr reference operator()(Indices... idxs) const {
    return acc_.access(ptr_, std::size_t(map_(static_cast<index_type>(idxs)...)));
  }

  static constexpr std::size_t rank() noexcept { return Extents::rank(); }
  constexpr index_type extent(std::size_t r) const noexcept { return map_.extents().extent(r); }
  constexpr const extents_type& extents() const noexcept { return map_.extents(); }
  constexpr std::size_t size() const noexcept { return std::size_t(map_.required_span_size()); }
  constexpr const data_handle_type& data_handle() const noexcept { return ptr_; }
  constexpr const mapping_type& mapping() const noexcept { return map_; }

private:
  data_handle_type ptr_ = nullptr;
  mapping_type map_;
  accessor_type acc_;
};

} // namespace stdex
