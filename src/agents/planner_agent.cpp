// The planner agent (agent.hpp): plan_shot over the legal targets, with
// position play, ball-in-hand placement, calls, nominations, a kick when
// nothing pots, a plain hit when even that fails, and the decisions by a
// documented simple policy (planner_choice()'s comment in agent.hpp).
//
// One decision is a short driver over a Turn and named steps: read the
// legal actions; decide (a decision is due), or break, or plan a pot of
// each set of kinds in turn (in hand, for position, or plain), else a
// safety; then the call and the nomination.
//
// Where the region of a ball in hand is `anywhere`, plan_ball_in_hand is
// given no region (the whole bed, its own default): a region adds spots
// where the line from the ghost ball first enters it, which for the whole
// bed is the ghost ball itself.
#include <algorithm>
#include <chrono>

#include "cueball/agents/agent.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/core/random.hpp"
#include "cueball/planning/ball_in_hand.hpp"
#include "cueball/planning/position_play.hpp"

namespace cueball {

namespace {

constexpr int kPlacementAttempts = 10000;
// Snooker ids (game.hpp): reds 1..15, yellow 16 .. black 21.
constexpr int kLastRed = 15, kYellow = 16, kBlack = 21;
constexpr int kEight = 8;

bool contains(const std::vector<int>& v, int id) { return std::find(v.begin(), v.end(), id) != v.end(); }

bool no_noise(const CueStrikeNoise& n) {
  return n.speed == 0.0 && n.aim == 0.0 && n.elevation == 0.0 && n.side_offset == 0.0 && n.height_offset == 0.0;
}

// One decision: filled by the steps below, in order.
struct Turn {
  const AgentOptions& options;
  const GameState& state;
  std::uint64_t seed = 0;
  LegalActions legal;
  CueStrikeNoise noise;
  std::vector<int> targets;
  PlannerChoice choice;
};

// A pot planned for one set of kinds.
struct Pot {
  bool found = false;
  PlannedShot shot;
  std::optional<Vec2> place;
  double next = -1.0;
  long long simulations = 0;
  std::string detail;
  std::vector<ConsideredOption> considered;  // the shot, then the plan's alternatives
};

PlanRequest plan_request(const Turn& t, const std::vector<int>& targets, const std::vector<ShotKind>& kinds,
                         std::uint64_t seed) {
  PlanRequest q;
  q.cue_ball = t.legal.cue_ball;
  if (targets.size() == 1)
    q.target = targets.front();
  else
    q.targets = targets;
  q.kinds = kinds;
  q.call_shot = t.legal.call_required;  // the pocket is called (WPA 1.6): a pot counts only there
  q.noise = t.noise;
  q.seed = seed;
  q.simulations = t.options.simulations;
  return q;
}

std::string fmt_spot(Vec2 p) {
  char b[64];
  std::snprintf(b, sizeof b, "in hand at (%.3f, %.3f): ", p.x, p.y);
  return b;
}

std::string describe(const PlannedShot& s) {
  char b[160];
  std::snprintf(b, sizeof b, " (window %.3f, screen %.3f)", s.window_probability, s.success_probability);
  return std::string(to_string(s.kind)) + " " + std::to_string(s.target) +
         (s.intermediate_ball >= 0 ? " via " + std::to_string(s.intermediate_ball) : "") + " " + s.pocket_name +
         (s.cushion.empty() ? "" : " off " + s.cushion) + b;
}

// The shots a plan weighed, the chosen one first, at most kConsideredShown
// (with position play each with its leave's next-shot estimate).
constexpr std::size_t kConsideredShown = 6;
std::vector<ConsideredOption> considered_of(const ShotPlanResult& plan, const Leave* leave,
                                            const std::vector<Leave>& alternative_leaves) {
  std::vector<ConsideredOption> out;
  const auto next_of = [](const Leave* l) { return l ? (l->next_feasible ? l->next_success_probability : 0.0) : -1.0; };
  out.push_back({describe(plan.shot), plan.shot.success_probability, next_of(leave)});
  for (std::size_t k = 0; k < plan.alternatives.size() && out.size() < kConsideredShown; ++k)
    out.push_back({describe(plan.alternatives[k]), plan.alternatives[k].success_probability,
                   next_of(k < alternative_leaves.size() ? &alternative_leaves[k] : nullptr)});
  return out;
}

// The next targets after a shot at any of `targets`: with one, next_targets();
// with several, the union of each one's sets, set by set (the 8-ball group
// after any of its balls, the colours after any red).
std::vector<std::vector<int>> next_targets_of(const GameState& state, const std::vector<int>& targets) {
  if (targets.size() == 1) return next_targets(state, targets.front());
  std::vector<std::vector<int>> sets;
  for (const int target : targets) {
    const std::vector<std::vector<int>> own = next_targets(state, target);
    for (std::size_t k = 0; k < own.size(); ++k) {
      if (sets.size() <= k) sets.emplace_back();
      for (const int id : own[k])
        if (!contains(sets[k], id)) sets[k].push_back(id);
    }
  }
  for (std::vector<int>& set : sets) std::sort(set.begin(), set.end());
  return sets;
}

// A pot of the targets with these kinds: in hand (plan_ball_in_hand), for
// position (plan_shot_for_position), or plain (plan_shot).
Pot plan_pot(const Turn& t, const std::vector<ShotKind>& kinds) {
  Pot pot;
  const PlanRequest q = plan_request(t, t.targets, kinds, t.seed);
  const bool in_hand = t.legal.ball_in_hand.has_value();
  const bool position = t.options.position_simulations > 0;
  try {
    if (in_hand || position) {
      PositionRequest p;
      p.shot = q;
      p.next_targets = next_targets_of(t.state, t.targets);
      p.next_simulations = position ? t.options.position_simulations : kInHandNextSimulations;
      p.noisy_leaves = t.options.position_noisy_leaves;
      p.candidate_noisy_leaves = t.options.position_candidate_noisy_leaves;
      p.depth = t.options.position_depth;
      p.valuation = t.options.position_valuation;
      const std::optional<int> game = game_ball(t.state);
      if (t.options.game_ball_combinations && t.options.position_valuation == LeaveValuation::ghost_ball && game &&
          find_ball(t.state.table.balls, *game)) {
        p.game_ball = game;
        p.later_shot_chance = kRunOutShotChance;
      }
      p.finalists = t.options.position_finalists;
      p.varied_shots = t.options.position_varied_shots;
      PositionPlanResult pr;
      if (in_hand) {
        BallInHandRequest h{p, std::nullopt};
        if (t.legal.ball_in_hand->kind != PlacementRegion::Kind::anywhere) h.region = t.legal.ball_in_hand;
        BallInHandResult r = plan_ball_in_hand(t.state.table, h);
        pot.place = r.cue_ball;
        pot.detail = fmt_spot(r.cue_ball);
        pr = std::move(r.plan);
      } else {
        pr = plan_shot_for_position(t.state.table, p);
      }
      pot.next = pr.leave.next_feasible ? pr.leave.next_success_probability : 0.0;
      pot.considered = considered_of(pr.plan, &pr.leave, pr.alternative_leaves);
      pot.shot = std::move(pr.plan.shot);
      pot.simulations = pr.plan.simulations;
    } else {
      ShotPlanResult r = plan_shot(t.state.table, q);
      pot.considered = considered_of(r, nullptr, {});
      pot.shot = std::move(r.shot);
      pot.simulations = r.simulations;
    }
    pot.found = true;
    pot.detail += describe(pot.shot);
  } catch (const NoFeasibleShot& e) {
    pot.simulations = t.options.simulations;  // the API does not report them: the budget is the upper bound
    pot.detail = std::string(e.what()).substr(0, 2000);
  }
  return pot;
}

// Step: a decision by decision_by_policy(), the table good when the best
// pot planned from it as it stands succeeds at least kPlannerGoodTable.
void decide(Turn& t) {
  GameState as_is = t.state;
  as_is.phase = GamePhase::play;
  as_is.decisions.clear();
  const LegalActions then = legal_actions(as_is);
  const std::vector<int> targets = shot_targets(as_is, then);
  Scenario table = as_is.table;
  bool playable = !targets.empty();
  if (playable && then.ball_in_hand) {
    const std::optional<Vec2> spot = ghost_ball_in_hand_spot(table, then.cue_ball, targets, *then.ball_in_hand);
    if (spot) table = with_cue_ball_at(table, then.cue_ball, *spot);
  }
  playable = playable && find_ball(table.balls, then.cue_ball) != nullptr;
  double p = 0.0;
  if (playable) {
    Turn probe{t.options, as_is, t.seed, then, t.noise, targets, {}};
    try {
      const ShotPlanResult r = plan_shot(table, plan_request(probe, targets, t.options.kinds, stream_seed(t.seed, 1)));
      p = r.shot.success_probability;
      t.choice.simulations += r.simulations;
    } catch (const NoFeasibleShot&) {
      t.choice.simulations += t.options.simulations;
    }
  }
  t.choice.kind = PlannerChoice::Kind::decision;
  t.choice.success_probability = p;
  t.choice.action.decision = decision_by_policy(t.legal.decisions, p >= kPlannerGoodTable);
  t.choice.detail = std::string(to_string(*t.choice.action.decision)) + ": the best pot from the table as it stands " +
                    (playable ? "succeeds " + std::to_string(p) : "is none");
}

// Step: a pot of options.kinds, then of options.fallback_kinds.
bool pot(Turn& t) {
  std::string why;
  for (int round = 0; round < 2; ++round) {
    const std::vector<ShotKind>& kinds = round == 0 ? t.options.kinds : t.options.fallback_kinds;
    if (kinds.empty()) continue;
    const Pot p = plan_pot(t, kinds);
    t.choice.simulations += p.simulations;
    if (!p.found) {
      why += (why.empty() ? "" : "; fallback: ") + p.detail;
      continue;
    }
    t.choice.kind = round == 0 ? PlannerChoice::Kind::pot : PlannerChoice::Kind::fallback;
    t.choice.action.strike = p.shot.strike;
    t.choice.action.place = p.place;
    t.choice.success_probability = p.shot.success_probability;
    t.choice.next_success_probability = p.next;
    t.choice.detail = (round == 0 ? "" : "fallback: ") + p.detail;
    t.choice.considered = p.considered;
    if (t.legal.call_required) {
      t.choice.action.called_ball = p.shot.target;
      t.choice.action.called_pocket = p.shot.pocket;
    }
    if (t.legal.nominate_required) t.choice.action.nominate = p.shot.target;
    return true;
  }
  t.choice.detail = why;
  return false;
}

// Step (AgentOptions::game_ball_combinations): the game ball by a
// combination through the ball on, played where no pot was found or where
// its chance beats the run-out's from the pot found (that pot's chance
// times its leave's value, times kRunOutShotChance for each ball left after
// the shots they cover: run_out_chance()) and is at least kSafetyThreshold
// (below it the safety planner would weigh a safety against the
// combination, not against the sure pot it replaced: a leave valued 0 by
// the ghost ball may still have a bank). True when it is played.
bool game_ball_combination(Turn& t, bool potted) {
  if (!t.options.game_ball_combinations) return false;
  long long simulations = 0;
  std::optional<GameBallCombination> c = plan_game_ball_combination(
      t.state, t.legal, plan_request(t, t.targets, {ShotKind::combination}, t.seed), simulations);
  t.choice.simulations += simulations;
  if (!c) return false;
  const double p = c->shot.success_probability;
  if (potted) {
    const bool leave_valued = t.choice.next_success_probability >= 0.0;
    const int covered = 1 + (leave_valued ? t.options.position_depth : 0);
    const double run_out =
        run_out_chance(t.choice.success_probability, leave_valued ? t.choice.next_success_probability : 1.0,
                       static_cast<int>(object_balls(t.state).size()) - covered);
    char b[160];
    std::snprintf(b, sizeof b, "the game ball by a combination %.3f against a run-out %.3f", p, run_out);
    if (p <= run_out || p < kSafetyThreshold) {  // under 1/2 a pot found is kept (the safety planner's line)
      t.choice.detail += std::string("; ") + b;
      return false;
    }
    t.choice.detail = std::string(b) + "; instead of " + t.choice.detail;
  } else {
    t.choice.detail = "no pot of the ball on: " + t.choice.detail;
  }
  t.choice.kind = PlannerChoice::Kind::pot;
  t.choice.action = Action{};
  t.choice.action.strike = c->shot.strike;
  t.choice.action.place = c->place;
  t.choice.success_probability = p;
  t.choice.next_success_probability = -1.0;  // the rack is won: no next shot
  t.choice.detail = (c->place ? fmt_spot(*c->place) : std::string()) + describe(c->shot) + " (" + t.choice.detail + ")";
  t.choice.considered.insert(t.choice.considered.begin(), ConsideredOption{describe(c->shot), p, -1.0});
  if (t.legal.call_required) {
    t.choice.action.called_ball = c->shot.target;
    t.choice.action.called_pocket = c->shot.pocket;
  }
  return true;
}

// Step: nothing pots: a plain hit of a target (from the ghost-ball spot, a
// random free spot, or where the cue ball lies, when in hand), announced as
// a push-out when one may be.
void safety(Turn& t) {
  Scenario table = t.state.table;
  const int cue = t.legal.cue_ball;
  if (t.legal.ball_in_hand) {
    std::optional<Vec2> spot = ghost_ball_in_hand_spot(table, cue, t.targets, *t.legal.ball_in_hand);
    const SimulationBall* lying = find_ball(table.balls, cue);
    if (!spot && !(lying && in_region(table.table, *t.legal.ball_in_hand, lying->state.position))) {
      RandomStream rng(stream_seed(t.seed, 2));
      std::vector<Vec2> others;
      for (const SimulationBall& b : table.balls)
        if (b.id != cue) others.push_back(b.state.position);
      spot = random_free_spot(table.table, others, table.table.ball.radius, rng, kPlacementAttempts,
                              *t.legal.ball_in_hand);
      if (!spot && !lying) throw InvalidArgument("state", "no free spot for the cue ball in its region");
    }
    if (spot) {
      table = with_cue_ball_at(table, cue, *spot);
      t.choice.action.place = spot;
    }
  }
  int ball = -1;
  const std::optional<ShotAction> hit = safe_hit(table, cue, t.targets, ball);
  if (!hit) throw InvalidArgument("state", "no ball on to play at");
  t.choice.kind = PlannerChoice::Kind::safety;
  t.choice.action.strike = *hit;
  t.choice.action.push_out = t.legal.push_out;
  t.choice.detail = "safety: a plain hit of the " + std::to_string(ball) + (t.legal.push_out ? ", pushed out" : "") +
                    " (" + t.choice.detail + ")";
  if (t.legal.call_required) {
    t.choice.action.called_ball = contains(t.legal.callable, ball) || t.legal.callable.empty() ? ball
                                                                                               : t.legal.callable.front();
    t.choice.action.called_pocket = nearest_pocket(table, *t.choice.action.called_ball);
  }
  if (t.legal.nominate_required && !t.legal.nominable.empty())
    t.choice.action.nominate = contains(t.legal.nominable, ball) ? ball : t.legal.nominable.front();
}

}  // namespace

CueStrikeNoise planning_noise(const AgentOptions& options, const GameState& state) {
  if (options.noise) return *options.noise;
  return no_noise(state.config.noise) ? tournament_noise() : state.config.noise;
}

std::vector<std::vector<int>> next_targets(const GameState& state, int target) {
  std::vector<int> ids = object_balls(state);
  std::sort(ids.begin(), ids.end());
  std::vector<std::vector<int>> sets;
  const auto add = [&](std::vector<int> set) {
    if (!set.empty()) sets.push_back(std::move(set));
  };
  switch (state.config.kind) {
    case GameKind::nine_ball:
    case GameKind::ten_ball:  // the lowest ball on (WPA 2.1, 9.1), one at a time
      for (const int id : ids)
        if (id != target) add({id});
      break;
    case GameKind::eight_ball: {  // the group (WPA 3.4), then the 8 (WPA 3.1)
      Group g = state.groups[state.to_shoot == 0 ? 0 : 1];
      if (g == Group::none && target != kEight) g = target < kEight ? Group::solids : Group::stripes;
      std::vector<int> group;
      for (const int id : ids)
        if (id != target && id != kEight &&
            ((g == Group::solids && id < kEight) || (g == Group::stripes && id > kEight)))
          group.push_back(id);
      add(group);
      if (target != kEight && contains(ids, kEight)) add({kEight});
      break;
    }
    case GameKind::snooker: {  // a red, then a colour (WPBSA 3.4); the clearance in order
      std::vector<int> reds, colours;
      for (const int id : ids) {
        if (id == target) continue;
        if (id <= kLastRed) reds.push_back(id);
        else if (id >= kYellow && id <= kBlack) colours.push_back(id);
      }
      if (target <= kLastRed) add(colours);
      else if (!reds.empty()) add(reds);
      else
        for (const int id : colours) add({id});
      break;
    }
    case GameKind::three_cushion: break;  // no pots
  }
  return sets;
}

PlannerChoice planner_choice(const AgentOptions& options, const GameState& state, std::uint64_t seed) {
  if (state.over) throw InvalidArgument("state", "the game is over (" + state.end_reason + ")");
  return planner_choice(options, state, legal_actions(state), seed);
}

PlannerChoice planner_choice(const AgentOptions& options, const GameState& state, const LegalActions& legal,
                             std::uint64_t seed) {
  validate(options);
  if (state.over) throw InvalidArgument("state", "the game is over (" + state.end_reason + ")");
  Turn t{options, state, seed, legal, planning_noise(options, state), {}, {}};
  if (state.config.kind == GameKind::three_cushion) {
    // carom_search at the planner's budget, without its position play
    // (measured at equal runs, it did not gain: docs/planner-benchmark.md).
    AgentOptions carom = options;
    carom.position_simulations = 0;
    t.choice.kind = PlannerChoice::Kind::safety;
    t.choice.action = carom_search_action(carom, state, seed);
    t.choice.detail = "three-cushion: carom_search";
    return t.choice;
  }
  if (!t.legal.shoot) {
    if (t.legal.decisions.empty()) throw InvalidArgument("state", "no action is open (the game is over)");
    decide(t);
    return t.choice;
  }
  if (plays_break_action(state, t.legal)) {
    t.choice.kind = PlannerChoice::Kind::break_shot;
    t.choice.action = break_action(state);
    t.choice.detail = "break";
    return t.choice;
  }
  t.targets = shot_targets(state, t.legal);
  if (t.targets.empty()) throw InvalidArgument("state", "no ball on to play at");
  const bool potted = pot(t);
  if (!game_ball_combination(t, potted) && !potted) safety(t);
  return t.choice;
}

Action planner_action(const AgentOptions& options, const GameState& state, std::uint64_t seed) {
  return planner_choice(options, state, seed).action;
}

}  // namespace cueball
