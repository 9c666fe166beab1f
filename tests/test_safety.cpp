// Safety play (src/agents/safety.cpp): the opponent's chance estimate
// (pot_chance) against its closed form; where every pot is blocked and the
// plain hit leaves an easy shot, the safety planner plays a legal safety
// that leaves the opponent less, by the ghost-ball estimate and by the
// planner's own (planned_chance); the planned estimate sees the banks the
// ghost ball misses; the choices of the planner and the safety planner are
// deterministic for a seed. (Their legality in random states of every
// discipline: test_agent_legality.cpp.) Small budgets: the file runs in
// seconds in Release.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cueball/agents/agent.hpp"
#include "cueball/core/random.hpp"
#include "cueball/planning/pocket_windows.hpp"
#include "game_actions.hpp"

namespace cueball {
namespace {

AgentOptions cheap() {
  AgentOptions o;
  o.kind = AgentKind::safety_planner;
  o.simulations = kMinPlanSimulations;
  return o;
}

GameState in_play(const std::vector<std::pair<int, Vec2>>& balls) {
  return test::rotation_in_play(GameKind::nine_ball, balls);
}

GameState noise_free(GameState s) {
  s.config.noise = CueStrikeNoise{};
  return s;
}

// The 1 in a ring of five balls (2..6, 2.5 radii from it, every 60 deg but
// towards the cue ball): every path of the 1 to a pocket is blocked; the
// cue ball's path to it is clear (the planner agent's test layout).
GameState ringed() {
  GameState s = new_game(default_config(GameKind::nine_ball));
  const double R = s.table.table.ball.radius;
  const Vec2 one{1.6, s.table.table.width / 2};
  std::vector<std::pair<int, Vec2>> balls{{0, {1.0, one.y}}, {1, one}};
  int id = 2;
  for (const double deg : {0.0, 60.0, -60.0, 120.0, -120.0})
    balls.emplace_back(id++, one + 2.5 * R * Vec2{std::cos(deg * std::numbers::pi / 180), std::sin(deg * std::numbers::pi / 180)});
  return in_play(balls);
}

TEST(Safety, PotChanceIsTheGhostBallAimToleranceUnderTheAimNoise) {
  // The 1 on the diagonal of the bottom-left corner pocket, the cue ball
  // behind it on that line: a straight-in, cut 0, so the score is
  // 1 / (|CG| |OP|) and the chance erf(2 R w score / (sigma sqrt 2)), w the
  // corner's window head on.
  const GameState s = in_play({{0, {0.9, 0.9}}, {1, {0.45, 0.45}}, {9, {2.2, 0.3}}});
  const std::optional<GhostBallShot> g = ghost_ball_shot(s.table, 0, {1});
  ASSERT_TRUE(g);
  const double R = s.table.table.ball.radius;
  const Vec2 O{0.45, 0.45}, C{0.9, 0.9};
  const Vec2 P = s.table.table.pockets[static_cast<std::size_t>(g->pocket)].centre;
  const double score = 1.0 / ((norm(O - C) - 2.0 * R) * norm(P - O));
  EXPECT_NEAR(g->score, score, 1e-9 * score);
  const CueStrikeNoise noise = tournament_noise();
  const double w = pocket_window_half_width(*pocket_windows(s.table), static_cast<std::size_t>(g->pocket), P - O);
  EXPECT_NEAR(g->aim_tolerance, 2.0 * R * w * g->score, 1e-15);
  EXPECT_NEAR(pot_chance(s, noise), std::erf(2.0 * R * w * score / (noise.aim * std::numbers::sqrt2)), 1e-12);
  // Twice the aim noise: a lower chance; no aim noise: certain.
  CueStrikeNoise wide = noise;
  wide.aim *= 2.0;
  EXPECT_LT(pot_chance(s, wide), pot_chance(s, noise));
  EXPECT_EQ(pot_chance(s, CueStrikeNoise{}), 1.0);
  // Every pot blocked: none.
  EXPECT_EQ(pot_chance(ringed(), noise), 0.0);
  // Ball in hand: placed straight in behind the ghost ball, an easier shot than from a distance.
  GameState far = in_play({{0, {2.3, 1.0}}, {1, {0.45, 0.45}}, {9, {2.2, 0.3}}});
  const double from_far = pot_chance(far, noise);
  far.ball_in_hand = PlacementRegion{};
  EXPECT_GT(pot_chance(far, noise), from_far);
}

// Seeded layouts where the shooter has no clear direct pot of the 1 and the
// plain hit at it (safe_hit) leaves the opponent one (found by drawing
// random 9-ball layouts of five balls). The planner banks the 1 at about
// 0.4 in the first, 0.15 in the second, and pots it at about 0.6 in the
// third (drawn again when the ghost-ball chance took the pocket windows:
// the old third's plain hit left a pot that the old chance put above 0.5
// and the planner makes a tenth of the time).
const std::vector<std::vector<std::pair<int, Vec2>>> kHidden{
    {{0, {1.403, 1.063}}, {1, {1.923, 0.503}}, {2, {2.441, 0.128}}, {3, {0.513, 0.972}}, {4, {1.138, 0.953}}, {9, {1.692, 0.080}}},
    {{0, {1.900, 0.297}}, {1, {0.113, 0.690}}, {2, {0.420, 0.869}}, {3, {2.409, 1.144}}, {4, {1.333, 0.349}}, {9, {0.742, 0.952}}},
    {{0, {0.592, 0.551}}, {1, {0.598, 1.129}}, {2, {0.640, 0.272}}, {3, {1.339, 0.312}}, {4, {0.649, 0.662}}, {9, {1.096, 1.204}}},
};

// The most a safety on those layouts may leave the opponent, by the planned reply.
constexpr double kSafetyBound = 0.35;

TEST(Safety, BlockedPotsGiveALegalSafetyThatLeavesTheOpponentLessThanThePlainHit) {
  const CueStrikeNoise noise = tournament_noise();
  for (std::size_t k = 0; k < kHidden.size(); ++k) {
    SCOPED_TRACE("layout " + std::to_string(k));
    const GameState s = in_play(kHidden[k]);
    EXPECT_EQ(pot_chance(s, noise), 0.0);
    // The plain hit (the planner agent's when nothing pots) leaves an easy shot.
    int ball = -1;
    const std::optional<ShotAction> plain = safe_hit(s.table, 0, {1}, ball);
    ASSERT_TRUE(plain);
    Action naive;
    naive.strike = *plain;
    const GameStep after_naive = play(noise_free(s), naive, 0);
    ASSERT_TRUE(after_naive.ruling.turn_over);
    const double left_by_naive = pot_chance(after_naive.next, noise);
    EXPECT_GT(left_by_naive, 0.5);

    // The safety planner plays a safety where the planner's best pot (a
    // bank) is below kSafetyThreshold (layouts 0 and 1), else that pot.
    AgentOptions planner = cheap();
    planner.kind = AgentKind::planner;
    const PlannerChoice pot = planner_choice(planner, s, 4);
    const PlannerChoice c = safety_planner_choice(cheap(), s, 4);
    if (k < 2) {
      EXPECT_LT(pot.success_probability, kSafetyThreshold) << pot.detail;
      EXPECT_EQ(c.kind, PlannerChoice::Kind::safety) << c.detail;
    } else {
      EXPECT_GE(pot.success_probability, kSafetyThreshold) << pot.detail;
      EXPECT_EQ(c.action.strike, pot.action.strike) << c.detail;
    }
    // The safety search's strike: legal, and it leaves less than the plain hit.
    const std::optional<SafetyPlan> plan = plan_safety(s, legal_actions(s), std::nullopt, noise, 9);
    ASSERT_TRUE(plan);
    EXPECT_FALSE(plan->action.push_out);
    const GameStep step = play(noise_free(s), plan->action, 0);
    EXPECT_FALSE(step.ruling.foul) << step.ruling.reason;  // contact with the 1, then a rail (WPA 6.3)
    EXPECT_EQ(step.facts.first_contact, 1);
    EXPECT_EQ(step.next.to_shoot, 1);
    const double left = pot_chance(step.next, noise);
    EXPECT_LT(left, left_by_naive) << plan->detail;
    // And by the planner's own search of the reply (banks too), which the safety was chosen by.
    long long runs = 0;
    const double planned_left = planned_chance(step.next, noise, 11, runs);
    const double planned_by_naive = planned_chance(after_naive.next, noise, 11, runs);
    EXPECT_LT(planned_left, kSafetyBound) << plan->detail;
    EXPECT_GT(planned_by_naive, planned_left + 0.2) << plan->detail;
    // Under noise too, on average over its repeats, the safety leaves less.
    double naive_value = 0.0;
    GameState noisy = s;
    noisy.config.noise = noise;
    for (int r = 0; r < kSafetyRepeats; ++r)
      naive_value += value_after_shot(play(noisy, naive, stream_seed(9, static_cast<std::uint64_t>(r))).next, 0, noise);
    EXPECT_GT(plan->value, naive_value / kSafetyRepeats) << plan->detail;
    EXPECT_GT(plan->legal, 0);
    EXPECT_LE(plan->screened, kSafetyScreened);
    EXPECT_EQ(plan->replies, std::min(plan->screened, kSafetyFinalists) * kSafetyReplyOutcomes);
    EXPECT_GE(plan->simulations, plan->candidates + plan->screened * kSafetyRepeats + plan->replies);
    EXPECT_LE(plan->simulations,
              plan->candidates + plan->screened * kSafetyRepeats + plan->replies * kSafetyReplySimulations);
  }
}

TEST(Safety, ThePlannedReplyFindsTheBanksThePotChanceMisses) {
  long long runs = 0;
  const CueStrikeNoise noise = tournament_noise();
  // A straight-in: the plan pots it about as often as the ghost-ball estimate says.
  const GameState easy = in_play({{0, {0.9, 0.9}}, {1, {0.45, 0.45}}, {9, {2.2, 0.3}}});
  const double planned = planned_chance(easy, noise, 3, runs);
  EXPECT_GT(planned, 0.7);
  EXPECT_GT(runs, 0);
  EXPECT_LE(runs, kSafetyReplySimulations);
  EXPECT_EQ(planned, planned_chance(easy, noise, 3, runs));  // deterministic for the seed
  // Every path of the 1 blocked: nothing for either estimate.
  EXPECT_EQ(planned_chance(ringed(), noise, 3, runs), 0.0);
  // No straight pot of the 1, but a bank: pot_chance calls it safe, the planner does not.
  const GameState hidden = in_play(kHidden[0]);
  EXPECT_EQ(pot_chance(hidden, noise), 0.0);
  EXPECT_GT(planned_chance(hidden, noise, 3, runs), 0.2);
}

TEST(Safety, DeterministicForASeed) {
  GameState s = ringed();
  s.push_out_available = true;
  AgentOptions planner = cheap();
  planner.kind = AgentKind::planner;
  for (const GameState& state : {ringed(), s, in_play(kHidden[0])}) {
    const PlannerChoice p = planner_choice(planner, state, 17);
    const PlannerChoice q = planner_choice(planner, state, 17);
    EXPECT_EQ(p.action.strike, q.action.strike);
    EXPECT_EQ(p.action.place, q.action.place);
    EXPECT_EQ(p.success_probability, q.success_probability);
    const PlannerChoice a = safety_planner_choice(cheap(), state, 17);
    const PlannerChoice b = safety_planner_choice(cheap(), state, 17);
    EXPECT_EQ(a.action.strike, b.action.strike);
    EXPECT_EQ(a.action.push_out, b.action.push_out);
    EXPECT_EQ(a.success_probability, b.success_probability);
    EXPECT_EQ(a.detail, b.detail);
    EXPECT_EQ(a.simulations, b.simulations);
    EXPECT_NO_THROW((void)play(state, a.action, 17));
  }
}

TEST(Safety, AnEasyPotIsPlayedNotASafety) {
  const GameState s = in_play({{0, {0.62, 0.62}}, {1, {0.45, 0.45}}, {2, {1.8, 0.9}}, {9, {2.2, 0.3}}});
  const PlannerChoice c = safety_planner_choice(cheap(), s, 5);
  EXPECT_EQ(c.kind, PlannerChoice::Kind::pot) << c.detail;
  EXPECT_GE(c.success_probability, kSafetyThreshold);
  AgentOptions planner = cheap();
  planner.kind = AgentKind::planner;
  EXPECT_EQ(c.action.strike, planner_choice(planner, s, 5).action.strike);
}

TEST(Safety, ChosenByName) {
  EXPECT_EQ(agent_kind_from_string("safety_planner"), AgentKind::safety_planner);
  EXPECT_STREQ(to_string(AgentKind::safety_planner), "safety_planner");
  EXPECT_NE(agent_kind_names().find("safety_planner"), std::string::npos);
  const GameState s = ringed();
  EXPECT_EQ(choose_action(cheap(), s, 3).strike, safety_planner_action(cheap(), s, 3).strike);
}

}  // namespace
}  // namespace cueball
