// The GGX cube prefilter (snell/toolkit/cube_prefilter.hpp) and the box mip chain it reads:
// energy conservation on a constant cube, an edge that blurs monotonically with the level and
// matches a brute-force CPU convolution, a small bright source that stays one smooth lobe (no
// ghosts of the sample pattern, no fireflies), level 0 a copy of the source, the mean and pattern
// of a checkerboard's box mips, bad input refused, and the pass's cost (reported, not asserted).
// Cubes are filled by uploading level 0 inside begin_capture / end_capture (what a capture
// does), read back as floats.
#include "gpu_fixture.hpp"

#include <snell/buffer.hpp>
#include <snell/gpu_timer.hpp>
#include <snell/math/cube.hpp>
#include <snell/toolkit/cube_prefilter.hpp>
#include <snell/toolkit/vk_check.hpp>

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <vector>

using namespace snell;

namespace {

constexpr double kPi = 3.14159265358979323846;

void require_ok(const Result<void>& r) {
  REQUIRE_MESSAGE(r.has_value(), r.error().message);
}

/// Requires a value, printing the error otherwise (error() is only valid without a value).
template <class T> void require_value(const Result<T>& r) {
  if (!r.has_value()) {
    FAIL(r.error().message);
  }
}

/// One synchronization2 barrier over `levels` levels (from `level`) of all six layers.
void image_barrier(VkCommandBuffer cmd, VkImage image, std::uint32_t level, std::uint32_t levels,
                   VkImageLayout from, VkImageLayout to, VkPipelineStageFlags2 src_stage,
                   VkAccessFlags2 src_access, VkPipelineStageFlags2 dst_stage,
                   VkAccessFlags2 dst_access) {
  auto b = vk_struct<VkImageMemoryBarrier2>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2);
  b.srcStageMask = src_stage;
  b.srcAccessMask = src_access;
  b.dstStageMask = dst_stage;
  b.dstAccessMask = dst_access;
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, level, levels, 0, 6};
  auto dep = vk_struct<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
  dep.imageMemoryBarrierCount = 1;
  dep.pImageMemoryBarriers = &b;
  vkCmdPipelineBarrier2(cmd, &dep);
}

/// The colour of texel (x, y) of `face` at level 0.
using Pattern = std::function<glm::vec4(std::uint32_t face, std::uint32_t x, std::uint32_t y)>;

/// Fills level 0 of an rgba16_float cube with `pattern` the way a capture does (begin_capture,
/// level 0 written, end_capture), so end_capture builds the box mip chain from it.
void fill_cube(Context& ctx, const CubeTarget& cube, const Pattern& pattern) {
  REQUIRE(cube.color_format() == ColorFormat::rgba16_float);
  const std::uint32_t s = cube.size();
  const VkDeviceSize face_bytes = VkDeviceSize{s} * s * 8;
  auto staging = Buffer::create(ctx, BufferDesc{.size = 6 * face_bytes,
                                                .usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                                .memory = MemoryUsage::upload,
                                                .debug_name = "cube fill"});
  REQUIRE(staging.has_value());
  auto* halves = static_cast<std::uint16_t*>(staging->mapped());
  for (std::uint32_t f = 0; f < 6; ++f) {
    for (std::uint32_t y = 0; y < s; ++y) {
      for (std::uint32_t x = 0; x < s; ++x) {
        const glm::vec4 c = pattern(f, x, y);
        std::uint16_t* texel = halves + ((std::size_t{f} * s + y) * s + x) * 4;
        for (int i = 0; i < 4; ++i) {
          texel[i] = glm::packHalf1x16(c[i]);
        }
      }
    }
  }
  require_ok(ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    cube.begin_capture(cmd);
    image_barrier(cmd, cube.color_image(), 0, 1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                  VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                  VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_NONE,
                  VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 6};
    region.imageExtent = {s, s, 1};
    vkCmdCopyBufferToImage(cmd, staging->handle(), cube.color_image(),
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    image_barrier(cmd, cube.color_image(), 0, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                  VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                  VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                  VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    cube.end_capture(cmd, true);
  }));
}

/// A face of one level as linear floats, rows top first.
struct Face {
  std::uint32_t size = 0;
  std::vector<glm::vec4> texels{};
  [[nodiscard]] glm::vec4 at(std::uint32_t x, std::uint32_t y) const {
    return texels[std::size_t{y} * size + x];
  }
};

/// Reads `face` of `level` of an rgba16_float cube (in SHADER_READ_ONLY_OPTIMAL).
Face read_face(Context& ctx, const CubeTarget& cube, std::uint32_t face, std::uint32_t level) {
  REQUIRE(cube.color_format() == ColorFormat::rgba16_float);
  const std::uint32_t s = std::max(1u, cube.size() >> level);
  auto buffer = Buffer::create(ctx, BufferDesc{.size = VkDeviceSize{s} * s * 8,
                                               .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                               .memory = MemoryUsage::readback,
                                               .debug_name = "cube face readback"});
  REQUIRE(buffer.has_value());
  require_ok(ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    auto b = vk_struct<VkImageMemoryBarrier2>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2);
    b.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    b.srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT;
    b.dstStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    b.dstAccessMask = VK_ACCESS_2_TRANSFER_READ_BIT;
    b.oldLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = cube.color_image();
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, level, 1, face, 1};
    auto dep = vk_struct<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &dep);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, face, 1};
    region.imageExtent = {s, s, 1};
    vkCmdCopyImageToBuffer(cmd, cube.color_image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           buffer->handle(), 1, &region);
    b.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    b.srcAccessMask = VK_ACCESS_2_NONE;
    b.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    b.dstAccessMask = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT;
    b.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    b.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    vkCmdPipelineBarrier2(cmd, &dep);
  }));
  Face out{s, std::vector<glm::vec4>(std::size_t{s} * s)};
  const auto* halves = static_cast<const std::uint16_t*>(buffer->mapped());
  for (std::size_t i = 0; i < out.texels.size(); ++i) {
    for (int c = 0; c < 4; ++c) {
      out.texels[i][c] = glm::unpackHalf1x16(halves[i * 4 + static_cast<std::size_t>(c)]);
    }
  }
  return out;
}

CubeTarget make_cube(Context& ctx, std::uint32_t size, bool storage, const char* name) {
  auto cube = CubeTarget::create(ctx, CubeTargetDesc{.size = size,
                                                     .color = ColorFormat::rgba16_float,
                                                     .mips = true,
                                                     .debug_name = name,
                                                     .storage = storage});
  require_value(cube);
  return std::move(*cube);
}

/// Prefilters `source` into `destination` in one submission.
void prefilter(Context& ctx, const CubePrefilter& filter, const CubePrefilterBinding& binding) {
  Result<void> recorded;
  require_ok(ctx.submit_and_wait(
      [&](VkCommandBuffer cmd) { recorded = filter.record(cmd, binding, nullptr); }));
  require_ok(recorded);
}

/// The direction of texel (x, y) of `face` in a face of `size` texels.
glm::vec3 texel_direction(std::uint32_t face, std::uint32_t x, std::uint32_t y,
                          std::uint32_t size) {
  const glm::vec2 uv((static_cast<float>(x) + 0.5f) / static_cast<float>(size),
                     (static_cast<float>(y) + 0.5f) / static_cast<float>(size));
  return cube_to_direction(static_cast<CubeFace>(face), uv);
}

/// Brute-force split-sum GGX prefilter (N = V = R) of the environment "1 where x > 0, else 0" in
/// direction `n`: sum over many GGX half vectors of [L.x > 0] N.L / sum N.L (Karis 2013), with
/// no mip chain, for roughness `roughness` (alpha = roughness^2).
double reference_half_space(glm::dvec3 n, double roughness) {
  const double a2 = std::pow(roughness, 4.0);
  const glm::dvec3 up = std::abs(n.z) < 0.999 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 t = glm::normalize(glm::cross(up, n));
  const glm::dvec3 b = glm::cross(n, t);
  constexpr int kU = 256, kPhi = 64; // a 256 x 64 grid of the GGX inverse CDF
  double lit = 0.0, total = 0.0;
  for (int i = 0; i < kU; ++i) {
    const double u = (i + 0.5) / kU;
    const double cos2 = (1.0 - u) / (1.0 + (a2 - 1.0) * u);
    const double n_dot_l = 2.0 * cos2 - 1.0;
    if (n_dot_l <= 0.0) {
      continue;
    }
    const double sc = 2.0 * std::sqrt(cos2 * (1.0 - cos2));
    for (int j = 0; j < kPhi; ++j) {
      const double phi = 2.0 * kPi * (j + 0.5) / kPhi;
      const glm::dvec3 l = t * (sc * std::cos(phi)) + b * (sc * std::sin(phi)) + n * n_dot_l;
      total += n_dot_l;
      lit += l.x > 0.0 ? n_dot_l : 0.0;
    }
  }
  return lit / total;
}

} // namespace

TEST_CASE("cube prefilter: a constant cube keeps its colour at every GGX level") {
  test::GpuFixture gpu;
  const glm::vec4 color(0.25f, 0.5f, 2.0f, 1.0f); // exact in fp16; HDR blue
  CubeTarget source = make_cube(gpu.ctx(), 64, false, "constant source");
  CubeTarget filtered = make_cube(gpu.ctx(), 64, true, "constant filtered");
  fill_cube(gpu.ctx(), source, [&](std::uint32_t, std::uint32_t, std::uint32_t) { return color; });
  auto filter = CubePrefilter::create(gpu.ctx());
  require_value(filter);
  auto binding = filter->bind(source, filtered);
  require_value(binding);
  CHECK(binding->levels() == 7);
  // Twice: the second pass overwrites a destination already finished (its barriers order the
  // overwrite after the first pass's writes and any reads).
  prefilter(gpu.ctx(), *filter, *binding);
  prefilter(gpu.ctx(), *filter, *binding);
  // The weights sum to 1 (normalised in double, stored as float: error ~1e-7) and every sample
  // reads the same colour, so each texel is the colour up to fp16 storage: relative error
  // <= 2^-11 per value. Tolerance 1e-3 relative (two fp16 ulps).
  float worst = 0.0f;
  for (std::uint32_t level = 0; level < filtered.mip_levels(); ++level) {
    for (std::uint32_t face = 0; face < 6; ++face) {
      const Face f = read_face(gpu.ctx(), filtered, face, level);
      for (const glm::vec4& t : f.texels) {
        for (int c = 0; c < 4; ++c) {
          worst = std::max(worst, std::abs(t[c] - color[c]) / color[c]);
        }
      }
    }
  }
  MESSAGE("constant cube: worst relative error over every level and face " << worst);
  CHECK(worst <= 1e-3f);
}

TEST_CASE("cube prefilter: level 0 is the source's level 0") {
  test::GpuFixture gpu;
  CubeTarget source = make_cube(gpu.ctx(), 32, false, "noise source");
  CubeTarget filtered = make_cube(gpu.ctx(), 32, true, "noise filtered");
  // A different value in every texel and channel (a hash), HDR up to 4.
  fill_cube(gpu.ctx(), source, [](std::uint32_t f, std::uint32_t x, std::uint32_t y) {
    std::uint32_t h = (f * 73856093u) ^ (x * 19349663u) ^ (y * 83492791u);
    glm::vec4 c;
    for (int i = 0; i < 4; ++i) {
      h = h * 1664525u + 1013904223u;
      c[i] = static_cast<float>(h >> 20) / 1024.0f;
    }
    return c;
  });
  auto filter = CubePrefilter::create(gpu.ctx());
  REQUIRE(filter.has_value());
  auto binding = filter->bind(source, filtered);
  require_value(binding);
  prefilter(gpu.ctx(), *filter, *binding);
  for (std::uint32_t face = 0; face < 6; ++face) {
    const Face a = read_face(gpu.ctx(), source, face, 0);
    const Face b = read_face(gpu.ctx(), filtered, face, 0);
    CAPTURE(face);
    CHECK(std::memcmp(a.texels.data(), b.texels.data(), a.texels.size() * sizeof(glm::vec4)) == 0);
  }
  // The roughness mapping the surface's lookup inverts: lod = roughness * (levels - 1).
  CHECK(cube_prefilter_roughness(0, 6) == 0.0f);
  CHECK(cube_prefilter_roughness(2, 6) == doctest::Approx(0.4f));
  CHECK(cube_prefilter_roughness(5, 6) == 1.0f);
  CHECK(cube_prefilter_roughness(0, 1) == 0.0f);
}

TEST_CASE("cube prefilter: an edge blurs monotonically with the level, as a CPU GGX "
          "convolution") {
  test::GpuFixture gpu;
  // The environment is white where x > 0 and black elsewhere: +X white, -X black, and on
  // +Y, -Y, +Z, -Z a straight edge through the face centre (between two texel columns).
  constexpr std::uint32_t kSize = 128;
  CubeTarget source = make_cube(gpu.ctx(), kSize, false, "edge source");
  CubeTarget filtered = make_cube(gpu.ctx(), kSize, true, "edge filtered");
  fill_cube(gpu.ctx(), source, [](std::uint32_t f, std::uint32_t x, std::uint32_t y) {
    const float white = texel_direction(f, x, y, kSize).x > 0.0f ? 1.0f : 0.0f;
    return glm::vec4(white, white, white, 1.0f);
  });
  auto filter = CubePrefilter::create(gpu.ctx());
  REQUIRE(filter.has_value());
  auto binding = filter->bind(source, filtered);
  require_value(binding);
  prefilter(gpu.ctx(), *filter, *binding);
  // Across the edge on face +Z (4), along the row just above its centre: the edge width is the
  // integral of v (1 - v) over the angle across the edge (0 for a step, growing with the blur;
  // v = 0.5 everywhere would give pi/8 over the face's 90 degrees), each texel weighted by the
  // angle it spans. Every texel of faces +Z and +Y (4, 2: the edge crosses both; on +Y the
  // shader's tangent frame flips sign at the middle row) is compared with reference_half_space.
  const std::uint32_t levels = filtered.mip_levels();
  std::vector<double> widths;
  double worst_reference = 0.0, worst_mean = 0.0;
  for (std::uint32_t level = 0; level < levels; ++level) {
    const float roughness = cube_prefilter_roughness(level, levels);
    double width = 0.0, worst = 0.0, sum = 0.0;
    std::size_t count = 0;
    for (const std::uint32_t face : {4u, 2u}) {
      const Face f = read_face(gpu.ctx(), filtered, face, level);
      if (face == 4) {
        const std::uint32_t row = f.size / 2 - (f.size > 1 ? 1 : 0);
        for (std::uint32_t x = 0; x < f.size; ++x) {
          const double s0 = 2.0 * x / f.size - 1.0, s1 = 2.0 * (x + 1) / f.size - 1.0;
          const double v = f.at(x, row).r;
          width += v * (1.0 - v) * (std::atan(s1) - std::atan(s0));
        }
      }
      if (level == 0) {
        continue;
      }
      for (std::uint32_t y = 0; y < f.size; ++y) {
        for (std::uint32_t x = 0; x < f.size; ++x) {
          const glm::vec3 d = texel_direction(face, x, y, f.size);
          const double e = std::abs(f.at(x, y).r - reference_half_space(glm::dvec3(d), roughness));
          worst = std::max(worst, e);
          sum += e;
          ++count;
        }
      }
    }
    widths.push_back(width);
    worst_reference = std::max(worst_reference, worst);
    worst_mean = std::max(worst_mean, count > 0 ? sum / static_cast<double>(count) : 0.0);
    MESSAGE("level " << level << " (" << (kSize >> level) << " px, roughness " << roughness << ", "
                     << (level > 0 ? filter->samples_at(roughness) : 0u) << " samples): edge width "
                     << width << " rad; difference from the CPU reference: largest " << worst
                     << ", mean " << (count > 0 ? sum / static_cast<double>(count) : 0.0));
  }
  CHECK(widths[0] == doctest::Approx(0.0)); // the copy keeps the step
  for (std::uint32_t level = 1; level < levels; ++level) {
    CAPTURE(level);
    CHECK(widths[level] > widths[level - 1]);
  }
  // The prefilter reads box-filtered mips one level coarser than each sample's share of the lobe
  // (filtered importance sampling, +1 lod bias) with 8 to 32 samples; the reference integrates
  // the step exactly. They differ by that extra blur, largest at the smoothest level (few
  // samples, so a coarse mip each): measured 0.109 of the step at level 1 and at most 0.067
  // elsewhere, means at most 0.044 (lavapipe). Bounds: 0.125 and 0.06.
  CHECK(worst_reference < 0.125);
  CHECK(worst_mean < 0.06);
}

/// Split-sum GGX prefilter (N = V = R) of a small source of radiance `radiance` covering texels
/// [x0, x1) x [y0, y1) of face `face` of a `size` px cube, in direction `n`: the integral over the
/// source of NoL D(H) / 4 (the pdf of L) divided by the integral of NoL D(H) / 4 over the
/// hemisphere (Karis's estimator in the limit), evaluated on 8 x 8 points per texel.
double reference_small_source(glm::dvec3 n, double roughness, double radiance, std::uint32_t face,
                              std::uint32_t x0, std::uint32_t x1, std::uint32_t y0,
                              std::uint32_t y1, std::uint32_t size) {
  const double a2 = std::pow(roughness, 4.0);
  const auto lobe = [&](glm::dvec3 l) { // NoL D(H) / 4 for N = V
    const double n_dot_l = glm::dot(n, l);
    if (n_dot_l <= 0.0) {
      return 0.0;
    }
    const double n_dot_h = glm::dot(n, glm::normalize(n + l));
    const double q = (a2 - 1.0) * n_dot_h * n_dot_h + 1.0;
    return n_dot_l * a2 / (kPi * q * q) / 4.0;
  };
  // The normalisation: the integral of NoL D / 4 over L, by the GGX inverse CDF (as above).
  constexpr int kU = 4096;
  double mean_n_dot_l = 0.0;
  for (int i = 0; i < kU; ++i) {
    const double u = (i + 0.5) / kU;
    const double cos2 = (1.0 - u) / (1.0 + (a2 - 1.0) * u);
    mean_n_dot_l += std::max(0.0, 2.0 * cos2 - 1.0) / kU;
  }
  constexpr int kSub = 8;
  double sum = 0.0;
  for (std::uint32_t y = y0; y < y1; ++y) {
    for (std::uint32_t x = x0; x < x1; ++x) {
      for (int j = 0; j < kSub; ++j) {
        for (int i = 0; i < kSub; ++i) {
          const glm::dvec2 uv((x + (i + 0.5) / kSub) / size, (y + (j + 0.5) / kSub) / size);
          const glm::dvec3 d(cube_to_direction(static_cast<CubeFace>(face), glm::vec2(uv)));
          // Solid angle of the sub-texel: (2 / (size * kSub))^2 / |p|^3 for p on the unit cube.
          const glm::dvec2 st = 2.0 * uv - 1.0;
          const double r2 = 1.0 + st.x * st.x + st.y * st.y;
          const double omega = std::pow(2.0 / (size * kSub), 2.0) / (r2 * std::sqrt(r2));
          sum += lobe(d) * omega;
        }
      }
    }
  }
  return radiance * sum / mean_n_dot_l;
}

TEST_CASE("cube prefilter: a small bright source gives one smooth lobe (no ghosts, no "
          "fireflies)") {
  test::GpuFixture gpu;
  // A 2 x 2 texel source of radiance 50 on +Z, black elsewhere: the hardest case for few samples
  // (each sample sees the source or misses it), at the face centre, off-centre and near an edge.
  constexpr std::uint32_t kSize = 128, kFace = 4;
  constexpr float kRadiance = 50.0f;
  CubeTarget source = make_cube(gpu.ctx(), kSize, false, "spot source");
  CubeTarget filtered = make_cube(gpu.ctx(), kSize, true, "spot filtered");
  auto filter = CubePrefilter::create(gpu.ctx());
  REQUIRE(filter.has_value());
  auto binding = filter->bind(source, filtered);
  require_value(binding);
  const std::uint32_t levels = filtered.mip_levels();
  for (const glm::uvec2 corner : {glm::uvec2(63, 63), glm::uvec2(37, 81), glm::uvec2(6, 100)}) {
    CAPTURE(corner.x);
    CAPTURE(corner.y);
    fill_cube(gpu.ctx(), source, [&](std::uint32_t f, std::uint32_t x, std::uint32_t y) {
      const bool lit =
          f == kFace && x >= corner.x && x < corner.x + 2 && y >= corner.y && y < corner.y + 2;
      return glm::vec4(lit ? kRadiance : 0.0f, 0.0f, 0.0f, 1.0f);
    });
    prefilter(gpu.ctx(), *filter, *binding);
    const bool centred = corner.x == kSize / 2 - 1 && corner.y == kSize / 2 - 1;
    for (std::uint32_t level = 1; level < levels; ++level) {
      CAPTURE(level);
      const float roughness = cube_prefilter_roughness(level, levels);
      const Face f = read_face(gpu.ctx(), filtered, kFace, level);
      const std::uint32_t n = f.size;
      double peak_ref = 0.0, peak = 0.0, asymmetry = 0.0;
      glm::uvec2 at(0), at_ref(0);
      for (std::uint32_t y = 0; y < n; ++y) {
        for (std::uint32_t x = 0; x < n; ++x) {
          const glm::dvec3 d(texel_direction(kFace, x, y, n));
          const double ref = reference_small_source(d, roughness, kRadiance, kFace, corner.x,
                                                    corner.x + 2, corner.y, corner.y + 2, kSize);
          const double v = f.at(x, y).r;
          if (ref > peak_ref) {
            peak_ref = ref;
            at_ref = {x, y};
          }
          if (v > peak) {
            peak = v;
            at = {x, y};
          }
          asymmetry = std::max(
              {asymmetry, std::abs(v - f.at(n - 1 - x, y).r), std::abs(v - f.at(x, n - 1 - y).r)});
        }
      }
      // One lobe: from the brightest texel outward along its row and column the values never
      // rise again (a ghost copy of the source, or a firefly, would).
      std::uint32_t rises = 0;
      const float slack = 1e-3f * static_cast<float>(peak);
      for (std::uint32_t i = at.x; i + 1 < n; ++i) {
        rises += f.at(i + 1, at.y).r > f.at(i, at.y).r + slack ? 1u : 0u;
      }
      for (std::uint32_t i = at.x; i > 0; --i) {
        rises += f.at(i - 1, at.y).r > f.at(i, at.y).r + slack ? 1u : 0u;
      }
      for (std::uint32_t i = at.y; i + 1 < n; ++i) {
        rises += f.at(at.x, i + 1).r > f.at(at.x, i).r + slack ? 1u : 0u;
      }
      for (std::uint32_t i = at.y; i > 0; --i) {
        rises += f.at(at.x, i - 1).r > f.at(at.x, i).r + slack ? 1u : 0u;
      }
      // Reported, not asserted: the peak is lower and the lobe wider than the reference's (the
      // +1 lod bias and the box mips blur the source; at level 1 the peak is 0.18 of the
      // reference's for the centred source), the price of no ghosts with 8 to 32 samples.
      MESSAGE("spot at " << corner.x << "," << corner.y << ", level " << level << " (" << n
                         << " px, roughness " << roughness << ", " << filter->samples_at(roughness)
                         << " samples): peak " << peak << " at " << at.x << "," << at.y
                         << " (reference " << peak_ref << " at " << at_ref.x << "," << at_ref.y
                         << "), rises " << rises << ", asymmetry " << 100.0 * asymmetry / peak
                         << "% of the peak");
      CHECK(rises == 0);
      // The brightest texel is where the reference has its peak, or next to it. Near a face
      // edge the per-face box mips (blits do not cross faces) move the energy of coarse levels
      // toward the texel centres, i.e. inward: there 2 texels.
      const std::uint32_t off = corner.x < 16 ? 2u : 1u;
      CHECK(std::max(at.x, at_ref.x) - std::min(at.x, at_ref.x) <= off);
      CHECK(std::max(at.y, at_ref.y) - std::min(at.y, at_ref.y) <= off);
      if (centred) {
        CHECK(asymmetry <= 0.15 * peak);
      }
    }
  }
}

TEST_CASE("cube mips: each box mip of a checkerboard keeps its mean, the pattern while a texel "
          "is within one square, and is uniform once a texel covers a pair") {
  test::GpuFixture gpu;
  // 64 px faces, 4 px squares: levels 0..2 (texels of 1, 2, 4 px) still resolve the squares,
  // level 3 (8 px texels) covers exactly one black + white pair in each direction.
  constexpr std::uint32_t kSize = 64, kSquare = 4;
  CubeTarget cube = make_cube(gpu.ctx(), kSize, false, "checkerboard");
  fill_cube(gpu.ctx(), cube, [](std::uint32_t, std::uint32_t x, std::uint32_t y) {
    const float white = ((x / kSquare + y / kSquare) % 2 == 0) ? 1.0f : 0.0f;
    return glm::vec4(white, white, white, 1.0f);
  });
  const std::uint32_t pair_level = 3; // 2^3 = 2 * kSquare
  for (std::uint32_t level = 0; level < cube.mip_levels(); ++level) {
    for (std::uint32_t face = 0; face < 6; ++face) {
      const Face f = read_face(gpu.ctx(), cube, face, level);
      CAPTURE(level);
      CAPTURE(face);
      double mean = 0.0;
      float lo = 1.0f, hi = 0.0f;
      for (const glm::vec4& t : f.texels) {
        mean += t.r;
        lo = std::min(lo, t.r);
        hi = std::max(hi, t.r);
      }
      mean /= static_cast<double>(f.texels.size());
      // Linear 2:1 blits of a power-of-two face average 2 x 2 texels exactly (0, 0.5, 1 and
      // their halves are exact in fp16): the mean stays 0.5 up to rounding.
      CHECK(mean == doctest::Approx(0.5).epsilon(1e-3));
      if ((1u << level) <= kSquare) {
        // One texel inside one square: the pattern is intact, 0 and 1 next to each other.
        CHECK(lo <= 0.01f);
        CHECK(hi >= 0.99f);
        const std::uint32_t per_square = kSquare >> level;
        CHECK(std::abs(f.at(0, 0).r - f.at(per_square, 0).r) >= 0.98f);
      } else {
        CHECK(level >= pair_level);
        CHECK(lo >= 0.5f - 1e-3f);
        CHECK(hi <= 0.5f + 1e-3f);
      }
    }
  }
}

TEST_CASE("cube prefilter: bad input is refused with a message") {
  test::GpuFixture gpu;
  auto bad_samples = CubePrefilter::create(gpu.ctx(), CubePrefilterDesc{.samples = 2});
  REQUIRE_FALSE(bad_samples.has_value());
  CHECK(bad_samples.error().code == ErrorCode::invalid_argument);
  CHECK(bad_samples.error().message.find("samples") != std::string::npos);
  auto no_name = CubePrefilter::create(gpu.ctx(), CubePrefilterDesc{.name = nullptr});
  REQUIRE_FALSE(no_name.has_value());

  auto filter = CubePrefilter::create(gpu.ctx(), CubePrefilterDesc{.name = "test.prefilter"});
  REQUIRE(filter.has_value());
  const CubeTarget source = make_cube(gpu.ctx(), 32, false, "source");
  const CubeTarget destination = make_cube(gpu.ctx(), 32, true, "destination");
  const CubeTarget smaller = make_cube(gpu.ctx(), 16, true, "smaller");
  const CubeTarget no_storage = make_cube(gpu.ctx(), 32, false, "no storage");
  auto flat = CubeTarget::create(gpu.ctx(), CubeTargetDesc{.size = 32,
                                                           .color = ColorFormat::rgba16_float,
                                                           .mips = false,
                                                           .storage = true});
  REQUIRE(flat.has_value());
  auto rgba8 = CubeTarget::create(
      gpu.ctx(), CubeTargetDesc{.size = 32, .color = ColorFormat::rgba8_unorm, .storage = true});
  REQUIRE(rgba8.has_value());

  const auto refused = [](const Result<CubePrefilterBinding>& r, ErrorCode code,
                          const char* words) {
    REQUIRE_FALSE(r.has_value());
    CAPTURE(r.error().message);
    CHECK(r.error().code == code);
    CHECK(r.error().message.find("test.prefilter") != std::string::npos);
    CHECK(r.error().message.find(words) != std::string::npos);
  };
  refused(filter->bind(source, smaller), ErrorCode::invalid_argument, "size and levels");
  refused(filter->bind(source, no_storage), ErrorCode::invalid_argument, "storage");
  refused(filter->bind(*flat, *flat), ErrorCode::invalid_argument, "same cube");
  refused(filter->bind(*flat, destination), ErrorCode::invalid_argument, "mip chain");
  refused(filter->bind(source, *rgba8), ErrorCode::unsupported, "rgba16_float");
  refused(filter->bind(CubeTarget(), destination), ErrorCode::invalid_argument, "empty");
  CHECK(filter->bind(source, destination).has_value());

  // A binding of a prefilter with other sample counts is refused before anything is recorded.
  auto other = CubePrefilter::create(gpu.ctx(), CubePrefilterDesc{.samples = 8});
  REQUIRE(other.has_value());
  auto foreign = other->bind(source, destination);
  REQUIRE(foreign.has_value());
  Result<void> recorded;
  require_ok(gpu.ctx().submit_and_wait(
      [&](VkCommandBuffer cmd) { recorded = filter->record(cmd, *foreign, nullptr); }));
  REQUIRE_FALSE(recorded.has_value());
  CHECK(recorded.error().message.find("sample counts") != std::string::npos);
  Result<void> empty;
  require_ok(gpu.ctx().submit_and_wait(
      [&](VkCommandBuffer cmd) { empty = filter->record(cmd, CubePrefilterBinding(), nullptr); }));
  CHECK_FALSE(empty.has_value());
}

TEST_CASE("cube prefilter: cost of the pass on a 256 px cube (reported, not asserted)") {
  test::GpuFixture gpu;
  constexpr std::uint32_t kSize = 256;
  CubeTarget source = make_cube(gpu.ctx(), kSize, false, "timed source");
  CubeTarget filtered = make_cube(gpu.ctx(), kSize, true, "timed filtered");
  fill_cube(gpu.ctx(), source, [](std::uint32_t f, std::uint32_t x, std::uint32_t y) {
    const float v = ((x / 16 + y / 16 + f) % 2 == 0) ? 1.0f : 0.1f;
    return glm::vec4(v, 0.5f * v, 0.25f, 1.0f);
  });
  auto filter = CubePrefilter::create(gpu.ctx());
  REQUIRE(filter.has_value());
  auto binding = filter->bind(source, filtered);
  require_value(binding);
  auto timer = GpuTimer::create(gpu.ctx(), 4);
  REQUIRE(timer.has_value());
  constexpr int kRuns = 5;
  std::vector<double> prefilter_ms, mips_ms;
  for (int run = 0; run < kRuns; ++run) {
    Result<void> recorded;
    require_ok(gpu.ctx().submit_and_wait([&](VkCommandBuffer cmd) {
      timer->reset(cmd);
      // The box mips of a capture (end_capture), for comparison, then the prefilter.
      timer->begin(cmd, "mips");
      source.begin_capture(cmd, true);
      source.end_capture(cmd, true);
      timer->end(cmd);
      recorded = filter->record(cmd, *binding, &*timer);
    }));
    require_ok(recorded);
    auto times = timer->read();
    REQUIRE(times.has_value());
    REQUIRE(times->size() == 2);
    CHECK((*times)[1].name == "cube_prefilter");
    mips_ms.push_back((*times)[0].ms);
    prefilter_ms.push_back((*times)[1].ms);
  }
  std::sort(prefilter_ms.begin(), prefilter_ms.end());
  std::sort(mips_ms.begin(), mips_ms.end());
  std::string counts;
  for (std::uint32_t level = 1; level < binding->levels(); ++level) {
    counts +=
        std::to_string(filter->samples_at(cube_prefilter_roughness(level, binding->levels()))) +
        (level + 1 < binding->levels() ? "/" : "");
  }
  MESSAGE(gpu.ctx().device_info().name
          << ": 256 px cube, " << binding->levels() << " levels, samples per texel " << counts
          << ": prefilter median " << prefilter_ms[kRuns / 2] << " ms (min " << prefilter_ms.front()
          << ", max " << prefilter_ms.back() << "); box mips median " << mips_ms[kRuns / 2]
          << " ms");
  // The pass still filters correctly when timed (spot check: a grey-ish result, no NaN).
  const Face top = read_face(gpu.ctx(), filtered, 2, binding->levels() - 1);
  CHECK(std::isfinite(top.at(0, 0).r));
  CHECK(top.at(0, 0).r > 0.1f);
  CHECK(top.at(0, 0).r < 1.0f);
}
