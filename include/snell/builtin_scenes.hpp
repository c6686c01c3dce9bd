// Snell scenes: the built-in procedural demo scenes and the procedural textures they use.
//
// The scenes need no asset files: meshes (with analytic normals, tangents and uvs) and textures
// are generated in memory, deterministically (the same call returns the same bytes). They
// recreate the source tutorials' set-ups (see seeds/README.md) in Snell's conventions: world
// right-handed, +Y up, units metres, front faces counter-clockwise seen from outside.
//
// Effects find where to attach through Scene::anchors ("water", "window", "probe"), never
// through object names, so a glTF scene with the same anchors works the same way.
//
// Layers (snell::layer): every object is drawn in the main view and captured into cube maps.
// An object that lies wholly under the pool's water has no `reflected` bit (a planar reflection
// only shows what is above the plane); one wholly above the water has no `refracted` bit. The
// spheres scene's probe owner has no `captured` bit, so a cube-map capture excludes it through
// the layer mask alone (see make_spheres_scene).
#pragma once

#include <snell/result.hpp>
#include <snell/scene.hpp>

#include <glm/vec3.hpp>

#include <cstdint>
#include <string_view>
#include <vector>

namespace snell {

/// Names accepted by make_builtin_scene, in a fixed order: {"pool", "window", "spheres", "room",
/// "mirror"}.
[[nodiscard]] std::vector<std::string_view> builtin_scene_names();

/// The built-in scene called `name` (case-sensitive, one of builtin_scene_names()).
/// Unknown name: Error{ErrorCode::unknown_name, "unknown scene 'x'; built-in scenes: pool,
/// window, spheres, room, mirror"}.
[[nodiscard]] Result<Scene> make_builtin_scene(std::string_view name);

/// Seed 000's water scene: a raised pool in a courtyard.
/// - ground: 40 x 40 m stone-flag plane at y = 1;
/// - back wall: brick box 24 x 10 x 0.6 m centred at (0, 6, 8) (the seed's wall position);
/// - basin: open-top pool standing on the ground, footprint centred at (0, 1, 0), inner water
///   area 8 x 8 m (x, z in [-4, 4]), walls 0.6 m thick, rim at y = 3, tiled floor at y = 1.25
///   ("bath at y = 2": the basin spans y 1..3);
/// - anchor "water": position (0, 2.75, 0) (the seed's water height), size (8, 0, 8): the water
///   plane y = 2.75 over the basin's inner area, 1.5 m above its floor, 0.25 m below the rim.
///   The water surface is not an object: the water effect draws it;
/// - under water (no `reflected` layer): a red box, a yellow sphere and a blue ring lying on the
///   pool floor; straddling the surface: an orange ball floating at (-1, 2.6, 2), radius 0.8;
///   above (no `refracted` layer): two columns on the back rim corners (radius 0.25, y 3..5.5)
///   and a white sphere (radius 0.7) on a pedestal behind the pool at (2, 4.1, 6.2);
/// - camera 0: eye (-6, 8, -12) looking at (0, 4.5, 1) (diagonally, like the seed's camera),
///   50 degree vertical field of view: at aspect 4:3 or wider the whole pool, the wall's top
///   and the wall's reflection in the water are in view;
/// - light from the front left (travelling toward +Z), daylight sky.
[[nodiscard]] Scene make_pool_scene();

/// Seed 003's glass scene: a spinning crate behind a window.
/// - floor: 20 x 20 m checker plane at y = 0; backdrop: brick box 12 x 6 x 0.3 m centred at
///   (0, 3, -5);
/// - crate: 1.4 m textured cube centred at (0, 1.5, -1.2), spinning about +Y at 0.5 rad/s
///   (Object::spin_axis / spin_rate), above a stone pedestal; a blue ball to its right;
/// - anchor "window": position (0, 1.5, 1.5), size (2.8, 2, 0): a quad in the plane z = 1.5
///   facing +Z (toward the camera), x in [-1.4, 1.4], y in [0.5, 2.5]. The glass is not an
///   object: the glass or ice effect draws it; a wooden frame object surrounds it;
/// - camera 0: eye (0, 2.1, 6) looking at (0, 1.4, -1.2), 45 degree vertical field of view,
///   so the crate is seen through the window and the rest of the room around it.
[[nodiscard]] Scene make_window_scene();

/// Seed 002's dynamic cube map scene: a reflective sphere surrounded by coloured objects.
/// - ground: 30 x 30 m checker plane at y = 0;
/// - probe sphere: radius 1 centred at (0, 1.5, 0) on a short pedestal, a smooth silver
///   material (what the scene renderer draws when no effect replaces it);
/// - anchor "probe": position (0, 1.5, 0), size (2, 2, 2) (the sphere's diameter), object = the
///   probe sphere's index. The sphere's layers omit `captured`, so any capture (whose mask
///   includes `captured`) excludes the owner without an object filter; the index lets the
///   dynamic cube-map effect draw the owner with its own material (same mesh and transform, so
///   a LESS_OR_EQUAL depth test draws exactly over it);
/// - around it, at radius 3.5..4.5 m and azimuths 0, 60, ..., 300 degrees (azimuth 0 = +Z):
///   a red box (spinning), a green sphere, a blue torus (tumbling), a yellow column, a purple
///   box (spinning), a cyan sphere, and a small orange sphere above the probe;
/// - camera 0: eye (5, 3.4, 7.5) looking at (0, 1.4, 0), 45 degree vertical field of view;
/// - light from behind the camera, warm evening sky (a colourful environment to reflect).
[[nodiscard]] Scene make_spheres_scene();
/// A closed room for box projection (parallax-corrected probes): its inside is exactly the
/// dynamic_cubemap's default box (-5, 0, -5)..(5, 5, 5).
/// - floor: 10 x 10 m checker plane at y = 0; walls: 0.2 m boxes whose inner faces are x = +-5
///   (right blue, left green), z = -5 (bricks), z = 5 (plaster); ceiling: inner face at y = 5;
/// - on the right wall (x = 5): a yellow painting (1 x 1.4 m, centre (4.98, 1.8, -2)) and a red
///   one (1.2 x 0.8 m, centre (4.98, 2, 1.2)), 2 cm proud of the wall;
/// - probe sphere: radius 0.7 at (2.8, 1.1, -0.4) on a pedestal, 2.2 m from the right wall,
///   silver, layers without `captured`; anchor "probe" as in the spheres scene;
/// - an orange box at (-2.5, 0.4, -2.5);
/// - camera 0: eye (4.7, 1.6, 0.9) near the right wall, looking at (2.8, 1, -0.4), 50 degree
///   vertical field of view: the ball shows the right wall and its paintings behind the camera,
///   where box projection's correction is large;
/// - light from above (no shadows: the ceiling does not block it).
[[nodiscard]] Scene make_room_scene();
/// The mirror effect's scene, after the classic Vulkan offscreen sample: objects above a mirror
/// floor with a wall behind.
/// - floor: 20 x 20 m checker plane at y = 0; mirror: "mirror_floor", a 6 x 6 m quad at
///   y = 0.01 (x, z in [-3, 3]) facing +Y, dark stone (drawn by the scene renderer without an
///   effect); anchor "mirror": position (0, 0.01, 0), size (6, 0, 6), object = mirror_floor;
/// - a brick wall 12 x 5 x 0.3 m centred at (0, 2.5, -4);
/// - a stone pedestal (radius 0.5, 0.8 m tall) standing on the mirror at the origin, a blue
///   torus (tumbling about X) above it at y = 1.55;
/// - a red box (0.7 m, turned 30 degrees) standing on the mirror at (1.8, 0.36, 1), an orange
///   ball (radius 0.35) floating 1 m above the mirror at (-1.8, 1.36, 1), a green ball
///   (radius 0.35) resting on it at (-1.8, 0.36, -1.2);
/// - camera 0: eye (0, 2.6, 7) looking at (0, 0.7, 0), 45 degree vertical field of view.
[[nodiscard]] Scene make_mirror_scene();

// --- Procedural textures ---------------------------------------------------------------------
// All generators are deterministic and tileable where stated; they reject arguments out of
// range with ErrorCode::invalid_argument (the message names the function, parameter and value)
// instead of clamping. Colours are display (sRGB-encoded) values in [0, 1], stored as
// round(255 * c) in an Image with srgb = true; normal maps are linear (srgb = false).

/// Largest width and height the generators accept (also the glTF loader's default limit).
inline constexpr std::uint32_t max_procedural_image_size = 8192;

/// A size x size checkerboard of `cells` x `cells` squares, colour `a` in the top-left square.
/// - size: pixels, [1, max_procedural_image_size];
/// - cells: squares per side, [1, size]; when size is not a multiple, square edges fall at
///   floor(x * cells / size). Tileable when `cells` is even;
/// - a, b: sRGB colours, each component in [0, 1].
[[nodiscard]] Result<Image> make_checker_image(std::uint32_t size, std::uint32_t cells, glm::vec3 a,
                                               glm::vec3 b);

/// A brick (or tile) pattern for make_brick_image; every field has a usable default.
struct BrickPattern {
  std::uint32_t columns = 4;            ///< Bricks per row, >= 1. Default 4.
  std::uint32_t rows = 8;               ///< Rows, even (so the image tiles), >= 2. Default 8.
  float row_offset = 0.5f;              ///< Shift of odd rows, in bricks, [0, 1). 0.5 = running
                                        ///< bond (default), 0 = square tiles.
  float mortar = 0.12f;                 ///< Joint width / brick height, [0, 0.5). Default 0.12.
  glm::vec3 brick{0.62f, 0.30f, 0.22f}; ///< sRGB brick colour, [0, 1]. Default red-brown.
  glm::vec3 joint{0.80f, 0.78f, 0.72f}; ///< sRGB mortar colour, [0, 1]. Default light grey.
  float variation = 0.12f;              ///< Per-brick brightness jitter, [0, 1]. Default 0.12.
  std::uint32_t seed = 1;               ///< Seed of the jitter; any value. Default 1.
};

/// A tileable size x size brick image (rows top first; joints between all bricks, including
/// across the image edges, so repeats line up).
/// - size: pixels, [1, max_procedural_image_size], and at least 4 pixels per brick in both
///   directions (size >= 4 * columns and size >= 4 * rows);
/// - pattern: see BrickPattern for each field's range.
[[nodiscard]] Result<Image> make_brick_image(std::uint32_t size, const BrickPattern& pattern = {});

/// A number in [0, 1) from three integers (lowbias32 hashes chained): the seeded hash every
/// procedural texture uses (also the glass plugin's frost), identical on every platform.
[[nodiscard]] float unit_hash(std::uint32_t a, std::uint32_t b = 0, std::uint32_t c = 0);

/// A tileable tangent-space normal map of gentle ripples (water, ice, frosted glass).
/// The height field is a sum of 16 sine waves with integer frequencies (1..8 cycles per image
/// in x and y) chosen from `seed`, so opposite edges continue each other exactly; the normal is
/// normalize(-strength * dh/du, strength * dh/dv_up, 1), encoded as round(255 * (n * 0.5 + 0.5))
/// in RGB (alpha 255), srgb = false. Green is +Y toward the image's top (glTF convention: pairs
/// with tangent = +u, bitangent = cross(normal, tangent) * w toward decreasing v).
/// - size: pixels, [1, max_procedural_image_size];
/// - strength: largest slope of the height field (0 = flat; 1 tilts at most 45 degrees),
///   finite, [0, 16];
/// - seed: chooses the waves; any value. The same (size, strength, seed) gives the same bytes.
[[nodiscard]] Result<Image> make_noise_normal_map(std::uint32_t size, float strength,
                                                  std::uint32_t seed);

} // namespace snell
