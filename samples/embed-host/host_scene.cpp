#include "host_scene.hpp"

#include "embed_host_shaders.hpp" // generated: embed::shaders::host_scene_vert, ...

#include <snell/math/plane.hpp>

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstring>

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

void HostScene::init(const HostDevice& device, const PoolWater& water) {
  dev_ = &device;
  const VkDevice d = device.device;

  // --- Geometry: every object is a box; layer bits say which views draw it. -------------------
  using snell::layer::all;
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
    objects_.push_back(
        Object{name, first, static_cast<std::uint32_t>(vertices.size()) - first, layers});
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
}

const HostScene::Pipelines* HostScene::pipelines_for(VkFormat color, VkFormat depth) {
  const auto key = std::make_pair(color, depth);
  if (auto it = pipelines_.find(key); it != pipelines_.end()) {
    return &it->second;
  }
  const VkDevice d = dev_->device;
  const bool has_color = color != VK_FORMAT_UNDEFINED;
  const bool has_depth = depth != VK_FORMAT_UNDEFINED;

  auto create = [&](bool sky, VkPipeline& out) -> VkResult {
    VkPipelineShaderStageCreateInfo stages[2]{};
    for (int i = 0; i < 2; ++i) {
      stages[i].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
      stages[i].stage = i == 0 ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
      stages[i].pName = "main";
    }
    stages[0].module = sky ? sky_vert_ : scene_vert_;
    stages[1].module = sky ? sky_frag_ : scene_frag_;
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
      vi.vertexAttributeDescriptionCount = 3;
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
    ci.layout = layout_;
    return vkCreateGraphicsPipelines(d, VK_NULL_HANDLE, 1, &ci, nullptr, &out);
  };

  Pipelines p;
  VkResult result = create(false, p.geometry);
  if (result == VK_SUCCESS && has_color) {
    result = create(true, p.sky); // the sky only colours; a depth-only pass needs none
  }
  if (result != VK_SUCCESS) {
    vkDestroyPipeline(d, p.geometry, nullptr);
    if (error_.empty()) {
      error_ = "embed-host: vkCreateGraphicsPipelines for colour format " + std::to_string(color) +
               ", depth format " + std::to_string(depth) + " failed (VkResult " +
               std::to_string(result) + ")";
    }
    return nullptr;
  }
  return &pipelines_.emplace(key, p).first->second;
}

void HostScene::draw_scene(VkCommandBuffer cmd, const snell::SceneView& view) {
  if (view.view_mask != 0) { // multiview (cube captures): not supported by this small host
    if (error_.empty()) {
      error_ = "embed-host: the scene cannot draw multiview views (view_mask != 0)";
    }
    return;
  }
  const Pipelines* p = pipelines_for(view.color_format, view.depth_format);
  if (p == nullptr) {
    return;
  }
  Push push;
  push.matrix = view.proj * view.view; // may be mirrored (reflection) and oblique
  // No plane: (0,0,0,1) gives every vertex a clip distance of 1, so nothing is clipped.
  push.clip_plane =
      view.clip_plane ? snell::to_vec4(*view.clip_plane) : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  push.light_dir = glm::vec4(light.direction, 0.0f);
  push.light_color = glm::vec4(light.color * light.intensity, 0.0f);
  push.ambient = glm::vec4(light.ambient, 0.0f);

  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p->geometry);
  // A mirrored view reverses the winding: swap which side is the front.
  vkCmdSetFrontFace(cmd, view.flip_front_face ? VK_FRONT_FACE_CLOCKWISE
                                              : VK_FRONT_FACE_COUNTER_CLOCKWISE);
  vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                     sizeof(Push), &push);
  const VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertices_, &offset);
  for (const Object& o : objects_) {
    if ((o.layers & view.layer_mask) != 0) {
      vkCmdDraw(cmd, o.vertex_count, 1, o.first_vertex, 0);
    }
  }
  if (p->sky != VK_NULL_HANDLE) {
    push.matrix = glm::inverse(push.matrix);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p->sky);
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(Push), &push);
    vkCmdDraw(cmd, 3, 1, 0, 0);
  }
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
  }
  vkDestroyPipelineLayout(d, layout_, nullptr);
  for (VkShaderModule m : {scene_vert_, scene_frag_, sky_vert_, sky_frag_}) {
    vkDestroyShaderModule(d, m, nullptr);
  }
  vkDestroyBuffer(d, vertices_, nullptr);
  vkFreeMemory(d, vertex_memory_, nullptr);
}

} // namespace embed
