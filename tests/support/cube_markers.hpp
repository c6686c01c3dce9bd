// Test support: six coloured markers around a point, one per cube face and off the face centres
// (a mirrored or rotated face would misplace them), and the check that a capture put each on
// the face, at the texel, that snell::direction_to_cube names. Used by the toolkit's capture
// tests (tests/gpu) and the dynamic_cubemap plugin's own.
#pragma once

#include "gpu_fixture.hpp"

#include <array>
#include <functional>

namespace snell::test {

/// The markers' emissive colours, face order (+X -X +Y -Y +Z -Z).
inline constexpr std::array<glm::vec3, 6> kMarkerColors = {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0),
                                                           glm::vec3(0, 0, 1), glm::vec3(1, 1, 0),
                                                           glm::vec3(1, 0, 1), glm::vec3(0, 1, 1)};

/// A dark scene with marker f (0.24 m cube of kMarkerColors[f]) at `center + offsets[f]`, 3 m
/// along face f's axis and off its centre. Fills `offsets`.
Scene six_marker_scene(glm::vec3 center, std::array<glm::vec3, 6>& offsets);

/// Checks the six faces of a capture of six_marker_scene taken at its centre: face(f) returns
/// face f as RGBA8 (rows top first), `size` pixels square. Marker f's centroid is within 1 px of
/// direction_to_cube(offsets[f]).uv * size on face f, and no other marker shows there.
void check_marker_faces(const std::function<Image(std::uint32_t face)>& face, float size,
                        const std::array<glm::vec3, 6>& offsets);

} // namespace snell::test
