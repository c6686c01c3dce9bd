// Snell plugins: declarative effect parameters. A plugin declares each parameter once (name,
// member of its typed struct, range, unit, doc) in a ParamTable; the schema, set, get and the
// validation of a whole struct are generated from that declaration, so no plugin writes a chain
// of `if (key == ...)`. This header uses C++17 only.
//
//   static const auto table = snell::ParamTable<FogParams>("fog", "Height fog.")
//       .number("density", &FogParams::density, 0.0f, 10.0f, "1/m", "Extinction per metre")
//       .color("color", &FogParams::color, "Colour of the fog (linear RGB)");
//   table.set(params, "density", 0.5f);   // validated; nothing changes on error
#pragma once

#include <snell/effect.hpp>
#include <snell/result.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace snell {

/// The error for a key `schema` does not have: ErrorCode::unknown_name, "<effect>: unknown
/// parameter '<key>'; valid: <every key>".
[[nodiscard]] Error unknown_param_error(const ParamSchema& schema, std::string_view key);
/// The error for an enumeration member holding `index`, which is not in [0, choices - 1] of
/// `spec` (a value cast into the enum): ErrorCode::invalid_argument naming `<effect>.<key>`, the
/// value and the valid range.
[[nodiscard]] Error enum_index_error(const ParamSchema& schema, const ParamSpec& spec,
                                     long long index);

/// The parameters of an effect whose typed parameters are the struct P (default-constructible
/// and copyable; its default values are the schema's defaults). Each builder call appends one
/// ParamSpec, in call order, and returns *this for chaining. Build the table once (e.g. a
/// function-local static) and share it: set, get and validate are const and thread-safe.
/// Declaring a name twice is a programming error (the first declaration wins in set/get), and
/// a default outside its declared range is refused by EffectRegistry::add (and by the
/// conformance test).
template <class P> class ParamTable {
public:
  /// `effect`: the registered name ("water"), used in every error message. `doc`: one line
  /// about the effect (ParamSchema::doc).
  ParamTable(std::string effect, std::string doc)
      : ParamTable(std::move(effect), std::move(doc), P{}) {}
  /// The same with the schema's defaults read from `defaults` instead of P{}: one struct, two
  /// registered names with their own defaults (glass and ice).
  ParamTable(std::string effect, std::string doc, P defaults) : defaults_(std::move(defaults)) {
    schema_.effect = std::move(effect);
    schema_.doc = std::move(doc);
  }

  /// A float member. `min`, `max`: inclusive bounds; `unit`: "m", "m/s", "1/m" or "" for none;
  /// `doc`: one line, what it does. The same for every builder below.
  ParamTable& number(std::string name, float P::*member, float min, float max, std::string unit,
                     std::string doc) {
    return plain(ParamType::number, std::move(name), member, min, max, std::move(unit),
                 std::move(doc));
  }
  /// An int member (also bit masks), within [min, max] (stored as floats in the ParamSpec:
  /// exact up to 2^24).
  ParamTable& integer(std::string name, int P::*member, int min, int max, std::string unit,
                      std::string doc) {
    return plain(ParamType::integer, std::move(name), member, static_cast<float>(min),
                 static_cast<float>(max), std::move(unit), std::move(doc));
  }
  /// A bool member (no range, no unit).
  ParamTable& boolean(std::string name, bool P::*member, std::string doc) {
    return plain(ParamType::boolean, std::move(name), member, 0.0f, 0.0f, "", std::move(doc));
  }
  /// A glm::vec2 member; each component within [min, max].
  ParamTable& vec2(std::string name, glm::vec2 P::*member, float min, float max, std::string unit,
                   std::string doc) {
    return plain(ParamType::vec2, std::move(name), member, min, max, std::move(unit),
                 std::move(doc));
  }
  /// A glm::vec3 member; each component within [min, max].
  ParamTable& vec3(std::string name, glm::vec3 P::*member, float min, float max, std::string unit,
                   std::string doc) {
    return plain(ParamType::vec3, std::move(name), member, min, max, std::move(unit),
                 std::move(doc));
  }
  /// A glm::vec4 member; each component within [min, max].
  ParamTable& vec4(std::string name, glm::vec4 P::*member, float min, float max, std::string unit,
                   std::string doc) {
    return plain(ParamType::vec4, std::move(name), member, min, max, std::move(unit),
                 std::move(doc));
  }
  /// A glm::vec3 member holding a linear RGB colour, each channel within [0, 1] (no unit).
  ParamTable& color(std::string name, glm::vec3 P::*member, std::string doc) {
    return plain(ParamType::color, std::move(name), member, 0.0f, 1.0f, "", std::move(doc));
  }
  /// A std::string member holding a texture file path (PNG/JPEG), "" for the built-in default.
  /// Only the type is checked here; the effect loads the file.
  ParamTable& texture(std::string name, std::string P::*member, std::string doc) {
    return plain(ParamType::texture, std::move(name), member, 0.0f, 0.0f, "", std::move(doc));
  }
  /// A std::string member holding text the effect interprets (e.g. a glTF node name), "" for
  /// none. Only the type is checked here; the effect refuses a text it cannot use (an unknown
  /// node) with a message naming it.
  ParamTable& string(std::string name, std::string P::*member, std::string doc) {
    return plain(ParamType::string, std::move(name), member, 0.0f, 0.0f, "", std::move(doc));
  }
  /// An enum member (enum or enum class, values 0..n-1): the value i is the text `choices[i]`,
  /// so `choices` lists the names in the enum's declaration order. A value outside [0, n-1]
  /// cast into the struct is refused by get and validate.
  template <class E>
  ParamTable& enumeration(std::string name, E P::*member, std::vector<std::string> choices,
                          std::string doc) {
    static_assert(std::is_enum<E>::value, "ParamTable::enumeration needs an enum member");
    ParamSpec spec{
        std::move(name), ParamType::enumeration, std::string(), 0.0f, 0.0f, std::move(choices), "",
        std::move(doc)};
    Entry entry{};
    entry.get = [member](const ParamSchema& schema, const ParamSpec& s,
                         const P& p) -> Result<ParamValue> {
      const auto index = static_cast<long long>(p.*member);
      if (index < 0 || index >= static_cast<long long>(s.choices.size())) {
        return enum_index_error(schema, s, index);
      }
      return ParamValue{s.choices[static_cast<std::size_t>(index)]};
    };
    entry.set = [member](const ParamSpec& s, P& p, const ParamValue& v) {
      const std::string& text = std::get<std::string>(v);
      for (std::size_t i = 0; i < s.choices.size(); ++i) {
        if (s.choices[i] == text) {
          p.*member = static_cast<E>(i);
        }
      }
    };
    return add(std::move(spec), std::move(entry));
  }
  /// A key that is no member of P but an action, e.g. water's `preset`: an enumeration of
  /// `choices` whose schema default is `default_choice`. set() validates the choice and calls
  /// `apply(p, choice)`. The table keeps no state, so get() returns `default_choice`; an effect
  /// whose get_param should read back the last choice applied stores it itself (water does;
  /// the conformance test requires it). validate() skips actions.
  ParamTable& action(std::string name, std::vector<std::string> choices, std::string default_choice,
                     std::function<void(P&, const std::string&)> apply, std::string doc) {
    ParamSpec spec{std::move(name),
                   ParamType::enumeration,
                   std::move(default_choice),
                   0.0f,
                   0.0f,
                   std::move(choices),
                   "",
                   std::move(doc)};
    Entry entry{};
    entry.set = [apply = std::move(apply)](const ParamSpec&, P& p, const ParamValue& v) {
      apply(p, std::get<std::string>(v));
    };
    return add(std::move(spec), std::move(entry));
  }

  /// Every declared parameter, in declaration order; defaults are those of a default-constructed
  /// P (actions: their default_choice).
  [[nodiscard]] const ParamSchema& schema() const { return schema_; }

  /// Validates `value` against `key`'s spec (validate_param: type, finiteness, range, choice)
  /// and stores it in `p` (an action calls its apply). Errors: unknown key -> unknown_name
  /// listing the valid keys; an invalid value -> invalid_argument naming `<effect>.<key>`, the
  /// value and the range. Nothing is clamped, and `p` is unchanged on error.
  [[nodiscard]] Result<void> set(P& p, std::string_view key, const ParamValue& value) const {
    const std::size_t i = index_of(key);
    if (i == entries_.size()) {
      return unknown_param_error(schema_, key);
    }
    const ParamSpec& spec = schema_.params[i];
    if (auto r = validate_param(schema_, spec, value); !r) {
      return r;
    }
    entries_[i].set(spec, p, value);
    return {};
  }

  /// The value of `key` in `p`, in the schema's type (an action: its default_choice). Errors:
  /// unknown key -> unknown_name; an enum member out of range -> invalid_argument.
  [[nodiscard]] Result<ParamValue> get(const P& p, std::string_view key) const {
    const std::size_t i = index_of(key);
    if (i == entries_.size()) {
      return unknown_param_error(schema_, key);
    }
    const ParamSpec& spec = schema_.params[i];
    if (!entries_[i].get) {
      return spec.default_value;
    }
    return entries_[i].get(schema_, spec, p);
  }

  /// Checks every member of `p` against its spec (non-finite, out of range, an enum value
  /// outside its choices); actions are skipped. The error is the first failure, invalid_argument
  /// naming `<effect>.<key>`, the value and the range.
  [[nodiscard]] Result<void> validate(const P& p) const {
    for (std::size_t i = 0; i < entries_.size(); ++i) {
      if (!entries_[i].get) {
        continue;
      }
      const ParamSpec& spec = schema_.params[i];
      auto value = entries_[i].get(schema_, spec, p);
      if (!value) {
        return value.error();
      }
      if (auto r = validate_param(schema_, spec, *value); !r) {
        return r;
      }
    }
    return {};
  }

  /// True when `key` is an action (declared with action()), false otherwise (also unknown).
  [[nodiscard]] bool is_action(std::string_view key) const {
    const std::size_t i = index_of(key);
    return i < entries_.size() && !entries_[i].get;
  }

private:
  /// How one parameter is read from and written to P. `get` is empty for actions; `set` runs
  /// only after the value passed validate_param.
  struct Entry {
    std::function<Result<ParamValue>(const ParamSchema&, const ParamSpec&, const P&)> get;
    std::function<void(const ParamSpec&, P&, const ParamValue&)> set;
  };

  /// A member stored as itself in ParamValue (T is one of its alternatives).
  template <class T>
  ParamTable& plain(ParamType type, std::string name, T P::*member, float min, float max,
                    std::string unit, std::string doc) {
    ParamSpec spec{std::move(name), type,          ParamValue{T()}, min, max, {},
                   std::move(unit), std::move(doc)};
    Entry entry{};
    entry.get = [member](const ParamSchema&, const ParamSpec&, const P& p) -> Result<ParamValue> {
      return ParamValue{p.*member};
    };
    entry.set = [member](const ParamSpec&, P& p, const ParamValue& v) {
      p.*member = std::get<T>(v);
    };
    return add(std::move(spec), std::move(entry));
  }

  ParamTable& add(ParamSpec spec, Entry entry) {
    if (entry.get) {
      // The default is read through the entry itself, so it is defaults_'s by construction.
      auto value = entry.get(schema_, spec, defaults_);
      spec.default_value = value ? *value : ParamValue{std::string()};
    }
    schema_.params.push_back(std::move(spec));
    entries_.push_back(std::move(entry));
    return *this;
  }

  std::size_t index_of(std::string_view key) const {
    for (std::size_t i = 0; i < schema_.params.size(); ++i) {
      if (schema_.params[i].name == key) {
        return i;
      }
    }
    return entries_.size();
  }

  P defaults_; ///< The values the schema reports as defaults.
  ParamSchema schema_;
  std::vector<Entry> entries_; ///< Parallel to schema_.params.
};

/// An effect's current parameters kept with their table: what Effect::set_param, get_param and a
/// typed set_params need, so a plugin writes none of it. It remembers the last choice of every
/// action (get reads a preset back), and lets the effect refuse a change it cannot apply (a
/// texture that does not load) before anything is stored.
template <class P> class ParamStore {
public:
  /// `table` must outlive the store (a function-local static does); `initial` is the starting
  /// value (e.g. the table's defaults adjusted from the scene).
  ParamStore(const ParamTable<P>& table, P initial) : table_(&table), value_(std::move(initial)) {}

  /// The current parameters.
  [[nodiscard]] const P& value() const { return value_; }
  /// Mutable access for an effect's own adjustments that need no validation (e.g. from its
  /// scene at creation).
  [[nodiscard]] P& value() { return value_; }

  /// Sets `key` (ParamTable::set on a copy), then calls `commit(next)`, which returns
  /// Result<void> and may refuse; only then stores the copy (and an action's choice). Nothing
  /// changes on any error.
  template <class Commit>
  [[nodiscard]] Result<void> set(std::string_view key, const ParamValue& value, Commit&& commit) {
    P next = value_;
    if (auto r = table_->set(next, key, value); !r) {
      return r;
    }
    if (auto r = commit(static_cast<const P&>(next)); !r) {
      return r;
    }
    value_ = std::move(next);
    if (table_->is_action(key)) {
      choices_[std::string(key)] = std::get<std::string>(value);
    }
    return {};
  }
  /// Validates all of `next` (ParamTable::validate), then `commit(next)`, then stores it.
  template <class Commit> [[nodiscard]] Result<void> set_all(const P& next, Commit&& commit) {
    if (auto r = table_->validate(next); !r) {
      return r;
    }
    if (auto r = commit(next); !r) {
      return r;
    }
    value_ = next;
    return {};
  }
  /// The value of `key`; an action reads back its last choice (its default before any).
  [[nodiscard]] Result<ParamValue> get(std::string_view key) const {
    if (const auto it = choices_.find(key); it != choices_.end()) {
      return ParamValue{it->second};
    }
    return table_->get(value_, key);
  }

private:
  const ParamTable<P>* table_;
  P value_;
  std::map<std::string, std::string, std::less<>> choices_; ///< Last choice per action.
};

} // namespace snell
