#include "gpu_fixture.hpp"

#include <snell/math.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <filesystem>

namespace snell::test {

GpuFixture::GpuFixture() {
  ContextDesc desc;
  desc.validation = true;
  auto ctx = Context::create(desc);
  if (!ctx) {
    FAIL("Context::create: " << ctx.error().message);
  }
  ctx_.emplace(std::move(*ctx));
}

GpuFixture::~GpuFixture() {
  if (!ctx_) {
    return;
  }
  vkDeviceWaitIdle(ctx_->device());
  if (ctx_->validation_error_count() != expected_errors_) {
    for (const std::string& m : ctx_->validation_messages()) {
      MESSAGE(m);
    }
  }
  CHECK(ctx_->validation_error_count() == expected_errors_);
}

namespace {
void add_face(Mesh& m, glm::vec3 center, glm::vec3 u, glm::vec3 v) {
  const glm::vec3 n = glm::normalize(glm::cross(u, v));
  const auto base = static_cast<std::uint32_t>(m.vertices.size());
  const glm::vec3 corners[4] = {center - u - v, center + u - v, center + u + v, center - u + v};
  const glm::vec2 uvs[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  for (int i = 0; i < 4; ++i) {
    m.vertices.push_back(Vertex{corners[i], n, glm::vec4(glm::normalize(u), 1.0f), uvs[i]});
  }
  for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) {
    m.indices.push_back(base + i);
  }
}
} // namespace

Mesh make_box_mesh(glm::vec3 h, int material) {
  Mesh m;
  m.name = "box";
  m.material = material;
  add_face(m, {h.x, 0, 0}, {0, 0, -h.z}, {0, h.y, 0});
  add_face(m, {-h.x, 0, 0}, {0, 0, h.z}, {0, h.y, 0});
  add_face(m, {0, h.y, 0}, {h.x, 0, 0}, {0, 0, -h.z});
  add_face(m, {0, -h.y, 0}, {h.x, 0, 0}, {0, 0, h.z});
  add_face(m, {0, 0, h.z}, {h.x, 0, 0}, {0, h.y, 0});
  add_face(m, {0, 0, -h.z}, {-h.x, 0, 0}, {0, h.y, 0});
  return m;
}

Mesh make_quad_mesh(glm::vec2 h, int material) {
  Mesh m;
  m.name = "quad";
  m.material = material;
  add_face(m, {0, 0, 0}, {h.x, 0, 0}, {0, 0, -h.y});
  return m;
}

int add_emissive_material(Scene& scene, glm::vec3 color) {
  Material mat;
  mat.name = "emissive";
  mat.base_color = glm::vec4(0, 0, 0, 1);
  mat.emissive = color;
  mat.specular = 0.0f;
  scene.materials.push_back(mat);
  return static_cast<int>(scene.materials.size()) - 1;
}

int add_object(Scene& scene, const Mesh& mesh, glm::vec3 position, std::uint32_t layers) {
  scene.meshes.push_back(mesh);
  Object o;
  o.name = mesh.name;
  o.mesh = static_cast<int>(scene.meshes.size()) - 1;
  o.transform = glm::translate(glm::mat4(1.0f), position);
  o.layers = layers;
  scene.objects.push_back(o);
  return static_cast<int>(scene.objects.size()) - 1;
}

Scene empty_dark_scene() {
  Scene s;
  s.name = "test";
  s.light.intensity = 0.0f;
  s.light.ambient = glm::vec3(0.0f);
  s.sky.zenith = s.sky.horizon = s.sky.ground = glm::vec3(0.0f);
  return s;
}

Image render_view(Context& ctx, SceneRenderer& renderer, const SceneView& view_in,
                  std::uint32_t width, std::uint32_t height) {
  auto target = RenderTarget::create(ctx, RenderTargetDesc{.width = width,
                                                           .height = height,
                                                           .color = ColorFormat::rgba8_unorm,
                                                           .debug_name = "test target"});
  REQUIRE_MESSAGE(target.has_value(), target.error().message);
  SceneView view = view_in;
  view.extent = {width, height};
  view.color_format = target->vk_color_format();
  view.depth_format = VK_FORMAT_D32_SFLOAT;
  const float clear[4] = {0, 0, 0, 1};
  Result<void> drawn;
  auto r = ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    target->begin_rendering(cmd, clear);
    drawn = renderer.draw_scene(cmd, view);
    target->end_rendering(cmd);
  });
  REQUIRE_MESSAGE(r.has_value(), r.error().message);
  CHECK_MESSAGE(drawn.has_value(), drawn.error().message);
  auto image = read_rgba8(ctx, *target);
  REQUIRE_MESSAGE(image.has_value(), image.error().message);
  return *image;
}

Blob find_color(const Image& image, glm::vec3 rgb, int tolerance) {
  Blob b;
  glm::dvec2 sum(0.0);
  const glm::ivec3 want = glm::ivec3(glm::round(glm::clamp(rgb, 0.0f, 1.0f) * 255.0f));
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const std::uint8_t* p = &image.rgba8[(std::size_t{y} * image.width + x) * 4];
      if (std::abs(p[0] - want.r) <= tolerance && std::abs(p[1] - want.g) <= tolerance &&
          std::abs(p[2] - want.b) <= tolerance) {
        sum += glm::dvec2(x + 0.5, y + 0.5);
        ++b.count;
      }
    }
  }
  if (b.count > 0) {
    b.centroid = glm::vec2(sum / static_cast<double>(b.count));
  }
  return b;
}

glm::vec2 predict_pixel(const glm::mat4& view_proj, glm::vec3 world, std::uint32_t width,
                        std::uint32_t height) {
  const glm::vec2 uv = project_to_uv(view_proj * glm::vec4(world, 1.0f), ClipConvention::vulkan);
  return uv * glm::vec2(width, height);
}

void save_png_in(const std::string& dir, const Image& image, const std::string& name) {
  std::filesystem::create_directories(dir);
  (void)write_png(std::filesystem::path(dir) / (name + ".png"), image);
}

} // namespace snell::test
