// Snell scenes (internal): procedural meshes for the built-in scenes.
//
// Every mesh has analytic normals, tangents and texture coordinates, so nothing depends on a
// tangent generator. Conventions, shared with the glTF loader and the scene shaders:
// - right-handed object space, +Y up; front faces are counter-clockwise seen from outside;
// - uv: v = 0 is an image's first (top) row; a face "seen from outside" shows its image upright;
// - tangent.xyz = direction of increasing u; tangent.w = +-1 such that
//   bitangent = cross(normal, tangent.xyz) * w points toward decreasing v (the image's top), the
//   glTF normal-map convention (+X right, +Y up in the image).
#pragma once

#include <snell/scene.hpp>

#include <cstdint>

namespace snell::detail {

/// Axis-aligned box centred on the origin with full extents `size` (> 0). 24 vertices (flat
/// faces). `uv_per_metre` == 0: every face maps the whole image [0,1]^2; > 0: uv = object-space
/// metres along the face times `uv_per_metre`, continuous across faces sharing a plane.
[[nodiscard]] Mesh make_box(glm::vec3 size, float uv_per_metre = 0.0f);

/// Horizontal plane y = 0 facing +Y, centred on the origin, `size` = (x, z) extents, split into
/// `divisions` x `divisions` quads (>= 1). u runs along +X, the image's top is toward -Z.
/// `uv_per_metre` as for make_box.
[[nodiscard]] Mesh make_plane(glm::vec2 size, std::uint32_t divisions = 1,
                              float uv_per_metre = 0.0f);

/// UV sphere centred on the origin. `segments` (>= 3) around +Y, `rings` (>= 2) pole to pole.
/// u = longitude / 2pi (0 at +Z, increasing toward +X), v = 0 at the north pole (+Y).
[[nodiscard]] Mesh make_sphere(float radius, std::uint32_t segments = 48, std::uint32_t rings = 24);

/// Capped cylinder along Y centred on the origin (y in [-height/2, height/2]), `segments` >= 3.
/// Side: u as for the sphere, v = 0 at the top. Caps: planar uv over the disc.
[[nodiscard]] Mesh make_cylinder(float radius, float height, std::uint32_t segments = 32);

/// Torus around the Y axis centred on the origin: ring radius `major`, tube radius `minor`
/// (0 < minor < major). u = angle around Y / 2pi, v runs around the tube.
[[nodiscard]] Mesh make_torus(float major, float minor, std::uint32_t segments = 48,
                              std::uint32_t sides = 24);

/// The two halves of an open-top basin, so that they can carry different materials.
enum class BasinPart : std::uint8_t {
  inside, ///< Floor and inner walls, normals facing into the pool.
  outside ///< Rim (top of the walls) and outer walls, normals facing out; no bottom face.
};

/// Open-top rectangular basin standing on y = 0 (its origin is the centre of its footprint).
/// `inner_size` = (x, z) extents of the water area; rim at y = `height`; walls `wall` thick;
/// the inner floor at y = `floor_thickness` (< height). uv in metres times `uv_per_metre`.
[[nodiscard]] Mesh make_basin(glm::vec2 inner_size, float height, float wall, float floor_thickness,
                              BasinPart part, float uv_per_metre = 1.0f);

} // namespace snell::detail
