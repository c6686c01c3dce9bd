// Internal: the URI policy of the glTF loader (see gltf_uri.hpp).
#include "gltf_uri.hpp"

#include <array>

namespace snell::detail {
namespace {

unsigned hex_value(char c) {
  if (c >= '0' && c <= '9') {
    return static_cast<unsigned>(c - '0');
  }
  if (c >= 'a' && c <= 'f') {
    return static_cast<unsigned>(c - 'a' + 10);
  }
  if (c >= 'A' && c <= 'F') {
    return static_cast<unsigned>(c - 'A' + 10);
  }
  return 0; // tinygltf's from_hex maps anything else to 0; so must we, to judge the same path.
}

bool is_alpha(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

// The data: headers tinygltf 2.7 decodes (IsDataURI); any other data: URI would be taken for a
// file name by tinygltf, so the loader refuses it as unsupported instead.
constexpr std::array<std::string_view, 7> supported_data_headers = {
    "data:application/octet-stream;base64,",
    "data:image/jpeg;base64,",
    "data:image/png;base64,",
    "data:image/bmp;base64,",
    "data:image/gif;base64,",
    "data:text/plain;base64,",
    "data:application/gltf-buffer;base64,",
};

} // namespace

std::string percent_decode(std::string_view uri) {
  std::string out;
  out.reserve(uri.size());
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      out += ' ';
    } else if (uri[i] == '%' && uri.size() > i + 2) {
      out += static_cast<char>((hex_value(uri[i + 1]) << 4) | hex_value(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

std::optional<std::string> uri_path_violation(std::string_view path) {
  if (path.empty()) {
    return "is empty";
  }
  for (const char c : path) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      return "contains a control character";
    }
    if (c == '\\') {
      return "contains a backslash (only '/' separates folders in a URI)";
    }
  }
  if (path.front() == '/') {
    return "is an absolute path";
  }
  // A scheme ("file:", "http:") or a drive letter ("C:") before the first '/': RFC 3986 forbids a
  // colon in the first segment of a relative reference, so this is never a plain file name.
  const std::size_t colon = path.find(':');
  if (colon != std::string_view::npos &&
      path.substr(0, colon).find('/') == std::string_view::npos) {
    if (colon == 1 && is_alpha(path[0])) {
      return "is an absolute path (drive letter)";
    }
    return "has a URI scheme ('" + std::string(path.substr(0, colon)) +
           ":'); only relative file references are allowed";
  }
  // Walk the segments: ".." may only undo a folder entered earlier in the same reference.
  long depth = 0;
  std::size_t start = 0;
  while (start <= path.size()) {
    std::size_t end = path.find('/', start);
    if (end == std::string_view::npos) {
      end = path.size();
    }
    const std::string_view segment = path.substr(start, end - start);
    if (segment == "..") {
      if (--depth < 0) {
        return "escapes the model's folder with '..'";
      }
    } else if (!segment.empty() && segment != ".") {
      ++depth;
    }
    start = end + 1;
  }
  return std::nullopt;
}

DataUri classify_data_uri(std::string_view uri) {
  DataUri result;
  if (uri.substr(0, 5) != "data:") {
    return result;
  }
  result.is_data = true;
  const std::size_t type_end = uri.find_first_of(";,", 5);
  result.media_type = std::string(
      uri.substr(5, type_end == std::string_view::npos ? std::string_view::npos : type_end - 5));
  for (const std::string_view header : supported_data_headers) {
    if (uri.substr(0, header.size()) == header) {
      result.supported = true;
      result.payload = uri.size() - header.size();
      break;
    }
  }
  return result;
}

std::string clip_for_message(std::string_view text, std::size_t max) {
  std::string out(text.substr(0, max));
  for (char& c : out) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      c = '?'; // Keep messages printable on one line.
    }
  }
  if (text.size() > max) {
    out += "...";
  }
  return out;
}

} // namespace snell::detail
