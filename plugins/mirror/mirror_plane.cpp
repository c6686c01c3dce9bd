// The plane of a mirror node's mesh: fitted once in object space, then placed per frame by the
// object's world transform (transform_plane: the inverse transpose).
#include "mirror_internal.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace snell::detail {

Result<MeshPlane> fit_mesh_plane(const Mesh& mesh, const std::string& node, const char* key) {
  if (mesh.vertices.empty() || mesh.indices.size() < 3) {
    return fail(ErrorCode::invalid_argument,
                std::string(key) + ": the object '" + node + "' has no triangles");
  }
  MeshPlane out;
  glm::dvec3 centroid(0.0);
  for (const Vertex& v : mesh.vertices) {
    centroid += glm::dvec3(v.position);
    out.bounds = expand(out.bounds, v.position);
  }
  centroid /= static_cast<double>(mesh.vertices.size());
  // Twice the area-weighted normal: the triangles' cross products, summed (their winding gives
  // the front side).
  glm::dvec3 normal(0.0);
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const glm::dvec3 a(mesh.vertices[mesh.indices[i]].position);
    const glm::dvec3 b(mesh.vertices[mesh.indices[i + 1]].position);
    const glm::dvec3 c(mesh.vertices[mesh.indices[i + 2]].position);
    normal += glm::cross(b - a, c - a);
  }
  const double length = glm::length(normal);
  if (!(length > 1e-12)) {
    return fail(ErrorCode::invalid_argument,
                std::string(key) + ": the object '" + node +
                    "' has no area facing one side (its triangles cancel out): not a mirror");
  }
  normal /= length;
  double worst = 0.0;
  for (const Vertex& v : mesh.vertices) {
    worst = std::max(worst, std::abs(glm::dot(glm::dvec3(v.position) - centroid, normal)));
  }
  const double size = glm::length(glm::dvec3(out.bounds.max) - glm::dvec3(out.bounds.min));
  const double tolerance = std::max(1e-4, 1e-3 * size);
  if (worst > tolerance) {
    std::ostringstream msg;
    msg << key << ": the object '" << node << "' is not planar: a vertex lies " << worst
        << " m off its best plane (tolerance " << tolerance
        << " m, 0.1 % of its size); a mirror must be flat";
    return fail(ErrorCode::invalid_argument, msg.str());
  }
  out.plane = glm::vec4(glm::vec3(normal), static_cast<float>(-glm::dot(normal, centroid)));
  return out;
}

} // namespace snell::detail
