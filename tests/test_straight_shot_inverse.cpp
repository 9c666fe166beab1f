// Tests of the inverse problem (src/physics/straight_shot_inverse.cpp): paper 001 eqs 25-28 and the
// variants, checked by rolling every plan forward with the closed-form motion.
#include "cueball/physics/straight_shot_inverse.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "cueball/physics/cloth_motion.hpp"
#include "cueball/core/errors.hpp"

namespace cueball {
namespace {

// Roll the plan forward from x0 and check it passes x2 at v2 at t2, with
// sliding ending at (t1, x1, v1).
void expect_plan_reaches_target(const ShotPlan& plan, const ShotTarget& target, const Parameters& p) {
  const BallState start{{target.x0, 0.0}, {plan.v0, 0.0}, {0.0, plan.w0, 0.0}};
  const BallState at_t2 = evolve(start, plan.t2, p);
  EXPECT_NEAR(at_t2.position.x, target.x2, 1e-9) << "x2";
  EXPECT_NEAR(at_t2.velocity.x, target.v2, 1e-9) << "v2";
  const BallState at_t1 = evolve(start, plan.t1, p);
  EXPECT_NEAR(at_t1.position.x, plan.x1, 1e-9) << "x1";
  EXPECT_NEAR(at_t1.velocity.x, plan.v1, 1e-9) << "v1";
  EXPECT_NE(motion_phase(at_t1, p), MotionPhase::sliding);
  if (plan.t1 > 1e-9) {
    EXPECT_EQ(motion_phase(evolve(start, 0.999 * plan.t1, p), p), MotionPhase::sliding);
  }
  // Validity, paper 001: v0 >= R w0 >= -5/2 v0.
  const double rw = p.ball.radius * plan.w0;
  EXPECT_GE(plan.v0 + 1e-12, rw);
  EXPECT_GE(rw + 1e-12, -2.5 * plan.v0);
}

std::string failed_condition(const std::function<void()>& f) {
  try {
    f();
  } catch (const InfeasibleShot& e) {
    return e.condition();
  }
  return "feasible";
}

std::string invalid_field(const std::function<void()>& f) {
  try {
    f();
  } catch (const InvalidArgument& e) {
    return e.field();
  }
  return "accepted";
}

TEST(Planner, PaperInverseProblemRoundTripsOverAGridOfTargets) {
  int checked = 0;
  for (const Parameters& p : {snooker_parameters(), pool_parameters()}) {
    for (double x0 : {0.0, -0.4, 1.0}) {
      for (double slide : {0.0, 0.01, 0.1, 0.4, 1.0}) {
        for (double roll : {0.0, 0.05, 0.5, 1.5, 3.0}) {
          for (double v2 : {0.0, 0.1, 0.5, 1.5}) {
            const ShotTarget target{x0, x0 + slide + roll, v2};
            if (slide + roll == 0.0 && v2 == 0.0) continue;
            const ShotPlan plan = plan_shot_with_slide_end(target, x0 + slide, p);
            EXPECT_EQ(plan.variant, PlanVariant::given_slide_end);
            EXPECT_NEAR(plan.x1, x0 + slide, 1e-12);
            SCOPED_TRACE("x0 " + std::to_string(x0) + " slide " + std::to_string(slide) + " roll " +
                         std::to_string(roll) + " v2 " + std::to_string(v2));
            expect_plan_reaches_target(plan, target, p);
            ++checked;
          }
        }
      }
    }
  }
  EXPECT_GT(checked, 500);
}

TEST(Planner, PaperEquations25To28HoldForTheReturnedPlan) {
  const Parameters p = snooker_parameters();
  const double mu_s_g = p.cloth.sliding_friction * p.cloth.gravity;
  const double mu_r_g = p.cloth.rolling_resistance * p.cloth.gravity;
  const ShotTarget target{0.0, 1.8, 0.3};
  const double x1 = 0.25;
  const ShotPlan plan = plan_shot_with_slide_end(target, x1, p);
  const double n = std::sqrt(70 * mu_r_g * (target.x2 - x1) + 49 * target.v2 * target.v2);  // (25)
  const double z = (-n + std::sqrt(n * n + 98 * (x1 - target.x0) * mu_s_g)) / 2;            // (26)
  EXPECT_NEAR(plan.v0, (n + 2 * z) / 7, 1e-12);                                              // (27)
  EXPECT_NEAR(plan.w0, (n - 5 * z) / (7 * p.ball.radius), 1e-10);                            // (28)
  EXPECT_NEAR(plan.v0 - p.ball.radius * plan.w0, z, 1e-12);                                  // (17)
  EXPECT_NEAR(5 * plan.v0 + 2 * p.ball.radius * plan.w0, n, 1e-12);                          // (18)
  EXPECT_NEAR(z * z + n * z - 24.5 * (x1 - target.x0) * mu_s_g, 0.0, 1e-12);                 // (26) itself
}

TEST(Planner, NaturalRollStartsRollingAndReachesTheTarget) {
  for (const Parameters& p : {snooker_parameters(), pool_parameters()}) {
    for (double d : {0.05, 0.7, 2.5}) {
      for (double v2 : {0.0, 0.4}) {
        const ShotTarget target{0.2, 0.2 + d, v2};
        const ShotPlan plan = plan_natural_roll_shot(target, p);
        EXPECT_EQ(plan.variant, PlanVariant::natural_roll);
        EXPECT_NEAR(p.ball.radius * plan.w0, plan.v0, 1e-14);
        EXPECT_EQ(plan.t1, 0.0);
        EXPECT_EQ(plan.x1, target.x0);
        expect_plan_reaches_target(plan, target, p);
        // The same as the paper's problem with x1 = x0.
        const ShotPlan paper = plan_shot_with_slide_end(target, target.x0, p);
        EXPECT_NEAR(paper.v0, plan.v0, 1e-14);
        EXPECT_NEAR(paper.w0, plan.w0, 1e-12);
      }
    }
  }
}

TEST(Planner, GivenSpinReturnsThatSpinAndReachesTheTarget) {
  int checked = 0;
  for (const Parameters& p : {snooker_parameters(), pool_parameters()}) {
    for (double w0 : {-120.0, -60.0, -10.0, 0.0, 10.0, 30.0}) {
      for (double d : {0.3, 1.0, 2.5}) {
        for (double v2 : {0.0, 0.3}) {
          const ShotTarget target{0.0, d, v2};
          ShotPlan plan{};
          try {
            plan = plan_shot_with_spin(target, w0, p);
          } catch (const InfeasibleShot&) {
            continue;  // each infeasible case is covered by the condition tests
          }
          EXPECT_EQ(plan.variant, PlanVariant::given_spin);
          EXPECT_NEAR(plan.w0, w0, 1e-9 * (1 + std::abs(w0)));
          SCOPED_TRACE("w0 " + std::to_string(w0) + " d " + std::to_string(d));
          expect_plan_reaches_target(plan, target, p);
          // Consistent with the paper's problem at the x1 it found.
          const ShotPlan paper = plan_shot_with_slide_end(target, plan.x1, p);
          EXPECT_NEAR(paper.v0, plan.v0, 1e-9);
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 50);
}

TEST(Planner, GivenSpeedReturnsThatSpeedAndReachesTheTarget) {
  int checked = 0;
  for (const Parameters& p : {snooker_parameters(), pool_parameters()}) {
    const double d = 1.2;
    const double natural = plan_natural_roll_shot({0.0, d, 0.0}, p).v0;
    for (double factor : {1.0, 1.05, 1.3, 2.0, 3.0}) {
      const ShotTarget target{0.0, d, 0.0};
      ShotPlan plan{};
      try {
        plan = plan_shot_with_speed(target, natural * factor, p);
      } catch (const InfeasibleShot&) {
        continue;
      }
      EXPECT_EQ(plan.variant, PlanVariant::given_speed);
      EXPECT_NEAR(plan.v0, natural * factor, 1e-12);
      if (factor > 1.0) {
        EXPECT_LT(plan.w0, plan.v0 / p.ball.radius) << "faster than natural roll needs less topspin";
      }
      expect_plan_reaches_target(plan, target, p);
      ++checked;
    }
  }
  EXPECT_GE(checked, 6);
}

TEST(Planner, EachValidityConditionProducesItsError) {
  const Parameters p = snooker_parameters();
  EXPECT_EQ(failed_condition([&] { plan_shot_with_slide_end({0.0, 1.0, 0.0}, -0.1, p); }), "x1 >= x0");
  EXPECT_EQ(failed_condition([&] { plan_shot_with_slide_end({0.0, 1.0, 0.0}, 1.2, p); }), "x2 >= x1");
  EXPECT_EQ(failed_condition([&] { plan_shot_with_slide_end({0.0, 1.0, -0.2}, 0.2, p); }), "v2 >= 0");
  EXPECT_EQ(failed_condition([&] { plan_shot_with_slide_end({0.5, 0.5, 0.0}, 0.5, p); }), "x2 > x0 or v2 > 0");
  EXPECT_EQ(failed_condition([&] { plan_natural_roll_shot({0.5, 0.2, 0.0}, p); }), "x2 >= x0");
  // Given spin: far more topspin than natural roll over a short distance.
  EXPECT_EQ(failed_condition([&] { plan_shot_with_spin({0.0, 0.3, 0.0}, 400.0, p); }), "x1 >= x0");
  // Given spin: strong draw that must still be fast at a near point.
  EXPECT_EQ(failed_condition([&] { plan_shot_with_spin({0.0, 0.02, 2.0}, -300.0, p); }), "x2 >= x1");
  // Given speed: too slow even rolling; too fast even with the most draw.
  EXPECT_EQ(failed_condition([&] { plan_shot_with_speed({0.0, 3.0, 0.0}, 0.5, p); }), "x1 >= x0");
  EXPECT_EQ(failed_condition([&] { plan_shot_with_speed({0.0, 0.05, 0.0}, 6.0, p); }), "x2 >= x1");
  EXPECT_EQ(failed_condition([&] { plan_shot_with_speed({0.0, 1.0, 1.0}, 0.5, p); }), "v0 >= v2");
}

TEST(Planner, InfeasibleErrorsExplainThemselves) {
  const Parameters p = snooker_parameters();
  try {
    plan_shot_with_slide_end({0.0, 1.0, 0.0}, 1.2, p);
    FAIL() << "expected InfeasibleShot";
  } catch (const InfeasibleShot& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("x2 >= x1"), std::string::npos) << what;
    EXPECT_NE(what.find("1.2"), std::string::npos) << what;
  }
}

TEST(Planner, BoundariesOfTheValidRangeAreFeasible) {
  const Parameters p = pool_parameters();
  // Z = 0 exactly (natural roll) and N = 0 exactly (a stop shot ending at x1 = x2).
  const ShotPlan stop = plan_shot_with_slide_end({0.0, 0.3, 0.0}, 0.3, p);
  EXPECT_NEAR(p.ball.radius * stop.w0, -2.5 * stop.v0, 1e-12);
  EXPECT_NEAR(stop.v1, 0.0, 1e-15);
  expect_plan_reaches_target(stop, {0.0, 0.3, 0.0}, p);
}

TEST(Planner, NonFiniteInputsAreRejectedNamingTheField) {
  const Parameters p = snooker_parameters();
  const double nan = std::nan("");
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(invalid_field([&] { plan_natural_roll_shot({nan, 1.0, 0.0}, p); }), "x0");
  EXPECT_EQ(invalid_field([&] { plan_natural_roll_shot({0.0, inf, 0.0}, p); }), "x2");
  EXPECT_EQ(invalid_field([&] { plan_natural_roll_shot({0.0, 1.0, nan}, p); }), "v2");
  EXPECT_EQ(invalid_field([&] { plan_shot_with_slide_end({0.0, 1.0, 0.0}, nan, p); }), "x1");
  EXPECT_EQ(invalid_field([&] { plan_shot_with_spin({0.0, 1.0, 0.0}, inf, p); }), "w0");
  EXPECT_EQ(invalid_field([&] { plan_shot_with_speed({0.0, 1.0, 0.0}, -1.0, p); }), "v0");
  Parameters bad = p;
  bad.ball.mass = -0.1;
  EXPECT_EQ(invalid_field([&] { plan_natural_roll_shot({0.0, 1.0, 0.0}, bad); }), "mass");
}

TEST(Planner, PositionsBeyondAKilometreAreRejectedAsTheCliDoes) {
  const Parameters p = snooker_parameters();
  EXPECT_EQ(invalid_field([&] { plan_natural_roll_shot({0.0, 1e9, 0.0}, p); }), "x2");
  EXPECT_EQ(invalid_field([&] { plan_natural_roll_shot({-1e4, 1.0, 0.0}, p); }), "x0");
  EXPECT_EQ(invalid_field([&] { plan_shot_with_slide_end({0.0, 1.0, 0.0}, 2e3, p); }), "x1");
  EXPECT_NO_THROW(plan_natural_roll_shot({-1000.0, 1000.0, 0.0}, pool_parameters()));
}

TEST(Planner, PlansBeyondTheSpeedCapNameTheInputThatAsksForThem) {
  // Once plan_natural_roll_shot(x2 = 1e9) returned v0 = 15,811 m/s without a word.
  const Parameters p = snooker_parameters();
  try {
    plan_natural_roll_shot({0.0, 999.0, 29.0}, p);
    ADD_FAILURE() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.field(), "x2");
    const std::string m = e.what();
    EXPECT_NE(m.find("v0 <= 30 m/s"), std::string::npos) << m;
    EXPECT_NE(m.find("x2 at most"), std::string::npos) << m;
  }
  EXPECT_EQ(invalid_field([&] { plan_shot_with_spin({0.0, 999.0, 29.0}, 0.0, p); }), "x2");
  // A plan at the cap is fine; every plan returned is within the caps.
  const ShotPlan fast = plan_natural_roll_shot({0.0, 100.0, 25.0}, p);
  EXPECT_LE(fast.v0, kMaxSpeed);
}

}  // namespace
}  // namespace cueball
