// Internal: checks of a glTF document that must happen before tinygltf parses it, because
// tinygltf acts on these values before the loader could look at its result: it decodes data:
// URIs of any size, allocates what buffers declare, opens external files, and hands images
// stored in buffer views to the decoder without checking that the view lies inside its buffer.
#pragma once

#include "gltf_context.hpp"

#include <snell/result.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace snell::detail {

/// Where the chunks of a .glb container are.
struct GlbLayout {
  std::string_view json; ///< The JSON chunk.
  std::size_t bin_size;  ///< Bytes in the BIN chunk (0 when there is none).
};

/// The layout of a .glb container, or nullopt when tinygltf 2.7 (LoadBinaryFromMemory) would
/// refuse its header or chunk sizes (the loader then reports tinygltf's own message).
[[nodiscard]] std::optional<GlbLayout> parse_glb_layout(const std::uint8_t* data, std::size_t size);

/// Deepest JSON nesting accepted. tinygltf converts "extras" and "extensions" recursively, so a
/// deeply nested document would overflow the stack; real glTF files nest fewer than 15 levels.
inline constexpr int max_json_depth = 128;

/// Checks the glTF JSON text `json` (the whole .gltf, or a .glb's JSON chunk with `bin_size`
/// bytes of BIN chunk). Returns true when checked and accepted; false when the text is not a JSON
/// object (tinygltf then reports its own parse error); an Error for a refusal:
///  - limit_exceeded: nesting over max_json_depth, a data: URI or buffer over the limits;
///  - access_denied: a buffer/image URI refused by uri_path_violation;
///  - unsupported: a data: URI whose media type tinygltf cannot decode;
///  - parse_error: a buffer without data, an image buffer view outside its buffer.
[[nodiscard]] Result<bool> prescan_gltf_json(std::string_view json, bool is_binary,
                                             std::size_t bin_size, const GltfLoadContext& ctx);

} // namespace snell::detail
