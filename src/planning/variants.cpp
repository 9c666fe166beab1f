// Step 4 of the shot planner (shot_planner.hpp), vary: the spin and speed
// variants of the best feasible shots, each variant's aim solved and windows
// found as in step 3 (its speed held).
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "planning/search_state.hpp"

namespace cueball::planning {

namespace {

// One variant of feasible[base]: its index in st.feasible, nullopt when it
// does not pot or the variants' budget is spent (st.variants_spent).
std::optional<std::size_t> vary(SearchState& st, std::size_t base, double side, double height,
                                std::optional<double> speed) {
  if (st.variants_spent) return std::nullopt;
  if (st.trials.runs() + kVariantRuns > st.variant_cap) {
    st.variants_spent = true;
    return std::nullopt;
  }
  st.trials.limit(st.variant_cap);
  const std::size_t ci = st.feasible_of[st.family[base]];
  const int runs_before = st.trials.runs();
  std::string why;
  std::optional<PlannedShot> v;
  try {
    v = speed ? search_candidate(st, st.candidates[ci], side, height, why,
                                 std::pair<double, double>{*speed, st.feasible[base].strike.aim_deg})
              : search_candidate(st, st.candidates[ci], side, height, why);
  } catch (const BudgetSpent&) {
    st.variants_spent = true;
  }
  if (!v) return std::nullopt;
  v->simulations = st.trials.runs() - runs_before;
  st.feasible.push_back(std::move(*v));
  st.family.push_back(st.family[base]);
  return st.feasible.size() - 1;
}

// The speed of a variant at `factor` times the base's, kept 3 sigma of
// speed noise inside the base's speed window; nullopt when that leaves
// it too close to the base's own speed.
std::optional<double> variant_speed(const PlannedShot& b, double factor, const CueStrikeNoise& noise) {
  double speed = b.strike.speed * factor;
  if (factor > 1.0) {
    speed = std::min(speed, b.speed_window[1] - 3.0 * noise.speed);
    if (speed < b.strike.speed * 1.2) return std::nullopt;
  } else if (factor < 1.0) {
    speed = std::max(speed, b.speed_window[0] + 3.0 * noise.speed);
    if (speed > b.strike.speed * 0.9) return std::nullopt;
  }
  return speed;
}

// The variant `v` (when found) in place of `best` if its window
// probability is higher.
bool improves(const SearchState& st, std::optional<std::size_t> v, std::size_t best) {
  return v && st.feasible[*v].window_probability > st.feasible[best].window_probability;
}

// The variants of one base shot: tip heights x speeds about it, one more
// speed step along the best's when it was at an end, a firm stroke at the
// best's tip height (kVariantFirmFactor x its speed, kept inside its speed
// window), and side either way at the best of each tip height, at its speed
// and at the speed chosen for it (unless the request gives the side).
void vary_shot(SearchState& st, std::size_t base) {
  const ShotSearch& o = st.o;
  const CueStrikeNoise& noise = st.q.noise;
  std::size_t best = base;
  double best_factor = 1.0;
  std::vector<std::size_t> best_of_height;  // the best variant of each tip height
  for (double height : o.variant_heights) {
    std::optional<std::size_t> best_here;
    if (height == st.feasible[base].strike.height) best_here = base;
    for (double factor : o.variant_speeds) {
      if (height == st.feasible[base].strike.height && factor == 1.0) continue;
      const std::optional<double> speed = variant_speed(st.feasible[base], factor, noise);
      if (!speed) continue;
      const std::optional<std::size_t> v = vary(st, base, st.feasible[base].strike.side, height, *speed);
      if (v && (!best_here || improves(st, v, *best_here))) best_here = *v;
      if (improves(st, v, best)) best = *v, best_factor = factor;
    }
    if (best_here) best_of_height.push_back(*best_here);
  }
  // Further along the speed of the best, when it was at an end.
  if (best_factor != 1.0) {
    const double factor = best_factor < 1.0 ? o.variant_speeds.front() : o.variant_speeds.back();
    if (const std::optional<double> speed = variant_speed(st.feasible[best], factor, noise))
      if (const std::optional<std::size_t> v =
              vary(st, best, st.feasible[best].strike.side, st.feasible[best].strike.height, *speed);
          improves(st, v, best))
        best = *v;
  }
  if (const std::optional<double> firm = variant_speed(st.feasible[best], kVariantFirmFactor, noise))
    vary(st, best, st.feasible[best].strike.side, st.feasible[best].strike.height, *firm);
  // Side spin, unless the request gives the side.
  if (st.q.side != 0.0) return;
  for (const double side : {-kVariantSide, kVariantSide}) {
    if (std::hypot(side, st.feasible[best].strike.height) <= kMiscueOffsetFraction)
      vary(st, best, side, st.feasible[best].strike.height, st.feasible[best].strike.speed);
    for (const std::size_t b : best_of_height)
      if (std::hypot(side, st.feasible[b].strike.height) <= kMiscueOffsetFraction)
        vary(st, b, side, st.feasible[b].strike.height, std::nullopt);  // the speed chosen for it
  }
}

}  // namespace

void vary_best(SearchState& st) {
  if (st.q.height) return;
  std::vector<std::size_t> order(st.feasible.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return better_by_window(st.feasible, a, b); });
  const std::size_t variant_candidates = std::min(st.o.varied_shots, order.size());
  // What the variants may spend: the finalists' screen and the final
  // estimate's reserve stay free.
  st.variant_cap = st.q.simulations + st.o.variant_runs - st.final_reserve -
                   static_cast<int>(kFinalists) * st.finalist_shots - st.screened_shots;
  for (std::size_t r = 0; r < variant_candidates && !st.variants_spent; ++r) {
    const std::size_t base = order[r];
    if (!st.o.vary_easy && st.feasible[base].window_probability >= kNothingToGain) continue;
    vary_shot(st, base);
  }
}

}  // namespace cueball::planning
