// The GLSL mirrors of the math (shaders/snell/*.glsl) against the C++ functions, on the GPU.
#include "gpu_fixture.hpp"

#include <snell/buffer.hpp>
#include <snell/math.hpp>

#include "snell_gpu_test_shaders.hpp"

#include <random>
#include <vector>

using namespace snell;

namespace {

struct Input {
  glm::vec4 incident, normal, plane, point, clip, misc;
};
struct Output {
  glm::vec4 refracted, fresnel, reflected, uv, uv_gl_cube, cube, reflected_dir;
};

/// Inputs over a grid of angles (normal to grazing, both sides of the critical angle) and
/// indices of refraction, plus random planes, points, clip positions and cube texels.
std::vector<Input> make_inputs() {
  std::vector<Input> in;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const float etas[] = {1.0f / 1.5f, 1.0f / ior::water, 1.0f, ior::water, 1.5f, 2.417f};
  for (const float eta : etas) {
    for (int a = 0; a <= 90; ++a) { // incidence angle in degrees, 90 = grazing
      const float theta = glm::radians(static_cast<float>(a));
      Input v{};
      v.incident = glm::vec4(std::sin(theta), -std::cos(theta), 0.0f, 0.0f);
      v.normal = glm::vec4(0.0f, 1.0f, 0.0f, eta);
      v.plane = glm::vec4(glm::normalize(glm::vec3(u(rng), u(rng), u(rng))), u(rng) * 5.0f);
      v.point = glm::vec4(u(rng) * 10.0f, u(rng) * 10.0f, u(rng) * 10.0f, std::cos(theta));
      v.clip = glm::vec4(u(rng), u(rng), u(rng), 0.5f + std::fabs(u(rng)) * 4.0f);
      v.misc = glm::vec4(f0_from_ior(1.0f, 1.0f / eta), static_cast<float>(a % 6),
                         0.5f + 0.5f * u(rng), 0.5f + 0.5f * u(rng));
      in.push_back(v);
    }
  }
  return in;
}

} // namespace

TEST_CASE("GLSL math mirrors agree with the C++ functions") {
  test::GpuFixture gpu;
  Context& ctx = gpu.ctx();
  const std::vector<Input> inputs = make_inputs();
  const auto n = static_cast<std::uint32_t>(inputs.size());
  auto in_buf =
      Buffer::create(ctx, BufferDesc{n * sizeof(Input), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                     MemoryUsage::upload, "inputs"});
  auto out_buf =
      Buffer::create(ctx, BufferDesc{n * sizeof(Output), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                     MemoryUsage::readback, "outputs"});
  REQUIRE(in_buf.has_value());
  REQUIRE(out_buf.has_value());
  REQUIRE(in_buf->upload(inputs.data(), n * sizeof(Input)));

  const VkDevice d = ctx.device();
  VkDescriptorSetLayoutBinding bindings[2] = {
      {0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
      {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}};
  VkDescriptorSetLayoutCreateInfo lci{};
  lci.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  lci.bindingCount = 2;
  lci.pBindings = bindings;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  REQUIRE(vkCreateDescriptorSetLayout(d, &lci, nullptr, &set_layout) == VK_SUCCESS);
  const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, 4};
  VkPipelineLayoutCreateInfo pli{};
  pli.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  pli.setLayoutCount = 1;
  pli.pSetLayouts = &set_layout;
  pli.pushConstantRangeCount = 1;
  pli.pPushConstantRanges = &push;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  REQUIRE(vkCreatePipelineLayout(d, &pli, nullptr, &layout) == VK_SUCCESS);
  VkShaderModuleCreateInfo smci{};
  smci.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  smci.codeSize = gpu_tests::shaders::math_check_comp.size_bytes();
  smci.pCode = gpu_tests::shaders::math_check_comp.data();
  VkShaderModule module = VK_NULL_HANDLE;
  REQUIRE(vkCreateShaderModule(d, &smci, nullptr, &module) == VK_SUCCESS);
  VkComputePipelineCreateInfo cpci{};
  cpci.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
  cpci.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  cpci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  cpci.stage.module = module;
  cpci.stage.pName = "main";
  cpci.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  REQUIRE(vkCreateComputePipelines(d, VK_NULL_HANDLE, 1, &cpci, nullptr, &pipeline) == VK_SUCCESS);
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2};
  VkDescriptorPoolCreateInfo dpci{};
  dpci.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  dpci.maxSets = 1;
  dpci.poolSizeCount = 1;
  dpci.pPoolSizes = &size;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  REQUIRE(vkCreateDescriptorPool(d, &dpci, nullptr, &pool) == VK_SUCCESS);
  VkDescriptorSetAllocateInfo ai{};
  ai.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  ai.descriptorPool = pool;
  ai.descriptorSetCount = 1;
  ai.pSetLayouts = &set_layout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  REQUIRE(vkAllocateDescriptorSets(d, &ai, &set) == VK_SUCCESS);
  const VkDescriptorBufferInfo infos[2] = {{in_buf->handle(), 0, VK_WHOLE_SIZE},
                                           {out_buf->handle(), 0, VK_WHOLE_SIZE}};
  VkWriteDescriptorSet writes[2]{};
  for (std::uint32_t i = 0; i < 2; ++i) {
    writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    writes[i].dstSet = set;
    writes[i].dstBinding = i;
    writes[i].descriptorCount = 1;
    writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[i].pBufferInfo = &infos[i];
  }
  vkUpdateDescriptorSets(d, 2, writes, 0, nullptr);
  REQUIRE(ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, 4, &n);
    vkCmdDispatch(cmd, (n + 63) / 64, 1, 1);
    VkMemoryBarrier2 mb{};
    mb.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2;
    mb.srcStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    mb.srcAccessMask = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
    mb.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
    mb.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
    VkDependencyInfo dep{};
    dep.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO;
    dep.memoryBarrierCount = 1;
    dep.pMemoryBarriers = &mb;
    vkCmdPipelineBarrier2(cmd, &dep);
  }));
  const auto* out = static_cast<const Output*>(out_buf->mapped());

  // Tolerance: GPU float arithmetic (sqrt, division, inversesqrt) is allowed a few ULP by the
  // Vulkan precision rules (SPIR-V environment, "Precision and Operation of SPIR-V
  // Instructions": division 2.5 ULP, inversesqrt 2 ULP, sqrt as inversesqrt * x), and the
  // compiler may contract a*b+c into fma. Results are O(1) or O(10) in magnitude, so 1e-5
  // absolute (about 100 ULP at 1.0) covers the allowed error with margin while any formula
  // mistake (a wrong sign, a missing term) shows up as an error of 1e-2 or more.
  const float tol = 1e-5f;
  int tir = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    const Input& v = inputs[i];
    const Output& o = out[i];
    CAPTURE(i);
    const float eta = v.normal.w;
    const auto t = refract(glm::vec3(v.incident), glm::vec3(v.normal), eta);
    CHECK((o.refracted.w == 1.0f) == t.has_value());
    if (t) {
      CHECK(glm::length(glm::vec3(o.refracted) - *t) < tol);
    } else {
      ++tir;
    }
    CHECK(std::fabs(o.fresnel.x - fresnel_dielectric(v.point.w, eta)) < tol);
    CHECK(std::fabs(o.fresnel.y - fresnel_schlick(v.point.w, v.misc.x)) < tol);
    CHECK(std::fabs(o.fresnel.z - f0_from_ior(1.0f, 1.0f / eta)) < tol);
    const Plane plane = plane_from_vec4(v.plane);
    CHECK(std::fabs(o.fresnel.w - signed_distance(plane, glm::vec3(v.point))) < 10 * tol);
    CHECK(glm::length(glm::vec3(o.reflected) - reflect_point(plane, glm::vec3(v.point))) <
          10 * tol);
    CHECK(glm::length(glm::vec3(o.reflected_dir) -
                      reflect_direction(plane, glm::vec3(v.incident))) < tol);
    const glm::vec2 uv_vk = project_to_uv(v.clip, ClipConvention::vulkan);
    const glm::vec2 uv_d3d = project_to_uv(v.clip, ClipConvention::d3d);
    const glm::vec2 uv_gl = project_to_uv(v.clip, ClipConvention::opengl);
    CHECK(glm::length(glm::vec2(o.uv.x, o.uv.y) - uv_vk) < tol);
    CHECK(glm::length(glm::vec2(o.uv.z, o.uv.w) - uv_d3d) < tol);
    CHECK(glm::length(glm::vec2(o.uv_gl_cube.x, o.uv_gl_cube.y) - uv_gl) < tol);
    const CubeTexel texel = direction_to_cube(glm::vec3(v.point));
    CHECK(static_cast<int>(o.cube.x) == static_cast<int>(texel.face));
    CHECK(glm::length(glm::vec2(o.uv_gl_cube.z, o.uv_gl_cube.w) - texel.uv) < tol);
    const auto face = static_cast<CubeFace>(static_cast<int>(v.misc.y));
    CHECK(glm::length(glm::vec3(o.cube.y, o.cube.z, o.cube.w) -
                      cube_to_direction(face, glm::vec2(v.misc.z, v.misc.w))) < tol);
  }
  // The grid crosses the critical angle: water 48.6 and glass 41.8 degrees, diamond 24.4.
  CHECK(tir > 100);

  vkDestroyPipeline(d, pipeline, nullptr);
  vkDestroyShaderModule(d, module, nullptr);
  vkDestroyDescriptorPool(d, pool, nullptr);
  vkDestroyPipelineLayout(d, layout, nullptr);
  vkDestroyDescriptorSetLayout(d, set_layout, nullptr);
}
