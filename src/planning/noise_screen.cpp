// Step 4 of the shot planner (shot_planner.hpp), under noise: the window
// probability, the brief screen of every feasible shot, the finalists
// screened on common draws, the chosen shot measured on fresh draws and the
// alternatives. (The spin and speed variants between the screens:
// variants.cpp.)
//
// Source: the tournament noise of Archibald et al. 2010 (shot_planner.hpp);
// common random numbers for a paired comparison of the finalists.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "planning/search_state.hpp"

namespace cueball::planning {

namespace {

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); }

// The chance that x + sigma z, z standard normal, lies in [lo, hi] (sigma 0:
// whether x does).
double inside_probability(double lo, double hi, double x, double sigma) {
  if (!(sigma > 0.0)) return lo <= x && x <= hi ? 1.0 : 0.0;
  return std::max(0.0, normal_cdf((hi - x) / sigma) - normal_cdf((lo - x) / sigma));
}

// The shot screened with `shots` noisy shots on the screen's common draws.
void screen(SearchState& st, PlannedShot& shot, int shots) {
  set_estimate(shot, noisy_successes(st.s, st.q, st.s.balls[st.cue].id, shot, shots, kScreenFirstShot), shots);
  shot.simulations += shots;
  st.screened_shots += shots;
}

// The indices 0 .. n - 1.
std::vector<std::size_t> indices(std::size_t n) {
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  return order;
}

}  // namespace

// The success probability the noise-free windows predict (header, step 4):
// the aim inside the aim window under the aim noise and the squirt of the
// side-offset noise (C8, linearised at the strike's offsets), times the cue
// speed inside the speed window under the speed noise. It leaves out what
// the windows do not see (a scratch or a kiss under the tip-height noise, a
// window that moves with the speed), which the noisy screen catches.
double window_probability(const PlannedShot& shot, const CueStrikeNoise& noise, const BallParameters& ball,
                          const CueParameters& cue) {
  const double a = shot.strike.side * ball.radius, b = shot.strike.height * ball.radius;
  constexpr double h = 1e-4;  // m
  const double squirt_rate = (squirt_angle(a + h, b, ball, cue) - squirt_angle(a - h, b, ball, cue)) / (2.0 * h);
  const double sigma_aim_deg = std::hypot(noise.aim, squirt_rate * noise.side_offset) / kDegree;
  return inside_probability(shot.aim_window_deg[0], shot.aim_window_deg[1], shot.strike.aim_deg, sigma_aim_deg) *
         inside_probability(shot.speed_window[0], shot.speed_window[1], shot.strike.speed, noise.speed);
}

bool better_by_window(const std::vector<PlannedShot>& feasible, std::size_t a, std::size_t b) {
  const double wa = std::floor(feasible[a].window_probability / kWindowStep);
  const double wb = std::floor(feasible[b].window_probability / kWindowStep);
  if (wa != wb) return wa > wb;
  return feasible[a].success_probability > feasible[b].success_probability;
}

void rank_by_windows(SearchState& st) {
  std::vector<std::size_t> order = indices(st.feasible.size());
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return st.feasible[a].window_probability > st.feasible[b].window_probability;
  });
  st.result.shot = st.feasible[order.front()];
  for (std::size_t k = 1; k < order.size(); ++k) st.result.alternatives.push_back(st.feasible[order[k]]);
}

void keep_most_screened(SearchState& st) {
  std::vector<PlannedShot>& feasible = st.feasible;
  if (feasible.size() > kMaxScreened) {
    for (std::size_t i = kMaxScreened; i < feasible.size(); ++i)
      st.result.rejected.push_back((st.targets.size() > 1 ? "ball " + std::to_string(feasible[i].target) + ": " : "") +
                                   to_string(feasible[i].kind) + " into " + feasible[i].pocket_name +
                                   ": not screened (more than " + std::to_string(kMaxScreened) + " feasible)");
    feasible.resize(kMaxScreened);
    st.feasible_of.resize(kMaxScreened);
  }
}

void screen_feasible(SearchState& st) {
  std::vector<PlannedShot>& feasible = st.feasible;
  const int budget = st.q.simulations;
  st.finalist_shots = std::min(kFinalistShots, budget / 15);
  st.final_reserve = budget / 5;
  const int base_screen =
      feasible.size() > 1 ? std::min(kBaseScreenShots, budget / (10 * static_cast<int>(feasible.size()))) : 0;
  if (base_screen > 0)
    for (PlannedShot& shot : feasible) screen(st, shot, base_screen);
  st.family = indices(feasible.size());
}

void choose_finalists(SearchState& st) {
  const std::vector<PlannedShot>& feasible = st.feasible;
  const auto by_window = [&](std::size_t a, std::size_t b) { return better_by_window(feasible, a, b); };
  std::vector<std::size_t> finalists = indices(feasible.size());
  std::stable_sort(finalists.begin(), finalists.end(), by_window);
  // The best by window probability, and the best by the brief screen.
  if (finalists.size() > kFinalists) {
    const auto screened_best =
        std::max_element(finalists.begin(), finalists.end(), [&](std::size_t a, std::size_t b) {
          return feasible[a].noisy_shots > 0 && feasible[b].noisy_shots > 0
                     ? feasible[a].success_probability < feasible[b].success_probability
                     : feasible[a].noisy_shots < feasible[b].noisy_shots;
        });
    if (screened_best - finalists.begin() >= static_cast<std::ptrdiff_t>(kFinalists))
      std::swap(finalists[kFinalists - 1], *screened_best);
    finalists.resize(kFinalists);
  }
  st.chosen = finalists.front();
  if (finalists.size() > 1 && st.finalist_shots > 0) {
    for (std::size_t i : finalists) screen(st, st.feasible[i], st.finalist_shots);
    for (std::size_t i : finalists) {
      const PlannedShot& a = feasible[i];
      const PlannedShot& b = feasible[st.chosen];
      if (a.success_probability > b.success_probability ||
          (a.success_probability == b.success_probability && a.window_probability > b.window_probability))
        st.chosen = i;
    }
  }
}

void estimate_chosen(SearchState& st) {
  st.result.simulations = st.trials.runs() + st.screened_shots;
  const int final_shots = std::max(1, st.q.simulations - st.result.simulations);
  if (st.o.keep_every) st.out.every = st.feasible;
  PlannedShot& best = st.feasible[st.chosen];
  set_estimate(best, noisy_successes(st.s, st.q, st.s.balls[st.cue].id, best, final_shots, 0), final_shots);
  best.simulations += final_shots;
  st.result.simulations += final_shots;
  st.result.shot = std::move(best);
}

void collect_alternatives(SearchState& st) {
  std::vector<PlannedShot>& feasible = st.feasible;
  // Best first: the screened probability (of the most shots screened), then the window's.
  std::vector<std::size_t> rest;
  for (std::size_t i = 0; i < feasible.size(); ++i)
    if (i != st.chosen) rest.push_back(i);
  std::stable_sort(rest.begin(), rest.end(), [&](std::size_t a, std::size_t b) {
    if (feasible[a].success_probability != feasible[b].success_probability)
      return feasible[a].success_probability > feasible[b].success_probability;
    return feasible[a].window_probability > feasible[b].window_probability;
  });
  // The alternatives: the best variant (tip height, speed, side) of each
  // other shot, a shot being its target, kind, pocket, cushions and
  // intermediate ball.
  const auto same_shot = [](const PlannedShot& a, const PlannedShot& b) {
    return a.target == b.target && a.kind == b.kind && a.pocket == b.pocket && a.cushions == b.cushions &&
           a.intermediate_ball == b.intermediate_ball;
  };
  std::vector<PlannedShot>& alternatives = st.result.alternatives;
  for (std::size_t i : rest) {
    const bool shown = same_shot(feasible[i], st.result.shot) ||
                       std::any_of(alternatives.begin(), alternatives.end(),
                                   [&](const PlannedShot& a) { return same_shot(a, feasible[i]); });
    if (!shown) alternatives.push_back(std::move(feasible[i]));
  }
}

}  // namespace cueball::planning
