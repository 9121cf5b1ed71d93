// Eq. (3)-(4): the closed-form line process minimizes z s + Psi(z) and gives rho.
#include "energy/geman_mcclure.h"

#include <gtest/gtest.h>

namespace lpd::energy {
namespace {

TEST(GemanMcClure, OptimalLineProcessBeatsDenseGridAndEqualsRho) {
  for (double mu : {5e-9, 1e-3, 0.13, 2.0}) {
    const GemanMcClure penalty(mu);
    for (double s : {0.0, 1e-10, 1e-6, 1e-3, 0.1, 1.0, 50.0}) {
      const double z_star = penalty.OptimalLineProcess(s);
      ASSERT_GE(z_star, 0.0);
      ASSERT_LE(z_star, 1.0);
      const double best = penalty.LineProcessCost(s, z_star);
      for (int g = 0; g <= 20000; ++g) {
        const double z = g / 20000.0;
        EXPECT_LE(best, penalty.LineProcessCost(s, z) + 1e-15 * (1.0 + s))
            << "mu " << mu << " s " << s << " z " << z;
      }
      // Eq. (3): inf_z z s + Psi(z) = rho(s), and rho(s) = s / (1 + s / mu) by hand.
      EXPECT_NEAR(best, s / (1.0 + s / mu), 1e-12 * (1.0 + s));
      EXPECT_NEAR(penalty.Rho(s), s / (1.0 + s / mu), 1e-15 * (1.0 + s));
    }
  }
}

TEST(GemanMcClure, PenaltyValuesByHand) {
  const GemanMcClure penalty(0.5);
  EXPECT_DOUBLE_EQ(penalty.Penalty(1.0), 0.0);
  EXPECT_DOUBLE_EQ(penalty.Penalty(0.0), 0.5);
  EXPECT_DOUBLE_EQ(penalty.Penalty(0.25), 0.5 * 0.25);
  EXPECT_DOUBLE_EQ(penalty.OptimalLineProcess(0.5), 0.25);
}

}  // namespace
}  // namespace lpd::energy
