// Internal: vertex-attribute generation and validation shared by the glTF loader and the
// procedural scenes. No Vulkan, no I/O.
#pragma once

#include <snell/scene.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace snell::detail {

/// How generate_flat_or_smooth_normals treats vertices shared by several triangles.
enum class NormalMode : std::uint8_t {
  /// Every triangle gets its own three vertices carrying its face normal (shared vertices are
  /// duplicated, `indices` becomes 0..n-1). glTF requires flat normals when a primitive has none.
  flat,
  /// Shared vertices keep one normal: the area-weighted average of the face normals of the
  /// triangles that use them.
  smooth,
};

/// Computes Vertex::normal from the indexed triangle list `indices` (3 per triangle).
/// The face normal follows the winding: counter-clockwise triangles (p0, p1, p2) face
/// cross(p1 - p0, p2 - p0). Degenerate triangles (zero area) contribute nothing; a vertex left
/// without any contribution gets +Y. Triangles with an index past `vertices.size()` and a trailing
/// partial triangle are ignored (callers validate indices first; this only keeps it memory-safe).
/// In flat mode the vertex and index arrays are rewritten (vertices.size() == indices.size()).
void generate_flat_or_smooth_normals(std::vector<Vertex>& vertices,
                                     std::vector<std::uint32_t>& indices, NormalMode mode);

/// Computes Vertex::tangent from positions, normals and UVs (normals must be set first).
/// tangent.xyz is the direction of increasing u, made orthogonal to the normal (Gram-Schmidt) and
/// normalised; tangent.w is the handedness such that cross(normal, tangent.xyz) * w points
/// towards decreasing v, i.e. "up" in the image, since glTF's v = 0 is the image's first row and
/// its normal textures use +Y = up. A vertex whose triangles all have degenerate UVs (or no area)
/// gets an arbitrary unit tangent perpendicular to its normal and w = +1 (any_perpendicular).
void generate_tangents(std::vector<Vertex>& vertices, const std::vector<std::uint32_t>& indices);

/// `v` scaled to unit length, or nullopt when it has no direction (all zero, or any NaN or
/// infinite component). Overflow-safe: components up to FLT_MAX normalise correctly.
[[nodiscard]] std::optional<glm::vec3> safe_normalize(glm::vec3 v);

/// A unit vector perpendicular to the unit vector `n` (stable for every direction).
[[nodiscard]] glm::vec3 any_perpendicular(glm::vec3 n);

/// Index of the first vertex whose position has a NaN or infinite component, or nullopt.
[[nodiscard]] std::optional<std::size_t> first_non_finite_position(const std::vector<Vertex>& v);

/// Index of the first vertex with any non-finite attribute (position, normal, tangent, uv).
[[nodiscard]] std::optional<std::size_t> first_non_finite_vertex(const std::vector<Vertex>& v);

/// Position in `indices` of the first value >= vertex_count, or nullopt.
[[nodiscard]] std::optional<std::size_t>
first_index_out_of_range(const std::vector<std::uint32_t>& indices, std::size_t vertex_count);

} // namespace snell::detail
