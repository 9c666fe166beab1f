// Tests of the ghost-ball pots (src/planning/ghost_ball.cpp): a straight-in
// pot's ghost ball, score, window and chance against their closed forms; the
// target sent through the middle of the pocket's window, checked by rolls; a
// ball on either path or a cut beyond kMaxCutDeg removes a pot; on random
// layouts every pot returned meets the definition, best first, and every
// pocket left out fails it. The combinations of one ball through another:
// a straight one's closed form, played on the engine within its tolerance;
// a ball on any of its three paths removes it; path_clear() at its
// clearance.
#include "cueball/planning/ghost_ball.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <numbers>
#include <random>
#include <vector>

#include "ball_layout.hpp"
#include "cueball/planning/pocket_windows.hpp"
#include "cueball/planning/shot_planner.hpp"

namespace cueball {
namespace {

using test::layout;

constexpr double kAim = 0.125 * std::numbers::pi / 180.0;  // tournament aim noise, rad

TEST(GhostBallPots, AStraightInPotIsTheClosedForm) {
  // The 1 on the diagonal of the bottom-left corner pocket, the cue ball behind it on that line.
  const Scenario s = layout({{0, {0.8, 0.8}}, {1, {0.45, 0.45}}});
  const double R = s.settings.parameters.ball.radius;
  const std::vector<GhostBallPot> pots = ghost_ball_pots(s, 0, {1});
  ASSERT_FALSE(pots.empty());
  const GhostBallPot& best = pots.front();
  EXPECT_EQ(best.target, 1);
  const Vec2 P = s.table.pockets[static_cast<std::size_t>(best.pocket)].centre;
  const Vec2 O{0.45, 0.45};
  EXPECT_NEAR(P.x, P.y, 1e-12);  // the corner on the diagonal
  const Vec2 u = (P - O) / norm(P - O);
  const Vec2 G = O - 2.0 * R * u;
  // Head on, the corner's window is symmetric to within its measurement:
  // the 1 is sent within a millimetre of the pocket's centre.
  EXPECT_LT(norm(best.pocket_aim - P), 1e-3);
  EXPECT_NEAR(best.ghost.x, G.x, 1e-4);
  EXPECT_NEAR(best.ghost.y, G.y, 1e-4);
  // Straight in: cos(cut) = 1, score 1 / (|CG| |OP|).
  EXPECT_NEAR(best.score, 1.0 / (norm(G - Vec2{0.8, 0.8}) * norm(P - O)), 1e-3 * best.score);
  // Head on into the corner: its window's half-width, wider than the 25 mm
  // a ball's centre has inside the 4.5 in mouth (the jaws turn balls in).
  EXPECT_EQ(best.window, pocket_window_half_width(*pocket_windows(s), static_cast<std::size_t>(best.pocket), u));
  EXPECT_GT(best.window, 0.030);
  EXPECT_LT(best.window, 0.040);
  EXPECT_NEAR(best.aim_tolerance, 2.0 * R * best.window * best.score, 1e-15);
  const double chance = ghost_ball_pot_chance(best.aim_tolerance, kAim);
  EXPECT_NEAR(chance, std::erf(2.0 * R * best.window * best.score / (kAim * std::numbers::sqrt2)), 1e-15);
  EXPECT_GT(chance, 0.9);  // 0.35 m and 0.45 m of path: an easy pot
  EXPECT_EQ(best_ghost_ball_chance(s, 0, {1}, kAim), chance);
  EXPECT_EQ(ghost_ball_pot_chance(best.aim_tolerance, 0.0), 1.0);          // no noise
  EXPECT_LT(ghost_ball_pot_chance(best.aim_tolerance, 4.0 * kAim), chance);  // more noise, less chance
  EXPECT_EQ(ghost_ball_pot_chance(0.0, kAim), 0.0);                          // a closed window
  // Farther back along the same line: a lower score and chance.
  const Scenario farther = layout({{0, {1.1, 1.1}}, {1, {0.45, 0.45}}});
  EXPECT_LT(best_ghost_ball_chance(farther, 0, {1}, kAim), chance);
}

// Whether a lone ball at O rolling at 1 m/s towards `at` turned by `turn`
// (rad) drops into pocket k.
bool rolls_in(const Scenario& s, Vec2 O, Vec2 at, double turn, std::size_t k) {
  const double R = s.settings.parameters.ball.radius;
  const double a = std::atan2(at.y - O.y, at.x - O.x) + turn;
  SimulationBall ball;
  ball.id = 1;
  ball.state.position = O;
  ball.state.velocity = Vec2{std::cos(a), std::sin(a)};
  ball.state.angular_velocity = Vec3{-ball.state.velocity.y / R, ball.state.velocity.x / R, 0.0};
  const SimulationResult r = simulate_unchecked(s.table, {ball}, s.settings);
  return r.balls.front().pocketed && r.balls.front().pocket == static_cast<int>(k);
}

TEST(GhostBallPots, TheTargetIsSentThroughTheMiddleOfThePocketsWindow) {
  // The 1 coming 20 degrees off the bottom-left corner's axis (-135 deg):
  // the middle of the lines that drop it lies well to one side of the
  // pocket's centre. Sent there, it drops with 80 % of the window's
  // half-width to spare either side; sent at the centre, it does not.
  const Scenario s = layout({});
  const std::size_t corner = 0;
  const Vec2 centre = s.table.pockets[corner].centre;
  ASSERT_LT(centre.x, 0.1);
  ASSERT_LT(centre.y, 0.1);
  const double a = (-135.0 + 20.0) * std::numbers::pi / 180.0;
  const Vec2 O = centre - 0.5 * Vec2{std::cos(a), std::sin(a)};
  const Scenario table = layout({{0, O + 0.6 * Vec2{std::cos(a), std::sin(a)} * -1.0}, {1, O}});
  const std::vector<GhostBallPot> pots = ghost_ball_pots(table, 0, {1});
  const GhostBallPot* pot = nullptr;
  for (const GhostBallPot& p : pots)
    if (p.pocket == static_cast<int>(corner)) pot = &p;
  ASSERT_NE(pot, nullptr);
  EXPECT_GT(norm(pot->pocket_aim - centre), 0.015);
  const double spare = 0.8 * pot->window / norm(pot->pocket_aim - O);
  EXPECT_TRUE(rolls_in(table, O, pot->pocket_aim, 0.0, corner));
  EXPECT_TRUE(rolls_in(table, O, pot->pocket_aim, spare, corner));
  EXPECT_TRUE(rolls_in(table, O, pot->pocket_aim, -spare, corner));
  EXPECT_FALSE(rolls_in(table, O, centre, spare, corner) && rolls_in(table, O, centre, -spare, corner));
  // The textbook rule (the ghost-ball agent's) sends it to the centre, with
  // the window of that direction.
  const double R = table.settings.parameters.ball.radius;
  const Vec2 u = (centre - O) / norm(centre - O);
  bool seen = false;
  for (const GhostBallPot& p : ghost_ball_pots(table, 0, {1}, GhostBallAim::pocket_centre))
    if (p.pocket == static_cast<int>(corner)) {
      seen = true;
      EXPECT_EQ(p.pocket_aim.x, centre.x);
      EXPECT_EQ(p.pocket_aim.y, centre.y);
      EXPECT_NEAR(norm(p.ghost - (O - 2.0 * R * u)), 0.0, 1e-15);
      EXPECT_EQ(p.window, pocket_window_half_width(*pocket_windows(table), corner, u));
    }
  EXPECT_TRUE(seen);
}

TEST(GhostBallPots, ABallOnEitherPathOrACutTooThinRemovesThePot) {
  const Scenario open = layout({{0, {0.8, 0.8}}, {1, {0.45, 0.45}}});
  const int corner = ghost_ball_pots(open, 0, {1}).front().pocket;
  auto has_corner = [&](const Scenario& s) {
    for (const GhostBallPot& p : ghost_ball_pots(s, 0, {1}))
      if (p.pocket == corner) return true;
    return false;
  };
  EXPECT_TRUE(has_corner(open));
  EXPECT_FALSE(has_corner(layout({{0, {0.8, 0.8}}, {1, {0.45, 0.45}}, {2, {0.25, 0.25}}})));  // on O -> P
  EXPECT_FALSE(has_corner(layout({{0, {0.8, 0.8}}, {1, {0.45, 0.45}}, {2, {0.62, 0.63}}})));  // on C -> G
  // The cue ball beside the line from the corner through the 1, past it: a cut over 80 degrees.
  EXPECT_FALSE(has_corner(layout({{0, {0.45 - 0.06, 0.45 + 0.06}}, {1, {0.45, 0.45}}})));
  EXPECT_TRUE(ghost_ball_pots(layout({{1, {0.45, 0.45}}}), 0, {1}).empty());  // no cue ball
  EXPECT_EQ(best_ghost_ball_chance(layout({{1, {0.45, 0.45}}}), 0, {1}, kAim), 0.0);
}

TEST(GhostBallPots, EveryPotMeetsTheDefinitionBestFirstAndEveryPocketLeftOutFailsIt) {
  const Scenario empty = layout({});
  const double R = empty.settings.parameters.ball.radius;
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> ux(0.1, 2.44), uy(0.1, 1.17);
  int pots_seen = 0, left_out = 0, closed = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<test::Placed> balls;
    while (balls.size() < 6) {
      const Vec2 p{ux(rng), uy(rng)};
      bool apart = ball_on_table(empty.table, p, R);
      for (const test::Placed& b : balls) apart = apart && norm(b.p - p) > 2.0 * R;
      if (apart) balls.push_back({static_cast<int>(balls.size()), p});
    }
    const Scenario s = layout(balls);
    const std::vector<int> targets{1, 2};
    const std::vector<GhostBallPot> pots = ghost_ball_pots(s, 0, targets);
    for (std::size_t k = 1; k < pots.size(); ++k) EXPECT_GE(pots[k - 1].aim_tolerance, pots[k].aim_tolerance);
    const Vec2 C = balls[0].p;
    for (const int t : targets) {
      const Vec2 O = balls[static_cast<std::size_t>(t)].p;
      for (std::size_t k = 0; k < s.table.pockets.size(); ++k) {
        // Sent to the middle of the window for its direction, found in two passes.
        const Vec2 centre = s.table.pockets[k].centre;
        Vec2 P = centre;
        for (int pass = 0; pass < 2; ++pass) {
          const Vec2 d = (P - O) / norm(P - O);
          P = centre + pocket_window_middle(*pocket_windows(s), k, d) * Vec2{-d.y, d.x};
        }
        const Vec2 u = (P - O) / norm(P - O);
        const Vec2 G = O - 2.0 * R * u;
        const double cos_cut = dot((G - C) / norm(G - C), u);
        bool clear = cos_cut >= std::cos(kMaxCutDeg * std::numbers::pi / 180.0);
        for (const test::Placed& b : balls)
          if (b.id != 0 && b.id != t)
            clear = clear && distance_to_segment(b.p, C, G) >= 2.0 * R && distance_to_segment(b.p, O, P) >= 2.0 * R;
        const GhostBallPot* found = nullptr;
        for (const GhostBallPot& p : pots)
          if (p.target == t && p.pocket == static_cast<int>(k)) found = &p;
        EXPECT_EQ(found != nullptr, clear) << "trial " << trial << " ball " << t << " pocket " << k;
        if (found) {
          ++pots_seen;
          EXPECT_NEAR(norm(found->pocket_aim - P), 0.0, 1e-12);
          EXPECT_NEAR(found->score, cos_cut / (norm(G - C) * norm(P - O)), 1e-12);
          EXPECT_EQ(found->window, pocket_window_half_width(*pocket_windows(s), k, u));
          EXPECT_NEAR(found->aim_tolerance, 2.0 * R * found->window * found->score, 1e-15);
          closed += found->window == 0.0 ? 1 : 0;
        } else {
          ++left_out;
        }
      }
    }
  }
  EXPECT_GT(pots_seen, 200);  // both kinds were exercised
  EXPECT_GT(left_out, 200);
  EXPECT_GT(closed, 0);  // a side pocket seen from too far along its rail
}

// The cue ball, the 2 and the 9 on the diagonal of the bottom-left corner:
// a straight combination, both cuts 0, its tolerance (2R)^2 w / (|CG| |AT|
// |OP|): the 2's error is magnified on the way to the 9, so it is harder
// than the 9 straight in from the same place. Played on the engine (a level
// stun stroke along C -> G), the 9 drops, and so it does with the aim turned
// by half the tolerance either way.
TEST(GhostBallPots, AStraightCombinationIsTheClosedFormAndDropsWithinItsTolerance) {
  const Vec2 C{1.0, 1.0}, A{0.7, 0.7}, O{0.4, 0.4};
  const Scenario s = layout({{0, C}, {2, A}, {9, O}});
  const double R = s.settings.parameters.ball.radius;
  const std::vector<GhostBallPot> combos = ghost_ball_combinations(s, 0, 2, 9);
  ASSERT_FALSE(combos.empty());
  const GhostBallPot& best = combos.front();
  EXPECT_EQ(best.target, 9);
  EXPECT_EQ(best.ball_on, 2);
  const Vec2 P = best.pocket_aim;
  const Vec2 u = (P - O) / norm(P - O);
  const Vec2 T = O - 2.0 * R * u;
  const Vec2 v = (T - A) / norm(T - A);
  const Vec2 G = A - 2.0 * R * v;
  EXPECT_NEAR(norm(best.ghost - G), 0.0, 1e-12);
  EXPECT_GT(dot(v, u), 0.9999);  // straight: the corner's window is symmetric to within a millimetre
  EXPECT_NEAR(best.score, 2.0 * R * dot((G - C) / norm(G - C), v) * dot(v, u) / (norm(G - C) * norm(T - A) * norm(P - O)),
              1e-12);
  EXPECT_NEAR(best.aim_tolerance, 2.0 * R * best.window * best.score, 1e-15);
  // The 9 straight in from the same place with the 2 off the table: easier.
  const std::vector<GhostBallPot> straight = ghost_ball_pots(layout({{0, C}, {9, O}}), 0, {9});
  ASSERT_FALSE(straight.empty());
  EXPECT_LT(best.aim_tolerance, straight.front().aim_tolerance);
  EXPECT_TRUE(ghost_ball_stroke(s, 0, best, 2.0, 0.0).potted);
  for (const double turn : {-0.5 * best.aim_tolerance, 0.5 * best.aim_tolerance}) {
    GhostBallPot turned = best;
    const Vec2 d = best.ghost - C;
    turned.ghost = C + Vec2{d.x * std::cos(turn) - d.y * std::sin(turn), d.x * std::sin(turn) + d.y * std::cos(turn)};
    const GhostBallStroke stroke = ghost_ball_stroke(s, 0, turned, 2.0, 0.0);
    EXPECT_TRUE(stroke.potted) << "turned " << turn << " rad";
    EXPECT_FALSE(stroke.scratched);
  }
  // Turned by three tolerances, one side misses.
  int missed = 0;
  for (const double turn : {-3.0 * best.aim_tolerance, 3.0 * best.aim_tolerance}) {
    GhostBallPot turned = best;
    const Vec2 d = best.ghost - C;
    turned.ghost = C + Vec2{d.x * std::cos(turn) - d.y * std::sin(turn), d.x * std::sin(turn) + d.y * std::cos(turn)};
    missed += ghost_ball_stroke(s, 0, turned, 2.0, 0.0).potted ? 0 : 1;
  }
  EXPECT_GE(missed, 1);
}

// path_clear(): a ball whose centre lies `clearance` or more from the
// segment (beside it or beyond its ends) leaves it clear, one just inside
// blocks it unless its id is excepted.
TEST(GhostBallPots, APathIsClearOfEveryBallButThoseExceptedAtTheClearance) {
  const double R = layout({}).settings.parameters.ball.radius;
  const Vec2 a{0.5, 0.5}, b{1.5, 0.5};
  const auto clear_with = [&](Vec2 p, std::initializer_list<int> except) {
    return path_clear(layout({{0, a}, {3, p}}).balls, a, b, 2.0 * R, except);
  };
  EXPECT_TRUE(clear_with({1.0, 0.5 + 2.0 * R + 1e-9}, {0}));   // beside it, just clear
  EXPECT_FALSE(clear_with({1.0, 0.5 + 2.0 * R - 1e-6}, {0}));  // just inside
  EXPECT_TRUE(clear_with({1.0, 0.5 + 2.0 * R - 1e-6}, {0, 3}));  // excepted
  EXPECT_TRUE(clear_with({1.5 + 2.0 * R + 1e-6, 0.5}, {0}));    // beyond the end
  EXPECT_FALSE(clear_with({1.5 + 2.0 * R - 1e-6, 0.5}, {0}));
  EXPECT_FALSE(path_clear(layout({{0, a}}).balls, a, b, 2.0 * R, {}));  // the ball at a itself, not excepted
}

TEST(GhostBallPots, ABallOnAnyOfACombinationsPathsRemovesIt) {
  const Vec2 C{1.0, 1.0}, A{0.7, 0.7}, O{0.4, 0.4};
  const int corner = ghost_ball_combinations(layout({{0, C}, {2, A}, {9, O}}), 0, 2, 9).front().pocket;
  const auto has_corner = [&](const std::vector<test::Placed>& balls) {
    for (const GhostBallPot& p : ghost_ball_combinations(layout(balls), 0, 2, 9))
      if (p.pocket == corner) return true;
    return false;
  };
  EXPECT_TRUE(has_corner({{0, C}, {2, A}, {9, O}, {3, {1.5, 0.3}}}));
  EXPECT_FALSE(has_corner({{0, C}, {2, A}, {9, O}, {3, {0.86, 0.86}}}));  // on C -> G
  EXPECT_FALSE(has_corner({{0, C}, {2, A}, {9, O}, {3, {0.56, 0.57}}}));  // on A -> T
  EXPECT_FALSE(has_corner({{0, C}, {2, A}, {9, O}, {3, {0.2, 0.2}}}));    // on O -> P
  // No cue ball, no ball on, the same ball twice: none.
  EXPECT_TRUE(ghost_ball_combinations(layout({{2, A}, {9, O}}), 0, 2, 9).empty());
  EXPECT_TRUE(ghost_ball_combinations(layout({{0, C}, {9, O}}), 0, 2, 9).empty());
  EXPECT_TRUE(ghost_ball_combinations(layout({{0, C}, {2, A}, {9, O}}), 0, 9, 9).empty());
}

}  // namespace
}  // namespace cueball
