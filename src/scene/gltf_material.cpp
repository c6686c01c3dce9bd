// Internal: conversion of glTF images, textures and materials (see gltf_material.hpp).
#include "gltf_material.hpp"

#include "gltf_uri.hpp"

#include <cmath>
#include <limits>
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

// Number `key` of extension `extension` on `material`: nullopt when the extension is absent,
// `fallback` when the extension is present without the key (its glTF default).
Result<std::optional<double>> extension_number(const tinygltf::Material& material,
                                               const char* extension, const char* key,
                                               double fallback, const std::string& what,
                                               const GltfLoadContext& ctx) {
  const auto it = material.extensions.find(extension);
  if (it == material.extensions.end()) {
    return std::optional<double>{};
  }
  if (!it->second.Has(key)) {
    return std::optional<double>(fallback);
  }
  const tinygltf::Value& value = it->second.Get(key);
  if (!value.IsNumber() || !std::isfinite(value.GetNumberAsDouble()) ||
      std::abs(value.GetNumberAsDouble()) >
          static_cast<double>(std::numeric_limits<float>::max())) {
    return ctx.fail(ErrorCode::parse_error,
                    what + ": " + extension + "." + key + " is not a finite number");
  }
  return std::optional<double>(value.GetNumberAsDouble());
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
    if (m.normal_texture >= 0) {
      scene.images[static_cast<std::size_t>(m.normal_texture)].srgb = false; // Vectors, not colour.
    }
    scene.materials.push_back(std::move(m));
  }
  return {};
}

} // namespace snell::detail
