// Snell: methods of the CPU scene model (include/snell/scene.hpp).
#include <snell/scene.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>

namespace snell {

glm::mat4 Object::world_at(float time) const {
  const float angle = spin_rate * time;
  // A static object, or an axis that cannot be normalised (glm::rotate would divide by zero and
  // turn the whole transform into NaN): the object does not spin.
  if (angle == 0.0f || !std::isfinite(angle) || glm::dot(spin_axis, spin_axis) <= 0.0f) {
    return transform;
  }
  return glm::rotate(transform, angle, spin_axis);
}

const Anchor* Scene::find_anchor(std::string_view anchor_name) const {
  for (const Anchor& anchor : anchors) {
    if (anchor.name == anchor_name) {
      return &anchor;
    }
  }
  return nullptr;
}

std::pair<glm::vec3, glm::vec3> Scene::bounds() const {
  // Exact bounds: every vertex of every object is transformed. Transforming the corners of each
  // mesh's local box would be cheaper but loose for rotated objects, and callers frame cameras
  // and size effects (water planes, probes) from this box.
  constexpr float inf = std::numeric_limits<float>::infinity();
  glm::vec3 lo(inf);
  glm::vec3 hi(-inf);
  for (const Object& object : objects) {
    if (object.mesh < 0 || static_cast<std::size_t>(object.mesh) >= meshes.size()) {
      continue; // No geometry to bound (an object without a valid mesh is not drawn either).
    }
    const glm::mat4& m = object.transform;
    for (const Vertex& v : meshes[static_cast<std::size_t>(object.mesh)].vertices) {
      const glm::vec3 p = glm::vec3(m * glm::vec4(v.position, 1.0f)); // Affine: w stays 1.
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
  if (!(lo.x <= hi.x)) {
    return {glm::vec3(0.0f), glm::vec3(0.0f)}; // Nothing drawn: the documented zero box.
  }
  return {lo, hi};
}

} // namespace snell
