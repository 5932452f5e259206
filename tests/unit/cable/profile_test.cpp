// Profiles along the cable and the mirror method (MODEL.md section 2).

#include <cmath>

#include <gtest/gtest.h>

#include "stockbridge/cable/cable.hpp"
#include "stockbridge/cable/masing_cable_law.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/numerics/gauss_legendre.hpp"

namespace stockbridge::cable {
namespace {

TEST(Profile, PiecewiseLinearAndHeldBeyondTheEnds) {
  const Profile p = Profile::table({0.0, 0.1, 0.3}, {3.0, 2.0, 2.5}, "ei");
  EXPECT_DOUBLE_EQ(p.at(0.0), 3.0);
  EXPECT_DOUBLE_EQ(p.at(0.05), 2.5);
  EXPECT_DOUBLE_EQ(p.at(0.2), 2.25);
  EXPECT_DOUBLE_EQ(p.at(0.5), 2.5);
  EXPECT_DOUBLE_EQ(p.min_value(), 2.0);
  EXPECT_THROW(Profile::table({0.0, 0.1, 0.1}, {1, 2, 3}, "ei"), InvalidParameter);
  EXPECT_THROW(Profile::table({0.0, 0.1}, {1}, "ei"), InvalidParameter);
  EXPECT_THROW(Profile::table({-0.1, 0.1}, {1, 2}, "ei"), InvalidParameter);
}

// The mirrored profile is symmetric about the middle and equals the identified
// one on the first half.
TEST(Profile, MirrorMethod) {
  CableDescription d = CableDescription::uniform(0.1875, 41, 1.0, {{20.0, 0.7}});
  d.ei = Profile::table({0.0, 0.05, 0.3}, {3.5, 2.8, 2.0}, "ei");
  d.jenkin[0].h = Profile::table({0.0, 0.3}, {0.9, 0.5}, "h");
  d.mirror_length = 0.3;
  const Cable cable(d);
  const auto& law = dynamic_cast<const MasingCableLaw&>(cable.law());
  const std::size_t n = cable.sections();
  for (std::size_t i = 0; i < n; ++i) {
    const double s = cable.positions()[i];
    EXPECT_NEAR(law.ei(i), law.ei(n - 1 - i), 1e-12) << "symmetric at s = " << s;
    EXPECT_NEAR(law.jenkin(i)[0].h, law.jenkin(n - 1 - i)[0].h, 1e-12);
    if (s <= 0.1875 / 2) {
      EXPECT_DOUBLE_EQ(law.ei(i), d.ei.at(s)) << "identified on the first half, s = " << s;
      EXPECT_DOUBLE_EQ(law.jenkin(i)[0].h, d.jenkin[0].h.at(s));
    }
  }
  d.length = 0.61;  // longer than twice the identified cable
  EXPECT_THROW(Cable{d}, InvalidParameter);
}

TEST(GaussLegendre, IntegratesPolynomialsExactly) {
  for (const int n : {1, 2, 5, 40}) {
    const auto rule = numerics::gauss_legendre(n, 0.0, 0.3);
    for (int degree = 0; degree <= 2 * n - 1 && degree < 30; ++degree) {
      double sum = 0.0;
      for (int i = 0; i < n; ++i) sum += rule.weights[i] * std::pow(rule.nodes[i], degree);
      const double exact = std::pow(0.3, degree + 1) / (degree + 1);
      EXPECT_NEAR(sum, exact, 1e-14 * std::max(exact, 1e-3)) << "n = " << n << ", degree " << degree;
    }
  }
}

}  // namespace
}  // namespace stockbridge::cable
