#include "host_scene.hpp"

#include "embed_host_shaders.hpp" // generated: embed::shaders::host_scene_vert, ...

#include <snell/math/plane.hpp>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <utility>

namespace embed {
namespace {

/// Mirrors the push-constant block of shaders/host_common.glsl.
struct Push {
  glm::mat4 matrix{1.0f};
  glm::vec4 clip_plane{0.0f, 0.0f, 0.0f, 1.0f};
  glm::vec4 light_dir{0.0f};
  glm::vec4 light_color{0.0f};
  glm::vec4 ambient{0.0f};
};
static_assert(sizeof(Push) == 128, "the minimum maxPushConstantsSize");

/// Mirrors the chrome material's push constants (shaders/host_chrome.glsl): per view.
struct ChromePush {
  glm::mat4 matrix{1.0f};
  glm::vec4 clip_plane{0.0f, 0.0f, 0.0f, 1.0f};
  glm::vec4 eye{0.0f};
};
static_assert(sizeof(ChromePush) <= 128, "the minimum maxPushConstantsSize");

/// std140 mirror of ChromeBlock (shaders/host_chrome.glsl): per frame slot.
struct ChromeBlock {
  glm::vec4 center_levels{0.0f}; ///< xyz: the probe's capture centre; w: its mip levels
  glm::vec4 box_min{0.0f};       ///< xyz; w: 1 when box-projected
  glm::vec4 box_max{0.0f};
  glm::vec4 f0_roughness{0.0f}; ///< rgb: F0; a: roughness
};

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec4 color; ///< rgb: linear colour; a: contrast of the 1 m tiles (0: plain)
};

/// Appends an axis-aligned box, counter-clockwise seen from outside (culled from inside).
void add_box(std::vector<Vertex>& out, glm::vec3 lo, glm::vec3 hi, glm::vec4 color) {
  const glm::vec3 c = 0.5f * (lo + hi);
  const glm::vec3 h = 0.5f * (hi - lo);
  const glm::vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  // Per face: normal n and tangents u, v with cross(u, v) == n, so u then v turns
  // counter-clockwise seen from the side n points to.
  const std::array<std::array<glm::vec3, 3>, 6> faces = {{
      {x, y, z},
      {-x, z, y},
      {y, z, x},
      {-y, x, z},
      {z, x, y},
      {-z, y, x},
  }};
  for (const auto& [n, u, v] : faces) {
    const glm::vec3 centre = c + n * glm::dot(glm::abs(n), h);
    const glm::vec3 du = u * glm::dot(glm::abs(u), h);
    const glm::vec3 dv = v * glm::dot(glm::abs(v), h);
    const glm::vec3 p00 = centre - du - dv, p10 = centre + du - dv, p11 = centre + du + dv,
                    p01 = centre - du + dv;
    for (const glm::vec3& p : {p00, p10, p11, p00, p11, p01}) {
      out.push_back(Vertex{p, n, color});
    }
  }
}

/// Appends a UV sphere (`slices` around, `stacks` pole to pole), counter-clockwise seen from
/// outside, with exact normals at the vertices.
void add_sphere(std::vector<Vertex>& out, glm::vec3 center, float radius, glm::vec4 color,
                int slices, int stacks) {
  constexpr float kPi = 3.14159265358979f;
  auto normal = [&](int stack, int slice) {
    const float theta = kPi * float(stack) / float(stacks); // from +y
    const float phi = 2.0f * kPi * float(slice) / float(slices);
    return glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                     std::sin(theta) * std::sin(phi));
  };
  for (int i = 0; i < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      const glm::vec3 quad[4] = {normal(i, j), normal(i, j + 1), normal(i + 1, j + 1),
                                 normal(i + 1, j)};
      for (const auto& tri : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
        glm::vec3 a = quad[tri[0]], b = quad[tri[1]], c = quad[tri[2]];
        const glm::vec3 face = glm::cross(b - a, c - a);
        if (glm::dot(face, face) < 1e-12f) {
          continue; // the degenerate half of a quad at a pole
        }
        if (glm::dot(face, a + b + c) < 0.0f) {
          std::swap(b, c); // counter-clockwise seen from outside
        }
        for (const glm::vec3& n : {a, b, c}) {
          out.push_back(Vertex{center + radius * n, n, color});
        }
      }
    }
  }
}

VkShaderModule make_module(VkDevice d, std::span<const std::uint32_t> code) {
  VkShaderModuleCreateInfo ci{};
  ci.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  ci.codeSize = code.size_bytes();
  ci.pCode = code.data();
  VkShaderModule module = VK_NULL_HANDLE;
  vk_check(vkCreateShaderModule(d, &ci, nullptr, &module), "vkCreateShaderModule");
  return module;
}

} // namespace

void HostScene::init(const HostDevice& device, const PoolWater& water,
                     std::uint32_t frames_in_flight) {
  dev_ = &device;
  const VkDevice d = device.device;

  // --- Geometry: every object is a box; layer bits say which views draw it. -------------------
  using snell::layer::all;
  using snell::layer::captured;
  using snell::layer::reflected;
  using snell::layer::refracted;
  const float h = water.height;
  const glm::vec2 c = water.center;
  const glm::vec2 r = 0.5f * water.size; // half size of the pool opening
  const float top = h + 0.25f, bottom = h - 1.7f, outer = 30.0f;
  const glm::vec4 stone{0.46f, 0.44f, 0.41f, 0.12f}; // tiled
  std::vector<Vertex> vertices;
  auto add = [&](const char* name, glm::vec3 lo, glm::vec3 hi, glm::vec4 color,
                 std::uint32_t layers) {
    const auto first = static_cast<std::uint32_t>(vertices.size());
    add_box(vertices, lo, hi, color);
    objects_.push_back(Object{name, first, static_cast<std::uint32_t>(vertices.size()) - first,
                              layers, lo, hi, color, false});
  };
  // Below the water only: not in reflections.
  add("pool floor", {c.x - r.x, bottom, c.y - r.y}, {c.x + r.x, h - 1.5f, c.y + r.y},
      {0.80f, 0.70f, 0.48f, 0.3f}, all & ~reflected);
  add("green box", {c.x + 0.8f, h - 1.5f, c.y + 0.6f}, {c.x + 1.8f, h - 0.6f, c.y + 1.6f},
      {0.15f, 0.65f, 0.25f, 0.0f}, all & ~reflected);
  // The deck around the opening: its walls go below the water, its top is above: every view.
  add("deck far", {c.x - outer, bottom, c.y - outer}, {c.x + outer, top, c.y - r.y}, stone, all);
  add("deck near", {c.x - outer, bottom, c.y + r.y}, {c.x + outer, top, c.y + outer}, stone, all);
  add("deck left", {c.x - outer, bottom, c.y - r.y}, {c.x - r.x, top, c.y + r.y}, stone, all);
  add("deck right", {c.x + r.x, bottom, c.y - r.y}, {c.x + outer, top, c.y + r.y}, stone, all);
  // Pillars standing in the water: partly above, partly below: every view.
  add("red pillar", {c.x - 3.6f, h - 1.5f, c.y - 2.2f}, {c.x - 2.9f, h + 2.2f, c.y - 1.5f},
      {0.75f, 0.12f, 0.10f, 0.0f}, all);
  add("blue pillar", {c.x + 2.5f, h - 1.5f, c.y - 2.7f}, {c.x + 3.2f, h + 1.2f, c.y - 2.0f},
      {0.12f, 0.25f, 0.80f, 0.0f}, all);
  // Above the water only: not in refractions.
  add("yellow box", {c.x - 1.6f, top, c.y - r.y - 2.2f}, {c.x - 0.4f, top + 1.2f, c.y - r.y - 1.0f},
      {0.90f, 0.72f, 0.10f, 0.0f}, all & ~refracted);
  add("orange tower", {c.x + 3.5f, top, c.y - r.y - 3.5f},
      {c.x + 4.5f, top + 3.0f, c.y - r.y - 2.5f}, {0.90f, 0.38f, 0.08f, 0.0f}, all & ~refracted);
  // Behind the camera: a pink wall, seen only in the chrome ball (its centre reflects it).
  add("back wall", {c.x - outer, top, c.y + r.y + 8.0f},
      {c.x + outer, top + 8.0f, c.y + r.y + 8.6f}, {0.80f, 0.30f, 0.55f, 0.0f}, all & ~refracted);
  // The chrome ball on the far deck, between the yellow box and the orange tower. Its probe
  // (Snell's dynamic_cubemap, centred here) captures the scene without it: no `captured` bit,
  // so it never sees itself; it is above the water: no `refracted` bit either. Without a probe
  // (use_probe(nullptr)) it is drawn like any object, in a flat steel grey.
  ball_.radius = 1.0f;
  ball_.center = {c.x + 1.5f, top + ball_.radius, c.y - r.y - 1.6f};
  {
    const auto first = static_cast<std::uint32_t>(vertices.size());
    const glm::vec4 steel{0.55f, 0.56f, 0.58f, 0.0f};
    add_sphere(vertices, ball_.center, ball_.radius, steel, 48, 24);
    objects_.push_back(Object{"chrome ball", first,
                              static_cast<std::uint32_t>(vertices.size()) - first,
                              all & ~refracted & ~captured, ball_.center - ball_.radius,
                              ball_.center + ball_.radius, steel, true});
  }

  // --- Vertex buffer: host-visible, written once. ----------------------------------------------
  VkBufferCreateInfo bi{};
  bi.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  bi.size = sizeof(Vertex) * vertices.size();
  bi.usage = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
  bi.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  vk_check(vkCreateBuffer(d, &bi, nullptr, &vertices_), "vkCreateBuffer (vertices)");
  VkMemoryRequirements req{};
  vkGetBufferMemoryRequirements(d, vertices_, &req);
  VkMemoryAllocateInfo ai{};
  ai.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  ai.allocationSize = req.size;
  ai.memoryTypeIndex =
      device.memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                 VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  vk_check(vkAllocateMemory(d, &ai, nullptr, &vertex_memory_), "vkAllocateMemory (vertices)");
  vk_check(vkBindBufferMemory(d, vertices_, vertex_memory_, 0), "vkBindBufferMemory");
  void* mapped = nullptr;
  vk_check(vkMapMemory(d, vertex_memory_, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
  std::memcpy(mapped, vertices.data(), bi.size);
  vkUnmapMemory(d, vertex_memory_);

  // --- Shaders and the pipeline layout (push constants only). ---------------------------------
  scene_vert_ = make_module(d, embed::shaders::host_scene_vert);
  scene_frag_ = make_module(d, embed::shaders::host_scene_frag);
  sky_vert_ = make_module(d, embed::shaders::host_sky_vert);
  sky_frag_ = make_module(d, embed::shaders::host_sky_frag);
  const VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                  sizeof(Push)};
  VkPipelineLayoutCreateInfo li{};
  li.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  li.pushConstantRangeCount = 1;
  li.pPushConstantRanges = &range;
  vk_check(vkCreatePipelineLayout(d, &li, nullptr, &layout_), "vkCreatePipelineLayout");
  create_chrome_material(frames_in_flight);
}

void HostScene::create_chrome_material(std::uint32_t frames_in_flight) {
  const VkDevice d = dev_->device;
  chrome_vert_ = make_module(d, embed::shaders::host_chrome_vert);
  chrome_frag_ = make_module(d, embed::shaders::host_chrome_frag);

  // Set 0: binding 0 the probe's cube (combined image sampler), binding 1 the ChromeBlock.
  const VkDescriptorSetLayoutBinding bindings[2] = {
      {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
  };
  VkDescriptorSetLayoutCreateInfo sli{};
  sli.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  sli.bindingCount = 2;
  sli.pBindings = bindings;
  vk_check(vkCreateDescriptorSetLayout(d, &sli, nullptr, &chrome_set_layout_),
           "vkCreateDescriptorSetLayout (chrome)");
  const VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                  sizeof(ChromePush)};
  VkPipelineLayoutCreateInfo li{};
  li.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  li.setLayoutCount = 1;
  li.pSetLayouts = &chrome_set_layout_;
  li.pushConstantRangeCount = 1;
  li.pPushConstantRanges = &range;
  vk_check(vkCreatePipelineLayout(d, &li, nullptr, &chrome_layout_),
           "vkCreatePipelineLayout (chrome)");

  // One set and one uniform block per frame in flight: a frame rewrites only its own slot, so
  // frames still on the GPU keep theirs.
  const VkDescriptorPoolSize sizes[2] = {
      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, frames_in_flight},
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, frames_in_flight},
  };
  VkDescriptorPoolCreateInfo pi{};
  pi.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  pi.maxSets = frames_in_flight;
  pi.poolSizeCount = 2;
  pi.pPoolSizes = sizes;
  vk_check(vkCreateDescriptorPool(d, &pi, nullptr, &chrome_pool_),
           "vkCreateDescriptorPool (chrome)");
  const std::vector<VkDescriptorSetLayout> layouts(frames_in_flight, chrome_set_layout_);
  std::vector<VkDescriptorSet> sets(frames_in_flight);
  VkDescriptorSetAllocateInfo ai{};
  ai.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  ai.descriptorPool = chrome_pool_;
  ai.descriptorSetCount = frames_in_flight;
  ai.pSetLayouts = layouts.data();
  vk_check(vkAllocateDescriptorSets(d, &ai, sets.data()), "vkAllocateDescriptorSets (chrome)");

  // The uniform blocks: one host-visible, coherent buffer, a slice per slot.
  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(dev_->physical_device, &props);
  const VkDeviceSize align = props.limits.minUniformBufferOffsetAlignment;
  const VkDeviceSize stride = (sizeof(ChromeBlock) + align - 1) / align * align;
  VkBufferCreateInfo bi{};
  bi.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  bi.size = stride * frames_in_flight;
  bi.usage = VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
  bi.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  vk_check(vkCreateBuffer(d, &bi, nullptr, &chrome_ubo_), "vkCreateBuffer (chrome)");
  VkMemoryRequirements req{};
  vkGetBufferMemoryRequirements(d, chrome_ubo_, &req);
  VkMemoryAllocateInfo mi{};
  mi.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  mi.allocationSize = req.size;
  mi.memoryTypeIndex =
      dev_->memory_type(req.memoryTypeBits,
                        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  vk_check(vkAllocateMemory(d, &mi, nullptr, &chrome_ubo_memory_), "vkAllocateMemory (chrome)");
  vk_check(vkBindBufferMemory(d, chrome_ubo_, chrome_ubo_memory_, 0), "vkBindBufferMemory");
  vk_check(vkMapMemory(d, chrome_ubo_memory_, 0, VK_WHOLE_SIZE, 0, &chrome_mapped_),
           "vkMapMemory (chrome)");
  for (std::uint32_t i = 0; i < frames_in_flight; ++i) {
    probe_slots_.push_back(ProbeSlot{sets[i], VK_NULL_HANDLE, VK_NULL_HANDLE, stride * i});
  }
}

void HostScene::use_probe(const snell::ProbeView* probe, std::uint64_t frame_index) {
  probe_slot_ = nullptr;
  if (probe == nullptr || probe->cube == VK_NULL_HANDLE || probe_slots_.empty()) {
    return; // nothing published: the ball is drawn flat this frame
  }
  ProbeSlot& slot = probe_slots_[static_cast<std::size_t>(frame_index % probe_slots_.size())];
  // The slot's last frame (frame_index - frames in flight) has completed: the host waited for
  // its fence before recording this frame, and this frame has not bound the set yet. So the
  // set and its uniform block may be written now, without racing the GPU or invalidating the
  // command buffer being recorded. The set is rewritten only when the probe's cube changed (a
  // time-sliced probe swaps its cubes when it publishes; a resized one makes a new cube).
  if (slot.cube != probe->cube || slot.sampler != probe->sampler) {
    const VkDescriptorImageInfo image{probe->sampler, probe->cube,
                                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const VkDescriptorBufferInfo buffer{chrome_ubo_, slot.offset, sizeof(ChromeBlock)};
    VkWriteDescriptorSet writes[2]{};
    for (VkWriteDescriptorSet& w : writes) {
      w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
      w.dstSet = slot.set;
      w.descriptorCount = 1;
    }
    writes[0].dstBinding = 0;
    writes[0].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    writes[0].pImageInfo = &image;
    writes[1].dstBinding = 1;
    writes[1].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    writes[1].pBufferInfo = &buffer;
    vkUpdateDescriptorSets(dev_->device, 2, writes, 0, nullptr);
    slot.cube = probe->cube;
    slot.sampler = probe->sampler;
  }
  // The lookup parameters of this frame's cube (coherent memory: visible at submission).
  ChromeBlock block;
  block.center_levels = glm::vec4(probe->center, float(probe->mip_levels));
  block.box_min = glm::vec4(probe->box_min, probe->box_projection ? 1.0f : 0.0f);
  block.box_max = glm::vec4(probe->box_max, 0.0f);
  block.f0_roughness = glm::vec4(ball_.f0, ball_.roughness);
  std::memcpy(static_cast<std::uint8_t*>(chrome_mapped_) + slot.offset, &block, sizeof(block));
  probe_slot_ = &slot;
}

const HostScene::Pipelines* HostScene::pipelines_for(VkFormat color, VkFormat depth) {
  const auto key = std::make_pair(color, depth);
  if (auto it = pipelines_.find(key); it != pipelines_.end()) {
    return &it->second;
  }
  const VkDevice d = dev_->device;
  const bool has_color = color != VK_FORMAT_UNDEFINED;
  const bool has_depth = depth != VK_FORMAT_UNDEFINED;

  enum class Kind { geometry, sky, chrome };
  auto create = [&](Kind kind, VkPipeline& out) -> VkResult {
    const bool sky = kind == Kind::sky;
    const bool chrome = kind == Kind::chrome;
    VkPipelineShaderStageCreateInfo stages[2]{};
    for (int i = 0; i < 2; ++i) {
      stages[i].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
      stages[i].stage = i == 0 ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
      stages[i].pName = "main";
    }
    stages[0].module = sky ? sky_vert_ : chrome ? chrome_vert_ : scene_vert_;
    stages[1].module = sky ? sky_frag_ : chrome ? chrome_frag_ : scene_frag_;
    const VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
    const VkVertexInputAttributeDescription attributes[3] = {
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal)},
        {2, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(Vertex, color)},
    };
    VkPipelineVertexInputStateCreateInfo vi{};
    vi.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
    if (!sky) { // the sky is a fullscreen triangle from gl_VertexIndex
      vi.vertexBindingDescriptionCount = 1;
      vi.pVertexBindingDescriptions = &binding;
      vi.vertexAttributeDescriptionCount = chrome ? 2 : 3; // chrome: position and normal
      vi.pVertexAttributeDescriptions = attributes;
    }
    VkPipelineInputAssemblyStateCreateInfo ia{};
    ia.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
    ia.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo vp{};
    vp.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
    vp.viewportCount = 1;
    vp.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo rs{};
    rs.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
    rs.depthClampEnable = VK_FALSE; // oblique clipping relies on near-plane clipping
    rs.polygonMode = VK_POLYGON_MODE_FILL;
    rs.cullMode = sky ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
    rs.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE; // geometry: dynamic (SceneView flag)
    rs.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo ms{};
    ms.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
    ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo ds{};
    ds.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
    ds.depthTestEnable = has_depth;
    ds.depthWriteEnable = has_depth && !sky;
    ds.depthCompareOp = sky ? VK_COMPARE_OP_LESS_OR_EQUAL : VK_COMPARE_OP_LESS;
    VkPipelineColorBlendAttachmentState blend{};
    blend.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                           VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    VkPipelineColorBlendStateCreateInfo cb{};
    cb.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
    cb.attachmentCount = has_color ? 1 : 0;
    cb.pAttachments = &blend;
    const VkDynamicState dynamic[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR,
                                      VK_DYNAMIC_STATE_FRONT_FACE};
    VkPipelineDynamicStateCreateInfo dyn{};
    dyn.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO;
    dyn.dynamicStateCount = sky ? 2 : 3;
    dyn.pDynamicStates = dynamic;
    // Dynamic rendering: the formats of the attachments this pipeline draws into.
    VkPipelineRenderingCreateInfo rendering{};
    rendering.sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO;
    rendering.colorAttachmentCount = has_color ? 1 : 0;
    rendering.pColorAttachmentFormats = &color;
    rendering.depthAttachmentFormat = depth;
    VkGraphicsPipelineCreateInfo ci{};
    ci.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
    ci.pNext = &rendering;
    ci.stageCount = 2;
    ci.pStages = stages;
    ci.pVertexInputState = &vi;
    ci.pInputAssemblyState = &ia;
    ci.pViewportState = &vp;
    ci.pRasterizationState = &rs;
    ci.pMultisampleState = &ms;
    ci.pDepthStencilState = &ds;
    ci.pColorBlendState = &cb;
    ci.pDynamicState = &dyn;
    ci.layout = chrome ? chrome_layout_ : layout_;
    return vkCreateGraphicsPipelines(d, VK_NULL_HANDLE, 1, &ci, nullptr, &out);
  };

  Pipelines p;
  VkResult result = create(Kind::geometry, p.geometry);
  if (result == VK_SUCCESS && has_color) {
    result = create(Kind::sky, p.sky); // the sky only colours; a depth-only pass needs none
  }
  if (result == VK_SUCCESS && has_color) {
    result = create(Kind::chrome, p.chrome); // a depth-only pass draws the ball flat
  }
  if (result != VK_SUCCESS) {
    vkDestroyPipeline(d, p.geometry, nullptr);
    vkDestroyPipeline(d, p.sky, nullptr);
    if (error_.empty()) {
      error_ = "embed-host: vkCreateGraphicsPipelines for colour format " + std::to_string(color) +
               ", depth format " + std::to_string(depth) + " failed (VkResult " +
               std::to_string(result) + ")";
    }
    return nullptr;
  }
  return &pipelines_.emplace(key, p).first->second;
}

snell::Result<void> HostScene::draw_scene(VkCommandBuffer cmd, const snell::SceneView& view) {
  if (view.view_mask != 0) { // multiview (cube captures): not supported by this small host
    return snell::fail(snell::ErrorCode::unsupported,
                       "embed-host: the scene cannot draw multiview views (view_mask != 0)");
  }
  const Pipelines* p = pipelines_for(view.color_format, view.depth_format);
  if (p == nullptr) {
    return snell::fail(snell::ErrorCode::vulkan_error, error_);
  }
  Push push;
  push.matrix = view.proj * view.view; // may be mirrored (reflection) and oblique
  // No plane: (0,0,0,1) gives every vertex a clip distance of 1, so nothing is clipped.
  push.clip_plane =
      view.clip_plane ? snell::to_vec4(*view.clip_plane) : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  push.light_dir = glm::vec4(light.direction, 0.0f);
  push.light_color = glm::vec4(light.color * light.intensity, 0.0f);
  push.ambient = glm::vec4(light.ambient, 0.0f);

  // The chrome ball gets its material when use_probe gave it a cube this frame and the pass
  // has a colour attachment; otherwise it is drawn flat with the rest.
  const bool chrome = probe_slot_ != nullptr && p->chrome != VK_NULL_HANDLE;
  const VkFrontFace front = view.flip_front_face ? VK_FRONT_FACE_CLOCKWISE // mirrored view:
                                                 : VK_FRONT_FACE_COUNTER_CLOCKWISE; // swapped
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p->geometry);
  vkCmdSetFrontFace(cmd, front);
  vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                     sizeof(Push), &push);
  const VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertices_, &offset);
  bool chrome_visible = false;
  for (const Object& o : objects_) {
    if ((o.layers & view.layer_mask) == 0) {
      continue;
    }
    if (o.chrome && chrome) {
      chrome_visible = true; // drawn below with its own pipeline
    } else {
      vkCmdDraw(cmd, o.vertex_count, 1, o.first_vertex, 0);
    }
  }
  if (chrome_visible) {
    ChromePush cp;
    cp.matrix = push.matrix;
    cp.clip_plane = push.clip_plane;
    cp.eye = glm::vec4(view.eye, 1.0f); // the mirrored eye in a reflection pass
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p->chrome);
    vkCmdSetFrontFace(cmd, front);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, chrome_layout_, 0, 1,
                            &probe_slot_->set, 0, nullptr);
    vkCmdPushConstants(cmd, chrome_layout_,
                       VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(ChromePush), &cp);
    for (const Object& o : objects_) {
      if (o.chrome && (o.layers & view.layer_mask) != 0) {
        vkCmdDraw(cmd, o.vertex_count, 1, o.first_vertex, 0);
      }
    }
  }
  if (p->sky != VK_NULL_HANDLE) {
    push.matrix = glm::inverse(push.matrix);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p->sky);
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(Push), &push);
    vkCmdDraw(cmd, 3, 1, 0, 0);
  }
  return {};
}

HostScene::~HostScene() {
  if (dev_ == nullptr) {
    return;
  }
  const VkDevice d = dev_->device;
  vkDeviceWaitIdle(d);
  for (auto& [key, p] : pipelines_) {
    vkDestroyPipeline(d, p.geometry, nullptr);
    vkDestroyPipeline(d, p.sky, nullptr);
    vkDestroyPipeline(d, p.chrome, nullptr);
  }
  vkDestroyPipelineLayout(d, layout_, nullptr);
  vkDestroyPipelineLayout(d, chrome_layout_, nullptr);
  vkDestroyDescriptorPool(d, chrome_pool_, nullptr); // frees the sets
  vkDestroyDescriptorSetLayout(d, chrome_set_layout_, nullptr);
  vkDestroyBuffer(d, chrome_ubo_, nullptr);
  vkFreeMemory(d, chrome_ubo_memory_, nullptr); // unmaps
  for (VkShaderModule m :
       {scene_vert_, scene_frag_, sky_vert_, sky_frag_, chrome_vert_, chrome_frag_}) {
    vkDestroyShaderModule(d, m, nullptr);
  }
  vkDestroyBuffer(d, vertices_, nullptr);
  vkFreeMemory(d, vertex_memory_, nullptr);
}

} // namespace embed
