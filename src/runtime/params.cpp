// Parameter schemas: validation and parsing of effect parameters (data-driven set_param).
#include <snell/effect.hpp>
#include <snell/param_table.hpp>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace snell {
namespace {

std::string number_text(float v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

std::string range_text(const ParamSpec& spec) {
  // Built with a stream: GCC 12 -O3 warns falsely (-Wrestrict) on "literal" + std::string.
  std::ostringstream os;
  os << '[' << spec.min << ", " << spec.max << ']';
  return os.str();
}

std::string where(const ParamSchema& schema, const ParamSpec& spec) {
  return schema.effect + "." + spec.name;
}

template <int N>
Result<void> check_components(const ParamSchema& schema, const ParamSpec& spec, const float* c) {
  for (int i = 0; i < N; ++i) {
    if (!std::isfinite(c[i])) {
      return fail(ErrorCode::invalid_argument,
                  where(schema, spec) + ": component " + std::to_string(i) + " is not finite");
    }
    if (c[i] < spec.min || c[i] > spec.max) {
      return fail(ErrorCode::invalid_argument, where(schema, spec) + ": component " +
                                                   std::to_string(i) + " = " + number_text(c[i]) +
                                                   " is outside " + range_text(spec));
    }
  }
  return {};
}

Result<float> parse_number(std::string_view text, const std::string& what) {
  const std::string s(text);
  errno = 0;
  char* end = nullptr;
  const float v = std::strtof(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || errno == ERANGE) {
    return fail(ErrorCode::invalid_argument, what + ": '" + s + "' is not a number");
  }
  return v;
}

} // namespace

std::string_view to_string(ParamType type) {
  switch (type) {
  case ParamType::boolean:
    return "bool";
  case ParamType::integer:
    return "int";
  case ParamType::number:
    return "float";
  case ParamType::enumeration:
    return "enum";
  case ParamType::vec2:
    return "vec2";
  case ParamType::vec3:
    return "vec3";
  case ParamType::vec4:
    return "vec4";
  case ParamType::color:
    return "color";
  case ParamType::texture:
    return "texture";
  case ParamType::string:
    return "string";
  }
  return "?";
}

std::string to_string(const ParamValue& value) {
  struct Visitor {
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(int i) const { return std::to_string(i); }
    std::string operator()(float f) const { return number_text(f); }
    std::string operator()(glm::vec2 v) const { return number_text(v.x) + "," + number_text(v.y); }
    std::string operator()(glm::vec3 v) const {
      return number_text(v.x) + "," + number_text(v.y) + "," + number_text(v.z);
    }
    std::string operator()(glm::vec4 v) const {
      return number_text(v.x) + "," + number_text(v.y) + "," + number_text(v.z) + "," +
             number_text(v.w);
    }
    std::string operator()(const std::string& s) const { return s; }
  };
  return std::visit(Visitor{}, value);
}

const ParamSpec* ParamSchema::find(std::string_view name) const {
  for (const ParamSpec& p : params) {
    if (p.name == name) {
      return &p;
    }
  }
  return nullptr;
}

std::string ParamSchema::key_list() const {
  std::string out;
  for (const ParamSpec& p : params) {
    if (!out.empty()) {
      out += ", ";
    }
    out += p.name;
  }
  return out;
}

Error unknown_param_error(const ParamSchema& schema, std::string_view key) {
  return fail(ErrorCode::unknown_name, schema.effect + ": unknown parameter '" + std::string(key) +
                                           "'; valid: " + schema.key_list());
}

Error enum_index_error(const ParamSchema& schema, const ParamSpec& spec, long long index) {
  std::ostringstream os;
  os << where(schema, spec) << " = " << index << " is outside [0, "
     << static_cast<long long>(spec.choices.size()) - 1 << "] (choices:";
  for (std::size_t i = 0; i < spec.choices.size(); ++i) {
    os << ' ' << i << '=' << spec.choices[i];
  }
  os << ')';
  return fail(ErrorCode::invalid_argument, os.str());
}

Result<void> validate_param(const ParamSchema& schema, const ParamSpec& spec,
                            const ParamValue& value) {
  const std::string name = where(schema, spec);
  auto wrong_type = [&]() -> Result<void> {
    return fail(ErrorCode::invalid_argument, name + ": expects " +
                                                 std::string(to_string(spec.type)) + ", got '" +
                                                 to_string(value) + "'");
  };
  switch (spec.type) {
  case ParamType::boolean:
    return std::holds_alternative<bool>(value) ? Result<void>{} : wrong_type();
  case ParamType::integer: {
    const int* i = std::get_if<int>(&value);
    if (i == nullptr) {
      return wrong_type();
    }
    if (*i < spec.min || *i > spec.max) {
      return fail(ErrorCode::invalid_argument,
                  name + " = " + std::to_string(*i) + " is outside " + range_text(spec));
    }
    return {};
  }
  case ParamType::number: {
    const float* f = std::get_if<float>(&value);
    if (f == nullptr) {
      return wrong_type();
    }
    if (!std::isfinite(*f)) {
      return fail(ErrorCode::invalid_argument, name + " = " + number_text(*f) + " is not finite");
    }
    if (*f < spec.min || *f > spec.max) {
      return fail(ErrorCode::invalid_argument,
                  name + " = " + number_text(*f) + " is outside " + range_text(spec));
    }
    return {};
  }
  case ParamType::enumeration: {
    const std::string* s = std::get_if<std::string>(&value);
    if (s == nullptr) {
      return wrong_type();
    }
    for (const std::string& c : spec.choices) {
      if (c == *s) {
        return {};
      }
    }
    std::string list;
    for (const std::string& c : spec.choices) {
      if (!list.empty()) {
        list += ", ";
      }
      list += c;
    }
    return fail(ErrorCode::invalid_argument, name + " = '" + *s + "' is not one of: " + list);
  }
  case ParamType::vec2: {
    const glm::vec2* v = std::get_if<glm::vec2>(&value);
    return v ? check_components<2>(schema, spec, &v->x) : wrong_type();
  }
  case ParamType::vec3:
  case ParamType::color: {
    const glm::vec3* v = std::get_if<glm::vec3>(&value);
    return v ? check_components<3>(schema, spec, &v->x) : wrong_type();
  }
  case ParamType::vec4: {
    const glm::vec4* v = std::get_if<glm::vec4>(&value);
    return v ? check_components<4>(schema, spec, &v->x) : wrong_type();
  }
  case ParamType::texture:
  case ParamType::string:
    return std::holds_alternative<std::string>(value) ? Result<void>{} : wrong_type();
  }
  return wrong_type();
}

Result<ParamValue> parse_param(const ParamSchema& schema, const ParamSpec& spec,
                               std::string_view text) {
  const std::string name = where(schema, spec);
  ParamValue value;
  auto components = [&](int n) -> Result<glm::vec4> {
    glm::vec4 v(0.0f);
    std::string s(text);
    std::stringstream ss(s);
    int count = 0;
    for (std::string part; std::getline(ss, part, ',');) {
      if (count >= n) {
        ++count;
        break;
      }
      auto f = parse_number(part, name);
      if (!f) {
        return f.error();
      }
      v[count++] = *f;
    }
    if (count != n) {
      return fail(ErrorCode::invalid_argument,
                  name + ": '" + s + "' must be " + std::to_string(n) + " comma-separated numbers");
    }
    return v;
  };
  switch (spec.type) {
  case ParamType::boolean:
    if (text == "true" || text == "1" || text == "on") {
      value = true;
    } else if (text == "false" || text == "0" || text == "off") {
      value = false;
    } else {
      return fail(ErrorCode::invalid_argument,
                  name + ": '" + std::string(text) + "' is not true/false");
    }
    break;
  case ParamType::integer: {
    const std::string s(text);
    errno = 0;
    char* end = nullptr;
    const long long v = std::strtoll(s.c_str(), &end, 0);
    if (s.empty() || end != s.c_str() + s.size() || errno == ERANGE || v < INT32_MIN ||
        v > INT32_MAX) {
      return fail(ErrorCode::invalid_argument, name + ": '" + s + "' is not an integer");
    }
    value = static_cast<int>(v);
    break;
  }
  case ParamType::number: {
    auto f = parse_number(text, name);
    if (!f) {
      return f.error();
    }
    value = *f;
    break;
  }
  case ParamType::vec2: {
    auto v = components(2);
    if (!v) {
      return v.error();
    }
    value = glm::vec2(*v);
    break;
  }
  case ParamType::vec3:
  case ParamType::color: {
    auto v = components(3);
    if (!v) {
      return v.error();
    }
    value = glm::vec3(*v);
    break;
  }
  case ParamType::vec4: {
    auto v = components(4);
    if (!v) {
      return v.error();
    }
    value = *v;
    break;
  }
  case ParamType::enumeration:
  case ParamType::texture:
  case ParamType::string:
    value = std::string(text);
    break;
  }
  if (auto r = validate_param(schema, spec, value); !r) {
    return r.error();
  }
  return value;
}

Result<void> EffectRegistry::add(std::string name, EffectFactory factory, ParamSchema schema) {
  if (name.empty() || !factory) {
    return fail(ErrorCode::invalid_argument,
                "EffectRegistry::add: a name and a factory are required");
  }
  if (entries_.count(name) != 0) {
    return fail(ErrorCode::duplicate_name, "effect '" + name + "' is already registered");
  }
  schema.effect = name;
  for (const ParamSpec& spec : schema.params) {
    if (auto r = validate_param(schema, spec, spec.default_value); !r) {
      return fail(ErrorCode::invalid_argument,
                  "effect '" + name + "': default of " + r.error().message);
    }
  }
  entries_.emplace(std::move(name), Entry{std::move(factory), std::move(schema)});
  return {};
}

Result<std::unique_ptr<Effect>> EffectRegistry::create(std::string_view name,
                                                       const EffectCreateInfo& info) const {
  const auto it = entries_.find(name);
  if (it == entries_.end()) {
    std::string known;
    for (const auto& [n, e] : entries_) {
      if (!known.empty()) {
        known += ", ";
      }
      known += n;
    }
    return fail(ErrorCode::unknown_name,
                "unknown effect '" + std::string(name) +
                    "'; registered effects: " + (known.empty() ? "(none)" : known));
  }
  if (info.context == nullptr) {
    return fail(ErrorCode::invalid_argument,
                "EffectCreateInfo::context is required to create '" + std::string(name) + "'");
  }
  return it->second.factory(info);
}

std::vector<std::string> EffectRegistry::names() const {
  std::vector<std::string> out;
  for (const auto& [n, e] : entries_) {
    out.push_back(n);
  }
  return out;
}

const ParamSchema* EffectRegistry::schema(std::string_view name) const {
  const auto it = entries_.find(name);
  return it == entries_.end() ? nullptr : &it->second.schema;
}

} // namespace snell
