// Surfaces: meshes an effect draws with its own shading, uploaded from one of three sources.
#include <snell/toolkit/surfaces.hpp>

#include "../scene/procedural_meshes.hpp"

#include <algorithm>
#include <string>

namespace snell {
namespace {

Result<Surface> upload(const Context& ctx, const Mesh& mesh, const glm::mat4& world,
                       const Material& material, int object, const std::string& what) {
  if (mesh.vertices.empty() || mesh.indices.empty() || mesh.indices.size() % 3 != 0) {
    return fail(ErrorCode::invalid_argument,
                what + ": a surface needs vertices and a triangle list (got " +
                    std::to_string(mesh.vertices.size()) + " vertices, " +
                    std::to_string(mesh.indices.size()) + " indices)");
  }
  for (const std::uint32_t i : mesh.indices) {
    if (i >= mesh.vertices.size()) {
      return fail(ErrorCode::invalid_argument,
                  what + ": index " + std::to_string(i) + " is out of range (" +
                      std::to_string(mesh.vertices.size()) + " vertices)");
    }
  }
  Surface s;
  const VkDeviceSize vbytes = mesh.vertices.size() * sizeof(Vertex);
  const VkDeviceSize ibytes = mesh.indices.size() * sizeof(std::uint32_t);
  auto vb = Buffer::create(ctx, BufferDesc{.size = vbytes,
                                           .usage = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                                           .debug_name = "surface vertices"});
  auto ib = Buffer::create(ctx, BufferDesc{.size = ibytes,
                                           .usage = VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                                           .debug_name = "surface indices"});
  if (!vb || !ib) {
    return !vb ? vb.error() : ib.error();
  }
  if (auto r = vb->upload(mesh.vertices.data(), vbytes); !r) {
    return r.error();
  }
  if (auto r = ib->upload(mesh.indices.data(), ibytes); !r) {
    return r.error();
  }
  s.vertices = std::move(*vb);
  s.indices = std::move(*ib);
  s.index_count = static_cast<std::uint32_t>(mesh.indices.size());
  s.world = world;
  s.material = material;
  s.object = object;
  s.bounds_min = s.bounds_max = mesh.vertices.front().position;
  for (const Vertex& v : mesh.vertices) {
    s.bounds_min = glm::min(s.bounds_min, v.position);
    s.bounds_max = glm::max(s.bounds_max, v.position);
  }
  return s;
}

} // namespace

Result<Surfaces> Surfaces::from_scene(const Context& ctx, const Scene& scene,
                                      const Selector& select) {
  Surfaces out;
  const Material fallback;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Object& o = scene.objects[i];
    if (o.mesh < 0 || static_cast<std::size_t>(o.mesh) >= scene.meshes.size()) {
      continue;
    }
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(o.mesh)];
    const bool has_material =
        mesh.material >= 0 && static_cast<std::size_t>(mesh.material) < scene.materials.size();
    const Material& material =
        has_material ? scene.materials[static_cast<std::size_t>(mesh.material)] : fallback;
    if (select && !select(o, mesh, material)) {
      continue;
    }
    auto s = upload(ctx, mesh, o.world_at(0.0f), material, static_cast<int>(i),
                    "surface from object '" + o.name + "'");
    if (!s) {
      return s.error();
    }
    out.surfaces_.push_back(std::move(*s));
    out.objects_.push_back(static_cast<int>(i));
  }
  return out;
}

Result<Surfaces> Surfaces::from_arrays(const Context& ctx, Span<const Vertex> vertices,
                                       Span<const std::uint32_t> indices, const glm::mat4& world,
                                       const Material& material) {
  Mesh mesh;
  mesh.name = "host arrays";
  mesh.vertices.assign(vertices.begin(), vertices.end());
  mesh.indices.assign(indices.begin(), indices.end());
  auto s = upload(ctx, mesh, world, material, -1, "surface from host arrays");
  if (!s) {
    return s.error();
  }
  Surfaces out;
  out.surfaces_.push_back(std::move(*s));
  return out;
}

Result<Surfaces> Surfaces::shape(const Context& ctx, Shape shape, const glm::mat4& world,
                                 const Material& material) {
  Mesh mesh;
  switch (shape) {
  case Shape::quad:
    mesh = detail::make_plane(glm::vec2(1.0f));
    break;
  case Shape::box:
    mesh = detail::make_box(glm::vec3(1.0f));
    break;
  case Shape::sphere:
    mesh = detail::make_sphere(0.5f);
    break;
  }
  auto s = upload(ctx, mesh, world, material, -1, "built-in surface shape");
  if (!s) {
    return s.error();
  }
  Surfaces out;
  out.surfaces_.push_back(std::move(*s));
  return out;
}

void Surfaces::append(Surfaces&& other) {
  for (Surface& s : other.surfaces_) {
    surfaces_.push_back(std::move(s));
  }
  objects_.insert(objects_.end(), other.objects_.begin(), other.objects_.end());
  other.surfaces_.clear();
  other.objects_.clear();
}

void Surfaces::draw(VkCommandBuffer cmd, std::size_t i) const {
  const Surface& s = surfaces_[i];
  const VkDeviceSize zero = 0;
  const VkBuffer vb = s.vertices.handle();
  vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &zero);
  vkCmdBindIndexBuffer(cmd, s.indices.handle(), 0, VK_INDEX_TYPE_UINT32);
  vkCmdDrawIndexed(cmd, s.index_count, 1, 0, 0, 0);
}

} // namespace snell
