// The default host's forward renderer: uploads a Scene and draws it for any SceneView.
#include <snell/buffer.hpp>
#include <snell/images.hpp>
#include <snell/math/bounds.hpp>
#include <snell/pipeline.hpp>
#include <snell/scene_renderer.hpp>

#include "context_impl.hpp"
#include "snell_runtime_shaders.hpp"
#include "vk_util.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cstring>
#include <map>
#include <tuple>

namespace snell {

using detail::vk_init;

bool needs_front_face_flip(const glm::mat4& view, const glm::mat4& proj) {
  const bool mirrored = glm::determinant(glm::mat3(view)) < 0.0f;
  const bool y_up_clip = proj[1][1] > 0.0f; // cube faces: clip y not flipped
  return mirrored != y_up_clip;
}

namespace {

/// std140 layout of shaders/scene_common.glsl's ViewBlock.
struct ViewBlock {
  glm::mat4 view_proj[6];
  glm::mat4 inv_view_proj[6];
  glm::vec4 eye;
  glm::vec4 clip_plane;
  glm::vec4 light_dir;
  glm::vec4 light_color;
  glm::vec4 ambient;
  glm::vec4 sky_zenith;
  glm::vec4 sky_horizon;
  glm::vec4 sky_ground;
};

/// Push constants of shaders/scene_common.glsl's DrawBlock (128 bytes).
struct DrawBlock {
  glm::mat4 model;
  glm::vec4 base_color;
  glm::vec4 emissive;
  glm::vec4 params;
  glm::vec4 flags;
};
static_assert(sizeof(DrawBlock) == 128, "push constants must fit the guaranteed 128 bytes");

struct GpuMesh {
  Buffer vertices;
  Buffer indices;
  std::uint32_t index_count = 0;
  Aabb bounds; ///< Object-space bounds of the vertices (culling).
};

/// Conservative visibility of objects for one SceneView (see SceneRenderer's culling note).
class ViewCulling {
public:
  explicit ViewCulling(const SceneView& view)
      : clip_plane_(view.clip_plane), single_(view.view_mask == 0),
        view_proj_(view.proj * view.view) {
    const VkRect2D& r = view.scissor;
    if (r.extent.width != 0 && r.extent.height != 0 && view.extent.width != 0 &&
        view.extent.height != 0) {
      // Pixels to NDC through Vulkan's standard viewport (x right, y down from the top row).
      const float w = static_cast<float>(view.extent.width);
      const float h = static_cast<float>(view.extent.height);
      const float x0 = static_cast<float>(r.offset.x);
      const float y0 = static_cast<float>(r.offset.y);
      rect_ = glm::vec4(2.0f * x0 / w - 1.0f, 2.0f * y0 / h - 1.0f,
                        2.0f * (x0 + static_cast<float>(r.extent.width)) / w - 1.0f,
                        2.0f * (y0 + static_cast<float>(r.extent.height)) / h - 1.0f);
    }
  }

  /// True when the object (mesh bounds `bounds` placed by `model`) cannot show in the view.
  [[nodiscard]] bool invisible(const Aabb& bounds, const glm::mat4& model) const {
    if (clip_plane_ && aabb_below_plane(transform_aabb(bounds, model), *clip_plane_)) {
      return true;
    }
    // A multiview pass (a cube capture) sees every direction: no frustum test.
    return single_ && aabb_outside_clip(bounds, view_proj_ * model, rect_, DepthRange::zero_to_one);
  }

private:
  std::optional<Plane> clip_plane_;
  bool single_;
  glm::mat4 view_proj_;
  glm::vec4 rect_{-1.0f, -1.0f, 1.0f, 1.0f};
};

struct Pipelines {
  VkPipeline opaque = VK_NULL_HANDLE;
  VkPipeline blend = VK_NULL_HANDLE;
  VkPipeline sky = VK_NULL_HANDLE;
};

} // namespace

struct SceneRenderer::Impl {
  const ContextState* ctx = nullptr;
  Scene scene;
  std::vector<GpuMesh> meshes;
  std::vector<Texture2D> textures;
  Texture2D white, flat_normal;
  Sampler sampler;
  Buffer view_ring;
  VkDeviceSize view_stride = 0;
  std::uint32_t next_view = 0;
  VkDescriptorSetLayout view_layout = VK_NULL_HANDLE;
  VkDescriptorSetLayout material_layout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkDescriptorSet view_set = VK_NULL_HANDLE;
  std::vector<VkDescriptorSet> material_sets; // one per material, plus the default at the end
  VkShaderModule scene_vert = VK_NULL_HANDLE, scene_frag = VK_NULL_HANDLE;
  VkShaderModule sky_vert = VK_NULL_HANDLE, sky_frag = VK_NULL_HANDLE;
  std::map<std::tuple<VkFormat, VkFormat, std::uint32_t>, Pipelines> pipelines;
  std::vector<bool> hidden; ///< Per object: drawn by an effect, left out here.
  SceneDrawStats stats;     ///< Of the last draw_scene.

  ~Impl() {
    if (ctx == nullptr) {
      return;
    }
    VkDevice d = ctx->device;
    vkDeviceWaitIdle(d);
    for (auto& [key, p] : pipelines) {
      vkDestroyPipeline(d, p.opaque, nullptr);
      vkDestroyPipeline(d, p.blend, nullptr);
      vkDestroyPipeline(d, p.sky, nullptr);
    }
    for (VkShaderModule m : {scene_vert, scene_frag, sky_vert, sky_frag}) {
      vkDestroyShaderModule(d, m, nullptr);
    }
    vkDestroyDescriptorPool(d, pool, nullptr);
    vkDestroyPipelineLayout(d, layout, nullptr);
    vkDestroyDescriptorSetLayout(d, view_layout, nullptr);
    vkDestroyDescriptorSetLayout(d, material_layout, nullptr);
  }

  Result<void> init(const Context& context);
  Result<const Pipelines*> pipelines_for(const SceneView& view);
  const Texture2D& texture_or(int index, const Texture2D& fallback) const {
    return index >= 0 && static_cast<std::size_t>(index) < textures.size()
               ? textures[static_cast<std::size_t>(index)]
               : fallback;
  }
};

namespace {

Image solid_image(const char* name, std::uint8_t r, std::uint8_t g, std::uint8_t b, bool srgb) {
  Image image;
  image.name = name;
  image.width = 1;
  image.height = 1;
  image.rgba8 = {r, g, b, 255};
  image.srgb = srgb;
  return image;
}

} // namespace

Result<void> SceneRenderer::Impl::init(const Context& context) {
  const VkDevice d = ctx->device;
  // Geometry.
  for (const Mesh& mesh : scene.meshes) {
    GpuMesh gm;
    if (mesh.vertices.empty() || mesh.indices.empty()) {
      meshes.push_back(std::move(gm));
      continue;
    }
    const VkDeviceSize vbytes = mesh.vertices.size() * sizeof(Vertex);
    const VkDeviceSize ibytes = mesh.indices.size() * sizeof(std::uint32_t);
    auto vb = Buffer::create(context, BufferDesc{vbytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                                                 MemoryUsage::gpu_only, "vertex buffer"});
    auto ib = Buffer::create(context, BufferDesc{ibytes, VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                                                 MemoryUsage::gpu_only, "index buffer"});
    if (!vb || !ib) {
      return fail(ErrorCode::out_of_memory,
                  "mesh '" + mesh.name + "': " + (!vb ? vb.error() : ib.error()).message);
    }
    if (auto r = vb->upload(mesh.vertices.data(), vbytes); !r) {
      return r.error();
    }
    if (auto r = ib->upload(mesh.indices.data(), ibytes); !r) {
      return r.error();
    }
    gm.vertices = std::move(*vb);
    gm.indices = std::move(*ib);
    gm.index_count = static_cast<std::uint32_t>(mesh.indices.size());
    for (const Vertex& v : mesh.vertices) {
      gm.bounds = expand(gm.bounds, v.position);
    }
    meshes.push_back(std::move(gm));
  }
  // Textures.
  for (const Image& image : scene.images) {
    auto t = Texture2D::create(context, image, true);
    if (!t) {
      return t.error();
    }
    textures.push_back(std::move(*t));
  }
  auto w = Texture2D::create(context, solid_image("white", 255, 255, 255, true), false);
  auto n = Texture2D::create(context, solid_image("flat normal", 128, 128, 255, false), false);
  // Anisotropic filtering is nearly free on GPUs but costs lavapipe ~3x the frame time
  // (measured: pool 1280x720, 150 ms at 8x vs 45 ms at 1x), so CPU devices go without.
  const float anisotropy = ctx->info.type == VK_PHYSICAL_DEVICE_TYPE_CPU ? 1.0f : 8.0f;
  auto s = Sampler::create(context, SamplerDesc{.linear = true,
                                                .mipmaps = true,
                                                .address = AddressMode::repeat,
                                                .max_anisotropy = anisotropy});
  if (!w || !n || !s) {
    return !w ? w.error() : !n ? n.error() : s.error();
  }
  white = std::move(*w);
  flat_normal = std::move(*n);
  sampler = std::move(*s);

  // Per-view uniform ring.
  const VkDeviceSize align =
      std::max<VkDeviceSize>(ctx->limits.minUniformBufferOffsetAlignment, 16);
  view_stride = (sizeof(ViewBlock) + align - 1) / align * align;
  auto ring = Buffer::create(context, BufferDesc{view_stride * kMaxViewsInFlight,
                                                 VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                                 MemoryUsage::upload, "scene view ring"});
  if (!ring) {
    return ring.error();
  }
  view_ring = std::move(*ring);

  // Descriptor layouts, pool, sets.
  VkDescriptorSetLayoutBinding view_binding{
      0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1,
      VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
  auto lci =
      vk_init<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
  lci.bindingCount = 1;
  lci.pBindings = &view_binding;
  SNELL_VK_TRY(vkCreateDescriptorSetLayout(d, &lci, nullptr, &view_layout), "scene view layout");
  VkDescriptorSetLayoutBinding tex_bindings[3];
  for (std::uint32_t i = 0; i < 3; ++i) {
    tex_bindings[i] = {i, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                       VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
  }
  lci.bindingCount = 3;
  lci.pBindings = tex_bindings;
  SNELL_VK_TRY(vkCreateDescriptorSetLayout(d, &lci, nullptr, &material_layout),
               "scene material layout");
  const VkDescriptorSetLayout set_layouts[] = {view_layout, material_layout};
  const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                 sizeof(DrawBlock)};
  auto pli = vk_init<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
  pli.setLayoutCount = 2;
  pli.pSetLayouts = set_layouts;
  pli.pushConstantRangeCount = 1;
  pli.pPushConstantRanges = &push;
  SNELL_VK_TRY(vkCreatePipelineLayout(d, &pli, nullptr, &layout), "scene pipeline layout");

  const std::uint32_t material_count = static_cast<std::uint32_t>(scene.materials.size()) + 1;
  const VkDescriptorPoolSize sizes[] = {
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1},
      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 3 * material_count}};
  auto pci = vk_init<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  pci.maxSets = 1 + material_count;
  pci.poolSizeCount = 2;
  pci.pPoolSizes = sizes;
  SNELL_VK_TRY(vkCreateDescriptorPool(d, &pci, nullptr, &pool), "scene descriptor pool");
  auto ai = vk_init<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
  ai.descriptorPool = pool;
  ai.descriptorSetCount = 1;
  ai.pSetLayouts = &view_layout;
  SNELL_VK_TRY(vkAllocateDescriptorSets(d, &ai, &view_set), "scene view set");
  const VkDescriptorBufferInfo view_info{view_ring.handle(), 0, sizeof(ViewBlock)};
  auto write = vk_init<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
  write.dstSet = view_set;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC;
  write.pBufferInfo = &view_info;
  vkUpdateDescriptorSets(d, 1, &write, 0, nullptr);

  material_sets.resize(material_count);
  std::vector<VkDescriptorSetLayout> layouts(material_count, material_layout);
  ai.descriptorSetCount = material_count;
  ai.pSetLayouts = layouts.data();
  SNELL_VK_TRY(vkAllocateDescriptorSets(d, &ai, material_sets.data()), "scene material sets");
  for (std::uint32_t m = 0; m < material_count; ++m) {
    const Material fallback;
    const Material& mat = m < scene.materials.size() ? scene.materials[m] : fallback;
    const VkDescriptorImageInfo images[3] = {
        {sampler.handle(), texture_or(mat.base_color_texture, white).view(),
         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
        {sampler.handle(), texture_or(mat.normal_texture, flat_normal).view(),
         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
        {sampler.handle(), texture_or(mat.emissive_texture, white).view(),
         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
    };
    auto w2 = vk_init<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    w2.dstSet = material_sets[m];
    w2.descriptorCount = 3;
    w2.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    w2.pImageInfo = images;
    vkUpdateDescriptorSets(d, 1, &w2, 0, nullptr);
  }

  // Shaders.
  auto module = [&](Span<const std::uint32_t> code, const char* name,
                    VkShaderModule& out) -> Result<void> {
    auto m = create_shader_module(d, code, name);
    if (!m) {
      return m.error();
    }
    out = *m;
    return {};
  };
  for (auto r : {module(shaders::scene_vert, "scene.vert", scene_vert),
                 module(shaders::scene_frag, "scene.frag", scene_frag),
                 module(shaders::sky_vert, "sky.vert", sky_vert),
                 module(shaders::sky_frag, "sky.frag", sky_frag)}) {
    if (!r) {
      return r.error();
    }
  }
  return {};
}

Result<const Pipelines*> SceneRenderer::Impl::pipelines_for(const SceneView& view) {
  const auto key = std::make_tuple(view.color_format, view.depth_format, view.view_mask);
  if (auto it = pipelines.find(key); it != pipelines.end()) {
    return &it->second;
  }
  RasterState desc;
  desc.color_formats = {view.color_format};
  desc.depth_format = view.depth_format;
  desc.view_mask = view.view_mask;
  Pipelines p;
  auto opaque = create_graphics_pipeline(ctx->device, scene_vert, scene_frag, layout, desc,
                                         "scene opaque pipeline");
  desc.alpha_blend = true;
  desc.depth_write = false;
  auto blend = create_graphics_pipeline(ctx->device, scene_vert, scene_frag, layout, desc,
                                        "scene blend pipeline");
  desc.vertex_input = false;
  desc.alpha_blend = false;
  desc.depth_compare = VK_COMPARE_OP_LESS_OR_EQUAL;
  auto sky =
      create_graphics_pipeline(ctx->device, sky_vert, sky_frag, layout, desc, "sky pipeline");
  if (!opaque || !blend || !sky) {
    for (auto* r : {&opaque, &blend, &sky}) {
      if (*r) {
        vkDestroyPipeline(ctx->device, **r, nullptr);
      }
    }
    return !opaque ? opaque.error() : !blend ? blend.error() : sky.error();
  }
  p.opaque = *opaque;
  p.blend = *blend;
  p.sky = *sky;
  return &(pipelines[key] = p);
}

SceneRenderer::SceneRenderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SceneRenderer::SceneRenderer(SceneRenderer&&) noexcept = default;
SceneRenderer& SceneRenderer::operator=(SceneRenderer&&) noexcept = default;
SceneRenderer::~SceneRenderer() = default;

Result<SceneRenderer> SceneRenderer::create(const Context& ctx, const Scene& scene) {
  auto impl = std::make_unique<Impl>();
  impl->ctx = context_state(ctx);
  impl->scene = scene;
  for (const Object& o : scene.objects) {
    if (o.mesh < 0 || static_cast<std::size_t>(o.mesh) >= scene.meshes.size()) {
      return fail(ErrorCode::invalid_argument, "scene '" + scene.name + "': object '" + o.name +
                                                   "' refers to mesh " + std::to_string(o.mesh) +
                                                   " of " + std::to_string(scene.meshes.size()));
    }
  }
  if (auto r = impl->init(ctx); !r) {
    return r.error();
  }
  return SceneRenderer(std::move(impl));
}

SceneDrawStats SceneRenderer::last_draw_stats() const {
  return impl_->stats;
}

const Scene& SceneRenderer::scene() const {
  return impl_->scene;
}
void SceneRenderer::set_hidden_objects(Span<const int> objects) {
  Impl& s = *impl_;
  s.hidden.assign(s.scene.objects.size(), false);
  for (const int i : objects) {
    if (i >= 0 && static_cast<std::size_t>(i) < s.hidden.size()) {
      s.hidden[static_cast<std::size_t>(i)] = true;
    }
  }
}

Result<void> SceneRenderer::draw_scene(VkCommandBuffer cmd, const SceneView& view) {
  Impl& s = *impl_;
  auto pipes = s.pipelines_for(view);
  if (!pipes) {
    return pipes.error();
  }
  const Pipelines& p = **pipes;

  // Per-view block into the next ring slot.
  ViewBlock block{};
  const bool multi = view.view_mask != 0;
  // Only the views a pass uses are filled: one, or six for a multiview cube capture.
  const int views = multi ? 6 : 1;
  for (int i = 0; i < views; ++i) {
    const glm::mat4 vp =
        multi ? view.multiview_view_proj[static_cast<std::size_t>(i)] : view.proj * view.view;
    block.view_proj[i] = vp;
    block.inv_view_proj[i] = glm::inverse(vp);
  }
  block.eye = glm::vec4(view.eye, 1.0f);
  block.clip_plane =
      view.clip_plane ? to_vec4(normalize(*view.clip_plane)) : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  const DirectionalLight& light = s.scene.light;
  block.light_dir = glm::vec4(glm::normalize(light.direction), light.intensity);
  block.light_color = glm::vec4(light.color, 1.0f);
  block.ambient = glm::vec4(light.ambient, 1.0f);
  block.sky_zenith = glm::vec4(s.scene.sky.zenith, 1.0f);
  block.sky_horizon = glm::vec4(s.scene.sky.horizon, 1.0f);
  block.sky_ground = glm::vec4(s.scene.sky.ground, 1.0f);
  const std::uint32_t slot = s.next_view;
  s.next_view = (s.next_view + 1) % kMaxViewsInFlight;
  const VkDeviceSize offset = s.view_stride * slot;
  std::memcpy(static_cast<char*>(s.view_ring.mapped()) + offset, &block, sizeof(block));
  const std::uint32_t dyn_offset = static_cast<std::uint32_t>(offset);

  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p.opaque);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, s.layout, 0, 1, &s.view_set, 1,
                          &dyn_offset);

  struct Blended {
    float distance;
    std::size_t object;
    glm::mat4 model;
  };
  std::vector<Blended> blended;
  auto draw_object = [&](std::size_t index, const glm::mat4& model) {
    const Object& o = s.scene.objects[index];
    const GpuMesh& gm = s.meshes[static_cast<std::size_t>(o.mesh)];
    const Mesh& mesh = s.scene.meshes[static_cast<std::size_t>(o.mesh)];
    const std::size_t mat_index =
        mesh.material >= 0 && static_cast<std::size_t>(mesh.material) < s.scene.materials.size()
            ? static_cast<std::size_t>(mesh.material)
            : s.scene.materials.size();
    const Material fallback;
    const Material& mat =
        mat_index < s.scene.materials.size() ? s.scene.materials[mat_index] : fallback;
    DrawBlock push{};
    push.model = model;
    push.base_color = mat.base_color;
    push.emissive = glm::vec4(mat.emissive, mat.base_color_texture >= 0 ? 1.0f : 0.0f);
    push.params = glm::vec4(mat.roughness, mat.specular, mat.normal_scale,
                            mat.alpha_mode == AlphaMode::mask ? mat.alpha_cutoff : -1.0f);
    push.flags =
        glm::vec4(mat.normal_texture >= 0 ? 1.0f : 0.0f, mat.uv_scale.x, mat.uv_scale.y, 0.0f);
    // Winding: the view's flip XOR a mirroring model transform (negative scale).
    const bool flip = view.flip_front_face != (glm::determinant(glm::mat3(push.model)) < 0.0f);
    vkCmdSetFrontFace(cmd, flip ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE);
    vkCmdSetCullMode(cmd, mat.double_sided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, s.layout, 1, 1,
                            &s.material_sets[mat_index], 0, nullptr);
    vkCmdPushConstants(cmd, s.layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(push), &push);
    const VkDeviceSize zero = 0;
    const VkBuffer vb = gm.vertices.handle();
    vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &zero);
    vkCmdBindIndexBuffer(cmd, gm.indices.handle(), 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cmd, gm.index_count, 1, 0, 0, 0);
  };
  const ViewCulling culling(view);
  s.stats = {};
  for (std::size_t i = 0; i < s.scene.objects.size(); ++i) {
    const Object& o = s.scene.objects[i];
    if ((o.layers & view.layer_mask) == 0 || (i < s.hidden.size() && s.hidden[i])) {
      continue;
    }
    const GpuMesh& gm = s.meshes[static_cast<std::size_t>(o.mesh)];
    if (gm.index_count == 0) {
      continue;
    }
    const glm::mat4 model = o.world_at(view.time);
    if (culling.invisible(gm.bounds, model)) {
      ++s.stats.culled;
      continue;
    }
    ++s.stats.drawn;
    const Mesh& mesh = s.scene.meshes[static_cast<std::size_t>(o.mesh)];
    const bool blend =
        mesh.material >= 0 && static_cast<std::size_t>(mesh.material) < s.scene.materials.size() &&
        s.scene.materials[static_cast<std::size_t>(mesh.material)].alpha_mode == AlphaMode::blend;
    if (blend) {
      blended.push_back({glm::length(glm::vec3(model[3]) - view.eye), i, model});
      continue;
    }
    draw_object(i, model);
  }
  // The sky fills what is still at the far plane (drawn after opaque geometry: less overdraw).
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p.sky);
  vkCmdSetCullMode(cmd, VK_CULL_MODE_NONE);
  vkCmdSetFrontFace(cmd, VK_FRONT_FACE_COUNTER_CLOCKWISE);
  vkCmdDraw(cmd, 3, 1, 0, 0);
  if (!blended.empty()) {
    std::sort(blended.begin(), blended.end(),
              [](const Blended& a, const Blended& b) { return a.distance > b.distance; });
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p.blend);
    for (const Blended& b : blended) {
      draw_object(b.object, b.model);
    }
  }
  return {};
}

} // namespace snell
