// Internal: conversion of glTF meshes (primitives) to snell::Mesh.
#pragma once

#include "gltf_context.hpp"
#include "gltf_tinygltf.hpp"

#include <snell/result.hpp>
#include <snell/scene.hpp>

#include <cstdint>
#include <vector>

namespace snell::detail {

/// Vertices and indices created so far (GltfLimits::max_total_vertices / max_total_indices).
struct GeometryTotals {
  std::uint64_t vertices = 0;
  std::uint64_t indices = 0;
};

/// Converts the primitives of glTF mesh `mesh_index` into Scene meshes appended to `scene.meshes`
/// (one per primitive: a Mesh has one material) and returns their indices there.
///  - Triangles are taken as they are; triangle strips and fans are converted to triangle lists.
///  - Points and lines are skipped: Snell's renderer draws triangles only, and a model that mixes
///    them in (helper lines, point clouds next to surfaces) still shows its surfaces. Primitives
///    without POSITION are skipped too (glTF: "client implementations SHOULD skip" them).
///  - Non-indexed primitives get indices 0..n-1.
///  - Missing normals are generated flat (glTF requires it; provided tangents are then ignored, as
///    glTF also requires); missing tangents are generated from the UVs (mesh_utils.hpp).
/// Errors: parse_error (bad accessor, index past the vertex count, non-finite value, triangle
/// list count not a multiple of 3), limit_exceeded (GltfLimits vertex/index totals).
[[nodiscard]] Result<std::vector<int>> convert_mesh(const tinygltf::Model& model, int mesh_index,
                                                    Scene& scene, GeometryTotals& totals,
                                                    const GltfLoadContext& ctx);

} // namespace snell::detail
