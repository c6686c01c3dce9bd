// CubePrefilter: GGX prefiltering of a cube map by a compute pass (see the header and
// docs/runtime.md, "GGX cube prefilter").
#include <snell/context.hpp>
#include <snell/gpu_timer.hpp>
#include <snell/toolkit/cube_prefilter.hpp>
#include <snell/toolkit/vk_check.hpp>

#include "../runtime/barriers.hpp"
#include "../runtime/image_alloc.hpp"
#include "../runtime/runtime_internal.hpp"

#include "snell_runtime_shaders.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

namespace snell {

using detail::ImageBarrier;

namespace {

constexpr float kPi = 3.14159265358979323846f;
constexpr std::uint32_t kGroupSize = 8;  ///< local_size_x/y of shaders/cube_prefilter.comp.
constexpr std::uint32_t kMinSamples = 4; ///< Never fewer samples per texel.
constexpr std::uint32_t kMaxSamples = 256;
/// Filtered importance sampling reads one mip coarser than the sample's solid angle (Colbert and
/// Krivanek's +1, Filament's K = 4). Measured (tests/gpu/test_cube_prefilter.cpp): 0.5 halves
/// the step error at the smoothest level but lets a small bright source near a face edge show
/// a second bump at 16 samples; 0 lets the sample pattern show (a lumpy lobe at 8 samples).
constexpr double kLodBias = 1.0;

/// One entry of a level's sample table (std140 vec4, shaders/cube_prefilter.comp): the
/// tangent-space direction L divided by L.z (x, y), the weight L.z / sum(L.z), the source lod.
struct SampleEntry {
  float x, y, weight, lod;
};

/// Van der Corput radical inverse in base 2: the second Hammersley coordinate.
float radical_inverse(std::uint32_t bits) {
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  return static_cast<float>(bits) * 2.3283064365386963e-10f; // / 2^32
}

/// The sample table of one level: `count` GGX samples of roughness `roughness` (alpha =
/// roughness^2) around N = V = (0, 0, 1), for a source cube of face size `size` with `levels`
/// levels.
///
/// H is importance-sampled from D(H) cos(theta_h) over the Hammersley set, restricted to the
/// half vectors whose reflection L = 2 (N.H) H - N lies above the horizon (N.L > 0, i.e.
/// cos^2(theta_h) > 1/2, i.e. u < 1 / (1 + alpha^2) in the inverse CDF below): every sample then
/// counts and no texel branches on a rejected one. The ratio estimator sum(c(L) N.L) / sum(N.L)
/// converges to the same value as with the whole distribution (the restriction only rescales the
/// pdf, which cancels). Filtered importance sampling (Colbert and Krivanek, GPU Gems 3, ch. 20):
/// a sample stands for the solid angle omega_s = 1 / (count * pdf(L)), pdf(L) = D(H) / 4 (N = V
/// makes N.H = V.H) over the restricted mass; it reads the source mip whose texels have that
/// solid angle, lod = 0.5 log2(omega_s / omega_p) + 1, with omega_p = 4 pi / (6 size^2) the
/// solid angle of a level-0 texel and +1 the usual bias (Filament's K = 4).
std::vector<SampleEntry> sample_table(float roughness, std::uint32_t count, std::uint32_t size,
                                      std::uint32_t levels) {
  const double alpha = std::max(double{roughness} * roughness, 1e-4);
  const double a2 = alpha * alpha;
  const double u_max = 1.0 / (1.0 + a2);
  const double omega_p = 4.0 * kPi / (6.0 * static_cast<double>(size) * size);
  const double max_lod = static_cast<double>(levels - 1);
  std::vector<SampleEntry> table(count);
  double weight_sum = 0.0;
  for (std::uint32_t i = 0; i < count; ++i) {
    const double u = (i + 0.5) / count * u_max; // stratified, inside the valid range
    const double phi = 2.0 * kPi * radical_inverse(i);
    const double cos2 = (1.0 - u) / (1.0 + (a2 - 1.0) * u);
    const double cos_h = std::sqrt(cos2);
    const double sin_h = std::sqrt(std::max(0.0, 1.0 - cos2));
    const double n_dot_l = 2.0 * cos2 - 1.0; // > 0 by the restriction of u
    const double lx = 2.0 * cos_h * sin_h * std::cos(phi);
    const double ly = 2.0 * cos_h * sin_h * std::sin(phi);
    const double d = a2 / (kPi * std::pow((a2 - 1.0) * cos2 + 1.0, 2.0));
    const double pdf = d / 4.0 / u_max;
    const double omega_s = 1.0 / (count * pdf);
    const double lod = std::clamp(0.5 * std::log2(omega_s / omega_p) + kLodBias, 0.0, max_lod);
    table[i] = {static_cast<float>(lx / n_dot_l), static_cast<float>(ly / n_dot_l),
                static_cast<float>(n_dot_l), static_cast<float>(lod)};
    weight_sum += n_dot_l;
  }
  for (SampleEntry& e : table) {
    e.weight = static_cast<float>(e.weight / weight_sum);
  }
  return table;
}

std::uint32_t level_extent(std::uint32_t size, std::uint32_t level) {
  return std::max(1u, size >> level);
}

} // namespace

float cube_prefilter_roughness(std::uint32_t level, std::uint32_t levels) {
  if (levels <= 1) {
    return 0.0f;
  }
  return std::min(1.0f, static_cast<float>(level) / static_cast<float>(levels - 1));
}

// --- CubePrefilterBinding ----------------------------------------------------------------------

CubePrefilterBinding::CubePrefilterBinding(CubePrefilterBinding&& other) noexcept {
  *this = std::move(other);
}

CubePrefilterBinding& CubePrefilterBinding::operator=(CubePrefilterBinding&& other) noexcept {
  if (this != &other) {
    reset();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    source_ = std::exchange(other.source_, VK_NULL_HANDLE);
    destination_ = std::exchange(other.destination_, VK_NULL_HANDLE);
    size_ = std::exchange(other.size_, 0u);
    levels_ = std::exchange(other.levels_, 0u);
    pool_ = std::exchange(other.pool_, VK_NULL_HANDLE);
    level_views_ = std::move(other.level_views_);
    level_sets_ = std::move(other.level_sets_);
    level_samples_ = std::move(other.level_samples_);
    table_ = std::move(other.table_);
    other.level_views_.clear();
    other.level_sets_.clear();
    other.level_samples_.clear();
  }
  return *this;
}

CubePrefilterBinding::~CubePrefilterBinding() {
  reset();
}

void CubePrefilterBinding::reset() {
  if (device_ != VK_NULL_HANDLE) {
    for (VkImageView view : level_views_) {
      vkDestroyImageView(device_, view, nullptr);
    }
    if (pool_ != VK_NULL_HANDLE) {
      vkDestroyDescriptorPool(device_, pool_, nullptr); // frees the sets
    }
  }
  level_views_.clear();
  level_sets_.clear();
  level_samples_.clear();
  pool_ = VK_NULL_HANDLE;
  table_ = Buffer();
  device_ = VK_NULL_HANDLE;
  source_ = destination_ = VK_NULL_HANDLE;
  size_ = levels_ = 0;
}

// --- CubePrefilter -----------------------------------------------------------------------------

Result<CubePrefilter> CubePrefilter::create(const Context& ctx, const CubePrefilterDesc& desc) {
  if (desc.name == nullptr) {
    return fail(ErrorCode::invalid_argument, "CubePrefilterDesc::name must not be null");
  }
  const std::string name = desc.name;
  if (desc.samples < kMinSamples || desc.samples > kMaxSamples) {
    return fail(ErrorCode::invalid_argument,
                name + ": CubePrefilterDesc::samples = " + std::to_string(desc.samples) +
                    " is outside [4, 256]");
  }
  CubePrefilter p;
  p.ctx_ = context_state(ctx);
  p.name_ = name;
  p.samples_ = desc.samples;
  const VkDescriptorSetLayoutBinding bindings[3] = {
      {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
      {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
      {2, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
  };
  auto lci = vk_struct<VkDescriptorSetLayoutCreateInfo>(
      VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
  lci.bindingCount = 3;
  lci.pBindings = bindings;
  SNELL_VK_TRY(vkCreateDescriptorSetLayout(ctx.device(), &lci, nullptr, &p.set_layout_),
               name + " descriptor set layout");
  // One pipeline per sample count of the schedule (samples_at): at most three.
  for (const float roughness : {0.0f, 0.25f, 0.5f}) {
    const std::uint32_t count = p.samples_at(roughness);
    if (std::find(p.counts_.begin(), p.counts_.end(), count) != p.counts_.end()) {
      continue;
    }
    const std::string label = name + " pipeline (" + std::to_string(count) + " samples)";
    auto pipeline =
        Pipeline::create(ctx, ComputePipelineDesc{.label = label.c_str(),
                                                  .compute = shaders::cube_prefilter_comp,
                                                  .set_layouts = {p.set_layout_},
                                                  .push_constants = {},
                                                  .constants = {count}});
    if (!pipeline) {
      return pipeline.error();
    }
    p.counts_.push_back(count);
    p.pipelines_.push_back(std::move(*pipeline));
  }
  return p;
}

CubePrefilter::CubePrefilter(CubePrefilter&& other) noexcept {
  *this = std::move(other);
}

CubePrefilter& CubePrefilter::operator=(CubePrefilter&& other) noexcept {
  if (this != &other) {
    reset();
    ctx_ = std::exchange(other.ctx_, nullptr);
    name_ = std::move(other.name_);
    samples_ = other.samples_;
    set_layout_ = std::exchange(other.set_layout_, VK_NULL_HANDLE);
    counts_ = std::move(other.counts_);
    pipelines_ = std::move(other.pipelines_);
    other.counts_.clear();
    other.pipelines_.clear();
  }
  return *this;
}

CubePrefilter::~CubePrefilter() {
  reset();
}

void CubePrefilter::reset() {
  pipelines_.clear();
  counts_.clear();
  if (ctx_ != nullptr && set_layout_ != VK_NULL_HANDLE) {
    vkDestroyDescriptorSetLayout(ctx_->device, set_layout_, nullptr);
  }
  set_layout_ = VK_NULL_HANDLE;
  ctx_ = nullptr;
}

const Pipeline* CubePrefilter::pipeline_for(std::uint32_t count) const {
  for (std::size_t i = 0; i < counts_.size(); ++i) {
    if (counts_[i] == count) {
      return &pipelines_[i];
    }
  }
  return nullptr;
}

std::uint32_t CubePrefilter::samples_at(float roughness) const {
  const std::uint32_t shift = roughness >= 0.5f ? 0u : roughness >= 0.25f ? 1u : 2u;
  return std::max(kMinSamples, samples_ >> shift);
}

Result<CubePrefilterBinding> CubePrefilter::bind(const CubeTarget& source,
                                                 const CubeTarget& destination) const {
  if (!*this) {
    return fail(ErrorCode::invalid_argument, "CubePrefilter::bind on an empty prefilter");
  }
  const std::string& name = name_;
  if (!source || !destination) {
    return fail(ErrorCode::invalid_argument,
                name + ": bind needs two cubes (the " +
                    (!source ? std::string("source") : std::string("destination")) + " is empty)");
  }
  if (source.color_image() == destination.color_image()) {
    return fail(ErrorCode::invalid_argument,
                name + ": the source and the destination are the same cube (each level reads "
                       "several source levels: filter into a second cube)");
  }
  if (source.mip_levels() < 2) {
    return fail(ErrorCode::invalid_argument,
                name + ": the source has " + std::to_string(source.mip_levels()) +
                    " level; the prefilter needs a mip chain (CubeTargetDesc::mips = true)");
  }
  if (destination.size() != source.size() || destination.mip_levels() != source.mip_levels()) {
    return fail(ErrorCode::invalid_argument,
                name + ": the destination (" + std::to_string(destination.size()) + " px, " +
                    std::to_string(destination.mip_levels()) +
                    " levels) must have the source's size and levels (" +
                    std::to_string(source.size()) + " px, " + std::to_string(source.mip_levels()) +
                    " levels)");
  }
  if (destination.color_format() != ColorFormat::rgba16_float) {
    return fail(ErrorCode::unsupported,
                name + ": the destination must be rgba16_float (CubeTargetDesc::color; the pass "
                       "stores HDR radiance)");
  }
  if (!destination.storage()) {
    return fail(ErrorCode::invalid_argument,
                name + ": the destination needs storage usage (CubeTargetDesc::storage = true)");
  }
  const ContextState& ctx = *ctx_;
  const std::uint32_t levels = source.mip_levels();
  const std::uint32_t size = source.size();
  CubePrefilterBinding b;
  b.device_ = ctx.device;
  b.source_ = source.color_image();
  b.destination_ = destination.color_image();
  b.size_ = size;
  b.levels_ = levels;
  const std::uint32_t jobs = levels - 1; // levels 1..levels-1 are computed

  // Sample tables, each at an offset aligned for uniform buffers.
  const VkDeviceSize align = std::max<VkDeviceSize>(ctx.limits.minUniformBufferOffsetAlignment, 16);
  std::vector<VkDeviceSize> offsets(jobs);
  std::vector<std::vector<SampleEntry>> tables(jobs);
  VkDeviceSize bytes = 0;
  for (std::uint32_t k = 1; k < levels; ++k) {
    const float roughness = cube_prefilter_roughness(k, levels);
    const std::uint32_t count = samples_at(roughness);
    b.level_samples_.push_back(count);
    tables[k - 1] = sample_table(roughness, count, size, levels);
    offsets[k - 1] = bytes;
    bytes += (count * sizeof(SampleEntry) + align - 1) / align * align;
  }
  auto table = create_buffer(ctx, BufferDesc{.size = bytes,
                                             .usage = VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                             .memory = MemoryUsage::upload,
                                             .debug_name = "cube prefilter sample tables"});
  if (!table) {
    return table.error();
  }
  b.table_ = std::move(*table);
  for (std::uint32_t j = 0; j < jobs; ++j) {
    std::memcpy(static_cast<char*>(b.table_.mapped()) + offsets[j], tables[j].data(),
                tables[j].size() * sizeof(SampleEntry));
  }

  // Storage views of the destination's levels 1.. (all six faces as a 2D array).
  for (std::uint32_t k = 1; k < levels; ++k) {
    auto view = detail::create_view(ctx, b.destination_, VK_IMAGE_VIEW_TYPE_2D_ARRAY,
                                    VK_FORMAT_R16G16B16A16_SFLOAT, VK_IMAGE_ASPECT_COLOR_BIT, k, 1,
                                    0, 6, name + " level view");
    if (!view) {
      return view.error();
    }
    b.level_views_.push_back(*view);
  }

  // One descriptor set per level, written once.
  const VkDescriptorPoolSize pool_sizes[3] = {
      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, jobs},
      {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, jobs},
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, jobs},
  };
  auto pci = vk_struct<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  pci.maxSets = jobs;
  pci.poolSizeCount = 3;
  pci.pPoolSizes = pool_sizes;
  SNELL_VK_TRY(vkCreateDescriptorPool(ctx.device, &pci, nullptr, &b.pool_),
               name + " descriptor pool");
  const std::vector<VkDescriptorSetLayout> layouts(jobs, set_layout_);
  b.level_sets_.resize(jobs);
  auto ai = vk_struct<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
  ai.descriptorPool = b.pool_;
  ai.descriptorSetCount = jobs;
  ai.pSetLayouts = layouts.data();
  SNELL_VK_TRY(vkAllocateDescriptorSets(ctx.device, &ai, b.level_sets_.data()),
               name + " descriptor sets");
  const VkDescriptorImageInfo source_info{
      ctx.samplers[static_cast<int>(StandardSampler::linear_clamp)], source.cube_view(),
      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  std::vector<VkDescriptorImageInfo> storage_infos(jobs);
  std::vector<VkDescriptorBufferInfo> buffer_infos(jobs);
  std::vector<VkWriteDescriptorSet> writes;
  writes.reserve(3 * std::size_t{jobs});
  for (std::uint32_t j = 0; j < jobs; ++j) {
    storage_infos[j] = {VK_NULL_HANDLE, b.level_views_[j], VK_IMAGE_LAYOUT_GENERAL};
    buffer_infos[j] = {b.table_.handle(), offsets[j],
                       b.level_samples_[j] * VkDeviceSize{sizeof(SampleEntry)}};
    auto w = vk_struct<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    w.dstSet = b.level_sets_[j];
    w.descriptorCount = 1;
    w.dstBinding = 0;
    w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    w.pImageInfo = &source_info;
    writes.push_back(w);
    w.dstBinding = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    w.pImageInfo = &storage_infos[j];
    writes.push_back(w);
    w.dstBinding = 2;
    w.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    w.pImageInfo = nullptr;
    w.pBufferInfo = &buffer_infos[j];
    writes.push_back(w);
  }
  vkUpdateDescriptorSets(ctx.device, static_cast<std::uint32_t>(writes.size()), writes.data(), 0,
                         nullptr);
  return b;
}

Result<void> CubePrefilter::record(VkCommandBuffer cmd, const CubePrefilterBinding& binding,
                                   GpuTimer* timer) const {
  if (!*this || !binding) {
    return fail(ErrorCode::invalid_argument,
                (name_.empty() ? std::string("cube_prefilter") : name_) +
                    ": record needs a prefilter and a binding made by its bind()");
  }
  // Every level's sample count needs a pipeline here (a binding made by a prefilter with another
  // CubePrefilterDesc::samples may use counts this one has none for): checked before recording.
  for (const std::uint32_t count : binding.level_samples_) {
    if (pipeline_for(count) == nullptr) {
      return fail(ErrorCode::invalid_argument,
                  name_ + ": the binding was made by a prefilter with other sample counts (" +
                      std::to_string(count) + " samples per texel)");
    }
  }
  GpuTimerScope scope(timer, cmd, name_.c_str());
  const std::uint32_t levels = binding.levels_;
  const VkImage src = binding.source_;
  const VkImage dst = binding.destination_;
  // Source level 0 becomes a copy source; the destination is discarded (its earlier readers,
  // e.g. frames still sampling it, finish first): level 0 a copy target, levels 1.. storage.
  const ImageBarrier start[3] = {
      {src, VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 6, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
       VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, detail::kReadStages, VK_ACCESS_2_NONE,
       VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT},
      {dst, VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 6, VK_IMAGE_LAYOUT_UNDEFINED,
       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, detail::kReadStages, VK_ACCESS_2_NONE,
       VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
      {dst, VK_IMAGE_ASPECT_COLOR_BIT, 1, levels - 1, 0, 6, VK_IMAGE_LAYOUT_UNDEFINED,
       VK_IMAGE_LAYOUT_GENERAL, detail::kReadStages, VK_ACCESS_2_NONE,
       VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
  };
  detail::barrier(cmd, start, 3);
  VkImageCopy copy{};
  copy.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 6};
  copy.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 6};
  copy.extent = {binding.size_, binding.size_, 1};
  vkCmdCopyImage(cmd, src, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
  // Source level 0 back for sampling (the dispatches read every source level); destination
  // level 0 finished.
  const ImageBarrier copied[2] = {
      {src, VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 6, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
       VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE,
       detail::kReadStages, detail::kReadAccess},
      {dst, VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 6, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
       VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
       VK_ACCESS_2_TRANSFER_WRITE_BIT, detail::kReadStages, detail::kReadAccess},
  };
  detail::barrier(cmd, copied, 2);
  // One dispatch per level; levels write disjoint subresources and only read the source, so no
  // barrier between them.
  const Pipeline* bound = nullptr;
  for (std::uint32_t k = 1; k < levels; ++k) {
    const Pipeline* pipeline = pipeline_for(binding.level_samples_[k - 1]);
    if (pipeline != bound) {
      pipeline->bind(cmd);
      bound = pipeline;
    }
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline->layout(), 0, 1,
                            &binding.level_sets_[k - 1], 0, nullptr);
    const std::uint32_t groups = (level_extent(binding.size_, k) + kGroupSize - 1) / kGroupSize;
    vkCmdDispatch(cmd, groups, groups, 6);
  }
  detail::barrier(
      cmd,
      ImageBarrier{dst, VK_IMAGE_ASPECT_COLOR_BIT, 1, levels - 1, 0, 6, VK_IMAGE_LAYOUT_GENERAL,
                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                   VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, detail::kReadStages, detail::kReadAccess});
  return {};
}

} // namespace snell
