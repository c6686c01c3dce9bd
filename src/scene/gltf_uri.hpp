// Internal: the URI policy of the glTF loader (which buffer/image URIs may be read).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace snell::detail {

/// Percent-decodes a URI exactly as tinygltf 2.7 does before it opens a file (dlib::urldecode:
/// "%XX" is decoded, '+' becomes a space, an invalid hex digit counts as 0), so that the policy
/// below judges the very string that would reach the file system.
[[nodiscard]] std::string percent_decode(std::string_view uri);

/// Why the decoded relative reference `path` may not be opened, or nullopt when it names a file
/// inside the model's folder. Refused: empty, absolute (leading '/' or '\', a drive letter or any
/// URI scheme such as file: or http:), backslashes, control characters, and `..` segments that
/// climb above the folder ("a/../b" is accepted, "a/../../b" is not).
[[nodiscard]] std::optional<std::string> uri_path_violation(std::string_view path);

/// A `data:` URI as tinygltf 2.7 understands it.
struct DataUri {
  bool is_data = false;    ///< Starts with "data:".
  bool supported = false;  ///< One of the base64 media types tinygltf decodes.
  std::size_t payload = 0; ///< Characters after the header (base64 text).
  std::string media_type;  ///< Between "data:" and the first ';' or ','.
  /// Upper bound of the decoded size: 3 bytes per 4 base64 characters (a partial group counts).
  [[nodiscard]] std::size_t decoded_bound() const {
    return payload / 4 * 3 + (payload % 4 ? 3 : 0);
  }
};

/// Classifies `uri` (no decoding is done).
[[nodiscard]] DataUri classify_data_uri(std::string_view uri);

/// `text` for an error message: at most `max` characters (data: URIs can be megabytes) and
/// control characters shown as '?'.
[[nodiscard]] std::string clip_for_message(std::string_view text, std::size_t max = 80);

} // namespace snell::detail
