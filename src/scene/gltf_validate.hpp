// Internal: structural validation of a parsed glTF model before it is converted.
#pragma once

#include "gltf_context.hpp"
#include "gltf_tinygltf.hpp"

#include <snell/result.hpp>

#include <cstdint>
#include <optional>

namespace snell::detail {

/// Checks everything the conversion relies on, so that it can index arrays without surprises:
///  - extensionsRequired only lists extensions Snell reads (else unsupported);
///  - every reference (buffer, bufferView, accessor, mesh, material, texture, image, sampler,
///    node, camera, light, scene) is in range (else parse_error naming both ends);
///  - buffer views lie inside their buffers, accessors (count * stride, sparse parts) inside their
///    buffer views, accessor component types are those of glTF 2.0 (else parse_error);
///  - node transforms have the right number of finite values; cameras and lights have sane values.
/// Animations and skins are not used by Snell and are not checked.
[[nodiscard]] Result<void> validate_model(const tinygltf::Model& model, const GltfLoadContext& ctx);

/// Bytes of one component of a glTF component type that Snell reads (1, 2 or 4), or 0 for any
/// other value (5124 INT and 5130 DOUBLE are not glTF 2.0 types).
[[nodiscard]] int component_size(int component_type);

/// Components of an accessor type (SCALAR 1, VEC2 2, VEC3 3, VEC4 4, MAT2 4, MAT3 9, MAT4 16),
/// or 0 for an unknown type.
[[nodiscard]] int component_count(int type);

/// offset + (count - 1) * stride + element, or nullopt if it overflows 64 bits (count >= 1).
[[nodiscard]] std::optional<std::uint64_t> span_end(std::uint64_t offset, std::uint64_t count,
                                                    std::uint64_t stride, std::uint64_t element);

} // namespace snell::detail
