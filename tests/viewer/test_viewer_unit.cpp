// The viewer's parts that need no window or GPU (label viewer): the camera controls, the script
// parser and player, and the panel's code path (set_param, refusals kept for the panel).
#include "camera.hpp"
#include "panel.hpp"
#include "script.hpp"

#include <doctest/doctest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <map>
#include <memory>

using namespace snell;
using namespace snell::viewer;

namespace {

CameraDesc home_camera() {
  CameraDesc c;
  c.eye = {0.0f, 2.0f, 10.0f};
  c.target = {0.0f, 2.0f, 0.0f};
  c.yfov = glm::radians(60.0f);
  c.z_near = 0.1f;
  return c;
}

bool near(const glm::vec3& a, const glm::vec3& b, float eps = 1e-4f) {
  return glm::length(a - b) <= eps;
}

/// Elevation of the eye above the target, degrees.
float elevation(const CameraDesc& c) {
  const glm::vec3 d = glm::normalize(c.eye - c.target);
  return glm::degrees(std::asin(d.y));
}

} // namespace

TEST_CASE("camera: orbit keeps the target and the distance, and stops short of the pole") {
  CameraController cam(home_camera());
  cam.orbit(glm::radians(90.0f), 0.0f);
  CHECK(near(cam.camera().target, {0, 2, 0}));
  CHECK(cam.distance() == doctest::Approx(10.0f));
  // Positive yaw turns the eye counter-clockwise seen from above: +z to +x.
  CHECK(near(cam.camera().eye, {10, 2, 0}, 1e-3f));
  cam.orbit(glm::radians(270.0f), 0.0f);
  CHECK(near(cam.camera().eye, home_camera().eye, 1e-3f));
  cam.orbit(0.0f, glm::radians(30.0f));
  CHECK(elevation(cam.camera()) == doctest::Approx(30.0f).epsilon(1e-3));
  cam.orbit(0.0f, glm::radians(500.0f)); // way past the pole: clamped at 89 degrees
  CHECK(elevation(cam.camera()) == doctest::Approx(89.0f).epsilon(1e-3));
  CHECK(cam.distance() == doctest::Approx(10.0f));
  cam.orbit(0.0f, glm::radians(-500.0f));
  CHECK(elevation(cam.camera()) == doctest::Approx(-89.0f).epsilon(1e-3));
}

TEST_CASE("camera: pan moves eye and target together by view heights") {
  CameraController cam(home_camera());
  const float view_height = 2.0f * 10.0f * std::tan(glm::radians(30.0f));
  cam.pan(1.0f, 0.0f); // the scene moves right: the camera left (-x for a camera looking -z)
  CHECK(near(cam.camera().eye, {-view_height, 2, 10}));
  CHECK(near(cam.camera().target, {-view_height, 2, 0}));
  cam.reset();
  cam.pan(0.0f, 0.5f); // the scene moves up: the camera down
  CHECK(near(cam.camera().target, {0, 2 - 0.5f * view_height, 0}));
  CHECK(cam.distance() == doctest::Approx(10.0f));
}

TEST_CASE("camera: zoom scales the distance by 0.85 a step, within its limits") {
  CameraController cam(home_camera());
  cam.zoom(1.0f);
  CHECK(cam.distance() == doctest::Approx(8.5f));
  CHECK(near(cam.camera().target, {0, 2, 0}));
  cam.zoom(-2.0f);
  CHECK(cam.distance() == doctest::Approx(10.0f / 0.85f));
  cam.zoom(1000.0f); // never reaches or passes the target
  CHECK(cam.distance() == doctest::Approx(cam.min_distance()));
  CHECK(cam.min_distance() == doctest::Approx(0.2f)); // max(10 / 100, 2 * z_near)
  CHECK(cam.camera().eye.z > 0.0f);
}

TEST_CASE("camera: look turns about the eye, fly moves along the view, reset returns") {
  CameraController cam(home_camera());
  cam.look(glm::radians(90.0f), 0.0f); // forward -z turned counter-clockwise: -x
  CHECK(near(cam.camera().eye, {0, 2, 10}));
  CHECK(near(cam.camera().target, {-10, 2, 10}, 1e-3f));
  cam.reset();
  cam.fly(1.0f, 2.0f, 3.0f); // right +x, up +y, forward -z
  CHECK(near(cam.camera().eye, {1, 4, 7}));
  CHECK(near(cam.camera().target, {1, 4, -3}));
  CHECK(cam.fly_speed() == doctest::Approx(2.5f)); // a quarter of home's distance, per second
  cam.look_at({1, 1, 1}, {1, 1, 1});               // refused: no direction
  CHECK(near(cam.camera().eye, {1, 4, 7}));
  cam.look_at({0, 5, 5}, {0, 0, 0});
  CHECK(near(cam.camera().eye, {0, 5, 5}));
  cam.reset();
  CHECK(near(cam.camera().eye, home_camera().eye));
  CHECK(near(cam.camera().target, home_camera().target));
}

TEST_CASE("script: every action parses, sorted by time, comments ignored") {
  const auto actions = parse_script(R"(# a capture
1.5 screenshot out.png scene
0   set water@2.wave_height=0.5   # inline comment
0.5 camera 0,5,10 0,0,0
0.5 orbit 10 -5
0.6 pan 0.1 0.2
0.7 zoom 2
0.8 fly 1 2 3
0.9 reset-camera
1.0 add glass
1.1 remove water@1
1.2 debug-targets on
1.3 panel off
1.4 resize 640x360
1.6 minimize
1.7 restore

2 quit
)",
                                    "t.txt");
  REQUIRE(actions);
  REQUIRE(actions->size() == 16);
  using Kind = ScriptAction::Kind;
  const ScriptAction& set = (*actions)[0];
  CHECK(set.kind == Kind::set);
  CHECK(set.effect == "water@2");
  CHECK(set.key == "wave_height");
  CHECK(set.value == "0.5");
  CHECK(set.line == 3);
  CHECK((*actions)[1].kind == Kind::camera);
  CHECK(near((*actions)[1].a, {0, 5, 10}));
  CHECK(near((*actions)[1].b, {0, 0, 0}));
  CHECK((*actions)[2].kind == Kind::orbit); // same time as camera: file order kept
  CHECK((*actions)[2].a.y == doctest::Approx(-5.0f));
  CHECK((*actions)[11].kind == Kind::resize);
  CHECK((*actions)[11].width == 640);
  CHECK((*actions)[11].height == 360);
  const ScriptAction& shot = (*actions)[12];
  CHECK(shot.kind == Kind::screenshot);
  CHECK(shot.path == "out.png");
  CHECK_FALSE(shot.window);
  CHECK((*actions)[10].kind == Kind::panel);
  CHECK_FALSE((*actions)[10].on);
  CHECK(actions->back().kind == Kind::quit);
}

TEST_CASE("script: errors name the line and what is wrong") {
  struct Case {
    const char* text;
    const char* needle;
  };
  for (const Case c :
       {Case{"x quit", "t.txt:1:"}, Case{"-1 quit", "time in seconds"},
        Case{"1", "an action must follow"}, Case{"1 jump", "unknown action 'jump'"},
        Case{"\n1 set water.wave_height", "t.txt:2: set: 'water.wave_height'"},
        Case{"1 camera 0,0,0 0,0,0", "must differ"},
        Case{"1 camera 0,0 1,1,1", "three comma-separated"},
        Case{"1 zoom many", "not a finite number"}, Case{"1 resize 0x10", "resize"},
        Case{"1 screenshot a.png both", "window or scene"},
        Case{"1 debug-targets yes", "on or off"}, Case{"1 quit now", "takes 0"},
        Case{"1 remove water@0", "EFFECT@K"}, Case{"1 add water@2", "an effect name"}}) {
    CAPTURE(c.text);
    const auto r = parse_script(c.text, "t.txt");
    REQUIRE_FALSE(r);
    CHECK(r.error().message.find(c.needle) != std::string::npos);
    CHECK(r.error().message.find("t.txt:") == 0);
  }
  CHECK(load_script("/nonexistent/script.txt").error().code == ErrorCode::file_not_found);
}

TEST_CASE("script: the player returns actions when their time has come") {
  auto actions = parse_script("0.1 panel off\n0.1 panel on\n0.5 quit\n", "t.txt");
  REQUIRE(actions);
  ScriptPlayer player(*actions);
  CHECK(player.due(0.0).empty());
  // The viewer's clock is ticks / 60: 6 / 60 is "0.1" whichever way the double rounds.
  CHECK(player.due(6.0 / 60.0).size() == 2);
  CHECK(player.due(6.0 / 60.0).empty());
  CHECK_FALSE(player.finished());
  CHECK(player.due(100.0).size() == 1);
  CHECK(player.finished());
}

namespace {

/// An effect with the schema's parameters and nothing else: what the panel's code path needs.
class FakeEffect final : public Effect {
public:
  explicit FakeEffect(const ParamSchema& schema) : schema_(schema) {
    for (const ParamSpec& p : schema.params) {
      values_.emplace(p.name, p.default_value);
    }
  }
  std::string_view type() const override { return schema_.effect; }
  Result<void> set_param(std::string_view key, const ParamValue& value) override {
    ++set_calls;
    const ParamSpec* spec = schema_.find(key);
    if (spec == nullptr) {
      return fail(ErrorCode::unknown_name, "unknown key; valid: " + schema_.key_list());
    }
    SNELL_TRY(validate_param(schema_, *spec, value));
    values_[std::string(key)] = value;
    return {};
  }
  Result<ParamValue> get_param(std::string_view key) const override {
    const auto it = values_.find(std::string(key));
    if (it == values_.end()) {
      return fail(ErrorCode::unknown_name, "unknown key");
    }
    return it->second;
  }
  Result<void> update(const FrameInfo&) override { return {}; }
  Result<void> record_passes(VkCommandBuffer, const FrameInfo&, SceneSource&) override {
    return {};
  }
  Result<void> record_draw(VkCommandBuffer, const FrameInfo&) override { return {}; }
  Span<const DebugTarget> debug_targets() const override { return {}; }
  int set_calls = 0;

private:
  const ParamSchema& schema_;
  std::map<std::string, ParamValue> values_;
};

ParamSchema fake_schema() {
  ParamSchema s;
  s.effect = "fake";
  s.params.push_back(ParamSpec{"height", ParamType::number, 0.5f, 0.0f, 2.0f, {}, "m", "A height"});
  s.params.push_back(
      ParamSpec{"mode", ParamType::enumeration, std::string("a"), 0, 0, {"a", "b"}, "", "A mode"});
  s.params.push_back(
      ParamSpec{"offset", ParamType::vec3, glm::vec3(0.0f), -1.0f, 1.0f, {}, "m", "An offset"});
  return s;
}

} // namespace

TEST_CASE("panel: every change goes through set_param, refusals are kept, then cleared") {
  const ParamSchema schema = fake_schema();
  EffectSlot slot;
  slot.name = "fake";
  slot.schema = &schema;
  auto effect = std::make_unique<FakeEffect>(schema);
  FakeEffect* fake = effect.get();
  slot.effect = std::move(effect);

  // Text typed into the panel (or a script's `set`) becomes a value of the type only: the range
  // and the choices are set_param's to check.
  auto far = text_to_value(schema, *schema.find("height"), "7");
  REQUIRE(far);
  auto r = apply_param(slot, "height", *far);
  CHECK_FALSE(r);
  CHECK(fake->set_calls == 1);
  REQUIRE(slot.errors.count("height") == 1);
  CHECK(slot.errors["height"].find("[0, 2]") != std::string::npos);
  CHECK(std::get<float>(*fake->get_param("height")) == doctest::Approx(0.5f)); // unchanged

  auto choice = text_to_value(schema, *schema.find("mode"), "c");
  REQUIRE(choice);
  CHECK_FALSE(apply_param(slot, "mode", *choice));
  CHECK(slot.errors.count("mode") == 1);
  CHECK(fake->set_calls == 2);

  CHECK_FALSE(text_to_value(schema, *schema.find("offset"), "1,2")); // not a vec3 at all
  CHECK_FALSE(text_to_value(schema, *schema.find("height"), "tall"));

  // A good value clears the parameter's error.
  CHECK(apply_param(slot, "height", ParamValue{1.5f}));
  CHECK(slot.errors.count("height") == 0);
  CHECK(std::get<float>(*fake->get_param("height")) == doctest::Approx(1.5f));
  CHECK(apply_param(slot, "offset", *text_to_value(schema, *schema.find("offset"), "0.5,0,-1")));
  CHECK(fake->set_calls == 4);
}

TEST_CASE("panel: instances are named as --set names them") {
  std::vector<EffectSlot> slots(4);
  slots[0].name = "water";
  slots[1].name = "glass";
  slots[2].name = "water";
  slots[3].name = "ice";
  CHECK(instance_label(slots, 0) == "water@1");
  CHECK(instance_label(slots, 1) == "glass");
  CHECK(instance_label(slots, 2) == "water@2");
  CHECK(find_instances(slots, "water") == std::vector<std::size_t>{0, 2});
  CHECK(find_instances(slots, "water@2") == std::vector<std::size_t>{2});
  CHECK(find_instances(slots, "water@3").empty());
  CHECK(find_instances(slots, "lava").empty());
  CHECK(find_instances(slots, "ice") == std::vector<std::size_t>{3});
}
