// The planner agent (src/agents/planner_agent.cpp): its action is legal in
// crafted states (ball in hand anywhere and in the kitchen, a push-out
// decision, a call, a nomination), deterministic for a seed; nothing pots:
// a plain hit (pushed out when it may be); the next targets follow the
// rules; a planner-vs-ghost-ball 9-ball game ends; a decision under a
// seconds budget plays the round it reached, exactly as that budget without
// one. Small budgets: the file runs in a few seconds in Release.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>

#include "cueball/agents/agent.hpp"
#include "cueball/games/break_shot.hpp"
#include "cueball/core/random.hpp"
#include "game_actions.hpp"
#include "expect_invalid.hpp"

namespace cueball {
namespace {

AgentOptions cheap() {
  AgentOptions o;
  o.kind = AgentKind::planner;
  o.simulations = kMinPlanSimulations;
  return o;
}

// A 9-ball game in play (after the break) with exactly these balls.
GameState in_play(const std::vector<std::pair<int, Vec2>>& balls) {
  return test::rotation_in_play(GameKind::nine_ball, balls);
}

bool contains(const std::vector<int>& v, int id) { return std::find(v.begin(), v.end(), id) != v.end(); }

// The 1 in a ring of five balls (2..6, 2.5 radii from it, every 60 deg but
// towards the cue ball): every path of the 1 to a pocket is blocked, the
// cue ball's path to it is clear.
GameState ringed() {
  GameState s = new_game(default_config(GameKind::nine_ball));
  const double R = s.table.table.ball.radius;
  const Vec2 one{1.6, s.table.table.width / 2};
  std::vector<std::pair<int, Vec2>> balls{{0, {1.0, one.y}}, {1, one}};
  const double pi = 3.14159265358979323846;
  int id = 2;
  for (const double deg : {0.0, 60.0, -60.0, 120.0, -120.0})
    balls.emplace_back(id++, one + 2.5 * R * Vec2{std::cos(deg * pi / 180), std::sin(deg * pi / 180)});
  return in_play(balls);
}

TEST(PlannerAgent, PotsAndIsDeterministicForASeed) {
  const GameState s = in_play({{0, {0.62, 0.62}}, {1, {0.45, 0.45}}, {2, {1.8, 0.9}}, {9, {2.2, 0.3}}});
  const PlannerChoice c = planner_choice(cheap(), s, 5);
  EXPECT_EQ(c.kind, PlannerChoice::Kind::pot) << c.detail;
  EXPECT_GT(c.success_probability, 0.5);
  EXPECT_GT(c.simulations, 0);
  EXPECT_LE(c.simulations, kMinPlanSimulations);
  const Action again = planner_action(cheap(), s, 5);
  EXPECT_EQ(c.action.strike, again.strike);
  const GameStep step = play(s, c.action, 5);
  EXPECT_TRUE(step.facts.pocketed(1));
  EXPECT_FALSE(step.ruling.foul) << step.ruling.reason;
  // With position play, the leave's next-shot estimate is reported.
  AgentOptions position = cheap();
  position.position_simulations = kMinPlanSimulations;
  const PlannerChoice p = planner_choice(position, s, 5);
  EXPECT_EQ(p.kind, PlannerChoice::Kind::pot);
  EXPECT_GE(p.next_success_probability, 0.0);
  EXPECT_NO_THROW((void)play(s, p.action, 5));
}

TEST(PlannerAgent, ItsReasoningIsTheShotPlannedAndTheAlternatives) {
  const GameState s = in_play({{0, {0.62, 0.62}}, {1, {0.45, 0.45}}, {2, {1.8, 0.9}}, {9, {2.2, 0.3}}});
  for (const int position : {0, kMinPlanSimulations}) {
    AgentOptions o = cheap();
    o.position_simulations = position;
    const PlannerChoice c = planner_choice(o, s, 5);
    const AgentChoice a = choose(o, s, 5);
    EXPECT_EQ(a.action.strike, c.action.strike);
    EXPECT_EQ(a.action.place, c.action.place);
    EXPECT_EQ(a.action.strike, choose_action(o, s, 5).strike);
    EXPECT_EQ(a.reasoning.summary, c.detail);
    ASSERT_FALSE(a.reasoning.considered.empty());
    // the chosen shot first, with the estimates the choice reports
    EXPECT_DOUBLE_EQ(a.reasoning.considered.front().estimate, c.success_probability);
    EXPECT_DOUBLE_EQ(a.reasoning.considered.front().next_estimate, c.next_success_probability);
    EXPECT_NE(a.reasoning.summary.find(a.reasoning.considered.front().what), std::string::npos);
    for (const ConsideredOption& k : a.reasoning.considered) {
      EXPECT_FALSE(k.what.empty());
      EXPECT_LE(k.estimate, 1.0);
      EXPECT_EQ(k.next_estimate >= 0.0, position > 0) << k.what;
    }
  }
  // a decision: the policy's reason and the estimate behind it
  GameState push = in_play({{0, {0.62, 0.62}}, {1, {0.45, 0.45}}, {9, {2.2, 0.3}}});
  push.phase = GamePhase::decision;
  push.decisions = {Decision::play, Decision::pass};
  const PlannerChoice c = planner_choice(cheap(), push, 2);
  const AgentChoice d = choose(cheap(), push, 2);
  ASSERT_TRUE(d.action.decision);
  EXPECT_EQ(d.action.decision, c.action.decision);
  EXPECT_EQ(d.reasoning.summary.rfind(to_string(*d.action.decision), 0), 0u) << d.reasoning.summary;
  ASSERT_EQ(d.reasoning.considered.size(), 1u);
  EXPECT_DOUBLE_EQ(d.reasoning.considered.front().estimate, c.success_probability);
}

TEST(PlannerAgent, BallInHandIsPlacedInsideTheRegion) {
  AgentOptions o = cheap();
  o.position_simulations = kMinPlanSimulations;
  for (const PlacementRegion::Kind kind : {PlacementRegion::Kind::anywhere, PlacementRegion::Kind::behind_head_string}) {
    GameState s = in_play({{1, {1.9, 0.4}}, {3, {2.1, 1.0}}, {9, {1.2, 0.9}}});  // the cue ball off the table
    PlacementRegion r;
    r.kind = kind;
    s.ball_in_hand = r;
    const PlannerChoice c = planner_choice(o, s, 11);
    ASSERT_TRUE(c.action.place) << c.detail;
    EXPECT_TRUE(in_region(s.table.table, r, *c.action.place)) << c.action.place->x;
    const GameStep step = play(s, c.action, 11);  // play() validates the spot
    EXPECT_EQ(step.facts.first_contact, 1) << c.detail;
  }
}

TEST(PlannerAgent, PushOutDecisionByThePolicy) {
  GameState s = in_play({{0, {0.62, 0.62}}, {1, {0.45, 0.45}}, {9, {2.2, 0.3}}});
  s.phase = GamePhase::decision;
  s.decisions = {Decision::play, Decision::pass};
  const PlannerChoice good = planner_choice(cheap(), s, 2);
  EXPECT_EQ(good.kind, PlannerChoice::Kind::decision);
  EXPECT_EQ(good.action.decision, Decision::play) << good.detail;  // an easy pot: play it
  EXPECT_GE(good.success_probability, kPlannerGoodTable);
  EXPECT_NO_THROW((void)play(s, good.action, 2));
  GameState bad = ringed();
  bad.phase = GamePhase::decision;
  bad.decisions = {Decision::play, Decision::pass};
  const PlannerChoice passed = planner_choice(cheap(), bad, 2);
  EXPECT_EQ(passed.action.decision, Decision::pass) << passed.detail;  // nothing pots: pass it back
  EXPECT_NO_THROW((void)play(bad, passed.action, 2));
}

TEST(PlannerAgent, NothingPotsAPlainHitPushedOutWhenAllowed) {
  GameState s = ringed();
  const PlannerChoice c = planner_choice(cheap(), s, 4);
  EXPECT_EQ(c.kind, PlannerChoice::Kind::safety) << c.detail;
  EXPECT_FALSE(c.action.push_out);
  const GameStep step = play(s, c.action, 4);
  EXPECT_EQ(step.facts.first_contact, 1);
  EXPECT_FALSE(step.ruling.foul) << step.ruling.reason;
  s.push_out_available = true;
  const PlannerChoice push = planner_choice(cheap(), s, 4);
  EXPECT_TRUE(push.action.push_out);
  EXPECT_TRUE(play(s, push.action, 4).ruling.push_out);
}

TEST(PlannerAgent, CallsTheChosenBallAndPocket) {
  // Legal actions as 10-ball gives them: the lowest ball on, any ball callable.
  const GameState s = in_play({{0, {0.62, 0.62}}, {1, {0.45, 0.45}}, {2, {1.8, 0.9}}, {9, {2.2, 0.3}}});
  LegalActions legal = legal_actions(s);
  legal.call_required = true;
  legal.callable = {1, 2, 9};
  const PlannerChoice c = planner_choice(cheap(), s, legal, 3);
  ASSERT_TRUE(c.action.called_ball);
  ASSERT_TRUE(c.action.called_pocket);
  EXPECT_EQ(*c.action.called_ball, 1);  // the ball on: the target planned
  EXPECT_EQ(*c.action.called_pocket, 0);
  EXPECT_FALSE(c.action.nominate);
  const GameStep step = play(s, [&] {
    Action a = c.action;  // 9-ball asks no call: the strike alone
    a.called_ball.reset();
    a.called_pocket.reset();
    return a;
  }(), 3);
  EXPECT_TRUE(step.facts.pocketed(1));
}

TEST(PlannerAgent, NominatesTheBallItPlays) {
  // Legal actions as snooker gives them after a red: nominate one of the
  // colours (here the 2 and the 3 stand for them), and hit it.
  const GameState s = in_play({{0, {1.2, 0.5}}, {1, {0.3, 1.0}}, {2, {2.2, 0.35}}, {3, {1.0, 1.1}}, {9, {1.5, 1.0}}});
  LegalActions legal = legal_actions(s);
  legal.on = {2, 3};
  legal.nominate_required = true;
  legal.nominable = {2, 3};
  const PlannerChoice c = planner_choice(cheap(), s, legal, 9);
  ASSERT_TRUE(c.action.nominate) << c.detail;
  EXPECT_TRUE(contains(legal.nominable, *c.action.nominate));
  EXPECT_NE(c.kind, PlannerChoice::Kind::safety) << c.detail;
}

TEST(PlannerAgent, NextTargetsFollowTheRules) {
  const GameState s = in_play({{0, {0.62, 0.62}}, {2, {0.45, 0.45}}, {5, {1.8, 0.9}}, {9, {2.2, 0.3}}});
  EXPECT_EQ(next_targets(s, 2), (std::vector<std::vector<int>>{{5}, {9}}));
  EXPECT_EQ(next_targets(s, 9), (std::vector<std::vector<int>>{{2}, {5}}));
  GameState eight = s;
  eight.config.kind = GameKind::eight_ball;
  eight.groups = {Group::stripes, Group::solids};
  for (const int id : {8, 10, 12}) {
    SimulationBall b;
    b.id = id;
    b.state.position = {0.3 + 0.1 * id, 1.0};
    eight.table.balls.push_back(b);
  }
  EXPECT_EQ(next_targets(eight, 10), (std::vector<std::vector<int>>{{9, 12}, {8}}));
  eight.to_shoot = 1;
  EXPECT_EQ(next_targets(eight, 2), (std::vector<std::vector<int>>{{5}, {8}}));
  GameState snooker = s;
  snooker.config.kind = GameKind::snooker;
  snooker.table.balls.clear();
  for (const int id : {0, 3, 7, 16, 21}) {
    SimulationBall b;
    b.id = id;
    b.state.position = {0.2 + 0.1 * id, 0.8};
    snooker.table.balls.push_back(b);
  }
  EXPECT_EQ(next_targets(snooker, 3), (std::vector<std::vector<int>>{{16, 21}}));  // after a red, the colours
  EXPECT_EQ(next_targets(snooker, 21), (std::vector<std::vector<int>>{{3, 7}}));   // after a colour, the reds
}

TEST(PlannerAgent, BreaksWithTheSharedBreak) {
  const GameState s = new_game(default_config(GameKind::nine_ball), 2);
  const PlannerChoice c = planner_choice(cheap(), s, 2);
  EXPECT_EQ(c.kind, PlannerChoice::Kind::break_shot);
  EXPECT_EQ(c.simulations, 0);
  EXPECT_EQ(c.action.strike, recommended_break(s).strike);
  ASSERT_TRUE(c.action.place);
  EXPECT_LE(c.action.place->x, head_string_x(s.table.table));
  EXPECT_EQ(play(s, c.action, 2).facts.first_contact, 1);
}

TEST(PlannerAgent, RefusesBadOptions) {
  const GameState s = in_play({{0, {0.62, 0.62}}, {1, {0.45, 0.45}}});
  AgentOptions o = cheap();
  o.kinds.clear();
  test::expect_invalid("kinds", [&] { (void)planner_action(o, s, 1); });
  o = cheap();
  o.fallback_kinds = {ShotKind::kick, ShotKind::kick};
  test::expect_invalid("fallback_kinds", [&] { (void)planner_action(o, s, 1); });
  o = cheap();
  o.simulations = 0;
  test::expect_invalid("simulations", [&] { (void)planner_action(o, s, 1); });
  o = cheap();
  o.position_simulations = 500;
  o.position_depth = kMaxPositionDepth + 1;
  o.position_valuation = LeaveValuation::ghost_ball;
  test::expect_invalid("position_depth", [&] { (void)choose_action(o, s, 1); });
  o.position_depth = kMaxWindowsDepth + 1;  // three shots deep by the ghost ball only
  o.position_valuation = LeaveValuation::windows;
  test::expect_invalid("position_depth", [&] { (void)choose_action(o, s, 1); });
  o = cheap();
  o.position_simulations = 500;
  o.position_candidate_noisy_leaves = kMaxPositionNoisyLeaves + 1;
  test::expect_invalid("position_candidate_noisy_leaves", [&] { (void)choose_action(o, s, 1); });
  o = cheap();
  o.position_simulations = 500;
  o.position_varied_shots = 0;
  test::expect_invalid("position_varied_shots", [&] { (void)choose_action(o, s, 1); });
}

// An 8-ball table from a match (seed 5004, shot 13) where the aim solver,
// stepping off the pocket's centre from a local slope near zero, returned
// a potting aim of 1697 degrees: a candidate the strongest agent's noisy
// leaves then played through the checked batch, which refused it, and the
// match stopped. The offsets are now bounded and every solved aim brought
// into (-180, 180]: the decision is made, and its strike is a legal one.
TEST(PlannerAgent, TheStrongestAgentPlansATableWhoseOffCentreAimOnceRanAway) {
  GameState s = new_game(default_config(GameKind::eight_ball));
  s.config.noise = tournament_noise();
  s.phase = GamePhase::play;
  s.ball_in_hand.reset();
  test::place_balls(s, {{0, {0.4296581800481384, 0.8689354928788358}},
                        {9, {0.03683094355886656, 0.377518540551229}},
                        {10, {0.4382181712150013, 1.138468979017901}},
                        {8, {1.1565799950432396, 1.2232848685245286}},
                        {15, {0.0054362046879856945, 1.2565178664920877}},
                        {6, {0.07317805103808972, 0.3306374989400485}}});
  s.groups = {Group::stripes, Group::solids};
  s.to_shoot = 0;
  s.on = {9, 10, 15};
  AgentChoice c;
  ASSERT_NO_THROW(c = choose(strongest_agent(), s, 16749438538978399966ULL));
  EXPECT_GE(c.action.strike.aim_deg, -360.0);
  EXPECT_LE(c.action.strike.aim_deg, 360.0);
  EXPECT_NO_THROW((void)play(s, c.action, 1));
}

TEST(PlannerAgent, PlaysANineBallGameAgainstTheGhostBallToTheEnd) {
  AgentOptions planner = cheap();
  AgentOptions ghost;
  ghost.kind = AgentKind::ghost_ball;
  GameConfig c = default_config(GameKind::nine_ball);
  c.noise = tournament_noise();
  c.max_shots = 60;
  GameState s = new_game(c, 1);
  int planner_shots = 0;
  while (!s.over) {
    const std::uint64_t seed = stream_seed(1, static_cast<std::uint64_t>(s.shots));
    const Action a = choose_action(s.to_shoot == 0 ? planner : ghost, s, seed);
    planner_shots += s.to_shoot == 0 ? 1 : 0;
    s = play(s, a, seed).next;  // throws InvalidArgument for an illegal action
  }
  EXPECT_TRUE(s.over);
  EXPECT_GT(planner_shots, 0);
  EXPECT_LE(s.shots, 60);
}

// AgentOptions::seconds (agent.cpp, choose_in_time()): the rounds' options.
TEST(AgentSeconds, RoundOptionsScaleThePositionBudgetAndDropTheSeconds) {
  AgentOptions o = strongest_agent();  // 4,000 runs a plan, 1,000 a next-shot plan
  o.seconds = 0.5;
  const AgentOptions first = timed_round_options(o, 500);
  EXPECT_EQ(first.simulations, 500);
  EXPECT_EQ(first.position_simulations, kMinPlanSimulations);  // 125 scaled, raised to the floor
  EXPECT_EQ(first.seconds, 0.0);
  EXPECT_EQ(timed_round_options(o, 2000).position_simulations, kMinPlanSimulations);
  EXPECT_EQ(timed_round_options(o, 3000).position_simulations, 750);
  EXPECT_EQ(timed_round_options(o, 4000).position_simulations, 1000);
  AgentOptions plain = cheap();
  plain.simulations = 2000;
  EXPECT_EQ(timed_round_options(plain, 1000).position_simulations, 0);  // position play stays off
}

TEST(AgentSeconds, ATinyBudgetPlaysTheFirstRoundAsThatBudgetWould) {
  const GameState s = in_play({{0, {0.62, 0.62}}, {1, {0.45, 0.45}}, {2, {1.8, 0.9}}, {9, {2.2, 0.3}}});
  AgentOptions o = cheap();
  o.simulations = 4000;
  o.seconds = 1e-9;  // no second round fits
  const AgentChoice timed = choose(o, s, 5);
  const AgentChoice first = choose(timed_round_options(o, kFirstTimedRoundSimulations), s, 5);
  EXPECT_EQ(timed.action.strike, first.action.strike);
  EXPECT_NE(timed.reasoning.summary.find("seconds 1e-09: 1 round in"), std::string::npos) << timed.reasoning.summary;
  EXPECT_NE(timed.reasoning.summary.find("played at 500 runs"), std::string::npos) << timed.reasoning.summary;
  EXPECT_EQ(timed.reasoning.summary.rfind(first.reasoning.summary, 0), 0u) << timed.reasoning.summary;
}

TEST(AgentSeconds, RoomForEveryRoundPlaysAtSimulationsAsWithoutSeconds) {
  const GameState s = in_play({{0, {0.62, 0.62}}, {1, {0.45, 0.45}}, {2, {1.8, 0.9}}, {9, {2.2, 0.3}}});
  AgentOptions o = cheap();
  o.simulations = 1000;  // the cap: rounds at 500, then 1,000
  o.seconds = kMaxAgentSeconds;
  const AgentChoice timed = choose(o, s, 7);
  AgentOptions untimed = o;
  untimed.seconds = 0.0;
  const AgentChoice plain = choose(untimed, s, 7);
  EXPECT_EQ(timed.action.strike, plain.action.strike);
  EXPECT_NE(timed.reasoning.summary.find(": 2 rounds in"), std::string::npos) << timed.reasoning.summary;
  EXPECT_NE(timed.reasoning.summary.find("played at 1000 runs"), std::string::npos) << timed.reasoning.summary;
  // An agent that searches nothing ignores the budget.
  AgentOptions ghost;
  ghost.kind = AgentKind::ghost_ball;
  ghost.seconds = 1.0;
  EXPECT_EQ(choose(ghost, s, 7).reasoning.summary, "");
}

TEST(AgentSeconds, TheBreakIsTheRecommendedOneWhateverTheBudget) {
  const GameState s = new_game(default_config(GameKind::nine_ball));
  AgentOptions o = cheap();
  o.seconds = 0.5;
  const AgentChoice c = choose(o, s, 3);
  EXPECT_EQ(c.reasoning.summary, "break");  // no rounds
  EXPECT_EQ(c.action.strike, recommended_break(s).strike);
}

TEST(AgentSeconds, OutOfRangeIsRefusedNamingTheField) {
  const GameState s = in_play({{0, {0.62, 0.62}}, {1, {0.45, 0.45}}});
  for (const double bad : {-1.0, kMaxAgentSeconds * 2, std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity()}) {
    AgentOptions o = cheap();
    o.seconds = bad;
    test::expect_invalid("seconds", [&] { (void)choose(o, s, 1); });
  }
}

}  // namespace
}  // namespace cueball
