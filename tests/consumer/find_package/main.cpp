// Consumer of an installed Snell (find_package(snell) + snell::math).
// Exits 0 iff the header-only math works through the installed package.
#include <snell/math.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdio>

int main() {
  int failures = 0;
  const auto check = [&failures](bool ok, const char* what) {
    std::printf("%s: %s\n", ok ? "ok  " : "FAIL", what);
    if (!ok) {
      ++failures;
    }
  };

  // The water plane y = 2 is {(0,1,0), -2}; (0,5,0) is 3 above it.
  const snell::Plane water{glm::vec3(0.0f, 1.0f, 0.0f), -2.0f};
  const float distance = snell::signed_distance(water, glm::vec3(0.0f, 5.0f, 0.0f));
  check(std::fabs(distance - 3.0f) <= 1e-6f, "signed_distance(y = 2, (0,5,0)) == 3");

  const glm::mat4 mirror = snell::reflection_matrix(water);
  check(std::fabs(glm::determinant(mirror) + 1.0f) <= 1e-6f, "det(reflection_matrix) == -1");

  const glm::vec4 mirrored = mirror * glm::vec4(0.0f, 5.0f, 0.0f, 1.0f);
  check(glm::all(glm::lessThanEqual(glm::abs(mirrored - glm::vec4(0.0f, -1.0f, 0.0f, 1.0f)),
                                    glm::vec4(1e-5f))),
        "reflection_matrix maps (0,5,0) to (0,-1,0)");

  return failures == 0 ? 0 : 1;
}
