#include "glass_fixture.hpp"

#include <snell/math.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace snell::test {

Scene glass_test_scene(glm::vec3 wall_color, float wall_z) {
  Scene s = empty_dark_scene();
  const int wall = add_emissive_material(s, wall_color);
  add_object(s, make_box_mesh({20.0f, 20.0f, 0.05f}, wall), {0.0f, 0.0f, wall_z - 0.05f});
  return s;
}

int add_marker(Scene& scene, glm::vec3 front_center, glm::vec2 half, glm::vec3 color) {
  const int material = add_emissive_material(scene, color);
  return add_object(scene, make_box_mesh({half.x, half.y, 0.005f}, material),
                    front_center - glm::vec3(0.0f, 0.0f, 0.005f));
}

int add_panel(Scene& scene, glm::vec3 center, glm::vec2 half, int material) {
  const int object = add_object(scene, make_quad_mesh(half, material), center);
  // The quad lies in XZ facing +Y: a quarter turn about +X makes it face +Z.
  scene.objects[static_cast<std::size_t>(object)].transform =
      glm::rotate(glm::translate(glm::mat4(1.0f), center), glm::radians(90.0f), {1, 0, 0});
  return object;
}

int add_transmissive_material(Scene& scene, glm::vec3 tint) {
  Material m;
  m.name = "transmissive";
  m.base_color = glm::vec4(tint, 1.0f);
  m.transmission = 1.0f;
  m.roughness = 0.0f; // Material's default 0.5 would frost it
  m.ior = 1.5f;
  m.thickness = 0.0f;
  scene.materials.push_back(m);
  return static_cast<int>(scene.materials.size()) - 1;
}

void GlassRig::init(Context& ctx) {
  init_frame(ctx);
  auto g = create_glass(effect_info(ctx));
  GLASS_REQUIRE_OK(g);
  glass = std::move(*g);
}

Image GlassRig::render(bool with_glass) {
  Effect* effects[] = {glass.get()};
  return with_glass ? render_effects(effects) : render_effects({});
}

void GlassRig::set(const GlassParams& p) {
  auto r = glass->set_params(p);
  GLASS_REQUIRE_OK(r);
}

glm::mat4 GlassRig::view_proj() const {
  const SceneView v = main_view();
  return v.proj * v.view;
}

Image host_render(Context& ctx, SceneRenderer& renderer, const RenderTarget& target, Effect& effect,
                  const CameraDesc& camera, const DirectionalLight& light,
                  std::uint64_t frame_index, SceneSnapshot* snapshot,
                  std::optional<VkRect2D> region) {
  FrameInfo frame;
  frame.frame_index = frame_index;
  frame.main_view = make_main_view(camera, target.width(), target.height());
  frame.main_view.color_format = target.vk_color_format();
  frame.main_view.depth_format = target.depth_format();
  frame.light = light;
  frame.snapshot = snapshot;
  GLASS_REQUIRE_OK(effect.update(frame));
  renderer.set_hidden_objects(effect.drawn_objects());
  Result<void> passes, scene_drawn, copied, drawn;
  const float clear[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  GLASS_REQUIRE_OK(ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    passes = effect.record_passes(cmd, frame, renderer);
    target.begin_rendering(cmd, clear);
    scene_drawn = renderer.draw_scene(cmd, frame.main_view);
    target.end_rendering(cmd);
    if (snapshot != nullptr && effect.wants_snapshot()) {
      SnapshotSource src;
      src.color = target.color_image();
      src.color_format = target.vk_color_format();
      src.color_layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
      src.depth = target.depth_image();
      src.depth_layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
      src.extent = {target.width(), target.height()};
      src.view_proj = frame.main_view.proj * frame.main_view.view;
      src.mips = effect.wants_snapshot_mips();
      src.region = region ? *region : effect.snapshot_region();
      copied = snapshot->record(cmd, src, frame_index);
    }
    target.continue_rendering(cmd);
    drawn = effect.record_draw(cmd, frame);
    target.end_rendering(cmd);
  }));
  GLASS_REQUIRE_OK(passes);
  GLASS_REQUIRE_OK(scene_drawn);
  GLASS_REQUIRE_OK(copied);
  GLASS_REQUIRE_OK(drawn);
  auto image = read_rgba8(ctx, target);
  GLASS_REQUIRE_OK(image);
  return *image;
}

GlassParams transmission_only(GlassParams p) {
  p.fresnel = GlassFresnel::none;
  p.specular_intensity = 0.0f;
  p.refraction_scale = 0.0f;
  p.color_blend = 0.0f;
  return p;
}

GlassParams pane_params(glm::vec3 normal, float thickness) {
  GlassParams p = transmission_only();
  p.pane = true;
  p.center = {0.0f, 1.5f, 0.0f};
  p.size = {4.0f, 4.0f};
  p.normal = normal;
  p.thickness = thickness;
  p.ior = 1.5f;
  return p;
}

CameraDesc front_camera() {
  CameraDesc c;
  c.eye = {0.0f, 1.5f, 3.0f};
  c.target = {0.0f, 1.5f, 0.0f};
  c.yfov = glm::radians(50.0f);
  return c;
}

glm::vec3 turned_normal(float degrees) {
  const float a = glm::radians(degrees);
  return {std::sin(a), 0.0f, std::cos(a)};
}

std::string first_difference(const GlassParams& a, const GlassParams& b) {
#define SNELL_GLASS_FIELD(f)                                                                       \
  if (!(a.f == b.f)) {                                                                             \
    return #f;                                                                                     \
  }
  SNELL_GLASS_FIELD(pane)
  SNELL_GLASS_FIELD(center)
  SNELL_GLASS_FIELD(size)
  SNELL_GLASS_FIELD(normal)
  SNELL_GLASS_FIELD(thickness)
  SNELL_GLASS_FIELD(ior)
  SNELL_GLASS_FIELD(dispersion)
  SNELL_GLASS_FIELD(roughness)
  SNELL_GLASS_FIELD(tint)
  SNELL_GLASS_FIELD(attenuation_color)
  SNELL_GLASS_FIELD(attenuation_distance)
  SNELL_GLASS_FIELD(refraction_scale)
  SNELL_GLASS_FIELD(color_blend)
  SNELL_GLASS_FIELD(normal_map)
  SNELL_GLASS_FIELD(color_texture)
  SNELL_GLASS_FIELD(texture_scale)
  SNELL_GLASS_FIELD(fresnel)
  SNELL_GLASS_FIELD(specular_power)
  SNELL_GLASS_FIELD(specular_intensity)
  SNELL_GLASS_FIELD(max_layers)
  SNELL_GLASS_FIELD(debug_view)
#undef SNELL_GLASS_FIELD
  return {};
}

double srgb_to_linear(double e) {
  return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
}

double linear_to_srgb(double l) {
  l = std::clamp(l, 0.0, 1.0);
  return l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
}

int channel(const Image& image, std::uint32_t x, std::uint32_t y, int c) {
  REQUIRE(x < image.width);
  REQUIRE(y < image.height);
  return image.rgba8[(std::size_t{y} * image.width + x) * 4 + static_cast<std::size_t>(c)];
}

double linear_at(const Image& image, std::uint32_t x, std::uint32_t y, int c) {
  return srgb_to_linear(channel(image, x, y, c) / 255.0);
}

glm::dvec2 weighted_centroid(const Image& image, int c, double floor, PixelBox box,
                             double* weight) {
  glm::dvec2 sum(0.0);
  double total = 0.0;
  for (int y = std::max(box.y0, 0); y < std::min(box.y1, static_cast<int>(image.height)); ++y) {
    for (int x = std::max(box.x0, 0); x < std::min(box.x1, static_cast<int>(image.width)); ++x) {
      const double w =
          linear_at(image, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), c) - floor;
      if (w > 0.0) {
        sum += w * glm::dvec2(x + 0.5, y + 0.5);
        total += w;
      }
    }
  }
  if (weight != nullptr) {
    *weight = total;
  }
  return total > 0.0 ? sum / total : glm::dvec2(-1.0);
}

PixelBox box_around(glm::dvec2 center, int half, const Image& image) {
  const int cx = static_cast<int>(std::floor(center.x)),
            cy = static_cast<int>(std::floor(center.y));
  return PixelBox{std::max(cx - half, 0), std::max(cy - half, 0),
                  std::min(cx + half + 1, static_cast<int>(image.width)),
                  std::min(cy + half + 1, static_cast<int>(image.height))};
}

Ray camera_ray(const SceneView& view, glm::dvec2 pixel, std::uint32_t width, std::uint32_t height) {
  const glm::dmat4 inv = glm::inverse(glm::dmat4(view.proj) * glm::dmat4(view.view));
  const glm::dvec2 ndc = pixel / glm::dvec2(width, height) * 2.0 - 1.0;
  const glm::dvec4 far = inv * glm::dvec4(ndc, 1.0, 1.0);
  const glm::dvec3 eye(view.eye);
  return Ray{eye, glm::normalize(glm::dvec3(far) / far.w - eye)};
}

glm::dvec2 project_pixel(const SceneView& view, glm::dvec3 world, std::uint32_t width,
                         std::uint32_t height) {
  const glm::dvec4 clip = glm::dmat4(view.proj) * glm::dmat4(view.view) * glm::dvec4(world, 1.0);
  const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
  return (ndc * 0.5 + 0.5) * glm::dvec2(width, height);
}

namespace {

/// Vector Snell's law, eta = n1 / n2, `n` facing the incident side; nullopt under TIR.
std::optional<glm::dvec3> refract_exact(glm::dvec3 d, glm::dvec3 n, double eta) {
  const double cos_i = -glm::dot(n, d);
  const double k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
  if (k < 0.0) {
    return std::nullopt;
  }
  return glm::normalize(eta * d + (eta * cos_i - std::sqrt(k)) * n);
}

} // namespace

std::optional<Ray> trace_slab(const Ray& ray, const Slab& slab) {
  const glm::dvec3 n = glm::normalize(slab.normal);
  const double side = glm::dot(ray.origin - slab.center, n) >= 0.0 ? 1.0 : -1.0;
  const glm::dvec3 face_n = side * n; // the entry face's outward normal, toward the ray's origin
  const glm::dvec3 entry_point = slab.center + face_n * (0.5 * slab.thickness);
  const double denom = glm::dot(ray.dir, face_n);
  if (denom >= 0.0) {
    return std::nullopt;
  }
  const double s1 = glm::dot(entry_point - ray.origin, face_n) / denom;
  if (s1 <= 0.0) {
    return std::nullopt;
  }
  const glm::dvec3 p1 = ray.origin + ray.dir * s1;
  const auto inside = refract_exact(ray.dir, face_n, 1.0 / slab.ior);
  if (!inside) {
    return std::nullopt;
  }
  // The exit face: the parallel plane `thickness` further along -face_n.
  const glm::dvec3 exit_point = slab.center - face_n * (0.5 * slab.thickness);
  const double s2 = glm::dot(exit_point - p1, face_n) / glm::dot(*inside, face_n);
  const glm::dvec3 p2 = p1 + *inside * s2;
  // Leaving: from glass into air; the normal facing the incident side (inside) is face_n.
  const auto out = refract_exact(*inside, face_n, slab.ior);
  if (!out) {
    return std::nullopt;
  }
  return Ray{p2, *out};
}

std::optional<glm::dvec2> pixel_through_slab(const SceneView& view, std::uint32_t width,
                                             std::uint32_t height, const Slab& slab,
                                             glm::dvec3 target, glm::dvec3 plane_normal) {
  const glm::dvec3 pn = glm::normalize(plane_normal);
  // Two axes spanning the target plane.
  const glm::dvec3 helper = std::abs(pn.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  const glm::dvec3 ax = glm::normalize(glm::cross(helper, pn));
  const glm::dvec3 ay = glm::cross(pn, ax);
  // Residual: where the traced ray of `pixel` meets the plane, minus the target, in the plane.
  auto residual = [&](glm::dvec2 pixel) -> std::optional<glm::dvec2> {
    const auto out = trace_slab(camera_ray(view, pixel, width, height), slab);
    if (!out) {
      return std::nullopt;
    }
    const double dn = glm::dot(out->dir, pn);
    if (std::abs(dn) < 1e-12) {
      return std::nullopt;
    }
    const double s = glm::dot(target - out->origin, pn) / dn;
    const glm::dvec3 hit = out->origin + out->dir * s;
    return glm::dvec2(glm::dot(hit - target, ax), glm::dot(hit - target, ay));
  };
  glm::dvec2 pixel = project_pixel(view, target, width, height);
  constexpr double h = 1e-3;
  for (int iteration = 0; iteration < 50; ++iteration) {
    const auto r = residual(pixel);
    if (!r) {
      return std::nullopt;
    }
    if (glm::length(*r) < 1e-9) {
      return pixel;
    }
    const auto rx0 = residual(pixel - glm::dvec2(h, 0)), rx1 = residual(pixel + glm::dvec2(h, 0));
    const auto ry0 = residual(pixel - glm::dvec2(0, h)), ry1 = residual(pixel + glm::dvec2(0, h));
    if (!rx0 || !rx1 || !ry0 || !ry1) {
      return std::nullopt;
    }
    const glm::dmat2 jacobian((*rx1 - *rx0) / (2.0 * h), (*ry1 - *ry0) / (2.0 * h));
    pixel -= glm::inverse(jacobian) * *r;
  }
  return std::nullopt;
}

double edge_width(const Image& image, std::uint32_t y, int x0, int x1, int c, int plateau) {
  std::vector<double> v;
  for (int x = x0; x < x1; ++x) {
    v.push_back(linear_at(image, static_cast<std::uint32_t>(x), y, c));
  }
  if (static_cast<int>(v.size()) < 2 * plateau + 2) {
    return -1.0;
  }
  double lo = 0.0, hi = 0.0;
  for (int i = 0; i < plateau; ++i) {
    lo += v[static_cast<std::size_t>(i)];
    hi += v[v.size() - 1 - static_cast<std::size_t>(i)];
  }
  lo /= plateau;
  hi /= plateau;
  if (hi - lo < 0.05) {
    return -1.0;
  }
  // First crossing of `level` going right, interpolated between pixel centres.
  auto crossing = [&](double fraction) {
    const double level = lo + fraction * (hi - lo);
    for (std::size_t i = 1; i < v.size(); ++i) {
      if (v[i - 1] < level && v[i] >= level) {
        return static_cast<double>(i - 1) + (level - v[i - 1]) / (v[i] - v[i - 1]);
      }
    }
    return -1.0;
  };
  const double a = crossing(0.1), b = crossing(0.9);
  return a >= 0.0 && b >= 0.0 ? b - a : -1.0;
}

} // namespace snell::test
