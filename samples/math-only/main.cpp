// Snell math-only sample: drop include/ into a project with GLM and use the math directly.
//
// Prints, for a camera above a water plane, the mirrored camera used to render the reflection,
// the oblique projection that clips the reflection pass at the water surface, and a table of
// Fresnel reflectance for air -> water. Build with nothing but GLM and include/:
//     c++ -std=c++17 -I include samples/math-only/main.cpp -o snell-math-sample
#include <snell/math.hpp>

#include <glm/trigonometric.hpp>

#include <cmath>

#include <cstdio>

namespace {

void print_matrix(const char* name, const glm::mat4& m) {
  std::printf("%s =\n", name);
  for (int row = 0; row < 4; ++row) {
    std::printf("  [% 9.4f % 9.4f % 9.4f % 9.4f]\n", static_cast<double>(m[0][row]),
                static_cast<double>(m[1][row]), static_cast<double>(m[2][row]),
                static_cast<double>(m[3][row]));
  }
}

void print_vec3(const char* name, glm::vec3 v) {
  std::printf("%s = (%.4f, %.4f, %.4f)\n", name, static_cast<double>(v.x), static_cast<double>(v.y),
              static_cast<double>(v.z));
}

} // namespace

int main() {
  // The seeds' set-up: water at height 2.75, a camera above it looking across the pool.
  const float water_height = 2.75f;
  const snell::Plane water{{0.0f, 1.0f, 0.0f}, -water_height};
  const glm::vec3 eye(-10.0f, 6.0f, -10.0f);
  const glm::vec3 target(0.0f, 2.0f, 0.0f);
  const glm::mat4 view = snell::look_at(eye, target, {0.0f, 1.0f, 0.0f});
  // Vulkan: depth [0,1], clip y flipped for a standard viewport.
  const glm::mat4 proj = snell::flip_clip_y(snell::perspective(
      glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 100.0f, snell::DepthRange::zero_to_one));

  std::printf("== Reflected camera (water plane y = %.2f) ==\n", static_cast<double>(water_height));
  print_vec3("eye", eye);
  print_vec3("mirrored eye", snell::reflect_point(water, eye));
  const glm::mat4 mirrored_view = snell::reflect_view(view, water);
  print_matrix("reflect_view(view, water)", mirrored_view);
  std::printf("det = %.4f (mirrored: swap the front face)\n\n",
              static_cast<double>(glm::determinant(mirrored_view)));

  std::printf("== Oblique projection: the water surface becomes the near plane ==\n");
  const glm::vec4 view_plane = snell::to_vec4(snell::transform_plane(water, mirrored_view));
  const glm::mat4 oblique =
      snell::oblique_projection(proj, view_plane, snell::DepthRange::zero_to_one);
  print_matrix("oblique_projection(proj, plane, zero_to_one)", oblique);
  const glm::vec4 on_water = oblique * mirrored_view * glm::vec4(1.0f, water_height, 2.0f, 1.0f);
  std::printf("depth of a point on the water: %.6f (near plane: 0)\n\n",
              static_cast<double>(on_water.z / on_water.w));

  std::printf("== Fresnel reflectance, air -> water (eta = 1/%.3f) ==\n",
              static_cast<double>(snell::ior::water));
  std::printf("  angle   exact    schlick\n");
  const float f0 = snell::f0_from_ior(snell::ior::air, snell::ior::water);
  for (int degrees = 0; degrees <= 90; degrees += 10) {
    const float c = std::cos(glm::radians(static_cast<float>(degrees)));
    std::printf(
        "  %3d    %.4f   %.4f\n", degrees,
        static_cast<double>(snell::fresnel_dielectric(c, snell::ior::air / snell::ior::water)),
        static_cast<double>(snell::fresnel_schlick(c, f0)));
  }
  std::printf(
      "critical angle water -> air: %.2f degrees\n",
      static_cast<double>(glm::degrees(snell::critical_angle(snell::ior::water, snell::ior::air))));
  return 0;
}
