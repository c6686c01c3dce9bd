// snell_image_compare ACTUAL.png EXPECTED.png [DIFF.png]: the golden tolerance of
// tests/golden (compare_with_golden): same size, at most 0.5% of pixels differing by more than 16
// 8-bit steps in any channel, and a mean absolute difference under 1 step. Lavapipe is
// deterministic for one Mesa build, so the viewer's screenshot and `snell render` of the same
// state are expected to be identical; the tolerance is the one every golden image gets.
// Exit 0 within it, 1 outside it (writing DIFF.png when given), 2 for unreadable files.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::fprintf(stderr, "usage: snell_image_compare ACTUAL.png EXPECTED.png [DIFF.png]\n");
    return 2;
  }
  int w[2] = {0, 0}, h[2] = {0, 0}, comp = 0;
  unsigned char* img[2] = {nullptr, nullptr};
  for (int i = 0; i < 2; ++i) {
    img[i] = stbi_load(argv[1 + i], &w[i], &h[i], &comp, 4);
    if (img[i] == nullptr) {
      std::fprintf(stderr, "snell_image_compare: cannot read %s\n", argv[1 + i]);
      return 2;
    }
  }
  if (w[0] != w[1] || h[0] != h[1]) {
    std::printf("size differs: %dx%d against %dx%d\n", w[0], h[0], w[1], h[1]);
    return 1;
  }
  const std::size_t pixels = static_cast<std::size_t>(w[0]) * static_cast<std::size_t>(h[0]);
  std::vector<unsigned char> diff(pixels * 4, 255);
  std::size_t big = 0, identical = 0;
  double sum = 0.0;
  for (std::size_t p = 0; p < pixels; ++p) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
      const int d = std::abs(int(img[0][p * 4 + c]) - int(img[1][p * 4 + c]));
      worst = std::max(worst, d);
      sum += d;
      diff[p * 4 + c] = static_cast<unsigned char>(std::min(255, d * 8));
    }
    big += worst > 16 ? 1 : 0;
    identical += worst == 0 ? 1 : 0;
  }
  const double mean = sum / double(pixels * 3);
  const double big_fraction = double(big) / double(pixels);
  const bool ok = big_fraction <= 0.005 && mean < 1.0;
  std::printf("%dx%d: %zu of %zu pixels identical, mean difference %.4f steps (< 1), %.4f%% "
              "differ by more than 16 (<= 0.5%%): %s\n",
              w[0], h[0], identical, pixels, mean, 100.0 * big_fraction, ok ? "match" : "MISMATCH");
  if (!ok && argc == 4) {
    stbi_write_png(argv[3], w[0], h[0], 4, diff.data(), w[0] * 4);
  }
  stbi_image_free(img[0]);
  stbi_image_free(img[1]);
  return ok ? 0 : 1;
}
