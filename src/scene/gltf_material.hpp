// Internal: conversion of glTF images, textures and materials.
#pragma once

#include "gltf_context.hpp"
#include "gltf_tinygltf.hpp"

#include <snell/result.hpp>
#include <snell/scene.hpp>

namespace snell::detail {

/// Fills scene.images (one per glTF image, same order, RGBA8) and scene.materials (one per glTF
/// material, same order). A material's texture slots name Scene::images indices: the glTF
/// texture's `source` (textures without a decodable source, e.g. only KHR_texture_basisu, count
/// as none). Images used as normal maps are marked linear (Image::srgb = false).
/// Material values kept: baseColorFactor/Texture, normalTexture (+scale), emissiveFactor (times
/// KHR_materials_emissive_strength) / Texture, roughnessFactor, alphaMode/alphaCutoff,
/// doubleSided, KHR_materials_transmission transmissionFactor, KHR_materials_ior ior,
/// KHR_materials_volume thicknessFactor / attenuationDistance / attenuationColor (not
/// thicknessTexture), KHR_materials_dispersion dispersion.
/// Only TEXCOORD_0 is read: texCoord sets other than 0 and KHR_texture_transform are ignored.
/// Errors: parse_error (an image without decoded data, extension values out of their glTF range;
/// the message names the material, the field, the value and the valid range).
[[nodiscard]] Result<void> convert_materials(const tinygltf::Model& model, Scene& scene,
                                             const GltfLoadContext& ctx);

} // namespace snell::detail
