// encode_png / write_png without a GPU: lossless round trip, RGB for opaque images, RGBA
// otherwise, options checked, write errors reported.
#include <snell/readback.hpp>

#include <doctest/doctest.h>
#include <stb_image.h>

#include <string>

namespace {

snell::Image gradient(std::uint32_t w, std::uint32_t h, bool opaque) {
  snell::Image image;
  image.name = "gradient";
  image.width = w;
  image.height = h;
  image.rgba8.resize(std::size_t{w} * h * 4);
  for (std::uint32_t y = 0; y < h; ++y) {
    for (std::uint32_t x = 0; x < w; ++x) {
      std::uint8_t* p = &image.rgba8[(std::size_t{y} * w + x) * 4];
      p[0] = static_cast<std::uint8_t>(x * 7);
      p[1] = static_cast<std::uint8_t>(y * 13);
      p[2] = static_cast<std::uint8_t>((x ^ y) * 3);
      p[3] = opaque ? 255 : static_cast<std::uint8_t>(x + y);
    }
  }
  return image;
}

/// Decodes PNG bytes to RGBA8 and checks the size.
std::vector<std::uint8_t> decode(const std::vector<std::uint8_t>& png, std::uint32_t w,
                                 std::uint32_t h, int& channels_in_file) {
  int dw = 0, dh = 0;
  stbi_uc* pixels = stbi_load_from_memory(png.data(), static_cast<int>(png.size()), &dw, &dh,
                                          &channels_in_file, 4);
  REQUIRE(pixels != nullptr);
  CHECK(static_cast<std::uint32_t>(dw) == w);
  CHECK(static_cast<std::uint32_t>(dh) == h);
  std::vector<std::uint8_t> out(pixels, pixels + std::size_t{w} * h * 4);
  stbi_image_free(pixels);
  return out;
}

} // namespace

TEST_CASE("png: opaque images are stored as RGB, others as RGBA, both lossless") {
  for (const bool opaque : {true, false}) {
    CAPTURE(opaque);
    const snell::Image image = gradient(37, 23, opaque);
    for (const int level : {5, 8, 32}) {
      CAPTURE(level);
      auto png = snell::encode_png(image, snell::PngOptions{level});
      REQUIRE(png);
      REQUIRE(png->size() > 26);
      // IHDR colour type (byte 25): 2 = RGB, 6 = RGBA.
      CHECK(int((*png)[25]) == (opaque ? 2 : 6));
      int channels = 0;
      CHECK(decode(*png, image.width, image.height, channels) == image.rgba8);
      CHECK(channels == (opaque ? 3 : 4));
    }
  }
}

TEST_CASE("png: bad images and levels are refused with the values") {
  snell::Image image = gradient(4, 4, true);
  auto r = snell::encode_png(image, snell::PngOptions{4});
  REQUIRE_FALSE(r);
  CHECK(r.error().message.find("compression_level 4 is outside [5, 32]") != std::string::npos);
  image.rgba8.pop_back();
  r = snell::encode_png(image);
  REQUIRE_FALSE(r);
  CHECK(r.error().code == snell::ErrorCode::invalid_argument);
  CHECK(r.error().message.find("4x4") != std::string::npos);
}

TEST_CASE("png: write_png reports a failed write with the path and the reason") {
  if (!std::filesystem::exists("/dev/full")) {
    MESSAGE("no /dev/full on this system");
    return;
  }
  const auto r = snell::write_png("/dev/full", gradient(64, 64, true));
  REQUIRE_FALSE(r);
  INFO(r.error().message);
  CHECK(r.error().message.find("/dev/full") != std::string::npos);
  CHECK(r.error().message.find("No space left on device") != std::string::npos);
}
