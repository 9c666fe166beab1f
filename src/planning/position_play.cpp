// Position play: a lookahead of one or two shots over plan_shot(); see position_play.hpp.
#include "cueball/planning/position_play.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <string>
#include <utility>

#include "cueball/core/errors.hpp"
#include "cueball/planning/ghost_ball.hpp"
#include "core/enum_names.hpp"
#include "planning/shot_search.hpp"

namespace cueball {

namespace {
constexpr std::array kLeaveValuations{LeaveValuation::windows, LeaveValuation::ghost_ball};
}  // namespace

const char* to_string(LeaveValuation valuation) {
  switch (valuation) {
    case LeaveValuation::windows: return "windows";
    case LeaveValuation::ghost_ball: return "ghost_ball";
  }
  return "?";
}
std::optional<LeaveValuation> leave_valuation_from_string(std::string_view name) {
  return value_named(kLeaveValuations, name);
}
std::string leave_valuation_names() { return names_of(kLeaveValuations, ""); }

namespace {

bool has_ball(const Scenario& s, int id) { return index_of(s.balls, id) < s.balls.size(); }

bool contains(const std::vector<int>& ids, int id) { return std::find(ids.begin(), ids.end(), id) != ids.end(); }

// Where the noise-free shot leaves the cue ball.
Vec2 cue_ball_end(const PlannedShot& shot, int cue_id) {
  const auto cue_end = std::find_if(shot.predicted.begin(), shot.predicted.end(),
                                    [&](const PredictedBall& p) { return p.id == cue_id; });
  return cue_end->position;
}

// A candidate shot, the table it leaves and its leave's scores.
struct Candidate {
  PlannedShot shot;
  Leave leave;
  Scenario left;
  std::vector<int> next_ids;  // the balls the next shot may pot on the table it leaves; empty: none left
  double next_window = 0.0;   // the best next shot's window probability (1: no ball left)
};

// One position plan: the request, the next targets in turn, the next shot's
// request and the engine runs counted so far.
struct Lookahead {
  const Scenario& s;
  const PositionRequest& q;
  int cue_id = 0;
  std::vector<std::vector<int>> next_targets;  // PositionRequest::next_targets, resolved
  PlanRequest next;      // the next shot's request (its targets set per leave)
  int simulations = 0;   // engine runs of every plan made
};

// PositionRequest::next_targets checked: each set not empty, each id a ball
// on the table other than the cue ball.
void check_next_targets(const Scenario& s, const PositionRequest& q, int cue_id) {
  if (q.next_target)
    throw InvalidArgument("next_targets", "next_targets and next = " + std::to_string(*q.next_target) +
                                              " are both given; allowed: one of them");
  for (std::size_t k = 0; k < q.next_targets.size(); ++k) {
    const std::string set = "next_targets[" + std::to_string(k) + "]";
    if (q.next_targets[k].empty()) throw InvalidArgument("next_targets", set + " is empty; allowed: one or more ball ids");
    for (std::size_t j = 0; j < q.next_targets[k].size(); ++j) {
      const int id = q.next_targets[k][j];
      const std::string name = set + "[" + std::to_string(j) + "] = " + std::to_string(id);
      if (!has_ball(s, id)) throw InvalidArgument("next_targets", name + " is not the id of a ball on the table");
      if (id == cue_id) throw InvalidArgument("next_targets", name + " is the cue ball; choose another ball");
    }
  }
}

// The next targets in turn: the request's next_targets, checked, or 9-ball's
// rule: next_target (checked) when given, then every other object ball but
// the shot's targets in id order, one at a time (the lowest ball left next).
std::vector<std::vector<int>> next_targets_of(const Scenario& s, const PositionRequest& q, int cue_id) {
  if (!q.next_targets.empty()) {
    check_next_targets(s, q, cue_id);
    return q.next_targets;
  }
  const std::vector<int> targets = target_ids(q.shot);
  std::vector<std::vector<int>> in_turn;
  if (q.next_target) {
    const int next = *q.next_target;
    if (!has_ball(s, next))
      throw InvalidArgument("next", "next = " + std::to_string(next) + " is not the id of a ball on the table");
    if (next == cue_id || contains(targets, next))
      throw InvalidArgument("next", "next = " + std::to_string(next) + " is the " +
                                        (next == cue_id ? std::string("cue ball") : q.shot.targets.empty() ? "target" : "a target") +
                                        "; choose another ball");
    in_turn.push_back({next});
  }
  std::vector<int> ids;
  for (const SimulationBall& b : s.balls)
    if (b.id != cue_id && !contains(targets, b.id) && !(q.next_target && b.id == *q.next_target)) ids.push_back(b.id);
  std::sort(ids.begin(), ids.end());
  for (int id : ids) in_turn.push_back({id});
  return in_turn;
}

// The balls the next shot may pot on table `left`: those of the first set
// in turn with a ball on it (other than the cue ball and `except`); empty
// when none.
std::vector<int> next_ids_on(const Scenario& left, const Lookahead& la, const std::vector<int>& except) {
  for (const std::vector<int>& set : la.next_targets) {
    std::vector<int> ids;
    for (int id : set)
      if (id != la.cue_id && !contains(except, id) && has_ball(left, id)) ids.push_back(id);
    if (!ids.empty()) return ids;
  }
  return {};
}

// The next shot's request for those balls (one: its target, as plan_shot()
// takes a lone target; several: its targets).
PlanRequest next_request(const Lookahead& la, const std::vector<int>& ids) {
  PlanRequest n = la.next;
  n.target = ids.front();
  n.targets = ids.size() > 1 ? ids : std::vector<int>{};
  return n;
}

double ghost_ball_shots(Lookahead& la, const Scenario& left, const std::vector<int>& ids, int shots);

// The next shot's value on table `left` for the balls `ids` (not empty), as
// PositionRequest::valuation says: the best window probability of a
// windows-only search (its runs counted), or the best ghost-ball chance
// (ghost_ball_shots() one shot deep: the game ball's combination counted).
double next_shot_value(Lookahead& la, const Scenario& left, const std::vector<int>& ids) {
  if (la.q.valuation == LeaveValuation::ghost_ball) return ghost_ball_shots(la, left, ids, 1);
  return best_window_probability(left, next_request(la, ids), la.simulations);
}

// next_shot_value() on table `left` for the next targets on it; 1 where it
// leaves no ball to play.
double next_value_on(Lookahead& la, const Scenario& left) {
  const std::vector<int> ids = next_ids_on(left, la, {});
  return ids.empty() ? 1.0 : next_shot_value(la, left, ids);
}

// PositionRequest::varied_shots' default is plan_shot()'s own.
static_assert(kPositionVariedShots == static_cast<int>(kVariantCandidates));

// Step 1's search: plan_shot()'s step 4 widened (every shot and variant kept).
ShotSearch wide_search(const PositionRequest& q) {
  ShotSearch wide;
  wide.variant_heights = {kPositionHeights.begin(), kPositionHeights.end()};
  wide.variant_speeds = {kPositionSpeedFactors.begin(), kPositionSpeedFactors.end()};
  wide.vary_easy = true;
  wide.keep_every = true;
  wide.variant_runs = kPositionVariantBudgets * q.shot.simulations;
  wide.varied_shots = static_cast<std::size_t>(q.varied_shots);
  return wide;
}

// A leave with no next shot: scored on this pot alone.
Leave leave_alone(const PlannedShot& shot, int cue_id) {
  Leave leave;
  leave.cue_ball = cue_ball_end(shot, cue_id);
  leave.screened_probability = shot.success_probability;
  leave.score = shot.success_probability;
  return leave;
}

// With no next ball: plan_shot()'s own plan, each leave (the alternatives'
// too) scored on its pot alone.
void plan_without_lookahead(const Lookahead& la, PositionPlanResult& result) {
  SearchedShots found = search_shots(la.s, la.q.shot, ShotSearch{});
  result.plan = std::move(found.plan);
  result.leave = leave_alone(result.plan.shot, la.cue_id);
  for (const PlannedShot& alternative : result.plan.alternatives)
    result.alternative_leaves.push_back(leave_alone(alternative, la.cue_id));
}

// Step 1's candidates: every shot and variant found, once per strike, at
// least kPositionKeepFraction of the best's window probability, best first;
// at most kPositionLeaves when their leaves are valued by window searches
// (a ghost-ball chance costs no engine run: then every one).
std::vector<Candidate> candidate_leaves(std::vector<PlannedShot>& every, LeaveValuation valuation) {
  std::vector<Candidate> candidates;
  double best_window = 0.0;
  for (const PlannedShot& shot : every) best_window = std::max(best_window, shot.window_probability);
  for (PlannedShot& shot : every) {
    const bool known = std::any_of(candidates.begin(), candidates.end(),
                                   [&](const Candidate& c) { return c.shot.strike == shot.strike; });
    if (!known && shot.window_probability >= kPositionKeepFraction * best_window)
      candidates.push_back({std::move(shot), {}, {}, {}, 0.0});
  }
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return a.shot.window_probability > b.shot.window_probability;
  });
  if (valuation == LeaveValuation::windows && candidates.size() > kPositionLeaves) candidates.resize(kPositionLeaves);
  return candidates;
}

// The k-th largest of `scores` (k >= 1); -1 when there are fewer.
double kth_largest(std::vector<double> scores, std::size_t k) {
  if (scores.size() < k) return -1.0;
  std::nth_element(scores.begin(), scores.begin() + static_cast<std::ptrdiff_t>(k - 1), scores.end(),
                   std::greater<>());
  return scores[k - 1];
}

// Step 2's value of a candidate's leave: the next shot's value on the table
// the noise-free shot leaves (next_shot_value(): its best window
// probability, or ghost-ball chance; 1 where it leaves no next ball),
// averaged with its value on the tables the successes among the shot's
// first PositionRequest::candidate_noisy_leaves noisy repeats leave (the
// finalists' noise stream: common draws for every candidate). Sets the
// candidate's next_window and its leave's candidate_* fields.
void value_candidate_leave(Lookahead& la, Candidate& c) {
  c.leave.cue_ball = cue_ball_end(c.shot, la.cue_id);
  c.left = table_left_by(la.s, c.shot);
  // The next targets on the table it leaves (by default the next ball, or
  // when the shot pots it too, the lowest ball left); none left: nothing
  // to score.
  c.next_ids = next_ids_on(c.left, la, {});
  c.next_window = 1.0;
  c.leave.candidate_next_window = 1.0;
  if (c.next_ids.empty()) return;
  c.next_window = next_shot_value(la, c.left, c.next_ids);
  const int repeats = la.q.candidate_noisy_leaves;
  if (repeats > 0) {
    const NoisyOutcomes noisy = noisy_outcomes(la.s, la.q.shot, la.cue_id, c.shot, repeats, kScreenFirstShot, repeats);
    la.simulations += repeats;
    double sum = c.next_window;
    for (const Scenario& left : noisy.leaves) sum += next_value_on(la, left);
    c.leave.candidate_noisy_leaves = static_cast<int>(noisy.leaves.size());
    c.next_window = sum / static_cast<double>(1 + noisy.leaves.size());
  }
  c.leave.candidate_next_window = c.next_window;
}

// Step 2: each leave valued by value_candidate_leave(), scored by this
// shot's window probability times that value; the
// PositionRequest::finalists best kept. The candidates come best window first
// and a leave's value is at most 1, so a leave whose own window is
// no more than the finalists-th score so far cannot be kept
// (nor can any after it; an equal score keeps the earlier leave): the
// scoring stops there, and the leaves kept are those of scoring them all.
void score_candidate_leaves(Lookahead& la, std::vector<Candidate>& candidates) {
  const auto finalists = static_cast<std::size_t>(la.q.finalists);
  std::vector<double> scores;
  std::size_t scored = 0;
  for (Candidate& c : candidates) {
    if (c.shot.window_probability <= kth_largest(scores, finalists)) break;
    ++scored;
    value_candidate_leave(la, c);
    scores.push_back(c.shot.window_probability * c.next_window);
  }
  candidates.resize(scored);
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return a.shot.window_probability * a.next_window > b.shot.window_probability * b.next_window;
  });
  if (candidates.size() > finalists) candidates.resize(finalists);
}

// Depth 2's value of a leave (PositionRequest::depth): the best over the
// next shot's kPositionSecondShots best shots, ranked by window probability
// without a noisy shot, of its window probability times the best window of
// the shot after it on the table it leaves (1 where it leaves no ball to
// play); 0 when the next shot has no feasible shot. The expectimax of
// PickPocket (Smith 2007) two plies deep, each ply's chance node read from
// the planner's window probability instead of sampled.
double two_shot_window(Lookahead& la, const Scenario& left, const std::vector<int>& ids) {
  const PlanRequest next = next_request(la, ids);
  ShotSearch windows_only;
  windows_only.noisy = false;
  SearchedShots found;
  try {
    found = search_shots(left, next, windows_only);
  } catch (const NoFeasibleShot&) {
    la.simulations += next.simulations;
    return 0.0;
  }
  la.simulations += found.plan.simulations;
  std::vector<const PlannedShot*> best{&found.plan.shot};
  for (const PlannedShot& alternative : found.plan.alternatives)
    if (best.size() < kPositionSecondShots) best.push_back(&alternative);
  double value = 0.0;
  for (const PlannedShot* shot : best) {
    // The shot after it has a window of at most 1: no gain possible.
    if (shot->window_probability <= value) continue;
    const Scenario after = table_left_by(left, *shot);
    const std::vector<int> after_ids = next_ids_on(after, la, {});
    const double after_window =
        after_ids.empty() ? 1.0 : best_window_probability(after, next_request(la, after_ids), la.simulations);
    value = std::max(value, shot->window_probability * after_window);
  }
  return value;
}

// The balls of the next targets in turn on table `left`: the shots a run
// of it takes.
int run_length(const Lookahead& la, const Scenario& left) {
  std::vector<int> ids;
  for (const std::vector<int>& set : la.next_targets)
    for (int id : set)
      if (id != la.cue_id && !contains(ids, id) && has_ball(left, id)) ids.push_back(id);
  return static_cast<int>(ids.size());
}

// PositionRequest::game_ball: the best ghost-ball combination's chance of
// the game ball through the next target `ids` (one ball, not the game
// ball) on table `left`, the run then won, over later_shot_chance for each
// ball of the run beyond the `shots` a run's value covers there (at most
// 1); 0 where there is none.
double game_ball_combination_value(const Lookahead& la, const Scenario& left, const std::vector<int>& ids, int shots) {
  if (!la.q.game_ball || ids.size() != 1 || ids.front() == *la.q.game_ball) return 0.0;
  const std::vector<GhostBallPot> pots = ghost_ball_combinations(left, la.cue_id, ids.front(), *la.q.game_ball);
  if (pots.empty()) return 0.0;
  const double chance = ghost_ball_pot_chance(pots.front().aim_tolerance, la.next.noise.aim);
  const int beyond = run_length(la, left) - shots;
  return std::min(1.0, chance / std::pow(la.q.later_shot_chance, std::max(0, beyond)));
}

// The first factor of a value by the ghost ball on table `left`: no value
// of ghost_ball_shots() there exceeds it.
double ghost_ball_bound(const Lookahead& la, const Scenario& left, const std::vector<int>& ids, int shots) {
  return std::max(best_ghost_ball_chance(left, la.cue_id, ids, la.next.noise.aim),
                  game_ball_combination_value(la, left, ids, shots));
}

// A table a next pot's stroke leaves, its bound and its next targets.
struct StrokeLeave {
  double bound = 0.0;    // ghost_ball_bound() of the shot after the pot on it (1: no ball left)
  Scenario left;
  std::vector<int> ids;  // the next targets on it; empty: none left
};

// The tables the strokes kGhostBallStrokeSpeeds x kGhostBallStrokeHeights
// of `pot` leave, played once each without noise (ghost_ball_stroke(), one
// engine run each), best bound first: those that drop the pot's ball, or
// where none does (a level stroke at the ghost ball does not allow for
// throw), every one with that ball taken off. A stroke that scratches
// leaves none.
std::vector<StrokeLeave> stroke_leaves(Lookahead& la, const Scenario& left, const GhostBallPot& pot, int shots) {
  std::vector<StrokeLeave> potted, unpotted;
  for (const double speed : kGhostBallStrokeSpeeds)
    for (const double height : kGhostBallStrokeHeights) {
      GhostBallStroke stroke = ghost_ball_stroke(left, la.cue_id, pot, speed, height);
      ++la.simulations;
      if (stroke.scratched) continue;
      if (!stroke.potted)
        stroke.left.balls.erase(stroke.left.balls.begin() +
                                static_cast<std::ptrdiff_t>(index_of(stroke.left.balls, pot.target)));
      StrokeLeave leave{1.0, std::move(stroke.left), {}};
      leave.ids = next_ids_on(leave.left, la, {});
      if (!leave.ids.empty()) leave.bound = ghost_ball_bound(la, leave.left, leave.ids, shots);
      (stroke.potted ? potted : unpotted).push_back(std::move(leave));
    }
  std::vector<StrokeLeave>& leaves = potted.empty() ? unpotted : potted;
  std::stable_sort(leaves.begin(), leaves.end(),
                   [](const StrokeLeave& a, const StrokeLeave& b) { return a.bound > b.bound; });
  return std::move(leaves);
}

// Depth 2 and 3 by the ghost ball (LeaveValuation::ghost_ball), `shots`
// shots on table `left` for the balls `ids`: one, the best ghost-ball
// chance; more, the best over the next shot's kPositionSecondShots best
// ghost-ball pots of its chance times the best, over the tables its
// strokes leave (stroke_leaves()), of the value of the shots - 1 after it
// (1 where it leaves no ball to play); 0 when the next shot has no
// ghost-ball pot. With PositionRequest::game_ball, at each of them the
// larger of that and game_ball_combination_value(). The expectimax of
// PickPocket (Smith 2007) `shots` plies deep, each chance node the
// ghost-ball chance, each later shot's stroke searched instead of planned.
// Exact branch and bound: a value is a product of chances, so no more than
// its first factor, or the combination's value (ghost_ball_bound()), and a
// pot (or a table) whose chance (bound) is no more than the best value
// found cannot raise it.
double ghost_ball_shots(Lookahead& la, const Scenario& left, const std::vector<int>& ids, int shots) {
  if (shots <= 1) return ghost_ball_bound(la, left, ids, shots);
  const std::vector<GhostBallPot> pots = ghost_ball_pots(left, la.cue_id, ids);
  double value = game_ball_combination_value(la, left, ids, shots);
  for (std::size_t k = 0; k < pots.size() && k < kPositionSecondShots; ++k) {
    const double chance = ghost_ball_pot_chance(pots[k].aim_tolerance, la.next.noise.aim);
    if (chance <= value) continue;
    double after = 0.0;
    for (const StrokeLeave& leave : stroke_leaves(la, left, pots[k], shots - 1)) {
      if (leave.bound <= after) break;  // best bound first: none after it can gain
      // One shot after it: its value is the bound already worked out.
      const double then = leave.ids.empty() ? 1.0
                          : shots - 1 <= 1  ? leave.bound
                                            : ghost_ball_shots(la, leave.left, leave.ids, shots - 1);
      after = std::max(after, then);
    }
    value = std::max(value, chance * after);
  }
  return value;
}

// A leave's value for the next shots on table `left` (1 where it leaves no
// ball to play): depth 1, the best next shot's window probability or
// ghost-ball chance; depth 2, two_shot_window() or ghost_ball_shots();
// depth 3, ghost_ball_shots() (the windows' depth stops at 2).
double leave_value(Lookahead& la, const Scenario& left) {
  if (la.q.depth < 2) return next_value_on(la, left);
  const std::vector<int> ids = next_ids_on(left, la, {});
  if (ids.empty()) return 1.0;
  return la.q.valuation == LeaveValuation::ghost_ball ? ghost_ball_shots(la, left, ids, la.q.depth)
                                                      : two_shot_window(la, left, ids);
}

// The mean over the tables some noisy successes leave of leave_value(); 0
// for none.
double noisy_next_window(Lookahead& la, const std::vector<Scenario>& leaves) {
  if (leaves.empty()) return 0.0;
  double sum = 0.0;
  for (const Scenario& left : leaves) sum += leave_value(la, left);
  return sum / static_cast<double>(leaves.size());
}

// Step 3's next shot by LeaveValuation::windows: plan_shot() in full from
// the noise-free leave.
void planned_next_shot(Lookahead& la, Candidate& c) {
  try {
    const ShotPlanResult n = plan_shot(c.left, next_request(la, c.next_ids));
    la.simulations += n.simulations;
    c.leave.next_feasible = true;
    c.leave.next_ball = n.shot.target;
    c.leave.next_success_probability = n.shot.success_probability;
    c.leave.next_kind = to_string(n.shot.kind);
    c.leave.next_pocket = n.shot.pocket_name;
  } catch (const NoFeasibleShot&) {
    la.simulations += la.q.next_simulations;
  }
}

// Step 3's next shot by LeaveValuation::ghost_ball: the best ghost-ball pot
// from the noise-free leave, or the game ball's combination through the
// next ball where its chance is larger (PositionRequest::game_ball), its
// chance as the next shot's probability.
void ghost_ball_next_shot(const Lookahead& la, Candidate& c) {
  std::vector<GhostBallPot> pots = ghost_ball_pots(c.left, la.cue_id, c.next_ids);
  if (la.q.game_ball && c.next_ids.size() == 1 && c.next_ids.front() != *la.q.game_ball) {
    const std::vector<GhostBallPot> combinations =
        ghost_ball_combinations(c.left, la.cue_id, c.next_ids.front(), *la.q.game_ball);
    if (!combinations.empty() && (pots.empty() || combinations.front().aim_tolerance > pots.front().aim_tolerance))
      pots.insert(pots.begin(), combinations.front());
  }
  if (pots.empty()) return;
  const GhostBallPot& best = pots.front();
  c.leave.next_feasible = true;
  c.leave.next_ball = best.target;
  c.leave.next_success_probability = ghost_ball_pot_chance(best.aim_tolerance, la.next.noise.aim);
  c.leave.next_kind = to_string(best.ball_on >= 0 ? ShotKind::combination : ShotKind::direct);
  c.leave.next_pocket = c.left.table.pockets[static_cast<std::size_t>(best.pocket)].name;
}

// Step 3: the finalists, each shot screened on the same noisy draws and the
// next shot planned in full on the table it leaves; best score first.
void screen_finalists(Lookahead& la, std::vector<Candidate>& candidates) {
  const PositionRequest& q = la.q;
  const int screen_shots = std::max(1, q.shot.simulations / kPositionScreenFraction);
  for (Candidate& c : candidates) {
    const NoisyOutcomes screened =
        noisy_outcomes(la.s, q.shot, la.cue_id, c.shot, screen_shots, kScreenFirstShot, q.noisy_leaves);
    set_estimate(c.shot, screened.hits, screen_shots);
    c.shot.simulations += screen_shots;
    c.leave.screened_probability = c.shot.success_probability;
    la.simulations += screen_shots;
    if (c.next_ids.empty()) {
      c.leave.score = c.leave.screened_probability;
      continue;
    }
    c.leave.noisy_leaves = static_cast<int>(screened.leaves.size());
    c.leave.noisy_next_window = noisy_next_window(la, screened.leaves);
    if (q.valuation == LeaveValuation::ghost_ball) ghost_ball_next_shot(la, c);
    else planned_next_shot(la, c);
    // With no noisy leave, the noise-free one: at depth 1 by the next
    // shot's full plan (the lookahead before issue 27) or its best
    // ghost-ball chance (the game ball's combination counted), at depth 2
    // by leave_value().
    const bool by_value = q.depth >= 2 || q.valuation == LeaveValuation::ghost_ball;
    if (c.leave.noisy_leaves == 0 && by_value) c.leave.noisy_next_window = leave_value(la, c.left);
    const bool by_windows = c.leave.noisy_leaves > 0 || by_value;
    c.leave.score = c.leave.screened_probability *
                    (by_windows ? c.leave.noisy_next_window : c.leave.next_success_probability);
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.leave.score > b.leave.score; });
}

// Step 4: the one played measured on fresh draws (those plan_shot()'s final
// estimate takes), so its estimate carries no selection bias; the others
// its alternatives.
void play_best(Lookahead& la, std::vector<Candidate>& candidates, PositionPlanResult& result) {
  PlannedShot& played = candidates.front().shot;
  const int final_shots = std::max(1, la.q.shot.simulations / kPositionEstimateFraction);
  set_estimate(played, noisy_successes(la.s, la.q.shot, la.cue_id, played, final_shots, 0), final_shots);
  played.simulations += final_shots;
  la.simulations += final_shots;
  result.plan.shot = std::move(played);
  result.leave = candidates.front().leave;
  for (std::size_t k = 1; k < candidates.size(); ++k) {
    result.plan.alternatives.push_back(std::move(candidates[k].shot));
    result.alternative_leaves.push_back(candidates[k].leave);
  }
}

}  // namespace

Scenario table_left_by(const Scenario& table_state, const PlannedShot& shot) {
  return table_after(table_state, shot.predicted);
}

PositionPlanResult plan_shot_for_position(const Scenario& table_state, const PositionRequest& q) {
  const auto start = std::chrono::steady_clock::now();
  const Scenario& s = table_state;
  if (q.next_simulations < kMinPlanSimulations || q.next_simulations > kMaxPlanSimulations)
    throw InvalidArgument("next_simulations", static_cast<double>(q.next_simulations),
                          "[" + std::to_string(kMinPlanSimulations) + ", " + std::to_string(kMaxPlanSimulations) + "]",
                          "engine runs of each next-shot plan");
  if (q.noisy_leaves < 0 || q.noisy_leaves > kMaxPositionNoisyLeaves)
    throw InvalidArgument("noisy_leaves", static_cast<double>(q.noisy_leaves),
                          "[0, " + std::to_string(kMaxPositionNoisyLeaves) + "]", "noisy leaves scored per finalist");
  if (q.depth < 1 || q.depth > kMaxPositionDepth)
    throw InvalidArgument("depth", static_cast<double>(q.depth), "[1, " + std::to_string(kMaxPositionDepth) + "]",
                          "shots looked ahead");
  if (q.depth > max_position_depth(q.valuation))
    throw InvalidArgument("depth", static_cast<double>(q.depth), "[1, " + std::to_string(kMaxWindowsDepth) + "]",
                          "shots looked ahead with valuation windows (deeper: ghost_ball)");
  if (q.candidate_noisy_leaves < 0 || q.candidate_noisy_leaves > kMaxPositionNoisyLeaves)
    throw InvalidArgument("candidate_noisy_leaves", static_cast<double>(q.candidate_noisy_leaves),
                          "[0, " + std::to_string(kMaxPositionNoisyLeaves) + "]", "noisy leaves valued per candidate");
  if (q.finalists < 1 || q.finalists > kMaxPositionFinalists)
    throw InvalidArgument("finalists", static_cast<double>(q.finalists),
                          "[1, " + std::to_string(kMaxPositionFinalists) + "]", "candidates screened under noise");
  if (q.varied_shots < 1 || q.varied_shots > kMaxPositionVariedShots)
    throw InvalidArgument("varied_shots", static_cast<double>(q.varied_shots),
                          "[1, " + std::to_string(kMaxPositionVariedShots) + "]", "feasible shots whose variants are searched");
  PositionPlanResult result;
  // The cue ball as plan_shot() takes it (which checks it, the target and the rest).
  Lookahead la{s, q, cue_ball_id(s, q.shot), {}, q.shot, 0};
  la.next_targets = next_targets_of(s, q, la.cue_id);
  if (!(q.later_shot_chance > 0.0 && q.later_shot_chance <= 1.0))
    throw InvalidArgument("later_shot_chance", q.later_shot_chance, "(0, 1]",
                          "the chance of each shot of a run beyond the lookahead");
  if (q.game_ball && q.valuation != LeaveValuation::ghost_ball)
    throw InvalidArgument("game_ball", "game_ball = " + std::to_string(*q.game_ball) +
                                           " needs valuation ghost_ball; allowed: none with valuation windows");
  if (q.game_ball && (!has_ball(s, *q.game_ball) || *q.game_ball == la.cue_id))
    throw InvalidArgument("game_ball", "game_ball = " + std::to_string(*q.game_ball) +
                                           (*q.game_ball == la.cue_id ? " is the cue ball"
                                                                      : " is not the id of a ball on the table") +
                                           "; allowed: an object ball on the table");
  const std::vector<int> next_ids = next_ids_on(s, la, target_ids(q.shot));
  result.next_target = next_ids.empty() ? -1 : next_ids.front();
  la.next.cue_ball = la.cue_id;
  la.next.pocket.reset();
  la.next.simulations = q.next_simulations;
  if (result.next_target < 0) {
    plan_without_lookahead(la, result);
    result.plan.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }
  // 1. The shot planned with the wide variant search: every feasible shot
  // and variant is a candidate leave.
  SearchedShots found = search_shots(s, q.shot, wide_search(q));
  la.simulations = found.plan.simulations;
  result.plan.rejected = std::move(found.plan.rejected);
  result.plan.cue_ball = la.cue_id;
  std::vector<Candidate> candidates = candidate_leaves(found.every, q.valuation);
  score_candidate_leaves(la, candidates);                       // 2.
  screen_finalists(la, candidates);                              // 3.
  play_best(la, candidates, result);                             // 4.
  result.plan.simulations = la.simulations;
  result.plan.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace cueball
