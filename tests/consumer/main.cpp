// Plans a shot and checks that rolling it forward reaches the target.
#include <cmath>
#include <cstdio>

#include <cueball/cloth_motion.hpp>
#include <cueball/planner.hpp>

int main() {
  const cueball::Parameters p = cueball::pool_parameters();
  const cueball::ShotPlan plan = cueball::plan_natural_roll_shot({0.0, 1.2, 0.0}, p);
  const cueball::StraightShot shot = cueball::straight_shot(plan.v0, plan.w0, 0.0, p);
  std::printf("v0 = %.6f m/s reaches x2 = %.9f m\n", plan.v0, shot.x2);
  return std::abs(shot.x2 - 1.2) < 1e-9 ? 0 : 1;
}
