#include "cube_markers.hpp"

#include <snell/math/cube.hpp>

namespace snell::test {

Scene six_marker_scene(glm::vec3 center, std::array<glm::vec3, 6>& offsets) {
  Scene scene = empty_dark_scene();
  for (std::size_t f = 0; f < 6; ++f) {
    const glm::vec3 axis = cube_face_forward(static_cast<CubeFace>(f));
    const glm::vec3 side =
        glm::vec3(axis.y != 0 ? 0.9f : 0.0f, axis.y == 0 ? 0.7f : 0.0f, axis.x != 0 ? -0.8f : 0.6f);
    offsets[f] = 3.0f * axis + side;
    add_object(scene,
               make_box_mesh(glm::vec3(0.12f), add_emissive_material(scene, kMarkerColors[f])),
               center + offsets[f]);
  }
  return scene;
}

void check_marker_faces(const std::function<Image(std::uint32_t face)>& face, float size,
                        const std::array<glm::vec3, 6>& offsets) {
  for (std::uint32_t f = 0; f < 6; ++f) {
    const Image image = face(f);
    const CubeTexel expected = direction_to_cube(offsets[f]);
    REQUIRE(static_cast<std::uint32_t>(expected.face) == f);
    const Blob blob = find_color(image, kMarkerColors[f]);
    CAPTURE(f);
    CAPTURE(blob.centroid);
    CAPTURE(expected.uv * size);
    REQUIRE(blob.count > 4);
    CHECK(glm::length(blob.centroid - expected.uv * size) <= 1.0f);
    for (std::uint32_t other = 0; other < 6; ++other) { // no marker on the wrong face
      if (other != f) {
        CHECK(find_color(image, kMarkerColors[other]).count == 0);
      }
    }
  }
}

} // namespace snell::test
