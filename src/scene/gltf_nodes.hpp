// Internal: the glTF node hierarchy: checks, world transforms, objects, cameras and the light.
#pragma once

#include "gltf_context.hpp"
#include "gltf_mesh.hpp"
#include "gltf_tinygltf.hpp"

#include <snell/result.hpp>
#include <snell/scene.hpp>

namespace snell::detail {

/// Walks the nodes of the displayed scene (the default scene, else scene 0, else, in a file
/// without scenes, every node without a parent) and fills scene.objects (one per triangle
/// primitive of each node's mesh, converting meshes on first use), scene.cameras (perspective
/// cameras in walk order; orthographic ones are skipped) and scene.light (the first directional
/// KHR_lights_punctual light; point and spot lights are ignored).
/// World transforms compose TRS or matrix transforms from the roots; negative scales are kept.
/// Errors: parse_error for a node with two parents, a cycle, a scene root that has a parent or
/// is listed twice, a non-finite world transform, a camera or light node whose transform has no
/// direction; limit_exceeded for a hierarchy deeper than GltfLimits::max_node_depth or more
/// objects than GltfLimits::max_objects; and the errors of convert_mesh.
[[nodiscard]] Result<void> convert_nodes(const tinygltf::Model& model, Scene& scene,
                                         GeometryTotals& totals, const GltfLoadContext& ctx);

} // namespace snell::detail
