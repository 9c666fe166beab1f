// Simultaneous impacts of touching clusters (contact_cluster.hpp), alone and
// in the simulator: restitution of a pair, Newton's cradle, the Hertz break
// of a perfect 15-ball rack, momentum, energy, index order, mirror images.
#include "cueball/simulation/contact_cluster.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <vector>

#include "cueball/io/scenario_json.hpp"
#include "cueball/simulation/scenario.hpp"
#include "cueball/simulation/simulator.hpp"
#include "cueball/table/rack.hpp"
#include "simulation_checks.hpp"
#include "test_support.hpp"

namespace cueball {
namespace {

constexpr double kR = 0.028575;

struct Cluster {
  std::vector<Vec2> positions, velocities;
  std::vector<ClusterContact> contacts;
};

// Every touching pair of the positions.
std::vector<ClusterContact> touching(const std::vector<Vec2>& p) {
  std::vector<ClusterContact> c;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      if (norm(p[j] - p[i]) < 2 * kR + 1e-9) c.push_back({i, j});
  return c;
}

// A frozen triangle of `rows` rows, apex at the origin pointing to -x, and a
// cue ball touching the apex moving at +speed along x.
Cluster struck_triangle(int rows, double speed) {
  Cluster c;
  c.positions.push_back({-2 * kR, 0.0});
  c.velocities.push_back({speed, 0.0});
  for (int row = 0; row < rows; ++row)
    for (int k = 0; k <= row; ++k) {
      c.positions.push_back({row * std::sqrt(3.0) * kR, (2 * k - row) * kR});
      c.velocities.push_back({});
    }
  c.contacts = touching(c.positions);
  return c;
}

ClusterSettings with_restitution(double e) {
  ClusterSettings s;
  s.restitution = e;
  s.stiffness = hertz_stiffness_per_mass(pool_parameters().ball);
  return s;
}

ClusterImpact solve(const Cluster& c, double e) { return resolve_cluster_impact(c.positions, c.velocities, c.contacts, with_restitution(e)); }

Vec2 momentum(const std::vector<Vec2>& v) { return std::accumulate(v.begin(), v.end(), Vec2{}); }
double energy(const std::vector<Vec2>& v) {
  double s = 0.0;
  for (Vec2 u : v) s += dot(u, u);
  return s;
}

TEST(ContactCluster, OnePairPartsWithNewtonsRestitution) {
  for (double e : {0.0, 0.5, 0.93, 1.0}) {
    Cluster c{{{0, 0}, {2 * kR, 0}}, {{3.0, 0.4}, {-1.0, 0.0}}, {{0, 1}}};
    const ClusterImpact r = solve(c, e);
    // Along the line of centres: closing 4 m/s leaves at 4 e; across it nothing changes.
    // (e = 0 is taken as 0.01.)
    EXPECT_NEAR(r.velocities[1].x - r.velocities[0].x, 4.0 * std::max(e, 0.01), 4e-3) << "e = " << e;
    EXPECT_EQ(r.velocities[0].y, 0.4);
    EXPECT_EQ(r.velocities[1].y, 0.0);
    EXPECT_NEAR(momentum(r.velocities).x, 2.0, 1e-14);
    EXPECT_NEAR(r.impulses[0], 2.0 * (1 + std::max(e, 0.01)), 1e-2);  // (1 + e) v / 2 per unit mass
  }
}

TEST(ContactCluster, NothingClosingChangesNothing) {
  Cluster c{{{0, 0}, {2 * kR, 0}, {4 * kR, 0}}, {{-1.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}}, {{0, 1}, {1, 2}}};
  const ClusterImpact r = solve(c, 0.9);
  EXPECT_EQ(r.steps, 0);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(r.velocities[i], c.velocities[i]);
}

// Newton's cradle: a ball into a line of four. With Hertz contacts the last
// ball leaves with nearly everything and the others keep a small remainder
// (Hinch & Saint-Jean 1999; Ceanga & Hurmuzlu 2001).
TEST(ContactCluster, NewtonsCradleSendsTheLastBallOff) {
  Cluster c;
  for (int k = 0; k < 5; ++k) {
    c.positions.push_back({2 * kR * k, 0.0});
    c.velocities.push_back({k == 0 ? 2.0 : 0.0, 0.0});
  }
  c.contacts = touching(c.positions);
  const ClusterImpact r = solve(c, 1.0);
  EXPECT_GT(r.velocities[4].x, 0.9 * 2.0);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_LT(std::abs(r.velocities[k].x), 0.2 * 2.0) << k;
  // Every ball leaves no faster than the one ahead of it: nothing closes again.
  for (std::size_t k = 0; k + 1 < 5; ++k) EXPECT_LE(r.velocities[k].x, r.velocities[k + 1].x);
  EXPECT_NEAR(momentum(r.velocities).x, 2.0, 1e-13);
  EXPECT_NEAR(energy(r.velocities), 4.0, 1e-3);
  EXPECT_LE(energy(r.velocities), 4.0);
}

// The perfectly centred break of a perfect 15-ball rack with elastic Hertz
// springs (contact_cluster.hpp [3]: the cue ball at 10, speeds after:
// cue 1.79 and the 1 1.20 back, the back corners 5.60, the back row's
// centre 2.63, its other two 2.57). Their integration moves the balls
// (overlaps under 0.025 % of R); ours freezes the geometry.
TEST(ContactCluster, PerfectFifteenBallBreakMatchesTheHertzIntegration) {
  const Cluster c = struck_triangle(5, 10.0);
  const ClusterImpact r = solve(c, 1.0);
  const auto speed = [&](std::size_t k) { return norm(r.velocities[k]); };
  // Ranks: 0 cue, 1 apex, rows 2-3, 4-6, 7-10, 11-15.
  EXPECT_NEAR(speed(0), 1.79, 0.03);
  EXPECT_LT(r.velocities[0].x, 0.0);
  EXPECT_NEAR(speed(1), 1.20, 0.03);
  EXPECT_NEAR(speed(11), 5.60, 0.03);
  EXPECT_NEAR(speed(15), 5.60, 0.03);
  EXPECT_NEAR(speed(13), 2.63, 0.03);
  EXPECT_NEAR(speed(12), 2.57, 0.03);
  // The back corners leave 30 degrees off the line of the break.
  EXPECT_NEAR(std::atan2(std::abs(r.velocities[11].y), r.velocities[11].x) * 180 / std::numbers::pi, 30.0, 0.5);
  EXPECT_NEAR(momentum(r.velocities).x, 10.0, 1e-12);
  EXPECT_NEAR(momentum(r.velocities).y, 0.0, 1e-12);
  EXPECT_LE(energy(r.velocities), 100.0);
  EXPECT_NEAR(energy(r.velocities), 100.0, 0.1);
}

// Random velocities on a frozen lattice, with restitution below 1: momentum
// to rounding, energy never up, nothing left closing.
TEST(ContactCluster, MomentumKeptEnergyNeverRisesNothingClosing) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (double e : {0.0, 0.1, 0.6, 0.95, 1.0})
    for (int trial = 0; trial < 20; ++trial) {
      Cluster c = struck_triangle(4, 5.0);
      for (Vec2& v : c.velocities) v = {u(rng), u(rng)};
      const ClusterImpact r = solve(c, e);
      const Vec2 p0 = momentum(c.velocities), p1 = momentum(r.velocities);
      EXPECT_NEAR(p1.x, p0.x, 1e-12);
      EXPECT_NEAR(p1.y, p0.y, 1e-12);
      EXPECT_LE(energy(r.velocities), energy(c.velocities));
      for (const ClusterContact& k : c.contacts) {
        const Vec2 n = (c.positions[k.b] - c.positions[k.a]) / norm(c.positions[k.b] - c.positions[k.a]);
        EXPECT_LE(dot(r.velocities[k.a] - r.velocities[k.b], n), 0.0);
      }
    }
}

// The balls in any order: the same result to the last bit.
TEST(ContactCluster, IndexOrderChangesNothing) {
  const Cluster c = struck_triangle(5, 9.0);
  const ClusterImpact r = solve(c, 0.93);
  std::vector<std::size_t> perm(c.positions.size());
  std::iota(perm.begin(), perm.end(), std::size_t{0});
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 5; ++trial) {
    std::shuffle(perm.begin(), perm.end(), rng);
    std::vector<std::size_t> where(perm.size());
    Cluster q;
    for (std::size_t k = 0; k < perm.size(); ++k) {
      where[perm[k]] = k;
      q.positions.push_back(c.positions[perm[k]]);
      q.velocities.push_back(c.velocities[perm[k]]);
    }
    for (const ClusterContact& k : c.contacts) q.contacts.push_back({where[k.b], where[k.a]});
    const ClusterImpact s = solve(q, 0.93);
    for (std::size_t k = 0; k < perm.size(); ++k) EXPECT_EQ(s.velocities[where[k]], r.velocities[k]) << k;
  }
}

// A mirror image (y -> -y) gives the mirror image; the straight break of a
// symmetric rack is symmetric.
TEST(ContactCluster, MirrorImageGivesTheMirrorImage) {
  Cluster c = struck_triangle(5, 9.0);
  c.velocities[0] = {8.0, 1.5};
  Cluster m = c;
  for (Vec2& p : m.positions) p.y = -p.y;
  for (Vec2& v : m.velocities) v.y = -v.y;
  const ClusterImpact r = solve(c, 0.93), s = solve(m, 0.93);
  for (std::size_t k = 0; k < c.positions.size(); ++k) {
    EXPECT_NEAR(s.velocities[k].x, r.velocities[k].x, 1e-12);
    EXPECT_NEAR(s.velocities[k].y, -r.velocities[k].y, 1e-12);
  }
  const ClusterImpact straight = solve(struck_triangle(5, 9.0), 0.93);
  // Rows: balls (row, k) and (row, row - k) are mirror images.
  std::size_t first = 1;
  for (std::size_t row = 0; row < 5; ++row) {
    for (std::size_t k = 0; k <= row; ++k) {
      const Vec2 a = straight.velocities[first + k], b = straight.velocities[first + row - k];
      EXPECT_NEAR(a.x, b.x, 1e-12);
      EXPECT_NEAR(a.y, -b.y, 1e-12);
    }
    first += row + 1;
  }
}

// The equations are homogeneous (contact_cluster.hpp): twice the speeds give
// twice the velocities.
TEST(ContactCluster, TwiceTheSpeedTwiceTheOutcome) {
  const ClusterImpact a = solve(struck_triangle(4, 3.0), 0.9), b = solve(struck_triangle(4, 6.0), 0.9);
  for (std::size_t k = 0; k < a.velocities.size(); ++k) {
    EXPECT_NEAR(b.velocities[k].x, 2 * a.velocities[k].x, 1e-9);
    EXPECT_NEAR(b.velocities[k].y, 2 * a.velocities[k].y, 1e-9);
  }
}

// The default step against four times finer: the outcome has converged.
TEST(ContactCluster, StepsConverge) {
  const Cluster c = struck_triangle(5, 10.0);
  const ClusterImpact coarse = solve(c, 0.93);
  ClusterSettings finer = with_restitution(0.93);
  finer.steps_per_contact_time *= 4;
  const ClusterImpact fine = resolve_cluster_impact(c.positions, c.velocities, c.contacts, finer);
  EXPECT_GT(fine.steps, 3 * coarse.steps);
  for (std::size_t k = 0; k < c.positions.size(); ++k) EXPECT_LT(norm(fine.velocities[k] - coarse.velocities[k]), 1e-3) << k;
}

// Hertz's law for two pool balls (contact_cluster.hpp): at 5 m/s about half
// a millimetre of compression and a quarter of a millisecond of contact.
TEST(ContactCluster, PhenolicBallsCompressAndTouchAsMeasured) {
  const double k = hertz_stiffness_per_mass(pool_parameters().ball);
  EXPECT_NEAR(hertz_compression(5.0, k), 4.8e-4, 0.2e-4);
  EXPECT_NEAR(hertz_contact_time(5.0, k), 2.8e-4, 0.2e-4);
}

// A gap far smaller than the compression hardly matters; one far larger is
// never crossed (a later collision: the ball behind it keeps still).
TEST(ContactCluster, GapsSmallerThanTheCompressionAreCrossed) {
  const Cluster frozen = struck_triangle(3, 9.0);
  Cluster tiny = frozen, wide = frozen;
  for (ClusterContact& c : tiny.contacts) c.gap = c.a == 0 ? 0.0 : 1e-8;
  for (ClusterContact& c : wide.contacts) c.gap = c.a == 0 ? 0.0 : 0.05;
  const ClusterImpact a = solve(frozen, 0.93), b = solve(tiny, 0.93), w = solve(wide, 0.93);
  for (std::size_t k = 0; k < a.velocities.size(); ++k) EXPECT_LT(norm(a.velocities[k] - b.velocities[k]), 0.02) << k;
  // Wide gaps: the cue ball and the apex collide as a pair (e = 0.93, head on).
  EXPECT_NEAR(w.velocities[0].x, 9.0 * (1 - 0.93) / 2, 0.01);
  EXPECT_NEAR(w.velocities[1].x, 9.0 * (1 + 0.93) / 2, 0.01);
  for (std::size_t k = 2; k < w.velocities.size(); ++k) EXPECT_EQ(w.velocities[k], Vec2{}) << k;
}

// ------------------------------------------------------------ the simulator

Scenario frozen_break(const char* rack) {
  return scenario_from_json(std::string(R"({"table": "pool_9ft", "rack": {"type": ")") + rack +
                            R"("}, "cue": {"ball": 0, "target": 1, "speed": 9.0}})");
}

// The same frozen rack given in reverse order: the same shot, ball for ball.
TEST(ContactClusterSimulation, ReversedBallOrderGivesTheSameBreak) {
  for (const char* rack : {"nine_ball", "eight_ball"}) {
    const Scenario s = frozen_break(rack);
    std::vector<SimulationBall> balls = balls_after_strike(s);
    const SimulationResult a = simulate(s.table, balls, s.settings);
    std::reverse(balls.begin(), balls.end());
    const SimulationResult b = simulate(s.table, balls, s.settings);
    ASSERT_EQ(a.balls.size(), b.balls.size());
    for (std::size_t k = 0; k < a.balls.size(); ++k) {
      const BallTrajectory& x = a.balls[k];
      const BallTrajectory& y = b.balls[a.balls.size() - 1 - k];
      ASSERT_EQ(x.id, y.id);
      EXPECT_EQ(x.pocketed, y.pocketed) << rack << " ball " << x.id;
      EXPECT_NEAR(x.final_state.position.x, y.final_state.position.x, 1e-9) << rack << " ball " << x.id;
      EXPECT_NEAR(x.final_state.position.y, y.final_state.position.y, 1e-9) << rack << " ball " << x.id;
    }
    EXPECT_NEAR(a.end_time, b.end_time, 1e-9);
  }
}

// The straight break along the long string of a frozen 9-ball rack (a rack
// symmetric about it): mirror-image balls end at mirror-image places.
TEST(ContactClusterSimulation, StraightBreakOfASymmetricRackIsSymmetric) {
  const Scenario s = frozen_break("nine_ball");
  const SimulationResult r = run_scenario(s);
  const double w = s.table.width;
  // 9-ball diamond 1-2-3-2-1 (rack.hpp): mirror pairs across the long string.
  const auto at = [&](int id) {
    for (const BallTrajectory& b : r.balls)
      if (b.id == id) return b;
    return BallTrajectory{};
  };
  EXPECT_NEAR(at(0).final_state.position.y, 0.5 * w, 1e-6);
  for (auto [a, b] : {std::pair{2, 3}, {4, 5}, {6, 7}}) {
    const BallTrajectory x = at(a), y = at(b);
    EXPECT_EQ(x.pocketed, y.pocketed) << a << " " << b;
    EXPECT_NEAR(x.final_state.position.x, y.final_state.position.x, 1e-6) << a << " " << b;
    EXPECT_NEAR(x.final_state.position.y, w - y.final_state.position.y, 1e-6) << a << " " << b;
  }
  EXPECT_LE(deepest_penetration(s.table, r, s.settings.parameters), 1e-9);
  EXPECT_LE(energy_rise(r, s.settings.parameters), 1e-12);
}

}  // namespace
}  // namespace cueball
