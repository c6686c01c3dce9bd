// Parameter conformance of every registered effect (docs/plugins.md, "The contract"): schema
// defaults, get/set round trips at min, max and midpoints, and refusals (out of range, non-finite,
// wrong type, unknown choice or key) that name `effect.key` and change nothing. The same checks
// run on ParamTable over a local struct without a GPU.
#include "gpu_fixture.hpp"

#include <snell/effect.hpp>
#include <snell/param_table.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <string>
#include <vector>

using namespace snell;

namespace {

using SetFn = std::function<Result<void>(std::string_view, const ParamValue&)>;
using GetFn = std::function<Result<ParamValue>(std::string_view)>;

/// The ParamValue alternative that holds a value of `type`.
std::size_t value_index(ParamType type) {
  switch (type) {
  case ParamType::boolean:
    return ParamValue(false).index();
  case ParamType::integer:
    return ParamValue(0).index();
  case ParamType::number:
    return ParamValue(0.0f).index();
  case ParamType::vec2:
    return ParamValue(glm::vec2(0.0f)).index();
  case ParamType::vec3:
  case ParamType::color:
    return ParamValue(glm::vec3(0.0f)).index();
  case ParamType::vec4:
    return ParamValue(glm::vec4(0.0f)).index();
  case ParamType::enumeration:
  case ParamType::texture:
  case ParamType::string:
    return ParamValue(std::string()).index();
  }
  return std::variant_npos;
}

int components(ParamType type) {
  switch (type) {
  case ParamType::vec2:
    return 2;
  case ParamType::vec3:
  case ParamType::color:
    return 3;
  case ParamType::vec4:
    return 4;
  default:
    return 0;
  }
}

/// `base` (a vector ParamValue) with component `c` set to `x`.
ParamValue with_component(const ParamValue& base, int c, float x) {
  return std::visit(
      [&](auto v) -> ParamValue {
        using T = decltype(v);
        if constexpr (std::is_same_v<T, glm::vec2> || std::is_same_v<T, glm::vec3> ||
                      std::is_same_v<T, glm::vec4>) {
          v[c] = x;
        }
        return v;
      },
      base);
}

/// A vector ParamValue of `type` with every component `x`.
ParamValue splat(ParamType type, float x) {
  switch (components(type)) {
  case 2:
    return glm::vec2(x);
  case 3:
    return glm::vec3(x);
  default:
    return glm::vec4(x);
  }
}

/// Values `spec` must accept: min, max and a midpoint (per component for vectors), each choice,
/// true/false, "" for textures.
std::vector<ParamValue> valid_values(const ParamSpec& spec) {
  const float mid = 0.5f * (spec.min + spec.max);
  switch (spec.type) {
  case ParamType::boolean:
    return {true, false};
  case ParamType::integer: {
    const int lo = static_cast<int>(spec.min);
    const int hi = static_cast<int>(spec.max);
    return {lo, hi, lo + (hi - lo) / 2};
  }
  case ParamType::number:
    return {spec.min, spec.max, mid};
  case ParamType::vec2:
  case ParamType::vec3:
  case ParamType::vec4:
  case ParamType::color: {
    std::vector<ParamValue> out{splat(spec.type, spec.min), splat(spec.type, spec.max)};
    for (int c = 0; c < components(spec.type); ++c) {
      for (const float x : {spec.min, spec.max, mid}) {
        out.push_back(with_component(spec.default_value, c, x));
      }
    }
    return out;
  }
  case ParamType::enumeration:
    return std::vector<ParamValue>(spec.choices.begin(), spec.choices.end());
  case ParamType::texture:
    return {std::string()};
  case ParamType::string:
    return {std::string()}; // "" (none) is valid for every string parameter
  }
  return {};
}

/// Values `spec` must refuse with invalid_argument: just and far outside the range, NaN and
/// +/-inf (per component for vectors), an unknown choice, and wrong types.
std::vector<ParamValue> invalid_values(const ParamSpec& spec) {
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> bad_floats = {std::nextafter(spec.min, -inf),
                                         spec.min - 1.0f - std::fabs(spec.min),
                                         std::nextafter(spec.max, inf),
                                         spec.max + 1.0f + std::fabs(spec.max),
                                         nan,
                                         inf,
                                         -inf};
  std::vector<ParamValue> out;
  switch (spec.type) {
  case ParamType::boolean:
    out = {1, 0.0f, std::string("true")};
    break;
  case ParamType::integer: {
    const long long lo = static_cast<long long>(spec.min);
    const long long hi = static_cast<long long>(spec.max);
    if (lo > std::numeric_limits<int>::min()) {
      out.push_back(static_cast<int>(lo - 1));
    }
    if (hi < std::numeric_limits<int>::max()) {
      out.push_back(static_cast<int>(hi + 1));
    }
    out.insert(out.end(), {ParamValue(static_cast<float>(lo)), ParamValue(true)});
    break;
  }
  case ParamType::number:
    out.assign(bad_floats.begin(), bad_floats.end());
    out.insert(out.end(),
               {ParamValue(1), ParamValue(glm::vec2(spec.min)), ParamValue(std::string("0"))});
    break;
  case ParamType::vec2:
  case ParamType::vec3:
  case ParamType::vec4:
  case ParamType::color:
    for (int c = 0; c < components(spec.type); ++c) {
      for (const float x : bad_floats) {
        out.push_back(with_component(spec.default_value, c, x));
      }
    }
    out.insert(out.end(), {ParamValue(spec.min), ParamValue(std::string("0,0,0"))});
    // A vector of another size.
    out.push_back(components(spec.type) == 3 ? ParamValue(glm::vec4(spec.min))
                                             : ParamValue(glm::vec3(spec.min)));
    break;
  case ParamType::enumeration:
    out = {std::string("no_such_choice"), std::string(), 0, 0.0f};
    break;
  case ParamType::texture:
  case ParamType::string:
    out = {0, 0.0f, false};
    break;
  }
  return out;
}

/// The contract, through set/get of one object whose parameters are described by `schema`.
void check_conformance(const ParamSchema& schema, const SetFn& set, const GetFn& get) {
  INFO("effect: ", schema.effect);
  REQUIRE_FALSE(schema.params.empty());
  std::set<std::string> keys;
  for (const ParamSpec& spec : schema.params) {
    INFO("key: ", spec.name);
    CHECK_FALSE(spec.name.empty());
    CHECK_FALSE(spec.doc.empty());
    CHECK(keys.insert(spec.name).second); // unique
    CHECK(spec.default_value.index() == value_index(spec.type));
    const Result<void> valid = validate_param(schema, spec, spec.default_value);
    CHECK_MESSAGE(valid.has_value(), (valid ? std::string() : valid.error().message));
  }
  // Right after creation every key reads back its schema default, in the schema's type.
  for (const ParamSpec& spec : schema.params) {
    INFO("key: ", spec.name);
    const Result<ParamValue> value = get(spec.name);
    REQUIRE_MESSAGE(value.has_value(), value.error().message);
    CHECK(value->index() == value_index(spec.type));
    CHECK_MESSAGE(*value == spec.default_value,
                  to_string(*value) << " != default " << to_string(spec.default_value));
  }
  for (const ParamSpec& spec : schema.params) {
    const std::string where = schema.effect + "." + spec.name;
    INFO("key: ", where);
    for (const ParamValue& v : valid_values(spec)) {
      INFO("valid value: ", to_string(v));
      const Result<void> r = set(spec.name, v);
      REQUIRE_MESSAGE(r.has_value(), r.error().message);
      const Result<ParamValue> back = get(spec.name);
      REQUIRE_MESSAGE(back.has_value(), back.error().message);
      CHECK_MESSAGE(*back == v, "read back " << to_string(*back)); // exactly, nothing clamped
    }
    const Result<ParamValue> before = get(spec.name);
    REQUIRE(before.has_value());
    for (const ParamValue& v : invalid_values(spec)) {
      INFO("invalid value: ", to_string(v), " (alternative ", v.index(), ")");
      const Result<void> r = set(spec.name, v);
      REQUIRE_FALSE(r.has_value());
      CHECK(r.error().code == ErrorCode::invalid_argument);
      CHECK_MESSAGE(r.error().message.find(where) != std::string::npos, r.error().message);
      const Result<ParamValue> after = get(spec.name);
      REQUIRE(after.has_value());
      CHECK_MESSAGE(*after == *before, "changed to " << to_string(*after)); // unchanged
    }
    const Result<void> reset = set(spec.name, spec.default_value);
    CHECK_MESSAGE(reset.has_value(), (reset ? std::string() : reset.error().message));
  }
  // Unknown keys: unknown_name, naming the key and listing every valid one.
  const std::string unknown = "no_such_key";
  const Result<void> set_unknown = set(unknown, 0.0f);
  const Result<ParamValue> get_unknown = get(unknown);
  REQUIRE_FALSE(set_unknown.has_value());
  REQUIRE_FALSE(get_unknown.has_value());
  for (const Error& e : {set_unknown.error(), get_unknown.error()}) {
    CHECK(e.code == ErrorCode::unknown_name);
    CHECK(e.message.find(unknown) != std::string::npos);
    for (const ParamSpec& spec : schema.params) {
      CHECK_MESSAGE(e.message.find(spec.name) != std::string::npos, spec.name);
    }
  }
}

} // namespace

TEST_CASE("conformance: every registered effect's parameters") {
  test::GpuFixture gpu;
  EffectRegistry registry;
  const Result<void> registered = register_builtin_effects(registry);
  REQUIRE_MESSAGE(registered.has_value(), registered.error().message);
  const std::vector<std::string> names = registry.names();
  REQUIRE_FALSE(names.empty());
  for (const std::string& name : names) {
    INFO("effect: ", name);
    const ParamSchema* schema = registry.schema(name);
    REQUIRE(schema != nullptr);
    CHECK(schema->effect == name);
    auto effect = registry.create(name, EffectCreateInfo{.context = &gpu.ctx()});
    REQUIRE_MESSAGE(effect.has_value(), effect.error().message);
    Effect& e = **effect;
    CHECK(e.type() == name);
    check_conformance(
        *schema, [&](std::string_view k, const ParamValue& v) { return e.set_param(k, v); },
        [&](std::string_view k) { return e.get_param(k); });
  }
}

namespace {

enum class Shape : std::uint8_t { box, sphere, plane };

struct Local {
  float f = 0.5f;
  int i = 3;
  bool b = true;
  glm::vec2 v2{0.25f, -0.5f};
  glm::vec3 v3{1.0f, 2.0f, 3.0f};
  glm::vec4 v4{0.0f};
  glm::vec3 c{0.1f, 0.2f, 0.3f};
  Shape shape = Shape::sphere;
  std::string tex;
  std::string node = "owner";
};

const ParamTable<Local>& local_table() {
  static const ParamTable<Local> t =
      ParamTable<Local>("local", "A local struct.")
          .number("f", &Local::f, 0.0f, 2.0f, "m", "a float")
          .action(
              "reset", {"keep", "zero"}, "keep",
              [](Local& p, const std::string& how) {
                if (how == "zero") {
                  p.f = 0.0f;
                  p.i = 0;
                }
              },
              "an action")
          .integer("i", &Local::i, -4, 10, "", "an int")
          .boolean("b", &Local::b, "a bool")
          .vec2("v2", &Local::v2, -1.0f, 1.0f, "m", "a vec2")
          .vec3("v3", &Local::v3, 0.0f, 5.0f, "1/m", "a vec3")
          .vec4("v4", &Local::v4, -2.0f, 2.0f, "", "a vec4")
          .color("c", &Local::c, "a colour")
          .enumeration("shape", &Local::shape, {"box", "sphere", "plane"}, "an enum")
          .texture("tex", &Local::tex, "a texture")
          .string("node", &Local::node, "a node name");
  return t;
}

} // namespace

TEST_CASE("conformance: ParamTable on a local struct (CPU)") {
  const ParamTable<Local>& table = local_table();
  const ParamSchema& schema = table.schema();
  // The schema: declaration order, types, defaults from Local{}, ranges, units, docs.
  CHECK(schema.effect == "local");
  CHECK(schema.doc == "A local struct.");
  CHECK(schema.key_list() == "f, reset, i, b, v2, v3, v4, c, shape, tex, node");
  const Local d;
  const std::vector<std::pair<ParamType, ParamValue>> expected = {
      {ParamType::number, d.f},
      {ParamType::enumeration, std::string("keep")},
      {ParamType::integer, d.i},
      {ParamType::boolean, d.b},
      {ParamType::vec2, d.v2},
      {ParamType::vec3, d.v3},
      {ParamType::vec4, d.v4},
      {ParamType::color, d.c},
      {ParamType::enumeration, std::string("sphere")},
      {ParamType::texture, std::string()},
      {ParamType::string, std::string("owner")}};
  REQUIRE(schema.params.size() == expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) {
    INFO("key: ", schema.params[k].name);
    CHECK(schema.params[k].type == expected[k].first);
    CHECK(schema.params[k].default_value == expected[k].second);
  }
  const ParamSpec& i = *schema.find("i");
  CHECK(i.min == -4.0f);
  CHECK(i.max == 10.0f);
  CHECK(schema.find("f")->unit == "m");
  CHECK(schema.find("v3")->unit == "1/m");
  CHECK(schema.find("v3")->doc == "a vec3");
  CHECK(schema.find("c")->min == 0.0f);
  CHECK(schema.find("c")->max == 1.0f);
  CHECK(schema.find("shape")->choices == std::vector<std::string>{"box", "sphere", "plane"});
  CHECK(schema.find("reset")->choices == std::vector<std::string>{"keep", "zero"});

  // The whole contract, through an adapter that keeps the action's last choice, as an effect
  // does.
  Local p;
  std::string last_reset = "keep";
  check_conformance(
      schema,
      [&](std::string_view k, const ParamValue& v) {
        auto r = table.set(p, k, v);
        if (r && k == "reset") {
          last_reset = std::get<std::string>(v);
        }
        return r;
      },
      [&](std::string_view k) -> Result<ParamValue> {
        return k == "reset" ? ParamValue(last_reset) : table.get(p, k);
      });

  // Typed values land in the members; the action runs its function; get of an action is its
  // default (the table keeps no state).
  Local q;
  REQUIRE(table.set(q, "shape", std::string("plane")).has_value());
  CHECK(q.shape == Shape::plane);
  REQUIRE(table.set(q, "v4", glm::vec4(-2.0f, 2.0f, 0.5f, 1.0f)).has_value());
  CHECK(q.v4 == glm::vec4(-2.0f, 2.0f, 0.5f, 1.0f));
  REQUIRE(table.set(q, "reset", std::string("zero")).has_value());
  CHECK(q.f == 0.0f);
  CHECK(q.i == 0);
  CHECK(q.shape == Shape::plane);
  CHECK(std::get<std::string>(*table.get(q, "reset")) == "keep");
  q.f = 1.0f;
  CHECK_FALSE(table.set(q, "reset", std::string("all")).has_value());
  CHECK(q.f == 1.0f); // the action did not run

  // validate(): the defaults pass; each bad member is named with its value and range.
  CHECK(table.validate(Local{}).has_value());
  const auto invalid = [&](const Local& bad, const std::string& needle) {
    const Result<void> r = table.validate(bad);
    REQUIRE_FALSE(r.has_value());
    CHECK(r.error().code == ErrorCode::invalid_argument);
    CHECK_MESSAGE(r.error().message.find(needle) != std::string::npos, r.error().message);
  };
  Local bad;
  bad.shape = static_cast<Shape>(7); // an enum value cast into the struct
  invalid(bad, "local.shape = 7 is outside [0, 2]");
  const Result<ParamValue> got = table.get(bad, "shape");
  REQUIRE_FALSE(got.has_value());
  CHECK(got.error().message.find("local.shape") != std::string::npos);
  bad = Local{};
  bad.f = std::numeric_limits<float>::quiet_NaN();
  invalid(bad, "local.f");
  bad = Local{};
  bad.i = 11;
  invalid(bad, "local.i = 11 is outside [-4, 10]");
  bad = Local{};
  bad.c.y = 1.5f;
  invalid(bad, "local.c: component 1 = 1.5 is outside [0, 1]");
  bad = Local{};
  bad.v2.x = -std::numeric_limits<float>::infinity();
  invalid(bad, "local.v2: component 0 is not finite");
}
