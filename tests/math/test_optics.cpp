#include "test_support.hpp"

#include <glm/gtc/constants.hpp>

using namespace snell;
using snell::test::near;

TEST_CASE("named indices of refraction") {
  CHECK(ior::vacuum == 1.0f);
  CHECK(ior::air == doctest::Approx(1.000293f));
  CHECK(ior::water == doctest::Approx(1.333f));
  CHECK(ior::ice == doctest::Approx(1.31f));
  CHECK(ior::glass == doctest::Approx(1.5f));
  CHECK(ior::diamond == doctest::Approx(2.417f));
}

TEST_CASE("refract obeys Snell's law and stays in the plane of incidence") {
  test::Random rng(50);
  int refracted = 0;
  for (int i = 0; i < 10000; ++i) {
    const float n1 = rng.uniform(1.0f, 2.5f);
    const float n2 = rng.uniform(1.0f, 2.5f);
    const glm::vec3 normal = rng.unit();
    glm::vec3 incident = rng.unit();
    if (glm::dot(incident, normal) > 0.0f) {
      incident = -incident;
    }
    const float cos1 = -glm::dot(incident, normal);
    if (cos1 < 1e-3f) {
      continue;
    }
    const auto t = refract(incident, normal, n1 / n2);
    const float sin1 = std::sqrt(std::max(0.0f, 1.0f - cos1 * cos1));
    if (n1 * sin1 > n2 * 1.0001f) {
      CHECK_FALSE(t.has_value()); // beyond the critical angle
      continue;
    }
    if (!t) {
      CHECK(n1 * sin1 >= n2 * 0.9999f);
      continue;
    }
    ++refracted;
    CHECK(glm::length(*t) == doctest::Approx(1.0f).epsilon(1e-4));
    const float cos2 = -glm::dot(*t, normal);
    CHECK(cos2 >= -1e-6f); // transmitted into the other side
    const float sin2 = std::sqrt(std::max(0.0f, 1.0f - cos2 * cos2));
    CHECK(near(n1 * sin1, n2 * sin2, 2e-3f));
    // Coplanar: t lies in the plane spanned by incident and normal.
    CHECK(std::fabs(glm::dot(*t, glm::normalize(glm::cross(incident, normal)))) < 1e-3f);
  }
  CHECK(refracted > 7000);
}

TEST_CASE("refract at normal incidence passes straight through, and eta 1 changes nothing") {
  const auto t = refract({0, -1, 0}, {0, 1, 0}, 1.0f / 1.5f);
  REQUIRE(t.has_value());
  CHECK(near(*t, {0, -1, 0}, 1e-6f));
  const glm::vec3 d = glm::normalize(glm::vec3(1, -2, 0.5f));
  CHECK(near(refract(d, {0, 1, 0}, 1.0f).value(), d, 1e-6f));
}

TEST_CASE("total internal reflection exactly past the critical angle") {
  struct Medium {
    float n;
    float critical_degrees;
  };
  for (const Medium m : {Medium{ior::water, 48.6066f}, Medium{ior::glass, 41.8103f}}) {
    CAPTURE(m.n);
    const float crit = critical_angle(m.n, 1.0f);
    CHECK(glm::degrees(crit) == doctest::Approx(m.critical_degrees).epsilon(1e-4));
    const glm::vec3 normal(0, 1, 0);
    // Leaving the denser medium (eta = n / 1 > 1), going up through the surface from below:
    // the normal facing the incident side points down.
    for (const float delta_deg : {-0.05f, 0.05f}) {
      const float theta = crit + glm::radians(delta_deg);
      const glm::vec3 incident(std::sin(theta), std::cos(theta), 0.0f);
      const auto t = refract(incident, -normal, m.n);
      CHECK(t.has_value() == (delta_deg < 0.0f));
      CHECK((fresnel_dielectric(std::cos(theta), m.n) == 1.0f) == (delta_deg > 0.0f));
    }
  }
  CHECK(critical_angle(1.0f, 1.5f) == doctest::Approx(glm::half_pi<float>()));
  CHECK(critical_angle(1.5f, 1.5f) == doctest::Approx(glm::half_pi<float>()));
}

TEST_CASE("fresnel_dielectric: reference values air to glass") {
  const float eta = 1.0f / 1.5f;
  CHECK(fresnel_dielectric(1.0f, eta) == doctest::Approx(0.04f).epsilon(1e-5));
  CHECK(fresnel_dielectric(0.5f, eta) == doctest::Approx(0.0891867f).epsilon(1e-5));
  CHECK(fresnel_dielectric(0.1f, eta) == doctest::Approx(0.5715925f).epsilon(1e-5));
  CHECK(fresnel_dielectric(0.0f, eta) == doctest::Approx(1.0f));
  CHECK(fresnel_dielectric(-0.5f, eta) == fresnel_dielectric(0.5f, eta)); // either normal side
  CHECK(fresnel_dielectric(2.0f, eta) == fresnel_dielectric(1.0f, eta));  // clamped
  CHECK(fresnel_dielectric(0.3f, 1.0f) == 0.0f);
  CHECK(f0_from_ior(1.0f, 1.5f) == doctest::Approx(0.04f));
  CHECK(f0_from_ior(1.5f, 1.0f) == doctest::Approx(0.04f));
  CHECK(f0_from_ior(1.0f, ior::water) == doctest::Approx(0.02037f).epsilon(1e-3));
}

TEST_CASE("fresnel_dielectric is symmetric under swapping media below the critical angle") {
  test::Random rng(51);
  for (int i = 0; i < 5000; ++i) {
    const float n1 = rng.uniform(1.0f, 2.5f);
    const float n2 = rng.uniform(1.0f, 2.5f);
    // Near grazing on the dense side the reflectance is ill-conditioned in float (cos_t^2 is a
    // difference of nearly equal numbers), so stay 1 degree away from 90.
    const float cos1 = rng.uniform(0.0175f, 1.0f);
    // The transmitted angle in double, so the test's own rounding does not dominate near grazing.
    const double sin1 = std::sqrt(1.0 - double(cos1) * cos1);
    const double sin2 = double(n1) / n2 * sin1;
    if (sin2 >= 0.9998) {
      CHECK(fresnel_dielectric(cos1, n1 / n2) >= (sin2 >= 1.0 ? 1.0f : 0.0f));
      continue;
    }
    const float cos2 = static_cast<float>(std::sqrt(1.0 - sin2 * sin2));
    const float forward = fresnel_dielectric(cos1, n1 / n2);
    const float backward = fresnel_dielectric(cos2, n2 / n1);
    // Near the critical angle cos2 -> 0 and the curve is steep; float error in cos2 grows.
    CAPTURE(n1);
    CAPTURE(n2);
    CAPTURE(cos1);
    CHECK(near(forward, backward, 1e-4f));
    CHECK(forward >= 0.0f);
    CHECK(forward <= 1.0f);
  }
}

TEST_CASE("fresnel_dielectric is monotonic in the angle and 1 under TIR") {
  for (const float eta : {1.0f / 1.5f, 1.0f / 1.333f, 1.333f, 1.5f}) {
    float previous = 2.0f;
    for (int i = 0; i <= 1000; ++i) {
      const float r = fresnel_dielectric(static_cast<float>(i) / 1000.0f, eta);
      CHECK(r <= previous + 1e-6f);
      previous = r;
    }
  }
  CHECK(fresnel_dielectric(0.2f, 1.5f) == 1.0f);
}

TEST_CASE("Schlick stays within its known error of the exact curve (air to glass, water)") {
  // Schlick's approximation, entering the denser medium, peaks in absolute error near grazing
  // incidence: 0.0592 at 83.8 degrees for water and 0.0357 at 85.0 degrees for glass (computed
  // independently in double precision, 100,001 samples; see docs/math.md). The bounds below add
  // a little margin for float evaluation.
  struct Case {
    float n2, bound;
  };
  for (const auto [n2, bound] : {Case{ior::water, 0.0600f}, Case{ior::glass, 0.0365f}}) {
    const float f0 = f0_from_ior(1.0f, n2);
    float max_err = 0.0f;
    for (int i = 0; i <= 1000; ++i) {
      const float c = static_cast<float>(i) / 1000.0f;
      max_err =
          std::max(max_err, std::fabs(fresnel_schlick(c, f0) - fresnel_dielectric(c, 1.0f / n2)));
    }
    CAPTURE(n2);
    CHECK(max_err < bound);
    CHECK(max_err > bound - 0.002f); // it is an approximation, not the exact curve
  }
  CHECK(fresnel_schlick(1.0f, 0.04f) == doctest::Approx(0.04f));
  CHECK(fresnel_schlick(0.0f, 0.04f) == doctest::Approx(1.0f));
}

TEST_CASE("slab_lateral_shift: reference values, ray tracing through both faces, limits") {
  // t sin(ti - tt) / cos(tt) for glass (1.5) in air, t = 1: 30 deg -> 0.193814, 60 deg -> 0.512472
  // (computed separately in double precision).
  const float eta = 1.0f / snell::ior::glass; // outside n = 1 (ior::air is 1.000293)
  CHECK(snell::slab_lateral_shift(1.0f, std::cos(glm::radians(30.0f)), eta).value() ==
        doctest::Approx(0.193814).epsilon(1e-4));
  CHECK(snell::slab_lateral_shift(1.0f, std::cos(glm::radians(60.0f)), eta).value() ==
        doctest::Approx(0.512472).epsilon(1e-4));
  CHECK(snell::slab_lateral_shift(2.0f, 1.0f, eta).value() == doctest::Approx(0.0));
  CHECK(snell::slab_lateral_shift(2.0f, 0.5f, 1.0f).value() == doctest::Approx(0.0));
  // Grazing incidence from air: the shift tends to the thickness.
  CHECK(snell::slab_lateral_shift(1.0f, 1e-6f, eta).value() == doctest::Approx(1.0).epsilon(1e-3));
  // From the denser side beyond the critical angle nothing crosses.
  CHECK_FALSE(snell::slab_lateral_shift(1.0f, std::cos(glm::radians(60.0f)), 1.5f).has_value());
  // Independent check: trace through the entry face z = 0 and the exit face z = -t with
  // refract(), then measure the distance between the incident line and the exit line.
  float previous = -1.0f;
  for (int deg = 0; deg <= 85; deg += 5) {
    const float a = glm::radians(static_cast<float>(deg));
    const glm::vec3 dir(std::sin(a), 0.0f, -std::cos(a));
    const glm::vec3 normal(0.0f, 0.0f, 1.0f);
    const float t = 0.7f;
    const glm::vec3 inside = snell::refract(dir, normal, eta).value();
    const glm::vec3 exit = inside * (t / -inside.z); // from the origin to z = -t
    const glm::vec3 out = snell::refract(inside, normal, 1.0f / eta).value();
    CHECK(glm::length(out - dir) < 1e-5f); // leaves parallel to where it came from
    const glm::vec3 across = exit - dir * glm::dot(exit, dir);
    const float shift = snell::slab_lateral_shift(t, std::cos(a), eta).value();
    CHECK(shift == doctest::Approx(glm::length(across)).epsilon(1e-4));
    CHECK(shift >= previous); // grows with the angle
    previous = shift;
  }
}

// Fails if the spread or its sign is off: BK7 (n_d 1.5168, Abbe number 64.17) has n_F - n_C =
// 0.00806 (Schott: n_F 1.52238, n_C 1.51432); red bends less than blue.
TEST_CASE("dispersion_iors: KHR_materials_dispersion's spread, BK7 reference") {
  const glm::vec3 n = snell::dispersion_iors(1.5168f, 20.0f / 64.17f);
  CHECK(n.g == 1.5168f);
  CHECK(n.b - n.r == doctest::Approx(0.00806).epsilon(0.01));
  CHECK(n.r < n.g);
  CHECK(n.g < n.b);
  CHECK(snell::dispersion_iors(1.5f, 0.0f) == glm::vec3(1.5f));
  CHECK(snell::dispersion_iors(1.0f, 1.0f) == glm::vec3(1.0f)); // vacuum does not disperse
}
