// Procedural meshes with analytic normals, tangents and uvs (see procedural_meshes.hpp for the
// conventions). Curved shapes are built from parametric surfaces P(u, v): the normal, dP/du
// (the tangent) and dP/dv (which fixes the handedness) are written down, not estimated.
#include "procedural_meshes.hpp"

#include <glm/geometric.hpp>

#include <cmath>

namespace snell::detail {
namespace {

constexpr float pi = 3.14159265358979f;

// glTF handedness: bitangent = cross(n, t) * w must point toward decreasing v, i.e. -dP/dv.
float handedness(glm::vec3 n, glm::vec3 t, glm::vec3 dp_dv) {
  return glm::dot(glm::cross(n, t), -dp_dv) >= 0.0f ? 1.0f : -1.0f;
}

Vertex make_vertex(glm::vec3 p, glm::vec3 n, glm::vec3 t, glm::vec3 dp_dv, glm::vec2 uv) {
  Vertex v;
  v.position = p;
  v.normal = n;
  v.tangent = glm::vec4(t, handedness(n, t, dp_dv));
  v.uv = uv;
  return v;
}

std::uint32_t next_index(const Mesh& mesh) {
  return static_cast<std::uint32_t>(mesh.vertices.size());
}

void add_triangle(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  mesh.indices.insert(mesh.indices.end(), {a, b, c});
}

// A flat rectangle seen from its front: `centre`, outward `normal`, `up` (unit, perpendicular
// to the normal, the image's top), full `width` x `height`, split into nx x ny quads.
// right = cross(up, normal) makes (right, up, normal) right-handed, so corners taken
// counter-clockwise in (right, up) are counter-clockwise seen from the front.
void add_face(Mesh& mesh, glm::vec3 centre, glm::vec3 normal, glm::vec3 up, float width,
              float height, float uv_per_metre, std::uint32_t nx = 1, std::uint32_t ny = 1) {
  const glm::vec3 right = glm::cross(up, normal);
  const glm::vec3 origin = centre - right * (0.5f * width) - up * (0.5f * height);
  const std::uint32_t base = next_index(mesh);
  for (std::uint32_t j = 0; j <= ny; ++j) {
    for (std::uint32_t i = 0; i <= nx; ++i) {
      const float s = static_cast<float>(i) / static_cast<float>(nx);
      const float t = static_cast<float>(j) / static_cast<float>(ny);
      const glm::vec3 p = origin + right * (s * width) + up * (t * height);
      // Metre mode projects the position on the face axes, so coplanar faces tile seamlessly.
      const glm::vec2 uv = uv_per_metre > 0.0f
                               ? glm::vec2(glm::dot(p, right), -glm::dot(p, up)) * uv_per_metre
                               : glm::vec2(s, 1.0f - t);
      mesh.vertices.push_back(make_vertex(p, normal, right, -up, uv));
    }
  }
  for (std::uint32_t j = 0; j < ny; ++j) {
    for (std::uint32_t i = 0; i < nx; ++i) {
      const std::uint32_t a = base + j * (nx + 1) + i;
      const std::uint32_t b = a + 1;
      const std::uint32_t c = b + nx + 1;
      const std::uint32_t d = a + nx + 1;
      add_triangle(mesh, a, b, c);
      add_triangle(mesh, a, c, d);
    }
  }
}

// Index grid over (columns + 1) x (rows + 1) vertices laid out row by row, where walking along
// a row goes "right" and down a column goes "down" seen from outside. Triangles that collapse
// at a pole (sphere) are skipped so every emitted triangle has a well-defined winding.
void add_grid_indices(Mesh& mesh, std::uint32_t base, std::uint32_t columns, std::uint32_t rows,
                      bool skip_first_row_top, bool skip_last_row_bottom) {
  for (std::uint32_t j = 0; j < rows; ++j) {
    for (std::uint32_t i = 0; i < columns; ++i) {
      const std::uint32_t a = base + j * (columns + 1) + i; // top left
      const std::uint32_t d = a + 1;                        // top right
      const std::uint32_t b = a + columns + 1;              // bottom left
      const std::uint32_t c = b + 1;                        // bottom right
      if (!(skip_last_row_bottom && j == rows - 1)) {
        add_triangle(mesh, a, b, c);
      }
      if (!(skip_first_row_top && j == 0)) {
        add_triangle(mesh, a, c, d);
      }
    }
  }
}

// Horizontal unit vectors of longitude phi: radial (0 at +Z) and its derivative (toward +X).
glm::vec3 radial(float phi) {
  return {std::sin(phi), 0.0f, std::cos(phi)};
}
glm::vec3 around(float phi) {
  return {std::cos(phi), 0.0f, -std::sin(phi)};
}

void add_cap(Mesh& mesh, float radius, float y, bool top, std::uint32_t segments) {
  const glm::vec3 normal(0.0f, top ? 1.0f : -1.0f, 0.0f);
  // The image's top is -Z seen from above and +Z seen from below, so v grows toward +Z on the
  // top cap and toward -Z on the bottom one; u grows toward +X on both.
  const float v_sign = top ? 1.0f : -1.0f;
  const glm::vec3 tangent(1.0f, 0.0f, 0.0f);
  const glm::vec3 dp_dv(0.0f, 0.0f, v_sign);
  auto cap_uv = [&](glm::vec3 p) {
    return glm::vec2(0.5f + p.x / (2.0f * radius), 0.5f + v_sign * p.z / (2.0f * radius));
  };
  const std::uint32_t centre = next_index(mesh);
  const glm::vec3 c(0.0f, y, 0.0f);
  mesh.vertices.push_back(make_vertex(c, normal, tangent, dp_dv, cap_uv(c)));
  for (std::uint32_t i = 0; i <= segments; ++i) {
    const float phi = 2.0f * pi * static_cast<float>(i) / static_cast<float>(segments);
    const glm::vec3 p = radial(phi) * radius + glm::vec3(0.0f, y, 0.0f);
    mesh.vertices.push_back(make_vertex(p, normal, tangent, dp_dv, cap_uv(p)));
  }
  for (std::uint32_t i = 0; i < segments; ++i) {
    // Increasing phi turns counter-clockwise seen from above (+Z toward +X).
    if (top) {
      add_triangle(mesh, centre, centre + 1 + i, centre + 2 + i);
    } else {
      add_triangle(mesh, centre, centre + 2 + i, centre + 1 + i);
    }
  }
}

} // namespace

Mesh make_box(glm::vec3 size, float uv_per_metre) {
  Mesh mesh;
  mesh.name = "box";
  const glm::vec3 h = size * 0.5f;
  const glm::vec3 x(1.0f, 0.0f, 0.0f), y(0.0f, 1.0f, 0.0f), z(0.0f, 0.0f, 1.0f);
  add_face(mesh, x * h.x, x, y, size.z, size.y, uv_per_metre);
  add_face(mesh, -x * h.x, -x, y, size.z, size.y, uv_per_metre);
  add_face(mesh, z * h.z, z, y, size.x, size.y, uv_per_metre);
  add_face(mesh, -z * h.z, -z, y, size.x, size.y, uv_per_metre);
  add_face(mesh, y * h.y, y, -z, size.x, size.z, uv_per_metre);  // top: image top toward -Z
  add_face(mesh, -y * h.y, -y, z, size.x, size.z, uv_per_metre); // bottom: toward +Z
  return mesh;
}

Mesh make_plane(glm::vec2 size, std::uint32_t divisions, float uv_per_metre) {
  Mesh mesh;
  mesh.name = "plane";
  const std::uint32_t n = divisions == 0 ? 1 : divisions;
  add_face(mesh, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f, 0.0f, -1.0f), size.x,
           size.y, uv_per_metre, n, n);
  return mesh;
}

Mesh make_sphere(float radius, std::uint32_t segments, std::uint32_t rings) {
  Mesh mesh;
  mesh.name = "sphere";
  // P(phi, theta) = r (sin theta radial(phi) + cos theta Y); theta = 0 at the north pole.
  // dP/dphi ~ around(phi) (the tangent, defined even at the poles); dP/dv ~ dP/dtheta.
  for (std::uint32_t j = 0; j <= rings; ++j) {
    const float v = static_cast<float>(j) / static_cast<float>(rings);
    const float theta = pi * v;
    for (std::uint32_t i = 0; i <= segments; ++i) {
      const float u = static_cast<float>(i) / static_cast<float>(segments);
      const float phi = 2.0f * pi * u;
      const glm::vec3 n = radial(phi) * std::sin(theta) + glm::vec3(0.0f, std::cos(theta), 0.0f);
      const glm::vec3 dn_dtheta =
          radial(phi) * std::cos(theta) - glm::vec3(0.0f, std::sin(theta), 0.0f);
      mesh.vertices.push_back(make_vertex(n * radius, n, around(phi), dn_dtheta, {u, v}));
    }
  }
  add_grid_indices(mesh, 0, segments, rings, true, true);
  return mesh;
}

Mesh make_cylinder(float radius, float height, std::uint32_t segments) {
  Mesh mesh;
  mesh.name = "cylinder";
  const float h = 0.5f * height;
  for (std::uint32_t j = 0; j <= 1; ++j) {
    const float y = j == 0 ? h : -h; // row 0 at the top: v = 0 is the image's top
    for (std::uint32_t i = 0; i <= segments; ++i) {
      const float u = static_cast<float>(i) / static_cast<float>(segments);
      const float phi = 2.0f * pi * u;
      const glm::vec3 n = radial(phi);
      mesh.vertices.push_back(make_vertex(n * radius + glm::vec3(0.0f, y, 0.0f), n, around(phi),
                                          glm::vec3(0.0f, -1.0f, 0.0f),
                                          {u, static_cast<float>(j)}));
    }
  }
  add_grid_indices(mesh, 0, segments, 1, false, false);
  add_cap(mesh, radius, h, true, segments);
  add_cap(mesh, radius, -h, false, segments);
  return mesh;
}

Mesh make_torus(float major, float minor, std::uint32_t segments, std::uint32_t sides) {
  Mesh mesh;
  mesh.name = "torus";
  // P(phi, psi) = (major + minor cos psi) radial(phi) + minor sin psi Y; psi = 0 on the outer
  // equator, growing upward there. Rows run with decreasing psi so that v grows downward on
  // the outside, like the sphere (the image stands upright).
  for (std::uint32_t k = 0; k <= sides; ++k) {
    const float v = static_cast<float>(k) / static_cast<float>(sides);
    const float psi = 2.0f * pi * (1.0f - v);
    for (std::uint32_t i = 0; i <= segments; ++i) {
      const float u = static_cast<float>(i) / static_cast<float>(segments);
      const float phi = 2.0f * pi * u;
      const glm::vec3 n = radial(phi) * std::cos(psi) + glm::vec3(0.0f, std::sin(psi), 0.0f);
      const glm::vec3 p = radial(phi) * major + n * minor;
      // dP/dv = -2pi dP/dpsi, and dP/dpsi ~ -sin psi radial + cos psi Y.
      const glm::vec3 dp_dv =
          -(radial(phi) * -std::sin(psi) + glm::vec3(0.0f, std::cos(psi), 0.0f));
      mesh.vertices.push_back(make_vertex(p, n, around(phi), dp_dv, {u, v}));
    }
  }
  add_grid_indices(mesh, 0, segments, sides, false, false);
  return mesh;
}

Mesh make_basin(glm::vec2 inner_size, float height, float wall, float floor_thickness,
                BasinPart part, float uv_per_metre) {
  Mesh mesh;
  const glm::vec3 x(1.0f, 0.0f, 0.0f), y(0.0f, 1.0f, 0.0f), z(0.0f, 0.0f, 1.0f);
  const float hx = 0.5f * inner_size.x, hz = 0.5f * inner_size.y; // inner half extents
  const float ox = hx + wall, oz = hz + wall;                     // outer half extents
  const float k = uv_per_metre;
  if (part == BasinPart::inside) {
    mesh.name = "basin_inside";
    const float wall_h = height - floor_thickness;
    const float yc = 0.5f * (height + floor_thickness);
    add_face(mesh, y * floor_thickness, y, -z, inner_size.x, inner_size.y, k);
    // Inner walls face the centre of the pool.
    add_face(mesh, glm::vec3(0.0f, yc, hz), -z, y, inner_size.x, wall_h, k);
    add_face(mesh, glm::vec3(0.0f, yc, -hz), z, y, inner_size.x, wall_h, k);
    add_face(mesh, glm::vec3(hx, yc, 0.0f), -x, y, inner_size.y, wall_h, k);
    add_face(mesh, glm::vec3(-hx, yc, 0.0f), x, y, inner_size.y, wall_h, k);
  } else {
    mesh.name = "basin_outside";
    // Rim: four strips around the opening (front/back span the full width, sides fill in).
    const float zs = 0.5f * (hz + oz), xs = 0.5f * (hx + ox);
    add_face(mesh, glm::vec3(0.0f, height, -zs), y, -z, 2.0f * ox, wall, k);
    add_face(mesh, glm::vec3(0.0f, height, zs), y, -z, 2.0f * ox, wall, k);
    add_face(mesh, glm::vec3(-xs, height, 0.0f), y, -z, wall, inner_size.y, k);
    add_face(mesh, glm::vec3(xs, height, 0.0f), y, -z, wall, inner_size.y, k);
    const float yc = 0.5f * height;
    add_face(mesh, glm::vec3(0.0f, yc, oz), z, y, 2.0f * ox, height, k);
    add_face(mesh, glm::vec3(0.0f, yc, -oz), -z, y, 2.0f * ox, height, k);
    add_face(mesh, glm::vec3(ox, yc, 0.0f), x, y, 2.0f * oz, height, k);
    add_face(mesh, glm::vec3(-ox, yc, 0.0f), -x, y, 2.0f * oz, height, k);
  }
  return mesh;
}

} // namespace snell::detail
