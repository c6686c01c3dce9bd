// Snell: a minimal C++17 view over contiguous elements, so that public headers need no C++20
// (`std::span`). It converts from anything with `data()` and `size()` (std::vector, std::array,
// std::span, std::string_view-like types) and from C arrays.
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>

namespace snell {

/// A non-owning view of `size()` contiguous `T` starting at `data()`. Like std::span<T> with a
/// dynamic extent, without subspans. The viewed elements must outlive the view.
template <class T> class Span {
public:
  using element_type = T;
  using value_type = std::remove_cv_t<T>;
  using size_type = std::size_t;
  using iterator = T*;

  /// An empty view.
  constexpr Span() noexcept = default;
  /// `count` elements starting at `data` (`data` may be null only when `count` is 0).
  constexpr Span(T* data, size_type count) noexcept : data_(data), size_(count) {}
  /// A whole C array.
  template <std::size_t N> constexpr Span(T (&array)[N]) noexcept : data_(array), size_(N) {}
  /// Any contiguous container with data() and size() whose elements convert to T*
  /// (std::vector, std::array, std::span, another Span).
  template <class C, class = std::enable_if_t<
                         !std::is_array_v<std::remove_reference_t<C>> &&
                         std::is_convertible_v<decltype(std::declval<C&>().data()), T*>>>
  constexpr Span(C&& container) noexcept // NOLINT: implicit, like std::span
      : data_(container.data()), size_(static_cast<size_type>(container.size())) {}

  [[nodiscard]] constexpr T* data() const noexcept { return data_; }
  [[nodiscard]] constexpr size_type size() const noexcept { return size_; }
  [[nodiscard]] constexpr bool empty() const noexcept { return size_ == 0; }
  [[nodiscard]] constexpr T* begin() const noexcept { return data_; }
  [[nodiscard]] constexpr T* end() const noexcept { return data_ + size_; }
  /// Element `i`; `i < size()` is a precondition (not checked).
  [[nodiscard]] constexpr T& operator[](size_type i) const noexcept { return data_[i]; }

private:
  T* data_ = nullptr;
  size_type size_ = 0;
};

} // namespace snell
