// Every agent (agent.hpp) is legal: in thousands of states of every
// discipline, drawn along random games (the random agent walks them through
// breaks, fouls, ball in hand, push-outs, calls, nominations, decisions and
// innings), each agent's action passes validate_action() and play() never
// throws InvalidArgument for it. The cheap agents (random, ghost-ball) act in
// every state; the searching ones (planner, safety planner, carom search,
// and the strongest agent's position play and ball in hand) at their
// smallest budgets in a stride of them, so that the file runs in
// seconds in Release and a tenth of it under the sanitizers
// (support/test_scale.hpp, spread_sample()).
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "cueball/agents/agent.hpp"
#include "cueball/core/random.hpp"
#include "cueball/planning/shot_planner.hpp"
#include "test_scale.hpp"

namespace cueball {
namespace {

// Games of at most this many steps: the states spread over many racks.
constexpr int kShotsAGame = 20;

// `count` states not over, along random games of `kind` with tournament
// noise (game g from new_game(config, g), at most kShotsAGame steps each).
std::vector<GameState> random_states(GameKind kind, int count) {
  AgentOptions random;
  random.kind = AgentKind::random;
  GameConfig config = default_config(kind);
  config.noise = tournament_noise();
  std::vector<GameState> states;
  const auto full = [&] { return states.size() >= static_cast<std::size_t>(count); };
  for (std::uint64_t game = 0; !full(); ++game) {
    GameState s = new_game(config, game);
    for (int k = 0; !s.over && k < kShotsAGame && !full(); ++k) {
      states.push_back(s);
      const std::uint64_t seed = stream_seed(game, static_cast<std::uint64_t>(k));
      s = play(s, choose_action(random, s, seed), seed).next;
    }
  }
  return states;
}

// Every `every`-th of `states`, and where that stride missed every state
// that asks one of the rarer things of an agent (the cue ball in hand, a
// decision, a call, a nomination, a push-out), the first state that does:
// the sanitizers' tenth of the states still reaches each of them (which
// ones a random game reaches depends on the engine's last digits; a
// snooker nomination, after a red is potted, is rare).
std::vector<GameState> spread_sample(const std::vector<GameState>& states, int every) {
  std::vector<std::array<bool, 5>> asks(states.size());
  for (std::size_t k = 0; k < states.size(); ++k) {
    const LegalActions legal = legal_actions(states[k]);
    asks[k] = {legal.ball_in_hand.has_value(), !legal.decisions.empty(), legal.call_required,
               legal.nominate_required, legal.push_out};
  }
  std::vector<bool> taken(states.size(), false);
  std::array<bool, 5> reached{};
  for (std::size_t k = 0; k < states.size(); k += static_cast<std::size_t>(every)) {
    taken[k] = true;
    for (std::size_t i = 0; i < reached.size(); ++i) reached[i] = reached[i] || asks[k][i];
  }
  std::vector<GameState> sample;
  for (std::size_t k = 0; k < states.size(); ++k) {
    for (std::size_t i = 0; i < reached.size(); ++i)
      if (asks[k][i] && !reached[i]) taken[k] = true, reached[i] = true;
    if (taken[k]) sample.push_back(states[k]);
  }
  return sample;
}

// What a discipline's states asked of the agents.
struct Tally {
  int states = 0, searched = 0, safeties = 0, strongest = 0;
  int in_hand = 0, decisions = 0, calls = 0, nominations = 0, push_outs = 0;
};

// The action must be legal and playable in `s`.
void expect_legal(const GameState& s, const Action& a, std::uint64_t seed, const std::string& who) {
  EXPECT_NO_THROW(validate_action(s, a)) << who;
  EXPECT_NO_THROW((void)play(s, a, seed)) << who;
}

AgentOptions smallest(AgentKind kind) {
  AgentOptions o;
  o.kind = kind;
  o.simulations = kind == AgentKind::carom_search ? 200 : kMinPlanSimulations;
  return o;
}

// Which states the searching agents act in: every `stride`-th state where
// the cue ball is not in hand, and the first `in_hand` states after the
// break where it is (placing it is the planner's dearest search: seconds).
struct Discipline {
  GameKind kind;
  int stride;
  int in_hand;
};

// Every agent's action: random and ghost-ball in every state, the searching
// agents in the states `d` names (the safety planner in every other of the
// strided ones, and in those in hand).
Tally check_agents(const Discipline& d, const std::vector<GameState>& states) {
  Tally t;
  const bool carom = d.kind == GameKind::three_cushion;
  int in_hand_left = d.in_hand;
  for (std::size_t k = 0; k < states.size(); ++k) {
    const GameState& s = states[k];
    const LegalActions legal = legal_actions(s);
    ++t.states;
    t.in_hand += legal.ball_in_hand ? 1 : 0;
    t.decisions += legal.decisions.empty() ? 0 : 1;
    t.calls += legal.call_required ? 1 : 0;
    t.nominations += legal.nominate_required ? 1 : 0;
    t.push_outs += legal.push_out ? 1 : 0;
    const std::uint64_t seed = stream_seed(7, k);
    const std::string where = std::string(to_string(d.kind)) + " state " + std::to_string(k) + ", ";
    expect_legal(s, random_action(s, seed), seed, where + "random");
    if (!carom) expect_legal(s, ghost_ball_action(s, seed), seed, where + "ghost_ball");
    const bool in_hand = legal.ball_in_hand && legal.shoot && s.phase != GamePhase::break_shot;
    const bool strided = !in_hand && k % static_cast<std::size_t>(d.stride) == 0;
    if (!strided && !(in_hand && in_hand_left > 0)) continue;
    in_hand_left -= in_hand ? 1 : 0;
    ++t.searched;
    if (carom) {
      expect_legal(s, carom_search_action(smallest(AgentKind::carom_search), s, seed), seed, where + "carom_search");
      continue;
    }
    expect_legal(s, planner_action(smallest(AgentKind::planner), s, seed), seed, where + "planner");
    if (in_hand || k % static_cast<std::size_t>(4 * d.stride) == 0) {
      // The strongest agent's options at the smallest budgets: position
      // play (leaves by the ghost ball), its ball in hand and its calls.
      AgentOptions strongest = strongest_agent();
      strongest.simulations = kMinPlanSimulations;
      strongest.position_simulations = kMinPlanSimulations;
      expect_legal(s, choose_action(strongest, s, seed), seed, where + "strongest");
      ++t.strongest;
    }
    if (strided && k % static_cast<std::size_t>(2 * d.stride) != 0) continue;
    const PlannerChoice c = safety_planner_choice(smallest(AgentKind::safety_planner), s, seed);
    expect_legal(s, c.action, seed, where + "safety_planner: " + c.detail);
    t.safeties += c.kind == PlannerChoice::Kind::safety ? 1 : 0;
  }
  return t;
}

TEST(AgentLegality, EveryAgentIsLegalInRandomStatesOfEveryDiscipline) {
  // 600 states a discipline (3,000 in all), under the sanitizers a tenth of
  // them spread over the same games (spread_sample()); the cue ball placed
  // by the planners in one state (9-ball's: the same search places it in
  // every discipline; test_planner_agent.cpp checks the regions).
  const int count = 600, every = test::scaled(1, 10);
  const std::vector<Discipline> disciplines{
      {GameKind::nine_ball, test::scaled(30, 6), 1},  {GameKind::ten_ball, test::scaled(30, 6), 0},
      {GameKind::eight_ball, test::scaled(30, 6), 0}, {GameKind::snooker, test::scaled(60, 12), 0},
      {GameKind::three_cushion, test::scaled(40, 8), 0},
  };
  Tally all;
  for (const Discipline& d : disciplines) {
    SCOPED_TRACE(to_string(d.kind));
    const std::vector<GameState> states = spread_sample(random_states(d.kind, count), every);
    const Tally t = check_agents(d, states);
    EXPECT_GE(t.states, count / every);
    EXPECT_GT(t.searched, 0);
    if (d.kind != GameKind::three_cushion) {
      EXPECT_GT(t.strongest, 0);
    }
    all.in_hand += t.in_hand;
    all.decisions += t.decisions;
    all.calls += t.calls;
    all.nominations += t.nominations;
    all.push_outs += t.push_outs;
    all.safeties += t.safeties;
  }
  // The random games reached what the rules ask of an agent, and the safety
  // planner searched and played safeties among them.
  EXPECT_GT(all.in_hand, 0);
  EXPECT_GT(all.decisions, 0);
  EXPECT_GT(all.calls, 0);
  EXPECT_GT(all.nominations, 0);
  EXPECT_GT(all.push_outs, 0);
  EXPECT_GT(all.safeties, 0);
}

}  // namespace
}  // namespace cueball
