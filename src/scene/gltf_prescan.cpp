// Internal: checks of a glTF document before tinygltf parses it (see gltf_prescan.hpp).
#include "gltf_prescan.hpp"

#include "gltf_uri.hpp"

#include <nlohmann/json.hpp>

#include <climits>
#include <cstring>
#include <limits>
#include <string>

namespace snell::detail {
namespace {

using json = nlohmann::json;

std::uint32_t read_u32_le(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
         (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}

// Deepest nesting of arrays/objects, counted on the raw text so that nothing recursive runs on
// a hostile document before this check.
int nesting_depth(std::string_view text) {
  int depth = 0;
  int deepest = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') {
        ++i; // Skip the escaped character (it may be a quote).
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > deepest) {
        deepest = depth;
      }
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

// tinygltf's reading of an integer property (GetInt): any JSON integer, truncated to int.
std::optional<int> tinygltf_int(const json& object, const char* key) {
  const auto it = object.find(key);
  if (it == object.end() || !it->is_number_integer()) {
    return std::nullopt;
  }
  return static_cast<int>(it->get<std::int64_t>());
}

// tinygltf's reading of an unsigned property (ParseUnsignedProperty): JSON unsigned integers.
std::optional<std::uint64_t> tinygltf_unsigned(const json& object, const char* key) {
  const auto it = object.find(key);
  if (it == object.end() || !it->is_number_unsigned()) {
    return std::nullopt;
  }
  return it->get<std::uint64_t>();
}

const json* array_member(const json& root, const char* key) {
  const auto it = root.find(key);
  return (it != root.end() && it->is_array()) ? &*it : nullptr;
}

class Prescan {
public:
  Prescan(const json& root, bool is_binary, std::size_t bin_size, const GltfLoadContext& ctx)
      : is_binary_(is_binary), bin_size_(bin_size), ctx_(ctx),
        buffers_(array_member(root, "buffers")), views_(array_member(root, "bufferViews")),
        images_(array_member(root, "images")) {}

  Result<void> run() {
    if (buffers_ != nullptr) {
      for (std::size_t i = 0; i < buffers_->size(); ++i) {
        if (Result<void> r = check_buffer(i, (*buffers_)[i]); !r) {
          return r;
        }
      }
    }
    if (images_ != nullptr) {
      for (std::size_t i = 0; i < images_->size(); ++i) {
        if (Result<void> r = check_image(i, (*images_)[i]); !r) {
          return r;
        }
      }
    }
    return {};
  }

private:
  Error fail(ErrorCode code, const std::string& what) const { return ctx_.fail(code, what); }

  // A data: URI or external file reference of `what` ("buffer 2", "image 0").
  Result<void> check_uri(const std::string& what, const std::string& uri) const {
    const DataUri data = classify_data_uri(uri);
    if (data.is_data) {
      if (!data.supported) {
        return fail(ErrorCode::unsupported,
                    what + ": data: URI with media type '" + clip_for_message(data.media_type) +
                        "' is not supported (base64 application/octet-stream, "
                        "application/gltf-buffer, image/png or image/jpeg expected)");
      }
      if (data.decoded_bound() > ctx_.limits.max_data_uri_bytes) {
        return fail(ErrorCode::limit_exceeded,
                    what + ": data: URI decodes to about " + std::to_string(data.decoded_bound()) +
                        " bytes, over the limit GltfLimits::max_data_uri_bytes = " +
                        std::to_string(ctx_.limits.max_data_uri_bytes));
      }
      return {};
    }
    const std::string decoded = percent_decode(uri);
    if (const std::optional<std::string> why = uri_path_violation(decoded)) {
      std::string shown = "'" + clip_for_message(uri) + "'";
      if (decoded != uri) {
        shown += " (decoded '" + clip_for_message(decoded) + "')";
      }
      return fail(ErrorCode::access_denied, what + " URI " + shown + " refused: it " + *why);
    }
    return {};
  }

  Result<void> check_buffer(std::size_t index, const json& buffer) {
    if (!buffer.is_object()) {
      return {}; // tinygltf refuses it with its own message.
    }
    const std::string what = "buffer " + std::to_string(index);
    const auto uri_it = buffer.find("uri");
    const bool has_uri = uri_it != buffer.end() && uri_it->is_string() &&
                         !uri_it->get_ref<const std::string&>().empty();
    if (has_uri) {
      if (Result<void> r = check_uri(what, uri_it->get<std::string>()); !r) {
        return r;
      }
    } else if (!is_binary_ || index > 0) {
      return fail(ErrorCode::parse_error,
                  what + " has no uri (only the first buffer of a .glb may omit it)");
    }
    const std::optional<std::uint64_t> length = tinygltf_unsigned(buffer, "byteLength");
    if (!length) {
      return {}; // Missing or not an unsigned integer: tinygltf refuses it.
    }
    if (*length == 0) {
      return fail(ErrorCode::parse_error, what + ": byteLength is 0 (the minimum is 1)");
    }
    const std::string declared = what + ": byteLength " + std::to_string(*length);
    if (!has_uri) {
      if (*length > bin_size_) {
        return fail(ErrorCode::parse_error, declared + " exceeds the .glb's BIN chunk (" +
                                                std::to_string(bin_size_) + " bytes)");
      }
    } else if (classify_data_uri(uri_it->get_ref<const std::string&>()).is_data) {
      if (*length > ctx_.limits.max_data_uri_bytes) {
        return fail(ErrorCode::limit_exceeded,
                    declared + " is over the limit GltfLimits::max_data_uri_bytes = " +
                        std::to_string(ctx_.limits.max_data_uri_bytes));
      }
    } else if (*length > ctx_.limits.max_file_bytes) {
      return fail(ErrorCode::limit_exceeded,
                  declared + " is over the limit GltfLimits::max_file_bytes = " +
                      std::to_string(ctx_.limits.max_file_bytes));
    }
    total_buffer_bytes_ += *length; // No overflow: each term is below a 64-bit limit checked above.
    if (total_buffer_bytes_ > ctx_.limits.max_total_buffer_bytes) {
      return fail(ErrorCode::limit_exceeded,
                  "buffers declare " + std::to_string(total_buffer_bytes_) + " bytes up to " +
                      what +
                      ", over the limit "
                      "GltfLimits::max_total_buffer_bytes = " +
                      std::to_string(ctx_.limits.max_total_buffer_bytes));
    }
    return {};
  }

  Result<void> check_image(std::size_t index, const json& image) {
    if (!image.is_object()) {
      return {};
    }
    const std::string what = "image " + std::to_string(index);
    const auto uri_it = image.find("uri");
    if (uri_it != image.end() && uri_it->is_string()) {
      if (Result<void> r = check_uri(what, uri_it->get<std::string>()); !r) {
        return r;
      }
    }
    const std::optional<int> view_index = tinygltf_int(image, "bufferView");
    if (!view_index || uri_it != image.end()) {
      return {}; // No buffer view, or both (tinygltf refuses that).
    }
    // tinygltf decodes from &buffer.data[view.byteOffset] for view.byteLength bytes with no
    // range check; buffer.data always holds exactly the buffer's declared byteLength.
    const std::string view_what = what + ": bufferView " + std::to_string(*view_index);
    if (views_ == nullptr || *view_index < 0 ||
        static_cast<std::size_t>(*view_index) >= views_->size()) {
      return fail(ErrorCode::parse_error, view_what + " does not exist");
    }
    const json& view = (*views_)[static_cast<std::size_t>(*view_index)];
    if (!view.is_object()) {
      return {};
    }
    const std::optional<int> buffer_index = tinygltf_int(view, "buffer");
    const std::optional<std::uint64_t> length = tinygltf_unsigned(view, "byteLength");
    if (!buffer_index || !length) {
      return {}; // tinygltf refuses the buffer view itself.
    }
    if (buffers_ == nullptr || *buffer_index < 0 ||
        static_cast<std::size_t>(*buffer_index) >= buffers_->size() ||
        !(*buffers_)[static_cast<std::size_t>(*buffer_index)].is_object()) {
      return fail(ErrorCode::parse_error, view_what + " names buffer " +
                                              std::to_string(*buffer_index) +
                                              ", which does not exist");
    }
    const std::optional<std::uint64_t> buffer_length =
        tinygltf_unsigned((*buffers_)[static_cast<std::size_t>(*buffer_index)], "byteLength");
    if (!buffer_length) {
      return {};
    }
    const std::uint64_t offset = tinygltf_unsigned(view, "byteOffset").value_or(0);
    if (*length == 0 || offset > *buffer_length || *length > *buffer_length - offset) {
      return fail(ErrorCode::parse_error, view_what + " (offset " + std::to_string(offset) +
                                              ", length " + std::to_string(*length) +
                                              ") lies outside buffer " +
                                              std::to_string(*buffer_index) + " (" +
                                              std::to_string(*buffer_length) + " bytes)");
    }
    if (*length > static_cast<std::uint64_t>(INT_MAX)) {
      return fail(ErrorCode::limit_exceeded, view_what + " holds " + std::to_string(*length) +
                                                 " bytes; images over 2 GiB are not supported");
    }
    return {};
  }

  bool is_binary_;
  std::size_t bin_size_;
  const GltfLoadContext& ctx_;
  const json* buffers_;
  const json* views_;
  const json* images_;
  std::uint64_t total_buffer_bytes_ = 0;
};

} // namespace

std::optional<GlbLayout> parse_glb_layout(const std::uint8_t* data, std::size_t size) {
  // The same checks, in the same order, as tinygltf 2.7's LoadBinaryFromMemory.
  if (size < 20 || size > std::numeric_limits<std::uint32_t>::max() ||
      std::memcmp(data, "glTF", 4) != 0) {
    return std::nullopt;
  }
  const std::uint64_t length = read_u32_le(data + 8);
  const std::uint64_t json_length = read_u32_le(data + 12);
  const std::uint32_t json_format = read_u32_le(data + 16);
  const std::uint64_t header_and_json = 20 + json_length;
  if (header_and_json > size || json_length < 1 || length > size || header_and_json > length ||
      json_format != 0x4E4F534Au) {
    return std::nullopt;
  }
  GlbLayout layout{std::string_view(reinterpret_cast<const char*>(data + 20),
                                    static_cast<std::size_t>(json_length)),
                   0};
  if (header_and_json == length) {
    return layout; // No BIN chunk.
  }
  if (header_and_json + 12 > length) {
    return std::nullopt;
  }
  const std::uint64_t bin_length = read_u32_le(data + header_and_json);
  const std::uint32_t bin_format = read_u32_le(data + header_and_json + 4);
  if (bin_length < 4 || bin_length % 4 != 0 || bin_length + header_and_json > length ||
      bin_format != 0x004E4942u) {
    return std::nullopt;
  }
  layout.bin_size = static_cast<std::size_t>(bin_length);
  return layout;
}

Result<bool> prescan_gltf_json(std::string_view text, bool is_binary, std::size_t bin_size,
                               const GltfLoadContext& ctx) {
  if (nesting_depth(text) > max_json_depth) {
    return ctx.fail(ErrorCode::limit_exceeded, "JSON nests arrays/objects deeper than " +
                                                   std::to_string(max_json_depth) + " levels");
  }
  const json root = json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
  if (root.is_discarded() || !root.is_object()) {
    return false;
  }
  if (Result<void> r = Prescan(root, is_binary, bin_size, ctx).run(); !r) {
    return r.error();
  }
  return true;
}

} // namespace snell::detail
