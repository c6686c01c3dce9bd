#include "water_fixture.hpp"

#include <snell/math.hpp>

namespace snell::test {

Scene water_test_scene() {
  Scene s = empty_dark_scene();
  s.anchors.push_back(Anchor{"water", {0.0f, 0.0f, 0.0f}, {20.0f, 0.0f, 20.0f}, -1});
  Material floor;
  floor.name = "floor";
  floor.base_color = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  floor.emissive = glm::vec3(0.2f);
  floor.specular = 0.0f;
  s.materials.push_back(floor);
  Mesh quad = make_quad_mesh({10.0f, 10.0f}, static_cast<int>(s.materials.size()) - 1);
  add_object(s, quad, {0.0f, -2.0f, 0.0f});
  return s;
}

void WaterRig::init(Context& ctx) {
  init_frame(ctx);
  auto w = create_water(effect_info(ctx));
  REQUIRE_MESSAGE(w.has_value(), (w ? std::string() : w.error().message));
  water = std::move(*w);
}

Image WaterRig::render(float time, bool with_water) {
  Effect* effects[] = {water.get()};
  return render_effects(with_water ? Span<Effect* const>(effects) : Span<Effect* const>(), time);
}

std::unique_ptr<WaterEffect> bare_water(Context& ctx) {
  EffectCreateInfo info;
  info.context = &ctx;
  auto created = create_water(info);
  REQUIRE_MESSAGE(created.has_value(), created.error().message);
  return std::move(*created);
}

PixelRay pixel_ray(const SceneView& view, std::uint32_t x, std::uint32_t y, std::uint32_t width,
                   std::uint32_t height) {
  const glm::mat4 inv = glm::inverse(view.proj * view.view);
  const glm::vec2 ndc((static_cast<float>(x) + 0.5f) / static_cast<float>(width) * 2.0f - 1.0f,
                      (static_cast<float>(y) + 0.5f) / static_cast<float>(height) * 2.0f - 1.0f);
  const glm::vec4 a = inv * glm::vec4(ndc, 0.0f, 1.0f);
  const glm::vec4 b = inv * glm::vec4(ndc, 1.0f, 1.0f);
  PixelRay ray;
  ray.origin = glm::vec3(a) / a.w;
  ray.dir = glm::normalize(glm::vec3(b) / b.w - ray.origin);
  return ray;
}

} // namespace snell::test
