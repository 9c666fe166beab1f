// Choosing an agent by name, and what the pool agents share: the break, the
// decision policy, the balls a shot may aim at, a plain hit (agent.hpp).
#include "cueball/agents/agent.hpp"

#include "cueball/games/break_shot.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>

#include "core/enum_names.hpp"
#include "cueball/core/errors.hpp"

namespace cueball {

namespace {
constexpr std::array kAgentKinds{AgentKind::random, AgentKind::ghost_ball, AgentKind::planner, AgentKind::carom_search,
                                 AgentKind::safety_planner};
}  // namespace

const char* to_string(AgentKind kind) {
  switch (kind) {
    case AgentKind::random: return "random";
    case AgentKind::ghost_ball: return "ghost_ball";
    case AgentKind::planner: return "planner";
    case AgentKind::carom_search: return "carom_search";
    case AgentKind::safety_planner: return "safety_planner";
  }
  return "?";
}
std::optional<AgentKind> agent_kind_from_string(std::string_view name) { return value_named(kAgentKinds, name); }
std::string agent_kind_names() { return names_of(kAgentKinds, ""); }

AgentOptions strongest_agent() {
  AgentOptions o;
  o.kind = AgentKind::safety_planner;
  o.simulations = kStrongestSimulations;
  o.position_simulations = kStrongestPositionSimulations;
  o.position_valuation = LeaveValuation::ghost_ball;
  o.position_noisy_leaves = kStrongestNoisyLeaves;
  o.position_candidate_noisy_leaves = kStrongestCandidateNoisyLeaves;
  o.position_depth = kStrongestDepth;
  o.position_finalists = kStrongestFinalists;
  o.position_varied_shots = kStrongestVariedShots;
  o.fallback_kinds = {ShotKind::kick};
  o.game_ball_combinations = true;
  return o;
}

std::optional<AgentOptions> agent_named(std::string_view name) {
  if (name == "strongest") return strongest_agent();
  const std::optional<AgentKind> kind = agent_kind_from_string(name);
  if (!kind) return std::nullopt;
  AgentOptions o;
  o.kind = *kind;
  return o;
}

std::string agent_names() { return agent_kind_names() + ", strongest"; }

void validate(const AgentOptions& options) {
  if (options.simulations < 1 || options.simulations > 1'000'000)
    throw InvalidArgument("simulations", std::to_string(options.simulations) + " is out of range [1, 1000000]");
  if (options.position_simulations < 0 || options.position_simulations > 1'000'000)
    throw InvalidArgument("position_simulations",
                          std::to_string(options.position_simulations) + " is out of range [0, 1000000]");
  if (options.position_noisy_leaves < 0 || options.position_noisy_leaves > kMaxPositionNoisyLeaves)
    throw InvalidArgument("position_noisy_leaves", std::to_string(options.position_noisy_leaves) +
                                                       " is out of range [0, " +
                                                       std::to_string(kMaxPositionNoisyLeaves) + "]");
  if (options.position_candidate_noisy_leaves < 0 || options.position_candidate_noisy_leaves > kMaxPositionNoisyLeaves)
    throw InvalidArgument("position_candidate_noisy_leaves", std::to_string(options.position_candidate_noisy_leaves) +
                                                                 " is out of range [0, " +
                                                                 std::to_string(kMaxPositionNoisyLeaves) + "]");
  if (options.position_depth < 1 || options.position_depth > kMaxPositionDepth)
    throw InvalidArgument("position_depth", std::to_string(options.position_depth) + " is out of range [1, " +
                                                std::to_string(kMaxPositionDepth) + "]");
  if (options.position_depth > max_position_depth(options.position_valuation))
    throw InvalidArgument("position_depth", std::to_string(options.position_depth) + " is out of range [1, " +
                                                std::to_string(kMaxWindowsDepth) +
                                                "] with position_valuation windows (deeper: ghost_ball)");
  if (options.position_varied_shots < 1 || options.position_varied_shots > kMaxPositionVariedShots)
    throw InvalidArgument("position_varied_shots", std::to_string(options.position_varied_shots) +
                                                       " is out of range [1, " +
                                                       std::to_string(kMaxPositionVariedShots) + "]");
  if (options.position_finalists < 1 || options.position_finalists > kMaxPositionFinalists)
    throw InvalidArgument("position_finalists", std::to_string(options.position_finalists) + " is out of range [1, " +
                                                    std::to_string(kMaxPositionFinalists) + "]");
  if (!(options.seconds >= 0.0 && options.seconds <= kMaxAgentSeconds))
    throw InvalidArgument("seconds", std::to_string(options.seconds) + " is out of range [0, 3600] (0: no time budget)");
  if (options.noise) validate(*options.noise);
  if (options.kinds.empty()) throw InvalidArgument("kinds", "is empty; allowed: one or more of " + shot_kind_names());
  const auto no_repeat = [](const std::vector<ShotKind>& kinds, const char* field) {
    for (std::size_t i = 0; i < kinds.size(); ++i)
      for (std::size_t j = i + 1; j < kinds.size(); ++j)
        if (kinds[i] == kinds[j])
          throw InvalidArgument(field, std::string(to_string(kinds[i])) + " is given twice");
  };
  no_repeat(options.kinds, "kinds");
  no_repeat(options.fallback_kinds, "fallback_kinds");
}

namespace {

// A planner agent's reasoning: its one-line detail and the options it
// weighed (the chosen one alone when it lists none).
Reasoning reasoning_of(PlannerChoice&& c) {
  Reasoning r;
  r.summary = std::move(c.detail);
  r.considered = std::move(c.considered);
  if (r.considered.empty() && c.success_probability >= 0.0)
    r.considered.push_back({r.summary, c.success_probability, c.next_success_probability});
  return r;
}

Reasoning reasoning_of(const CaromSearchResult& c) {
  Reasoning r;
  const double share = c.noisy_tries > 0 ? static_cast<double>(c.noisy_points) / c.noisy_tries : -1.0;
  r.summary = std::string("carom_search: the strike found ") + (c.point ? "scores" : "does not score") +
              " noise-free; " + std::to_string(c.noisy_points) + " of " + std::to_string(c.noisy_tries) +
              " noisy repeats score (" + std::to_string(c.simulations) + " engine runs)";
  r.considered.push_back({"the strike found", share, c.next_point_rate});
  return r;
}

}  // namespace

AgentOptions timed_round_options(const AgentOptions& options, int simulations) {
  AgentOptions r = options;
  r.seconds = 0.0;
  r.simulations = simulations;
  if (options.position_simulations > 0) {
    const long long scaled =
        static_cast<long long>(options.position_simulations) * simulations / std::max(options.simulations, 1);
    r.position_simulations = static_cast<int>(std::clamp<long long>(
        scaled, std::min(kMinPlanSimulations, options.position_simulations), options.position_simulations));
  }
  return r;
}

// AgentOptions::seconds: rounds at doubling budgets while the last round's
// time, scaled to the next round's runs (a plan's time grows with its runs,
// a little less than in proportion), says the next one ends within the
// budget; the last round takes the runs the time left allows.
TimedRounds plan_in_time(const AgentOptions& options, const std::function<void(const AgentOptions&)>& round) {
  using Clock = std::chrono::steady_clock;
  const auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  const Clock::time_point start = Clock::now();
  TimedRounds t;
  t.budget = options.seconds;
  t.simulations = std::min(options.simulations, kFirstTimedRoundSimulations);
  for (;;) {
    const Clock::time_point round_start = Clock::now();
    round(timed_round_options(options, t.simulations));
    ++t.rounds;
    const double took = seconds_since(round_start);
    if (t.simulations >= options.simulations) break;
    // The next round doubles the runs, or takes what the time left allows
    // at this round's pace when that is less, if it is a quarter more.
    const double left = options.seconds - seconds_since(start);
    const double affordable = left > 0.0 && took > 0.0 ? t.simulations * (left / took) : 0.0;
    const long long next = std::min<long long>(
        {2LL * t.simulations, options.simulations, static_cast<long long>(std::min(affordable, 2e9))});
    if (next < t.simulations + t.simulations / 4) break;
    t.simulations = static_cast<int>(next);
  }
  t.seconds = seconds_since(start);
  return t;
}

std::string TimedRounds::summary() const {
  char text[160];
  std::snprintf(text, sizeof text, "seconds %g: %d round%s in %.3g s, played at %d runs", budget, rounds,
                rounds == 1 ? "" : "s", seconds, simulations);
  return text;
}

namespace {

AgentChoice choose_at_budget(const AgentOptions& options, const GameState& state, std::uint64_t seed) {
  switch (options.kind) {
    case AgentKind::random: return {random_action(state, seed), {}};          // nothing weighed
    case AgentKind::ghost_ball: return {ghost_ball_action(state, seed), {}};  // a rule, nothing weighed
    case AgentKind::planner: {
      PlannerChoice c = planner_choice(options, state, seed);
      Action a = c.action;
      return {std::move(a), reasoning_of(std::move(c))};
    }
    case AgentKind::carom_search: {
      const CaromSearchResult c = carom_search(options, state, seed);
      return {c.action, reasoning_of(c)};
    }
    case AgentKind::safety_planner: {
      PlannerChoice c = safety_planner_choice(options, state, seed);
      Action a = c.action;
      return {std::move(a), reasoning_of(std::move(c))};
    }
  }
  throw InvalidArgument("kind", "unknown agent; allowed: " + agent_kind_names());
}

// Whether the agent breaks with break_action(), which no budget changes.
bool plays_fixed_break(const AgentOptions& options, const GameState& state) {
  if (state.phase != GamePhase::break_shot || options.kind == AgentKind::carom_search) return false;
  const LegalActions legal = legal_actions(state);
  return legal.shoot && plays_break_action(state, legal);
}

AgentChoice choose_in_time(const AgentOptions& options, const GameState& state, std::uint64_t seed) {
  AgentChoice choice;
  const TimedRounds t = plan_in_time(
      options, [&](const AgentOptions& round) { choice = choose_at_budget(round, state, seed); });
  choice.reasoning.summary += (choice.reasoning.summary.empty() ? "" : "; ") + t.summary();
  return choice;
}

}  // namespace

AgentChoice choose(const AgentOptions& options, const GameState& state, std::uint64_t seed) {
  validate(options);
  if (state.over) throw InvalidArgument("state", "the game is over (" + state.end_reason + ")");
  const bool searches = options.kind == AgentKind::planner || options.kind == AgentKind::safety_planner ||
                        options.kind == AgentKind::carom_search;
  if (options.seconds > 0.0 && searches && !plays_fixed_break(options, state)) return choose_in_time(options, state, seed);
  return choose_at_budget(options, state, seed);
}

Action choose_action(const AgentOptions& options, const GameState& state, std::uint64_t seed) {
  return choose(options, state, seed).action;
}

// ------------------------------------------------------------------ shared by the pool agents

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kClearElevationsDeg[] = {0.0, 2.0, 5.0, 10.0, 15.0, 20.0, 25.0, 30.0};

bool contains(const std::vector<int>& v, int id) { return std::find(v.begin(), v.end(), id) != v.end(); }

const SimulationBall* ball(const Scenario& table, int id) { return find_ball(table.balls, id); }


}  // namespace

int nearest_pocket(const Scenario& table, int id) {
  const SimulationBall* b = ball(table, id);
  if (!b) throw InvalidArgument("ball", std::to_string(id) + " is not on the table");
  int best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < table.table.pockets.size(); ++k) {
    const double d = norm(table.table.pockets[k].centre - b->state.position);
    if (d < best_d) {
      best_d = d;
      best = static_cast<int>(k);
    }
  }
  return best;
}

bool plays_break_action(const GameState& state, const LegalActions& legal) {
  return state.phase == GamePhase::break_shot && state.config.kind != GameKind::three_cushion &&
         !legal.call_required && !legal.nominate_required;
}

Action break_action(const GameState& state) {
  const LegalActions legal = legal_actions(state);
  if (!legal.shoot) throw InvalidArgument("state", "a decision is due, not a break");
  Action a = recommended_break(state);  // games/break_shot.hpp: measured in docs/break.md
  if (legal.call_required || (legal.nominate_required && !legal.nominable.empty())) {
    // No discipline asks for a call or a nomination on its opening shot
    // today; should a variant do so, the ball on nearest the foot spot.
    const std::vector<int> targets = shot_targets(state, legal);
    if (targets.empty()) throw InvalidArgument("state", "no ball on to break at");
    const Vec2 foot = foot_spot(state.table.table);
    int apex = targets.front();
    double apex_d = std::numeric_limits<double>::infinity();
    for (const int id : targets) {
      const double d = norm(ball(state.table, id)->state.position - foot);
      if (d < apex_d) {
        apex_d = d;
        apex = id;
      }
    }
    if (legal.call_required) {
      a.called_ball = contains(legal.callable, apex) || legal.callable.empty() ? apex : legal.callable.front();
      a.called_pocket = nearest_pocket(state.table, *a.called_ball);
    }
    if (legal.nominate_required) a.nominate = contains(legal.nominable, apex) ? apex : legal.nominable.front();
  }
  return a;
}

Decision decision_by_policy(const std::vector<Decision>& open, bool table_good) {
  if (open.empty()) throw InvalidArgument("decisions", "no decision is open");
  const auto is_open = [&](Decision d) { return std::find(open.begin(), open.end(), d) != open.end(); };
  const std::array good{Decision::play, Decision::respot_eight};
  const std::array bad{Decision::restore, Decision::rerack_and_break, Decision::rerack, Decision::pass};
  if (table_good) {
    for (const Decision d : good)
      if (is_open(d)) return d;
  } else {
    for (const Decision d : bad)
      if (is_open(d)) return d;
  }
  return open.front();
}

Scenario with_cue_ball_at(const Scenario& table, int cue_ball, Vec2 spot) {
  Scenario out = table;
  SimulationBall b;
  b.id = cue_ball;
  b.name = "cue";
  if (const SimulationBall* lying = find_ball(table.balls, cue_ball)) b = *lying;
  b.state = BallState{};
  b.state.position = spot;
  std::erase_if(out.balls, [&](const SimulationBall& x) { return x.id == cue_ball; });
  out.balls.insert(out.balls.begin(), b);
  return out;
}

std::vector<int> shot_targets(const GameState& state, const LegalActions& legal) {
  const Scenario& table = state.table;
  const auto on_table_only = [&](const std::vector<int>& ids) {
    std::vector<int> out;
    for (const int id : ids)
      if (id != legal.cue_ball && ball(table, id)) out.push_back(id);
    return out;
  };
  std::vector<int> targets = on_table_only(legal.nominate_required ? legal.nominable : legal.on);
  if (legal.call_required) {
    std::vector<int> callable;
    for (const int id : targets)
      if (contains(legal.callable, id)) callable.push_back(id);
    if (!callable.empty()) targets = std::move(callable);
  }
  if (legal.cue_must_leave_kitchen) {  // WPA 1.6: a ball behind the head string may not be hit first
    std::vector<int> beyond;
    const double head = head_string_x(table.table);
    for (const int id : targets)
      if (ball(table, id)->state.position.x >= head) beyond.push_back(id);
    if (!beyond.empty()) targets = std::move(beyond);
  }
  return targets;
}

std::optional<double> lowest_clear_elevation_deg(const Scenario& table, int cue_ball, ShotAction action) {
  const double radius = table.settings.parameters.ball.radius;
  for (const double e : kClearElevationsDeg) {
    action.elevation_deg = e;
    if (!cue_obstructed(table.table, table.balls, cue_ball, to_strike(action, radius), table.settings.parameters.ball))
      return e;
  }
  return std::nullopt;
}

std::optional<ShotAction> safe_hit(const Scenario& table, int cue_ball, const std::vector<int>& targets, int& target) {
  const SimulationBall* cue = ball(table, cue_ball);
  if (!cue) return std::nullopt;
  const Vec2 C = cue->state.position;
  const double R = table.settings.parameters.ball.radius;
  int nearest = -1, nearest_clear = -1;
  double d_nearest = std::numeric_limits<double>::infinity(), d_clear = d_nearest;
  for (const int id : targets) {
    const SimulationBall* b = ball(table, id);
    if (!b || id == cue_ball) continue;
    const Vec2 O = b->state.position;
    const double d = norm(O - C);
    if (d < d_nearest) {
      d_nearest = d;
      nearest = id;
    }
    if (path_clear(table.balls, C, O, 2.0 * R, {cue_ball, id}) && d < d_clear) {
      d_clear = d;
      nearest_clear = id;
    }
  }
  target = nearest_clear >= 0 ? nearest_clear : nearest;
  if (target < 0) return std::nullopt;
  const Vec2 O = ball(table, target)->state.position;
  ShotAction a;
  a.speed = kSafeHitSpeed;
  a.aim_deg = std::atan2(O.y - C.y, O.x - C.x) / kDeg;
  a.elevation_deg = lowest_clear_elevation_deg(table, cue_ball, a).value_or(kClearElevationsDeg[std::size(kClearElevationsDeg) - 1]);
  return a;
}

}  // namespace cueball
