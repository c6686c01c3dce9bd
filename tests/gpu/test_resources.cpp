#include "gpu_fixture.hpp"

#include <snell/buffer.hpp>
#include <snell/pipeline.hpp>

#include <cstring>

using namespace snell;

TEST_CASE("resources: zero-sized and oversized targets are refused with the field named") {
  test::GpuFixture gpu;
  auto zero = RenderTarget::create(gpu.ctx(), RenderTargetDesc{.width = 0, .height = 16});
  REQUIRE_FALSE(zero.has_value());
  CHECK(zero.error().code == ErrorCode::invalid_argument);
  CHECK(zero.error().message.find("0x16") != std::string::npos);
  auto huge = RenderTarget::create(gpu.ctx(), RenderTargetDesc{.width = 100000, .height = 16});
  REQUIRE_FALSE(huge.has_value());
  CHECK(huge.error().message.find("100000") != std::string::npos);
  auto cube = CubeTarget::create(gpu.ctx(), CubeTargetDesc{.size = 0});
  REQUIRE_FALSE(cube.has_value());
  auto buffer =
      Buffer::create(gpu.ctx(), BufferDesc{.size = 0, .usage = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT});
  REQUIRE_FALSE(buffer.has_value());
  CHECK(buffer.error().message.find("size") != std::string::npos);
  Image bad;
  bad.name = "inconsistent";
  bad.width = 4;
  bad.height = 4;
  bad.rgba8.resize(10);
  auto tex = Texture2D::create(gpu.ctx(), bad);
  REQUIRE_FALSE(tex.has_value());
  CHECK(tex.error().message.find("inconsistent") != std::string::npos);
  auto missing = Texture2D::load(gpu.ctx(), "/nonexistent/file.png");
  REQUIRE_FALSE(missing.has_value());
  CHECK(missing.error().code == ErrorCode::file_not_found);
  CHECK(missing.error().message.find("/nonexistent/file.png") != std::string::npos);
}

TEST_CASE("resources: buffers upload through staging and round-trip") {
  test::GpuFixture gpu;
  std::vector<std::uint32_t> data(1000);
  for (std::uint32_t i = 0; i < data.size(); ++i) {
    data[i] = i * 2654435761u;
  }
  auto gpu_buffer = Buffer::create(
      gpu.ctx(), BufferDesc{.size = 4000, .usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT});
  REQUIRE(gpu_buffer.has_value());
  REQUIRE(gpu_buffer->upload(data.data(), 4000));
  CHECK_FALSE(gpu_buffer->upload(data.data(), 8, 3996)); // past the end
  auto readback = Buffer::create(gpu.ctx(), BufferDesc{.size = 4000,
                                                       .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                                       .memory = MemoryUsage::readback});
  REQUIRE(readback.has_value());
  REQUIRE(gpu.ctx().submit_and_wait([&](VkCommandBuffer cmd) {
    const VkBufferCopy region{0, 0, 4000};
    vkCmdCopyBuffer(cmd, gpu_buffer->handle(), readback->handle(), 1, &region);
  }));
  CHECK(std::memcmp(readback->mapped(), data.data(), 4000) == 0);
  Buffer moved = std::move(*gpu_buffer);
  CHECK(moved.size() == 4000);
  CHECK_FALSE(static_cast<bool>(*gpu_buffer));
}

TEST_CASE("resources: render target clear, mip chain and readback of every level") {
  test::GpuFixture gpu;
  for (const ColorFormat format :
       {ColorFormat::rgba8_unorm, ColorFormat::rgba8_srgb, ColorFormat::rgba16_float}) {
    auto target = RenderTarget::create(
        gpu.ctx(),
        RenderTargetDesc{.width = 64, .height = 32, .color = format, .depth = true, .mips = true});
    REQUIRE(target.has_value());
    CHECK(target->mip_levels() == 7); // 64 -> 1
    const float clear[4] = {0.25f, 0.5f, 1.0f, 1.0f};
    REQUIRE(gpu.ctx().submit_and_wait([&](VkCommandBuffer cmd) {
      target->begin_rendering(cmd, clear);
      target->end_rendering(cmd);
    }));
    for (std::uint32_t level = 0; level < target->mip_levels(); ++level) {
      auto f = read_float(gpu.ctx(), *target, level);
      REQUIRE(f.has_value());
      CHECK(f->width == std::max(1u, 64u >> level));
      CHECK(f->height == std::max(1u, 32u >> level));
      // A uniform image stays uniform down the chain (mips are really generated).
      const float tol = format == ColorFormat::rgba8_unorm ? 1.0f / 255.0f : 0.01f;
      CHECK(f->rgba[0] == doctest::Approx(0.25f).epsilon(tol * 4));
      CHECK(f->rgba[1] == doctest::Approx(0.5f).epsilon(tol * 4));
      CHECK(f->rgba[2] == doctest::Approx(1.0f).epsilon(tol * 4));
    }
    auto depth = read_depth(gpu.ctx(), *target);
    REQUIRE(depth.has_value());
    CHECK((*depth)[0] == 1.0f);
    CHECK_FALSE(read_float(gpu.ctx(), *target, 7).has_value()); // level out of range
  }
}

TEST_CASE("resources: texture upload with GPU mips, cube target views, samplers") {
  test::GpuFixture gpu;
  Image checker;
  checker.name = "checker";
  checker.width = 16;
  checker.height = 16;
  checker.srgb = false;
  for (std::uint32_t y = 0; y < 16; ++y) {
    for (std::uint32_t x = 0; x < 16; ++x) {
      const std::uint8_t v = ((x + y) % 2) != 0 ? 255 : 0;
      checker.rgba8.insert(checker.rgba8.end(), {v, v, v, 255});
    }
  }
  auto tex = Texture2D::create(gpu.ctx(), checker);
  REQUIRE(tex.has_value());
  CHECK(tex->mip_levels() == 5);
  auto cube = CubeTarget::create(gpu.ctx(), CubeTargetDesc{.size = 32});
  REQUIRE(cube.has_value());
  CHECK(cube->mip_levels() == 6);
  for (std::uint32_t f = 0; f < 6; ++f) {
    CHECK(cube->face_view(f) != VK_NULL_HANDLE);
  }
  CHECK(cube->cube_view() != VK_NULL_HANDLE);
  CHECK(cube->array_view() != VK_NULL_HANDLE);
  auto sampler = Sampler::create(gpu.ctx(), SamplerDesc{});
  REQUIRE(sampler.has_value());
  auto bad = Sampler::create(gpu.ctx(), SamplerDesc{.max_anisotropy = 0.5f});
  REQUIRE_FALSE(bad.has_value());
  CHECK(bad.error().message.find("max_anisotropy") != std::string::npos);
}

// Fails if a pipeline binds attributes its vertex shader does not read (a validation message) or
// drops one it reads: the input locations come from the SPIR-V itself.
TEST_CASE("pipeline: vertex_input_locations reads the vertex shader's input locations") {
  const auto op = [](std::uint32_t count, std::uint32_t code) { return count << 16 | code; };
  const std::vector<std::uint32_t> spirv = {
      0x07230203u, 0x00010300u, 0u, 10u, 0u, // header
      op(4, 71),   5,           30, 3,       // OpDecorate %5 Location 3
      op(4, 71),   6,           30, 1,       // OpDecorate %6 Location 1
      op(4, 71),   7,           30, 0,       // OpDecorate %7 Location 0
      op(4, 59),   4,           5,  1,       // %5 = OpVariable %4 Input
      op(4, 59),   4,           6,  3,       // %6 = OpVariable %4 Output (not an input)
      op(4, 59),   4,           7,  1};      // %7 = OpVariable %4 Input
  CHECK(vertex_input_locations(spirv) == ((1u << 3) | 1u));
  const std::vector<std::uint32_t> truncated = {0x07230203u, 0x00010300u, 0u, 10u, 0u, op(9, 71)};
  CHECK(vertex_input_locations(truncated) == ~0u); // unreadable: bind everything
}
