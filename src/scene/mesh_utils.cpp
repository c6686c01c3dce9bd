// Internal: vertex-attribute generation and validation (see mesh_utils.hpp).
#include "mesh_utils.hpp"

#include <glm/geometric.hpp>

#include <cmath>

namespace snell::detail {
namespace {

bool finite(glm::vec2 v) {
  return std::isfinite(v.x) && std::isfinite(v.y);
}
bool finite(glm::vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool finite(glm::vec4 v) {
  return finite(glm::vec3(v)) && std::isfinite(v.w);
}

// Squared lengths below this are treated as zero: vectors built from float positions in the
// usual ranges are many orders of magnitude longer, and dividing by such a length would amplify
// rounding noise into an arbitrary direction.
constexpr float tiny_length2 = 1e-30f;

bool triangle_in_range(const std::vector<std::uint32_t>& indices, std::size_t first,
                       std::size_t vertex_count) {
  return indices[first] < vertex_count && indices[first + 1] < vertex_count &&
         indices[first + 2] < vertex_count;
}

glm::vec3 normalized_or(glm::vec3 v, glm::vec3 fallback) {
  const float len2 = glm::dot(v, v);
  if (!(len2 > tiny_length2) || !std::isfinite(len2)) {
    return fallback;
  }
  return v / std::sqrt(len2);
}

} // namespace

glm::vec3 any_perpendicular(glm::vec3 n) {
  // Cross with the coordinate axis least aligned with n, so the result is never near zero.
  const glm::vec3 a = glm::abs(n);
  const glm::vec3 axis = (a.x <= a.y && a.x <= a.z) ? glm::vec3(1, 0, 0)
                         : (a.y <= a.z)             ? glm::vec3(0, 1, 0)
                                                    : glm::vec3(0, 0, 1);
  return normalized_or(glm::cross(n, axis), glm::vec3(1, 0, 0));
}

void generate_flat_or_smooth_normals(std::vector<Vertex>& vertices,
                                     std::vector<std::uint32_t>& indices, NormalMode mode) {
  const std::size_t triangle_count = indices.size() / 3;
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  if (mode == NormalMode::flat) {
    std::vector<Vertex> flat;
    flat.reserve(triangle_count * 3);
    for (std::size_t t = 0; t < triangle_count; ++t) {
      if (!triangle_in_range(indices, 3 * t, vertices.size())) {
        continue;
      }
      const Vertex& a = vertices[indices[3 * t]];
      const Vertex& b = vertices[indices[3 * t + 1]];
      const Vertex& c = vertices[indices[3 * t + 2]];
      const glm::vec3 n =
          normalized_or(glm::cross(b.position - a.position, c.position - a.position), up);
      for (const Vertex* v : {&a, &b, &c}) {
        flat.push_back(*v);
        flat.back().normal = n;
      }
    }
    vertices = std::move(flat);
    indices.resize(vertices.size());
    for (std::size_t i = 0; i < indices.size(); ++i) {
      indices[i] = static_cast<std::uint32_t>(i);
    }
    return;
  }

  std::vector<glm::vec3> sum(vertices.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t < triangle_count; ++t) {
    if (!triangle_in_range(indices, 3 * t, vertices.size())) {
      continue;
    }
    const std::uint32_t i0 = indices[3 * t], i1 = indices[3 * t + 1], i2 = indices[3 * t + 2];
    // The unnormalised cross product's length is twice the triangle's area: summing it weights
    // every face by its area, so slivers at a seam do not skew the result.
    const glm::vec3 face = glm::cross(vertices[i1].position - vertices[i0].position,
                                      vertices[i2].position - vertices[i0].position);
    if (!finite(face)) {
      continue;
    }
    sum[i0] += face;
    sum[i1] += face;
    sum[i2] += face;
  }
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    vertices[i].normal = normalized_or(sum[i], up);
  }
}

void generate_tangents(std::vector<Vertex>& vertices, const std::vector<std::uint32_t>& indices) {
  std::vector<glm::vec3> tan_sum(vertices.size(), glm::vec3(0.0f));
  std::vector<glm::vec3> up_sum(vertices.size(), glm::vec3(0.0f)); // direction of decreasing v
  const std::size_t triangle_count = indices.size() / 3;
  for (std::size_t t = 0; t < triangle_count; ++t) {
    if (!triangle_in_range(indices, 3 * t, vertices.size())) {
      continue;
    }
    const std::uint32_t i0 = indices[3 * t], i1 = indices[3 * t + 1], i2 = indices[3 * t + 2];
    const glm::vec3 e1 = vertices[i1].position - vertices[i0].position;
    const glm::vec3 e2 = vertices[i2].position - vertices[i0].position;
    const glm::vec2 d1 = vertices[i1].uv - vertices[i0].uv;
    const glm::vec2 d2 = vertices[i2].uv - vertices[i0].uv;
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (!std::isfinite(det) || std::abs(det) < 1e-20f) {
      continue; // Degenerate UVs: this triangle says nothing about the tangent frame.
    }
    // Solve [e1 e2] = [T B] [d1 d2] for T = dP/du and B = dP/dv (Lengyel). Each triangle's
    // contribution is scaled by |det| (its UV area) relative to the plain solution, so small UV
    // islands at seams do not dominate.
    const float sign = det > 0.0f ? 1.0f : -1.0f;
    const glm::vec3 dp_du = (e1 * d2.y - e2 * d1.y) * sign;
    const glm::vec3 dp_dv = (e2 * d1.x - e1 * d2.x) * sign;
    if (!finite(dp_du) || !finite(dp_dv)) {
      continue;
    }
    for (const std::uint32_t i : {i0, i1, i2}) {
      tan_sum[i] += dp_du;
      up_sum[i] -= dp_dv;
    }
  }
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    Vertex& v = vertices[i];
    const glm::vec3 n = normalized_or(v.normal, glm::vec3(0, 1, 0));
    // Gram-Schmidt: remove the normal component so that the frame is orthonormal.
    const glm::vec3 t = tan_sum[i] - n * glm::dot(n, tan_sum[i]);
    const float len2 = glm::dot(t, t);
    if (!(len2 > tiny_length2) || !std::isfinite(len2)) {
      v.tangent = glm::vec4(any_perpendicular(n), 1.0f);
      continue;
    }
    const glm::vec3 tn = t / std::sqrt(len2);
    const float handedness = glm::dot(glm::cross(n, tn), up_sum[i]) < 0.0f ? -1.0f : 1.0f;
    v.tangent = glm::vec4(tn, handedness);
  }
}

std::optional<std::size_t> first_non_finite_position(const std::vector<Vertex>& v) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!finite(v[i].position)) {
      return i;
    }
  }
  return std::nullopt;
}

std::optional<std::size_t> first_non_finite_vertex(const std::vector<Vertex>& v) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!finite(v[i].position) || !finite(v[i].normal) || !finite(v[i].tangent) ||
        !finite(v[i].uv)) {
      return i;
    }
  }
  return std::nullopt;
}

std::optional<std::size_t> first_index_out_of_range(const std::vector<std::uint32_t>& indices,
                                                    std::size_t vertex_count) {
  for (std::size_t i = 0; i < indices.size(); ++i) {
    if (indices[i] >= vertex_count) {
      return i;
    }
  }
  return std::nullopt;
}

} // namespace snell::detail
