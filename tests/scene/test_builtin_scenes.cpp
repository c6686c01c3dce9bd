// The built-in procedural scenes: names, structure, and the geometric set-up each effect needs
// (water between the pool's floor and rim, crate behind the window, probe at the sphere).
#include <snell/builtin_scenes.hpp>

#include <doctest/doctest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace snell;

namespace snell_test {
void check_mesh_valid(const Mesh& mesh); // test_procedural.cpp
} // namespace snell_test

namespace {

struct Box {
  glm::vec3 lo{1e30f}, hi{-1e30f};
};

// World bounds of one object at `time` (spinning objects move).
Box object_bounds(const Scene& scene, const Object& object, float time = 0.0f) {
  Box box;
  const glm::mat4 m = object.world_at(time);
  for (const Vertex& v : scene.meshes.at(static_cast<std::size_t>(object.mesh)).vertices) {
    const glm::vec3 p(m * glm::vec4(v.position, 1.0f));
    box.lo = glm::min(box.lo, p);
    box.hi = glm::max(box.hi, p);
  }
  return box;
}

const Object& object_named(const Scene& scene, const std::string& name) {
  for (const Object& o : scene.objects) {
    if (o.name == name) {
      return o;
    }
  }
  FAIL("no object '" << name << "' in scene '" << scene.name << "'");
  throw std::logic_error("unreachable");
}

Scene scene_named(std::string_view name) {
  Result<Scene> r = make_builtin_scene(name);
  REQUIRE(r);
  return std::move(r).value();
}

// Clip-space position of `p` through camera `c` at aspect 4:3 (the narrowest usual framing;
// wider images only show more at the sides).
glm::vec4 clip(const CameraDesc& c, glm::vec3 p) {
  const glm::mat4 proj = glm::perspective(c.yfov, 4.0f / 3.0f, c.z_near, c.z_far);
  return proj * glm::lookAt(c.eye, c.target, c.up) * glm::vec4(p, 1.0f);
}

bool in_view(const CameraDesc& c, glm::vec3 p) {
  const glm::vec4 q = clip(c, p);
  return q.w > 0.0f && std::abs(q.x) < q.w && std::abs(q.y) < q.w;
}

// Where the segment from `from` to `to` crosses the plane `axis` = `value` (0 x, 1 y, 2 z).
glm::vec3 cross_plane(glm::vec3 from, glm::vec3 to, int axis, float value) {
  const float t = (value - from[axis]) / (to[axis] - from[axis]);
  return from + (to - from) * t;
}

} // namespace

TEST_CASE("builtin scenes: names and lookup") {
  const std::vector<std::string_view> names = builtin_scene_names();
  REQUIRE(names.size() == 5);
  CHECK(names[0] == "pool");
  CHECK(names[1] == "window");
  CHECK(names[2] == "spheres");
  CHECK(names[3] == "room");
  CHECK(names[4] == "mirror");
  for (std::string_view name : names) {
    const Result<Scene> r = make_builtin_scene(name);
    REQUIRE(r);
    CHECK(r->name == name);
  }
  const Result<Scene> unknown = make_builtin_scene("lake");
  REQUIRE(!unknown);
  CHECK(unknown.error().code == ErrorCode::unknown_name);
  CHECK(unknown.error().message ==
        "unknown scene 'lake'; built-in scenes: pool, window, spheres, room, mirror");
  CHECK(!make_builtin_scene(""));
  CHECK(!make_builtin_scene("Pool")); // case-sensitive
}

TEST_CASE("builtin scenes: every scene is structurally valid") {
  for (std::string_view name : builtin_scene_names()) {
    const Scene s = scene_named(name);
    INFO("scene " << s.name);
    REQUIRE(!s.objects.empty());
    for (const Mesh& mesh : s.meshes) {
      snell_test::check_mesh_valid(mesh);
      CHECK(mesh.material >= -1);
      CHECK(mesh.material < static_cast<int>(s.materials.size()));
    }
    auto valid_image = [&](int i) { return i >= -1 && i < static_cast<int>(s.images.size()); };
    for (const Material& m : s.materials) {
      INFO("material " << m.name);
      CHECK(valid_image(m.base_color_texture));
      CHECK(valid_image(m.normal_texture));
      CHECK(valid_image(m.emissive_texture));
      CHECK(m.uv_scale.x > 0.0f);
      CHECK(m.uv_scale.y > 0.0f);
    }
    for (const Image& image : s.images) {
      CHECK(image.width > 0);
      CHECK(image.height > 0);
      CHECK(image.rgba8.size() == std::size_t{image.width} * image.height * 4u);
    }
    for (const Object& o : s.objects) {
      INFO("object " << o.name);
      REQUIRE(o.mesh >= 0);
      REQUIRE(o.mesh < static_cast<int>(s.meshes.size()));
      CHECK((o.layers & layer::main) != 0);
      CHECK((o.layers & ~layer::all) == 0);
      for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
          CHECK(std::isfinite(o.transform[c][r]));
        }
      }
      if (o.spin_rate != 0.0f) {
        CHECK(glm::length(o.spin_axis) == doctest::Approx(1.0f));
      }
    }
    REQUIRE(!s.cameras.empty());
    const CameraDesc& cam = s.cameras[0];
    const glm::vec3 view = cam.target - cam.eye;
    CHECK(glm::length(view) > 1.0f);
    CHECK(glm::length(glm::cross(glm::normalize(view), glm::normalize(cam.up))) > 0.1f);
    CHECK(cam.z_near > 0.0f);
    CHECK(cam.z_far > cam.z_near);
    CHECK(cam.yfov > 0.1f);
    CHECK(cam.yfov < 2.0f);
    CHECK(glm::length(s.light.direction) == doctest::Approx(1.0f));
    CHECK(s.light.direction.y < 0.0f); // sunlight comes from above
    for (const Anchor& a : s.anchors) {
      CHECK(std::isfinite(a.position.x + a.position.y + a.position.z));
      CHECK(a.object >= -1);
      CHECK(a.object < static_cast<int>(s.objects.size()));
    }
    // The scene is in front of the camera: its bounds' centre projects in front.
    const auto [lo, hi] = s.bounds();
    CHECK(clip(cam, 0.5f * (lo + hi)).w > 0.0f);
  }
}

TEST_CASE("builtin scenes: deterministic") {
  for (std::string_view name : builtin_scene_names()) {
    const Scene a = scene_named(name);
    const Scene b = scene_named(name);
    INFO("scene " << a.name);
    REQUIRE(a.images.size() == b.images.size());
    for (std::size_t i = 0; i < a.images.size(); ++i) {
      CHECK(a.images[i].rgba8 == b.images[i].rgba8);
    }
    REQUIRE(a.meshes.size() == b.meshes.size());
    for (std::size_t i = 0; i < a.meshes.size(); ++i) {
      CHECK(a.meshes[i].indices == b.meshes[i].indices);
      REQUIRE(a.meshes[i].vertices.size() == b.meshes[i].vertices.size());
      for (std::size_t v = 0; v < a.meshes[i].vertices.size(); ++v) {
        CHECK(a.meshes[i].vertices[v].position == b.meshes[i].vertices[v].position);
      }
    }
  }
}

TEST_CASE("pool scene: water between the basin floor and rim with objects under and above it") {
  const Scene s = scene_named("pool");
  const Anchor* water = s.find_anchor("water");
  REQUIRE(water != nullptr);
  const float h = water->position.y;
  CHECK(h == doctest::Approx(2.75f)); // seed 000
  CHECK(water->size.y == 0.0f);
  CHECK(water->size.x > 0.0f);
  CHECK(water->size.z > 0.0f);

  // The water fills the basin's inner area, above its floor and below its rim.
  const Box inside = object_bounds(s, object_named(s, "basin_inside"));
  const Box outside = object_bounds(s, object_named(s, "basin_outside"));
  CHECK(inside.lo.y < h - 1.0f);
  CHECK(inside.hi.y > h);
  CHECK(outside.hi.y > h);
  CHECK(water->position.x - 0.5f * water->size.x == doctest::Approx(inside.lo.x));
  CHECK(water->position.x + 0.5f * water->size.x == doctest::Approx(inside.hi.x));
  CHECK(water->position.z - 0.5f * water->size.z == doctest::Approx(inside.lo.z));
  CHECK(water->position.z + 0.5f * water->size.z == doctest::Approx(inside.hi.z));
  // Seed 000's layout: ground at y = 1, wall centred at (0, 6, 8).
  CHECK(object_bounds(s, object_named(s, "ground")).hi.y == doctest::Approx(1.0f));
  const Box wall = object_bounds(s, object_named(s, "wall"));
  CHECK(0.5f * (wall.lo + wall.hi).y == doctest::Approx(6.0f));
  CHECK(0.5f * (wall.lo + wall.hi).z == doctest::Approx(8.0f));

  int under = 0, above = 0, across = 0;
  for (const Object& o : s.objects) {
    const Box b = object_bounds(s, o);
    INFO("object " << o.name);
    const bool in_pool = b.lo.x >= inside.lo.x && b.hi.x <= inside.hi.x && b.lo.z >= inside.lo.z &&
                         b.hi.z <= inside.hi.z;
    if (b.hi.y < h) {
      // Wholly under water: refracted, never in the reflection (which shows y > h only).
      CHECK((o.layers & layer::reflected) == 0);
      under += in_pool && o.name != "basin_inside";
      if (in_pool) {
        CHECK(b.lo.y >= inside.lo.y - 1e-4f); // resting on the floor, not sunk into it
        CHECK((o.layers & layer::refracted) != 0);
      }
    } else if (b.lo.y > h) {
      CHECK((o.layers & layer::reflected) != 0);
      CHECK((o.layers & layer::refracted) == 0);
      ++above;
    } else {
      CHECK(o.layers == layer::all);
      across += in_pool;
    }
  }
  CHECK(under >= 2);
  CHECK(above >= 2);
  CHECK(across >= 1);

  // Camera 0 looks down at the water from above it and sees all of it and the wall's top.
  const CameraDesc& cam = s.cameras[0];
  CHECK(cam.eye.y > h + 2.0f);
  for (float sx : {-0.5f, 0.5f}) {
    for (float sz : {-0.5f, 0.5f}) {
      const glm::vec3 corner =
          water->position + glm::vec3(sx * water->size.x, 0, sz * water->size.z);
      CHECK(in_view(cam, corner));
    }
  }
  const glm::vec3 wall_top(0.0f, wall.hi.y - 0.5f, wall.lo.z);
  CHECK(in_view(cam, wall_top));
  // ... and most of the wall above the water is mirrored in it: the ray toward the mirror image
  // of a point on the wall meets the water plane inside the pool.
  for (float y : {0.5f * (h + wall.hi.y), h + 0.75f * (wall.hi.y - h)}) {
    const glm::vec3 mirrored(0.0f, 2.0f * h - y, wall.lo.z);
    const glm::vec3 hit = cross_plane(cam.eye, mirrored, 1, h);
    INFO("wall point at y = " << y);
    CHECK(std::abs(hit.x - water->position.x) < 0.5f * water->size.x);
    CHECK(std::abs(hit.z - water->position.z) < 0.5f * water->size.z);
  }
}

TEST_CASE("window scene: the spinning crate is wholly behind the window as seen from camera 0") {
  const Scene s = scene_named("window");
  const Anchor* window = s.find_anchor("window");
  REQUIRE(window != nullptr);
  CHECK(window->size.z == 0.0f); // a quad in the plane z = position.z
  CHECK(window->size.x > 0.0f);
  CHECK(window->size.y > 0.0f);
  const float wz = window->position.z;
  const glm::vec2 wlo = glm::vec2(window->position) - 0.5f * glm::vec2(window->size);
  const glm::vec2 whi = glm::vec2(window->position) + 0.5f * glm::vec2(window->size);
  const CameraDesc& cam = s.cameras[0];
  CHECK(cam.eye.z > wz); // the camera is on the window's front (+Z) side

  const Object& crate = object_named(s, "crate");
  CHECK(crate.spin_rate > 0.0f);
  REQUIRE(crate.mesh >= 0);
  CHECK(s.materials
            .at(static_cast<std::size_t>(s.meshes[static_cast<std::size_t>(crate.mesh)].material))
            .base_color_texture >= 0);
  // Over a whole turn, every vertex of the crate is behind the glass and seen through it.
  const float period = 2.0f * 3.14159265f / crate.spin_rate;
  int outside = 0, in_front = 0;
  for (int step = 0; step < 16; ++step) {
    const glm::mat4 m = crate.world_at(period * static_cast<float>(step) / 16.0f);
    for (const Vertex& v : s.meshes[static_cast<std::size_t>(crate.mesh)].vertices) {
      const glm::vec3 p(m * glm::vec4(v.position, 1.0f));
      in_front += p.z >= wz;
      const glm::vec3 hit = cross_plane(cam.eye, p, 2, wz);
      outside += hit.x <= wlo.x || hit.x >= whi.x || hit.y <= wlo.y || hit.y >= whi.y;
    }
  }
  CHECK(in_front == 0);
  CHECK(outside == 0);
  // The whole window is in view, and so is the backdrop behind the crate.
  for (float sx : {-0.5f, 0.5f}) {
    for (float sy : {-0.5f, 0.5f}) {
      CHECK(
          in_view(cam, window->position + glm::vec3(sx * window->size.x, sy * window->size.y, 0)));
    }
  }
  const Box backdrop = object_bounds(s, object_named(s, "backdrop"));
  CHECK(backdrop.hi.z < object_bounds(s, crate).lo.z);
  // Nothing but the frame sits on the window plane or between it and the camera.
  for (const Object& o : s.objects) {
    if (o.name.rfind("frame", 0) == 0 || o.name == "floor") {
      continue;
    }
    INFO("object " << o.name);
    CHECK(object_bounds(s, o).hi.z < wz);
  }
}

TEST_CASE("spheres scene: probe anchor at the centre sphere with objects all around it") {
  const Scene s = scene_named("spheres");
  const Anchor* probe = s.find_anchor("probe");
  REQUIRE(probe != nullptr);
  REQUIRE(probe->object >= 0);
  REQUIRE(probe->object < static_cast<int>(s.objects.size()));
  const Object& owner = s.objects[static_cast<std::size_t>(probe->object)];
  const Box ob = object_bounds(s, owner);
  CHECK(glm::length(0.5f * (ob.lo + ob.hi) - probe->position) < 1e-4f);
  CHECK(glm::length((ob.hi - ob.lo) - probe->size) < 1e-3f);
  // The owner is drawn but never captured into its own cube map.
  CHECK((owner.layers & layer::main) != 0);
  CHECK((owner.layers & layer::captured) == 0);

  const float radius = 0.5f * probe->size.x;
  int quadrants = 0, spinning = 0, captured = 0;
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    const Object& o = s.objects[i];
    if (static_cast<int>(i) == probe->object) {
      continue;
    }
    INFO("object " << o.name);
    captured += (o.layers & layer::captured) != 0;
    spinning += o.spin_rate != 0.0f;
    // Nothing intersects the probe sphere (the pedestal may touch it from below).
    for (int step = 0; step < 8; ++step) {
      const Box b = object_bounds(s, o, static_cast<float>(step));
      const glm::vec3 closest = glm::clamp(probe->position, b.lo, b.hi);
      CHECK(glm::length(closest - probe->position) >= radius - 1e-4f);
    }
    const Box b = object_bounds(s, o);
    const glm::vec3 c = 0.5f * (b.lo + b.hi) - probe->position;
    if (glm::length(glm::vec2(c.x, c.z)) > 2.0f && b.hi.x - b.lo.x < 5.0f) {
      quadrants |= 1 << ((c.x > 0.0f ? 1 : 0) + (c.z > 0.0f ? 2 : 0));
    }
  }
  CHECK(quadrants == 0xF); // surrounded: every horizontal cube face sees something
  CHECK(spinning >= 2);
  CHECK(captured == static_cast<int>(s.objects.size()) - 1);

  const CameraDesc& cam = s.cameras[0];
  CHECK(in_view(cam, probe->position));
  CHECK(glm::length(cam.eye - probe->position) > radius + cam.z_near);
}
