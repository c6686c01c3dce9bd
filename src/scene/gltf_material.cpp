// Internal: conversion of glTF images, textures and materials (see gltf_material.hpp).
#include "gltf_material.hpp"

#include "gltf_uri.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>

namespace snell::detail {
namespace {

// The Scene::images index behind glTF texture `texture`, or -1.
int image_of(const tinygltf::Model& model, int texture) {
  if (texture < 0 || static_cast<std::size_t>(texture) >= model.textures.size()) {
    return -1;
  }
  const int source = model.textures[static_cast<std::size_t>(texture)].source;
  return (source >= 0 && static_cast<std::size_t>(source) < model.images.size()) ? source : -1;
}

// Extension `extension` on `material`, or nullptr when the material does not use it.
const tinygltf::Value* find_extension(const tinygltf::Material& material, const char* extension) {
  const auto it = material.extensions.find(extension);
  return it == material.extensions.end() ? nullptr : &it->second;
}

// `value` for messages: "%g" keeps 1e-09 and 3e+38 readable where std::to_string would print
// "0.000000" or 39 digits.
std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// "<model>: <material>: <field> <value> is outside <range>": names everything a user needs to find
// and fix the value.
Error out_of_range(const std::string& what, const std::string& field, double value,
                   const char* range, const GltfLoadContext& ctx) {
  return ctx.fail(ErrorCode::parse_error,
                  what + ": " + field + " " + number_text(value) + " is outside " + range);
}

// Number `key` of extension `extension` on `material`: nullopt when the extension is absent,
// `fallback` when the extension is present without the key (its glTF default).
Result<std::optional<double>> extension_number(const tinygltf::Material& material,
                                               const char* extension, const char* key,
                                               double fallback, const std::string& what,
                                               const GltfLoadContext& ctx) {
  const tinygltf::Value* ext = find_extension(material, extension);
  if (ext == nullptr) {
    return std::optional<double>{};
  }
  if (!ext->Has(key)) {
    return std::optional<double>(fallback);
  }
  const tinygltf::Value& value = ext->Get(key);
  const std::string field = what + ": " + extension + "." + key;
  if (!value.IsNumber()) {
    return ctx.fail(ErrorCode::parse_error, field + " is not a number");
  }
  // Materials store floats: a finite double beyond FLT_MAX would not convert (undefined
  // behaviour in C++).
  const double number = value.GetNumberAsDouble();
  if (!std::isfinite(number) ||
      std::abs(number) > static_cast<double>(std::numeric_limits<float>::max())) {
    return ctx.fail(ErrorCode::parse_error,
                    field + " " + number_text(number) + " is not a finite float");
  }
  return std::optional<double>(number);
}

// Linear colour `key` of extension `extension` on `material`, like extension_number: nullopt when
// the extension is absent, `fallback` when the key is. glTF's schemas bound colour factors to
// exactly 3 numbers in [0, 1]; anything else is refused, so the renderer never sees a colour that
// amplifies light or is not a number.
Result<std::optional<glm::vec3>> extension_color(const tinygltf::Material& material,
                                                 const char* extension, const char* key,
                                                 glm::vec3 fallback, const std::string& what,
                                                 const GltfLoadContext& ctx) {
  const tinygltf::Value* ext = find_extension(material, extension);
  if (ext == nullptr) {
    return std::optional<glm::vec3>{};
  }
  if (!ext->Has(key)) {
    return std::optional<glm::vec3>(fallback);
  }
  const tinygltf::Value& value = ext->Get(key);
  const std::string field = std::string(extension) + "." + key;
  if (!value.IsArray() || value.ArrayLen() != 3) {
    return ctx.fail(
        ErrorCode::parse_error,
        what + ": " + field + " is not an array of 3 numbers in [0, 1]" +
            (value.IsArray() ? " (it has " + std::to_string(value.ArrayLen()) + ")" : ""));
  }
  glm::vec3 color(0.0f);
  for (int c = 0; c < 3; ++c) {
    const tinygltf::Value& component = value.Get(c);
    const std::string component_field = field + "[" + std::to_string(c) + "]";
    if (!component.IsNumber()) {
      return ctx.fail(ErrorCode::parse_error, what + ": " + component_field + " is not a number");
    }
    const double v = component.GetNumberAsDouble();
    if (!(v >= 0.0 && v <= 1.0)) { // Also refuses NaN.
      return out_of_range(what, component_field, v, "[0, 1]", ctx);
    }
    color[c] = static_cast<float>(v);
  }
  return std::optional<glm::vec3>(color);
}

Result<void> convert_images(const tinygltf::Model& model, Scene& scene,
                            const GltfLoadContext& ctx) {
  scene.images.reserve(model.images.size());
  for (std::size_t i = 0; i < model.images.size(); ++i) {
    const tinygltf::Image& source = model.images[i];
    const std::size_t expected = static_cast<std::size_t>(source.width > 0 ? source.width : 0) *
                                 static_cast<std::size_t>(source.height > 0 ? source.height : 0) *
                                 4;
    // Every image goes through load_image_data, which records its failures; an image that still
    // has no pixels here was skipped by tinygltf (e.g. an external file it could not find).
    if (expected == 0 || source.component != 4 || source.bits != 8 ||
        source.image.size() != expected) {
      return ctx.fail(
          ErrorCode::parse_error,
          describe("image", i, source.name) +
              (source.uri.empty() ? "" : " (URI '" + clip_for_message(source.uri) + "')") +
              ": no decoded RGBA8 data");
    }
    Image image;
    image.name = !source.name.empty()  ? source.name
                 : !source.uri.empty() ? source.uri
                                       : ctx.name + " image " + std::to_string(i);
    image.width = static_cast<std::uint32_t>(source.width);
    image.height = static_cast<std::uint32_t>(source.height);
    image.rgba8 = source.image;
    scene.images.push_back(std::move(image));
  }
  return {};
}

// KHR_materials_volume and KHR_materials_dispersion into `m`. Values that pass extension_number
// are finite floats; the checks here are the extensions' own ranges.
Result<void> read_volume_and_dispersion(const tinygltf::Material& source, Material& m,
                                        const std::string& what, const GltfLoadContext& ctx) {
  // thicknessTexture is ignored: the renderer has one thickness per material, so
  // thicknessFactor alone (the texture's scale in glTF) is the best single value.
  Result<std::optional<double>> thickness =
      extension_number(source, "KHR_materials_volume", "thicknessFactor", 0.0, what, ctx);
  // An absent attenuationDistance means no attenuation (+infinity); a value from the file is
  // finite (extension_number), so only its lower bound is left to check.
  Result<std::optional<double>> distance =
      extension_number(source, "KHR_materials_volume", "attenuationDistance",
                       std::numeric_limits<double>::infinity(), what, ctx);
  Result<std::optional<double>> dispersion =
      extension_number(source, "KHR_materials_dispersion", "dispersion", 0.0, what, ctx);
  for (const auto* r : {&thickness, &distance, &dispersion}) {
    if (!*r) {
      return r->error();
    }
  }
  Result<std::optional<glm::vec3>> color = extension_color(
      source, "KHR_materials_volume", "attenuationColor", glm::vec3(1.0f), what, ctx);
  if (!color) {
    return color.error();
  }
  if (*thickness) {
    if (!(**thickness >= 0.0)) {
      return out_of_range(what, "KHR_materials_volume.thicknessFactor", **thickness, "[0, inf)",
                          ctx);
    }
    m.thickness = static_cast<float>(**thickness);
  }
  if (*distance) {
    if (!(**distance > 0.0)) {
      return out_of_range(what, "KHR_materials_volume.attenuationDistance", **distance, "(0, inf)",
                          ctx);
    }
    m.attenuation_distance = static_cast<float>(**distance);
  }
  if (*color) {
    m.attenuation_color = **color;
  }
  // Kept as given even on a thin-walled material, where glTF says it has no effect: the renderer
  // decides what a zero thickness means.
  if (*dispersion) {
    if (!(**dispersion >= 0.0)) {
      return out_of_range(what, "KHR_materials_dispersion.dispersion", **dispersion, "[0, inf)",
                          ctx);
    }
    m.dispersion = static_cast<float>(**dispersion);
  }
  return {};
}

} // namespace

Result<void> convert_materials(const tinygltf::Model& model, Scene& scene,
                               const GltfLoadContext& ctx) {
  if (Result<void> r = convert_images(model, scene, ctx); !r) {
    return r;
  }
  scene.materials.reserve(model.materials.size());
  for (std::size_t i = 0; i < model.materials.size(); ++i) {
    const tinygltf::Material& source = model.materials[i];
    const std::string what = describe("material", i, source.name);
    const auto& pbr = source.pbrMetallicRoughness;
    Material m;
    m.name = source.name.empty() ? "material " + std::to_string(i) : source.name;
    // validate_model checked the sizes and finiteness of these factors.
    m.base_color = glm::vec4(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2],
                             pbr.baseColorFactor[3]);
    m.base_color_texture = image_of(model, pbr.baseColorTexture.index);
    m.normal_texture = image_of(model, source.normalTexture.index);
    m.normal_scale = static_cast<float>(source.normalTexture.scale);
    m.emissive =
        glm::vec3(source.emissiveFactor[0], source.emissiveFactor[1], source.emissiveFactor[2]);
    m.emissive_texture = image_of(model, source.emissiveTexture.index);
    m.roughness = static_cast<float>(pbr.roughnessFactor);
    m.alpha_mode = source.alphaMode == "MASK"    ? AlphaMode::mask
                   : source.alphaMode == "BLEND" ? AlphaMode::blend
                                                 : AlphaMode::opaque;
    m.alpha_cutoff = static_cast<float>(source.alphaCutoff);
    m.double_sided = source.doubleSided;

    Result<std::optional<double>> strength = extension_number(
        source, "KHR_materials_emissive_strength", "emissiveStrength", 1.0, what, ctx);
    Result<std::optional<double>> transmission = extension_number(
        source, "KHR_materials_transmission", "transmissionFactor", 0.0, what, ctx);
    Result<std::optional<double>> ior =
        extension_number(source, "KHR_materials_ior", "ior", 1.5, what, ctx);
    for (const auto* r : {&strength, &transmission, &ior}) {
      if (!*r) {
        return r->error();
      }
    }
    if (*strength) {
      if (**strength < 0.0) {
        return ctx.fail(ErrorCode::parse_error, what + ": emissiveStrength is negative");
      }
      m.emissive *= static_cast<float>(**strength);
      if (!std::isfinite(m.emissive.x + m.emissive.y + m.emissive.z)) {
        return ctx.fail(ErrorCode::parse_error,
                        what + ": emissiveFactor * emissiveStrength is not a finite float");
      }
    }
    if (*transmission) {
      if (!(**transmission >= 0.0 && **transmission <= 1.0)) {
        return ctx.fail(ErrorCode::parse_error, what + ": transmissionFactor " +
                                                    std::to_string(**transmission) +
                                                    " is outside [0, 1]");
      }
      m.transmission = static_cast<float>(**transmission);
    }
    if (*ior) {
      // glTF allows ior >= 1, and exactly 0 (a "perfect mirror" convention); kept as given.
      if (!(**ior >= 1.0 || **ior == 0.0)) {
        return ctx.fail(ErrorCode::parse_error,
                        what + ": ior " + std::to_string(**ior) + " is neither 0 nor >= 1");
      }
      m.ior = static_cast<float>(**ior);
    }
    if (Result<void> r = read_volume_and_dispersion(source, m, what, ctx); !r) {
      return r;
    }
    if (m.normal_texture >= 0) {
      scene.images[static_cast<std::size_t>(m.normal_texture)].srgb = false; // Vectors, not colour.
    }
    scene.materials.push_back(std::move(m));
  }
  return {};
}

} // namespace snell::detail
