// The shot planner: ghost-ball and mirror geometry, corrected on the exact
// simulation, scored under execution noise; see shot_planner.hpp. This file
// holds the public entry points, the request's validation and the driver
// over the steps (search_state.hpp names the file of each).
//
// Sources: ghost-ball aiming and the mirror systems of banks and kicks (D. G.
// Alciatore, "The Illustrated Principles of Pool and Billiards", 2004); the secant
// method with a bisection fallback once the root is bracketed (the safeguard
// of Dekker's method: R. P. Brent, "Algorithms for Minimization without
// Derivatives", 1973, ch. 4); the tournament noise of Archibald et al. 2010.
#include "cueball/planning/shot_planner.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>
#include <utility>

#include "cueball/core/errors.hpp"
#include "core/enum_names.hpp"
#include "planning/search_state.hpp"

namespace cueball {

namespace planning {

namespace {

// The indices of the request's targets (PlanRequest::targets, else its
// target), each a ball on the table other than the cue ball, none twice.
// `ids`: the table's ids, for the messages.
std::vector<std::size_t> target_indices(const Scenario& s, const PlanRequest& q, std::size_t cue,
                                        const std::string& ids) {
  std::vector<std::size_t> targets;
  if (q.targets.empty()) {
    const std::size_t target = index_of(s.balls, q.target);
    if (target == s.balls.size())
      throw InvalidArgument("target", "target = " + std::to_string(q.target) +
                                          " is not the id of a ball on the table; allowed: " + ids);
    if (target == cue)
      throw InvalidArgument("target", "target = " + std::to_string(q.target) + " is the cue ball; choose another ball");
    targets.push_back(target);
  }
  for (std::size_t k = 0; k < q.targets.size(); ++k) {
    const std::string name = "targets[" + std::to_string(k) + "] = " + std::to_string(q.targets[k]);
    const std::size_t target = index_of(s.balls, q.targets[k]);
    if (target == s.balls.size())
      throw InvalidArgument("targets", name + " is not the id of a ball on the table; allowed: " + ids);
    if (target == cue) throw InvalidArgument("targets", name + " is the cue ball; choose another ball");
    if (std::find(targets.begin(), targets.end(), target) != targets.end())
      throw InvalidArgument("targets", name + " is given twice; allowed: each ball once");
    targets.push_back(target);
  }
  return targets;
}

}  // namespace

std::pair<std::size_t, std::vector<std::size_t>> validate_request(const Scenario& s, const PlanRequest& q) {
  validate_simulation_input(s.table, s.balls, s.settings);
  std::string ids;
  for (const SimulationBall& b : s.balls) ids += (ids.empty() ? "" : ", ") + std::to_string(b.id);
  const int cue_id = cue_ball_id(s, q);
  const std::size_t cue = index_of(s.balls, cue_id);
  if (cue == s.balls.size()) {  // the request's cue_ball, else the scenario's cue.ball (0 without a cue)
    const std::string f = q.cue_ball ? "cue_ball" : "scenario.cue.ball";
    throw InvalidArgument(f, f + " = " + std::to_string(cue_id) + (q.cue_ball || s.cue ? "" : " (the default: no cue given)") +
                                 " is not the id of a ball on the table; allowed: " + ids);
  }
  std::vector<std::size_t> targets = target_indices(s, q, cue, ids);
  if (q.ball_on) {
    const std::size_t on = index_of(s.balls, *q.ball_on);
    if (on == s.balls.size())
      throw InvalidArgument("ball_on", "ball_on = " + std::to_string(*q.ball_on) +
                                           " is not the id of a ball on the table; allowed: " + ids);
    if (on == cue)
      throw InvalidArgument("ball_on", "ball_on = " + std::to_string(*q.ball_on) + " is the cue ball; choose another ball");
  }
  if (s.table.pockets.empty()) throw InvalidArgument("pocket", "the table has no pockets");
  if (q.pocket && (*q.pocket < 0 || static_cast<std::size_t>(*q.pocket) >= s.table.pockets.size()))
    throw InvalidArgument("pocket", static_cast<double>(*q.pocket),
                          "[0, " + std::to_string(s.table.pockets.size() - 1) + "]", "index into the table's pockets");
  if (q.kinds.empty()) throw InvalidArgument("kinds", "kinds is empty; give one or more of " + shot_kind_names());
  if (q.simulations < kMinPlanSimulations || q.simulations > kMaxPlanSimulations)
    throw InvalidArgument("simulations", static_cast<double>(q.simulations),
                          "[" + std::to_string(kMinPlanSimulations) + ", " + std::to_string(kMaxPlanSimulations) + "]",
                          "engine runs the plan may use");
  require_in_range("side", q.side, -kMiscueOffsetFraction, kMiscueOffsetFraction, "tip offset to the right, ball radii");
  const double given_height = q.height.value_or(0.0);
  require_in_range("height", given_height, -kMiscueOffsetFraction, kMiscueOffsetFraction, "tip offset above the centre, ball radii");
  // Draw and follow (+-0.3) are tried with a centre-ball side of at most 0.4.
  const double most_height = q.height ? std::abs(given_height) : 0.3;
  if (std::hypot(q.side, most_height) > kMiscueOffsetFraction * (1.0 + 1e-12))
    throw InvalidArgument("side", q.side, "a tip offset sqrt(side^2 + height^2) <= 0.5 (height " + format_number(most_height) + ")",
                          "tip offset to the right, ball radii");
  validate(q.noise);
  return {cue, targets};
}

void throw_no_feasible_shot(const SearchState& st) {
  const std::vector<std::string>& rejected = st.result.rejected;
  // A summary by reason first (the message is cut in the middle when long), then each.
  std::string why, summary;
  for (const std::string& r : rejected) why += (why.empty() ? "" : "; ") + r;
  const auto count = [&](const char* reason, const char* said) {
    std::size_t n = 0;
    for (const std::string& r : rejected) n += r.find(reason) != std::string::npos ? 1u : 0u;
    if (n > 0) summary += (summary.empty() ? "" : ", ") + std::to_string(n) + " " + said;
  };
  count("blocked", "blocked by a ball");
  count("deg > ", "cut too thin");
  count("bank point", "bank point off the cushion");
  count("the cushion at", "bank too shallow");
  count("obstructed", "cue obstructed");
  count("exact simulation", "no potting aim on the exact simulation");
  if (why.empty()) why = "no candidate of the requested kinds";
  throw NoFeasibleShot("no feasible shot pots " + targets_text(target_ids(st.q)) + " (" +
                       std::to_string(rejected.size()) + " candidates" + (summary.empty() ? "" : ": " + summary) +
                       "): " + why,
                       st.trials.runs());
}

}  // namespace planning


const char* to_string(ShotKind kind) {
  switch (kind) {
    case ShotKind::direct: return "direct";
    case ShotKind::bank: return "bank";
    case ShotKind::kick: return "kick";
    case ShotKind::combination: return "combination";
  }
  return "direct";
}

std::optional<ShotKind> shot_kind_from_string(std::string_view name) {
  return value_named(kShotKinds, name);
}

std::string shot_kind_names(std::string_view quote) {
  return names_of(kShotKinds, quote);
}

CueStrikeNoise tournament_noise() {
  CueStrikeNoise n;
  n.speed = 0.075;
  n.aim = 0.125 * kDegree;
  n.elevation = 0.1 * kDegree;
  n.side_offset = 0.0005;
  n.height_offset = 0.0005;
  return n;
}

bool cue_obstructed(const Table& table, const std::vector<SimulationBall>& balls, int cue_ball, const CueStrike& strike,
                    const BallParameters& ball) {
  const std::size_t cue = index_of(balls, cue_ball);
  if (cue == balls.size())
    throw InvalidArgument("cue_ball", "cue_ball = " + std::to_string(cue_ball) + " is not the id of a ball on the table");
  std::vector<Vec2> others;
  others.reserve(balls.size());
  for (std::size_t i = 0; i < balls.size(); ++i)
    if (i != cue) others.push_back(balls[i].state.position);
  return cue_obstructed(table, balls[cue].state.position, others, strike, ball.radius);
}

Scenario scenario_with_shot(const Scenario& table_state, int cue_ball, const PlannedShot& shot,
                            const CueStrikeNoise& noise) {
  Scenario s = table_state;
  ShotStrike cue;
  cue.ball = cue_ball;
  cue.strike = to_strike(shot.strike, s.settings.parameters.ball.radius);
  cue.given = CueStrikeInUnits{shot.strike.aim_deg, shot.strike.elevation_deg, shot.strike.side, shot.strike.height};
  s.cue = cue;
  s.noise = noise;
  return s;
}

NoisyOutcomes noisy_outcomes(const Scenario& table_state, const PlanRequest& q, int cue_ball, const PlannedShot& shot,
                             int shots, std::uint64_t first_shot, int leaves) {
  Scenario noisy = table_state;
  noisy.cue = ShotStrike{};  // simulate_many strikes cue.ball with each action
  noisy.cue->ball = cue_ball;
  noisy.noise = q.noise;
  const std::size_t cue = index_of(noisy.balls, cue_ball), target = index_of(noisy.balls, shot.target);
  const int first_contact = shot.intermediate_ball >= 0 ? shot.intermediate_ball : shot.target;
  const std::optional<int> pocket = q.pocket || q.call_shot ? std::optional<int>(shot.pocket) : std::nullopt;
  const std::vector<ShotAction> actions(static_cast<std::size_t>(shots), shot.strike);
  ManyOptions options;
  options.seed = q.seed;
  options.noise = true;
  options.first_shot = first_shot;
  const ManyResult m = simulate_many(noisy, actions, {}, options);
  const auto n = static_cast<std::size_t>(m.balls);
  NoisyOutcomes out;
  for (std::size_t k = 0; k < static_cast<std::size_t>(m.shots); ++k) {
    const bool hit = !m.miscue[k] && !m.failure[k] &&
                     pots_target(m.first_contact[k], first_contact, m.pocket[k * n + target], pocket,
                                 m.pocketed[k * n + cue]);
    if (!hit) continue;
    ++out.hits;
    if (static_cast<int>(out.leaves.size()) >= leaves) continue;
    std::vector<BallAfterShot> after;
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t e = k * n + j;
      after.push_back({noisy.balls[j].id, {m.final_position[2 * e], m.final_position[2 * e + 1]}, m.pocketed[e] != 0,
                       m.pocket[e]});
    }
    out.leaves.push_back(table_after(table_state, after));
  }
  return out;
}

int noisy_successes(const Scenario& table_state, const PlanRequest& q, int cue_ball, const PlannedShot& shot, int shots,
                    std::uint64_t first_shot) {
  return noisy_outcomes(table_state, q, cue_ball, shot, shots, first_shot, 0).hits;
}

void set_estimate(PlannedShot& shot, int hits, int shots) {
  shot.noisy_shots = shots;
  shot.success_probability = static_cast<double>(hits) / shots;
  const double p = shot.success_probability;
  shot.success_standard_error = std::sqrt(p * (1.0 - p) / shots);
}

ShotPlanResult plan_shot(const Scenario& table_state, const PlanRequest& q) {
  return search_shots(table_state, q, ShotSearch{}).plan;
}


SearchedShots search_shots(const Scenario& table_state, const PlanRequest& q, const ShotSearch& o) {
  using namespace planning;  // the steps (search_state.hpp)
  auto [cue, targets] = validate_request(table_state, q);
  SearchState st(table_state, q, o, cue, std::move(targets));
  st.result.cue_ball = table_state.balls[cue].id;
  geometric_candidates(st);   // 1-2. candidates in order of ease
  search_candidates(st);      // 3. solve aim, choose speed, windows
  scan_for_candidates(st);    // 2b. the aim scan
  st.result.simulations = st.trials.runs();
  if (st.feasible.empty()) throw_no_feasible_shot(st);
  keep_most_screened(st);
  if (!o.noisy) {  // 4, without noise: ranked by window probability
    rank_by_windows(st);
  } else {         // 4. screen, vary, finalists, estimate, alternatives
    screen_feasible(st);
    vary_best(st);
    choose_finalists(st);
    estimate_chosen(st);
    collect_alternatives(st);
  }
  st.result.seconds = st.seconds();
  st.out.plan = std::move(st.result);
  return std::move(st.out);
}

std::string targets_text(const std::vector<int>& ids) {
  if (ids.size() == 1) return "ball " + std::to_string(ids.front());
  std::string text = "any of balls ";
  for (std::size_t k = 0; k < ids.size(); ++k) text += (k == 0 ? "" : ", ") + std::to_string(ids[k]);
  return text;
}

double best_window_probability(const Scenario& table_state, const PlanRequest& q, int& simulations) {
  ShotSearch windows_only;
  windows_only.noisy = false;
  try {
    const SearchedShots w = search_shots(table_state, q, windows_only);
    simulations += w.plan.simulations;
    return w.plan.shot.window_probability;
  } catch (const NoFeasibleShot&) {
    simulations += q.simulations;
    return 0.0;
  }
}

}  // namespace cueball
