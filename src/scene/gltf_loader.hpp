// Internal: the glTF loader's entry point for data already in memory (used by load_gltf and by
// the fuzzer, tests/fuzz/gltf_fuzzer.cpp, so that both run the very same checks).
#pragma once

#include <snell/result.hpp>
#include <snell/scene.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace snell::detail {

/// Loads a glTF document from `size` bytes at `data`: a .glb container when `is_binary`, else
/// .gltf JSON text. External URIs resolve under `base_dir` (made absolute; it need not exist, in
/// which case every external reference is file_not_found). `name` (the model's path) starts every
/// error message. Same checks, limits and results as snell::load_gltf; never throws.
[[nodiscard]] Result<Scene> load_gltf_from_memory(const std::uint8_t* data, std::size_t size,
                                                  const std::filesystem::path& base_dir,
                                                  bool is_binary, const GltfLimits& limits,
                                                  const std::string& name);

} // namespace snell::detail
