// Internal: reading glTF accessors into plain arrays.
#pragma once

#include "gltf_context.hpp"
#include "gltf_tinygltf.hpp"

#include <snell/result.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace snell::detail {

/// Reads accessor `index` (of type `expected_type`, e.g. TINYGLTF_TYPE_VEC3) as count * components
/// floats, following glTF: byte strides, normalised integers mapped to [0,1] / [-1,1], other
/// integers converted as is, accessors without a buffer view read as zeros, sparse values
/// substituted. `what` names the use in messages ("mesh 0 primitive 1 POSITION").
/// Errors: parse_error (wrong type, a sparse index past the count, a non-finite value),
/// limit_exceeded when the accessor has more than `max_elements` elements (checked before any
/// allocation: an accessor without a buffer view may declare any count).
/// Requires validate_model() to have accepted the model.
[[nodiscard]] Result<std::vector<float>> read_float_accessor(const tinygltf::Model& model,
                                                             int index, int expected_type,
                                                             const std::string& what,
                                                             std::uint64_t max_elements,
                                                             const GltfLoadContext& ctx);

/// Reads an index accessor (SCALAR of unsigned byte, short or int, as glTF requires).
/// Errors as read_float_accessor.
[[nodiscard]] Result<std::vector<std::uint32_t>>
read_index_accessor(const tinygltf::Model& model, int index, const std::string& what,
                    std::uint64_t max_elements, const GltfLoadContext& ctx);

} // namespace snell::detail
