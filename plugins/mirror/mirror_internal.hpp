// Internal to the mirror plugin: its parameter table and the plane fitted to a node's mesh.
#pragma once

#include <snell/math/bounds.hpp>
#include <snell/mirror.hpp>
#include <snell/param_table.hpp>
#include <snell/scene.hpp>

#include <glm/vec4.hpp>

namespace snell::detail {

/// The parameter table (schema, set, get, validation).
const ParamTable<MirrorParams>& mirror_table();

/// A mesh's plane in object space.
struct MeshPlane {
  glm::vec4 plane{0.0f, 1.0f, 0.0f, 0.0f}; ///< xyz unit normal (the front faces' side), w offset.
  Aabb bounds{};                           ///< Object-space bounds of the vertices.
};

/// Fits the plane of `mesh` (area-weighted triangle normals, through the vertices' centroid) and
/// checks that every vertex lies on it within max(0.1 mm, 0.1 % of the mesh's size). Errors
/// name `key`, the node and how far the farthest vertex is off the plane.
Result<MeshPlane> fit_mesh_plane(const Mesh& mesh, const std::string& node, const char* key);

} // namespace snell::detail
