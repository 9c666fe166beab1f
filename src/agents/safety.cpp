// Safety play (agent.hpp): the safety search, the opponent's chance it is
// scored by (pot_chance), and the safety planner agent that uses them.
//
// The search is a short driver over a SafetySearch and named steps:
// propose the strikes, play them noise-free through the rules and keep the
// legal ones, rank them by their noise-free value, play the best out under
// noise, score the few best again by the opponent's reply as the planner
// searches it (plan_shot on the tables they leave), choose. Every strike is
// played by play() (games/game.hpp), so the
// rules themselves judge the contact, the rail, the scratch, the push-out
// and who shoots next; the noisy repeats draw the game's noise model
// (shot_normals, as simulate_many and simulate_batch do) from common seeds,
// so the candidates are compared on the same draws.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "cueball/agents/agent.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/core/random.hpp"
#include "cueball/planning/ghost_ball.hpp"
#include "cueball/planning/shot_planner.hpp"

namespace cueball {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

bool contains(const std::vector<int>& v, int id) { return std::find(v.begin(), v.end(), id) != v.end(); }

// The state as the player to act would shoot from it: a decision due is
// taken as play from the table as it stands.
GameState as_played(const GameState& state) {
  GameState view = state;
  if (view.phase == GamePhase::decision) {
    view.phase = GamePhase::play;
    view.decisions.clear();
  }
  return view;
}

struct Candidate {
  Action action;
  int target = -1;
  double cut = 0.0;    // the contact's offset, ball diameters (safe_hit: 0)
  double exact = -1.0; // value noise-free; -1: fouls or illegal
  double mean = 0.0;   // mean value over the noisy repeats
  double replied = -1.0;  // value by the planned reply (finalists only)
  std::vector<GameState> outcomes;  // the noise-free outcome, then the first noisy repeats'
};

// One safety search: filled by the steps below, in order.
struct SafetySearch {
  const GameState& state;
  const LegalActions& legal;
  std::optional<Vec2> place;
  CueStrikeNoise noise;
  std::uint64_t seed = 0;
  Scenario table;      // the cue ball where it is struck from
  GameState exact;     // the state with no execution noise
  GameState noisy;     // the state with `noise`
  std::vector<Candidate> candidates;
  std::vector<std::size_t> ranked;  // indices of the legal candidates, best noise-free first
  std::vector<std::size_t> finalists;  // of them, the best by mean value
  SafetyPlan plan;
};

// The call and the nomination a shot at `target` needs (as the planner's
// plain hit fills them).
void complete(const SafetySearch& s, Action& a, int target) {
  a.place = s.place;
  if (s.legal.call_required) {
    a.called_ball = contains(s.legal.callable, target) || s.legal.callable.empty() ? target : s.legal.callable.front();
    a.called_pocket = nearest_pocket(s.table, *a.called_ball);
  }
  if (s.legal.nominate_required && !s.legal.nominable.empty())
    a.nominate = contains(s.legal.nominable, target) ? target : s.legal.nominable.front();
}

// Step: the strikes (kSafetyTargets nearest balls on x kSafetyCuts x
// kSafetySpeeds, and safe_hit()), each also pushed out when one may be.
void propose(SafetySearch& s) {
  const int cue = s.legal.cue_ball;
  const SimulationBall* cue_ball = find_ball(s.table.balls, cue);
  if (!cue_ball) return;
  const Vec2 C = cue_ball->state.position;
  const double R = s.table.settings.parameters.ball.radius;
  std::vector<int> targets = shot_targets(s.state, s.legal);
  std::stable_sort(targets.begin(), targets.end(), [&](int a, int b) {
    return norm(find_ball(s.table.balls, a)->state.position - C) < norm(find_ball(s.table.balls, b)->state.position - C);
  });
  if (targets.size() > static_cast<std::size_t>(kSafetyTargets)) targets.resize(static_cast<std::size_t>(kSafetyTargets));
  std::vector<Candidate> strikes;
  for (const int id : targets) {
    const Vec2 O = find_ball(s.table.balls, id)->state.position;
    const double d = norm(O - C);
    for (const double cut : kSafetyCuts) {
      const double b = 2.0 * R * cut;  // the ghost ball's offset across the line of centres
      if (std::abs(b) >= d) continue;
      const double aim = std::atan2(O.y - C.y, O.x - C.x) + std::atan2(b, std::sqrt(d * d - b * b));
      for (const double speed : kSafetySpeeds) {
        Candidate c;
        c.target = id;
        c.cut = cut;
        c.action.strike.speed = speed;
        c.action.strike.aim_deg = aim / kDeg;
        const std::optional<double> e = lowest_clear_elevation_deg(s.table, cue, c.action.strike);
        if (!e) continue;
        c.action.strike.elevation_deg = *e;
        complete(s, c.action, id);
        strikes.push_back(c);
      }
    }
  }
  int hit = -1;
  if (const std::optional<ShotAction> plain = safe_hit(s.table, cue, targets, hit)) {
    Candidate c;
    c.target = hit;
    c.action.strike = *plain;
    complete(s, c.action, hit);
    strikes.push_back(c);
  }
  s.candidates = strikes;
  if (s.legal.push_out)
    for (Candidate c : strikes) {
      c.action.push_out = true;
      s.candidates.push_back(c);
    }
  s.plan.candidates = static_cast<int>(s.candidates.size());
}

// Step: each strike once noise-free; a foul (or an action the rules refuse)
// drops it, the others get their noise-free value.
void screen_noise_free(SafetySearch& s) {
  for (Candidate& c : s.candidates) {
    try {
      const GameStep step = play(s.exact, c.action, 0);
      ++s.plan.simulations;
      if (step.ruling.foul) continue;
      c.exact = value_after_shot(step.next, s.state.to_shoot, s.noise);
      c.outcomes.push_back(step.next);
    } catch (const InvalidArgument&) {
      // an action the rules refuse (e.g. a spot that is not free): not a candidate
    }
  }
}

// Step: the legal strikes, best noise-free first (the first of equal ones).
void rank(SafetySearch& s) {
  for (std::size_t k = 0; k < s.candidates.size(); ++k)
    if (s.candidates[k].exact >= 0.0) s.ranked.push_back(k);
  std::stable_sort(s.ranked.begin(), s.ranked.end(),
                   [&](std::size_t a, std::size_t b) { return s.candidates[a].exact > s.candidates[b].exact; });
  s.plan.legal = static_cast<int>(s.ranked.size());
  if (s.ranked.size() > static_cast<std::size_t>(kSafetyScreened)) s.ranked.resize(static_cast<std::size_t>(kSafetyScreened));
  s.plan.screened = static_cast<int>(s.ranked.size());
}

// Step: the ranked strikes kSafetyRepeats times each under the noise, on
// common seeds.
void play_out_under_noise(SafetySearch& s) {
  for (const std::size_t k : s.ranked) {
    Candidate& c = s.candidates[k];
    double sum = 0.0;
    for (int r = 0; r < kSafetyRepeats; ++r) {
      const GameStep step = play(s.noisy, c.action, stream_seed(s.seed, static_cast<std::uint64_t>(r)));
      ++s.plan.simulations;
      sum += value_after_shot(step.next, s.state.to_shoot, s.noise);
      if (r + 1 < kSafetyReplyOutcomes) c.outcomes.push_back(step.next);
    }
    c.mean = sum / kSafetyRepeats;
  }
}

// Step: the kSafetyFinalists best by mean value (the first of equal ones,
// in rank order), each scored again on its kSafetyReplyOutcomes outcomes by
// the reply the planner would plan from them; the reply plans of every
// finalist share the seeds, outcome by outcome.
void search_replies(SafetySearch& s) {
  s.finalists = s.ranked;
  std::stable_sort(s.finalists.begin(), s.finalists.end(),
                   [&](std::size_t a, std::size_t b) { return s.candidates[a].mean > s.candidates[b].mean; });
  if (s.finalists.size() > static_cast<std::size_t>(kSafetyFinalists))
    s.finalists.resize(static_cast<std::size_t>(kSafetyFinalists));
  for (const std::size_t k : s.finalists) {
    Candidate& c = s.candidates[k];
    double sum = 0.0;
    for (std::size_t j = 0; j < c.outcomes.size(); ++j) {
      const std::uint64_t seed = stream_seed(s.seed, static_cast<std::uint64_t>(kSafetyRepeats) + j);
      sum += planned_value_after_shot(c.outcomes[j], s.state.to_shoot, s.noise, seed, s.plan.simulations);
      ++s.plan.replies;
    }
    c.replied = sum / static_cast<double>(c.outcomes.size());
  }
}

// Step: the finalist with the best value by the planned reply (the first
// of equal ones, in order of their mean value).
void choose(SafetySearch& s) {
  const Candidate* best = nullptr;
  for (const std::size_t k : s.finalists)
    if (!best || s.candidates[k].replied > best->replied) best = &s.candidates[k];
  if (!best) return;
  s.plan.action = best->action;
  s.plan.value = best->replied;
  s.plan.screen_value = best->mean;
  s.plan.noise_free_value = best->exact;
  char b[300];
  std::snprintf(b, sizeof b,
                "safety: hit the %d at %.2f ball, %.2f m/s%s: value %.3f by the planned reply (screen %.3f under "
                "noise, %.3f noise-free); %d legal of %d strikes, %d played out %d times, %d replies planned",
                best->target, best->cut, best->action.strike.speed, best->action.push_out ? ", pushed out" : "",
                best->replied, best->mean, best->exact, s.plan.legal, s.plan.candidates, s.plan.screened,
                kSafetyRepeats, s.plan.replies);
  s.plan.detail = b;
}

// The planner's choice at a decision, taken again with the safety's value:
// the table is good when the better of the planner's pot from it and the
// safety from it is at least 1/2.
PlannerChoice decide_by_value(PlannerChoice c, const GameState& state, const LegalActions& legal,
                              const CueStrikeNoise& noise, std::uint64_t seed) {
  double best = c.success_probability;
  std::string why = "the best pot from the table " + std::to_string(best);
  if (best < 0.5) {
    const GameState view = as_played(state);
    const LegalActions then = legal_actions(view);
    if (then.shoot && !then.ball_in_hand && !shot_targets(view, then).empty()) {
      const std::optional<SafetyPlan> plan = plan_safety(view, then, std::nullopt, noise, seed);
      if (plan) {
        c.simulations += plan->simulations;
        best = std::max(best, plan->value);
        why += ", the best safety " + std::to_string(plan->value);
      }
    }
  }
  c.action.decision = decision_by_policy(legal.decisions, best >= 0.5);
  c.detail = std::string(to_string(*c.action.decision)) + ": " + why;
  return c;
}

// The shooter's value after a shot that led to `next` (not over), the
// player to act potting with probability q.
double shooter_value(const GameState& next, int shooter, double q) {
  const double v = next.phase == GamePhase::decision ? std::max(q, 1.0 - q) : q;  // play or pass
  return next.to_shoot == shooter ? v : 1.0 - v;
}

// The table the player to act in `state` shoots from, as both estimates of
// their chance take it: decisions due taken as play, the cue ball in hand
// at ghost_ball_in_hand_spot() (no spot: where it lies). None when the game
// is over, no shot is open, no ball is on, or the cue ball is off the table.
struct Reply {
  Scenario table;
  int cue_ball = 0;
  std::vector<int> targets;
  bool call_shot = false;  // the reply's pocket is called (WPA 1.6)
};
std::optional<Reply> reply_table(const GameState& state) {
  if (state.over) return std::nullopt;
  const GameState view = as_played(state);
  const LegalActions legal = legal_actions(view);
  if (!legal.shoot) return std::nullopt;
  Reply r{view.table, legal.cue_ball, shot_targets(view, legal), legal.call_required};
  if (r.targets.empty()) return std::nullopt;
  if (legal.ball_in_hand)
    if (const std::optional<Vec2> spot = ghost_ball_in_hand_spot(r.table, r.cue_ball, r.targets, *legal.ball_in_hand))
      r.table = with_cue_ball_at(r.table, r.cue_ball, *spot);
  if (!find_ball(r.table.balls, r.cue_ball)) return std::nullopt;
  return r;
}

}  // namespace

double value_after_shot(const GameState& next, int shooter, const CueStrikeNoise& noise) {
  if (next.over) return next.winner ? (*next.winner == shooter ? 1.0 : 0.0) : 0.5;
  return shooter_value(next, shooter, pot_chance(next, noise));
}

double planned_value_after_shot(const GameState& next, int shooter, const CueStrikeNoise& noise, std::uint64_t seed,
                                long long& simulations) {
  if (next.over) return next.winner ? (*next.winner == shooter ? 1.0 : 0.0) : 0.5;
  return shooter_value(next, shooter, planned_chance(next, noise, seed, simulations));
}

double planned_chance(const GameState& state, const CueStrikeNoise& noise, std::uint64_t seed,
                      long long& simulations) {
  const std::optional<Reply> reply = reply_table(state);
  if (!reply) return 0.0;
  PlanRequest q;
  q.cue_ball = reply->cue_ball;
  if (reply->targets.size() == 1)
    q.target = reply->targets.front();
  else
    q.targets = reply->targets;
  q.kinds = {ShotKind::direct, ShotKind::bank};
  q.call_shot = reply->call_shot;
  q.noise = noise;
  q.seed = seed;
  q.simulations = kSafetyReplySimulations;
  double planned = 0.0;
  try {
    const ShotPlanResult r = plan_shot(reply->table, q);
    simulations += r.simulations;
    planned = r.shot.success_probability;
  } catch (const NoFeasibleShot&) {
    simulations += kSafetyReplySimulations;  // the API does not report them: the budget is the upper bound
  }
  return std::max(planned, pot_chance(state, noise));
}

double pot_chance(const GameState& state, const CueStrikeNoise& noise) {
  const std::optional<Reply> reply = reply_table(state);
  if (!reply) return 0.0;
  const std::optional<GhostBallShot> shot = likeliest_ghost_ball_shot(reply->table, reply->cue_ball, reply->targets);
  if (!shot) return 0.0;
  return ghost_ball_pot_chance(shot->aim_tolerance, noise.aim);
}

std::optional<SafetyPlan> plan_safety(const GameState& state, const LegalActions& legal, std::optional<Vec2> place,
                                      const CueStrikeNoise& noise, std::uint64_t seed) {
  SafetySearch s{state, legal, place, noise, seed, state.table, state, state, {}, {}, {}, {}};
  if (place) s.table = with_cue_ball_at(state.table, legal.cue_ball, *place);
  s.exact.config.noise = CueStrikeNoise{};
  s.noisy.config.noise = noise;
  propose(s);
  screen_noise_free(s);
  rank(s);
  if (s.ranked.empty()) return std::nullopt;
  play_out_under_noise(s);
  search_replies(s);
  choose(s);
  return s.plan;
}

PlannerChoice safety_planner_choice(const AgentOptions& options, const GameState& state, std::uint64_t seed) {
  validate(options);
  if (state.over) throw InvalidArgument("state", "the game is over (" + state.end_reason + ")");
  const LegalActions legal = legal_actions(state);
  PlannerChoice c = planner_choice(options, state, legal, seed);
  if (state.config.kind == GameKind::three_cushion || c.kind == PlannerChoice::Kind::break_shot) return c;
  const CueStrikeNoise noise = planning_noise(options, state);
  if (c.kind == PlannerChoice::Kind::decision) return decide_by_value(c, state, legal, noise, stream_seed(seed, 3));
  const bool pot = c.kind == PlannerChoice::Kind::pot || c.kind == PlannerChoice::Kind::fallback;
  if (pot && c.success_probability >= kSafetyThreshold) return c;
  const std::optional<Vec2> place = legal.ball_in_hand ? c.action.place : std::nullopt;
  const std::optional<SafetyPlan> plan = plan_safety(state, legal, place, noise, stream_seed(seed, 3));
  if (!plan) {
    c.detail += "; no legal safety";
    return c;
  }
  c.simulations += plan->simulations;
  if (pot && plan->value <= c.success_probability + kSafetyMargin) {
    c.detail += "; the pot beats the " + plan->detail;
    return c;
  }
  PlannerChoice safety;
  safety.kind = PlannerChoice::Kind::safety;
  safety.action = plan->action;
  safety.success_probability = plan->value;
  safety.simulations = c.simulations;
  safety.detail = plan->detail + "; instead of: " + c.detail.substr(0, 200);
  return safety;
}

Action safety_planner_action(const AgentOptions& options, const GameState& state, std::uint64_t seed) {
  return safety_planner_choice(options, state, seed).action;
}

}  // namespace cueball
