// Snell runtime: fallible results. Every call a user can make fail returns a Result<T>: a value
// or an Error whose message names the offending file, parameter or value.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

namespace snell {

/// What kind of failure an Error reports; the message says exactly what and where.
enum class ErrorCode {
  invalid_argument, ///< A parameter is out of range, non-finite or inconsistent.
  file_not_found,   ///< A file does not exist or cannot be opened.
  io_error,         ///< Reading or writing a file failed part-way.
  parse_error,      ///< A file's content is malformed (JSON, glTF, image, ...).
  limit_exceeded,   ///< An input exceeds a configured limit (file size, image size, count).
  access_denied,    ///< A path is refused (absolute path or `..` escape in an asset).
  unsupported,      ///< Valid input the SDK does not handle (a format, a glTF feature).
  no_device,        ///< No Vulkan device matches the request.
  missing_feature,  ///< The device lacks a required feature or extension.
  vulkan_error,     ///< A Vulkan call failed (the message names the call and VkResult).
  out_of_memory,    ///< Host or device memory allocation failed.
  unknown_name,     ///< An effect, parameter or scene name is not known (lists the known ones).
  duplicate_name,   ///< A name is registered twice.
};

/// A failure: its kind and a readable, specific message.
struct Error {
  ErrorCode code = ErrorCode::invalid_argument; ///< Kind of failure. Default invalid_argument.
  std::string message{};                        ///< Human-readable; names file/parameter/value.
  /// The VkResult of the Vulkan call that failed (code vulkan_error or out_of_memory), as its
  /// integer value; 0 (VK_SUCCESS) when the failure did not come from Vulkan. Default 0.
  std::int32_t vk_result = 0;
};

/// Thrown only by `Result::value()` when called on an error: a programming error, like
/// `std::expected::value()`. Check `has_value()` (or `if (result)`) first.
class bad_result_access : public std::logic_error {
public:
  explicit bad_result_access(const std::string& message)
      : std::logic_error("snell::Result::value() on an error: " + message) {}
};

/// A value of type T or an Error.
template <class T> class [[nodiscard]] Result {
public:
  Result(T value) : storage_(std::in_place_index<0>, std::move(value)) {}     // NOLINT: implicit
  Result(Error error) : storage_(std::in_place_index<1>, std::move(error)) {} // NOLINT: implicit

  /// True when a value is held.
  [[nodiscard]] bool has_value() const noexcept { return storage_.index() == 0; }
  explicit operator bool() const noexcept { return has_value(); }

  /// The value; throws bad_result_access when an error is held.
  [[nodiscard]] T& value() & {
    check();
    return std::get<0>(storage_);
  }
  [[nodiscard]] const T& value() const& {
    check();
    return std::get<0>(storage_);
  }
  [[nodiscard]] T&& value() && {
    check();
    return std::get<0>(std::move(storage_));
  }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }

  /// The error; only valid when `!has_value()`.
  [[nodiscard]] const Error& error() const& { return std::get<1>(storage_); }

private:
  void check() const {
    if (!has_value()) {
      throw bad_result_access(std::get<1>(storage_).message);
    }
  }
  std::variant<T, Error> storage_;
};

/// Success or an Error.
template <> class [[nodiscard]] Result<void> {
public:
  Result() = default;
  Result(Error error) : error_(std::move(error)), ok_(false) {} // NOLINT: implicit

  [[nodiscard]] bool has_value() const noexcept { return ok_; }
  explicit operator bool() const noexcept { return ok_; }
  /// Throws bad_result_access when an error is held.
  void value() const {
    if (!ok_) {
      throw bad_result_access(error_.message);
    }
  }
  [[nodiscard]] const Error& error() const& { return error_; }

private:
  Error error_{};
  bool ok_ = true;
};

/// Shorthand to build an Error result: `return fail(ErrorCode::parse_error, "x.gltf: ...");`
[[nodiscard]] inline Error fail(ErrorCode code, std::string message) {
  return Error{code, std::move(message)};
}

} // namespace snell

/// Returns the error of `expr` (a snell::Result<void>) from the enclosing function, which
/// returns a snell::Result.
#define SNELL_TRY(expr)                                                                            \
  do {                                                                                             \
    if (auto snell_try_result_ = (expr); !snell_try_result_) {                                     \
      return snell_try_result_.error();                                                            \
    }                                                                                              \
  } while (false)

/// Evaluates `expr` (a snell::Result<T>); on error returns it from the enclosing function, else
/// moves the value into `lhs` (an existing object, e.g. a member).
#define SNELL_ASSIGN_OR_RETURN(lhs, expr)                                                          \
  do {                                                                                             \
    auto snell_assign_result_ = (expr);                                                            \
    if (!snell_assign_result_) {                                                                   \
      return snell_assign_result_.error();                                                         \
    }                                                                                              \
    (lhs) = std::move(*snell_assign_result_);                                                      \
  } while (false)
