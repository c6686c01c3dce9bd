// Internal: the sandboxed file access of the glTF loader.
#pragma once

#include "gltf_context.hpp"
#include "gltf_tinygltf.hpp"

#include <snell/result.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace snell::detail {

/// Reads the whole regular file `path` if it has at most `max_bytes` bytes.
/// Errors (messages start with `label`): file_not_found (missing, or not a regular file),
/// limit_exceeded (too large, naming the size and the limit), io_error (open or read failed).
[[nodiscard]] Result<std::vector<std::uint8_t>> read_file_limited(const std::filesystem::path& path,
                                                                  std::uint64_t max_bytes,
                                                                  const std::string& label);

/// tinygltf file-system callbacks bound to `ctx` (which must outlive the load): a URI is opened
/// only if it names a regular file inside ctx.base_dir (also after resolving symbolic links) and
/// passes uri_path_violation; files over GltfLimits::max_file_bytes are refused; writing is
/// refused. Refusals are recorded in ctx.error with the precise ErrorCode.
[[nodiscard]] tinygltf::FsCallbacks make_fs_callbacks(GltfLoadContext& ctx);

} // namespace snell::detail
