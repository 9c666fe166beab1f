// Inside the library: plan_shot() with a wider or a cheaper search, for its
// callers here (position play). The public entry is shot_planner.hpp.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cueball/planning/shot_planner.hpp"

namespace cueball {

/// The feasible shots plan_shot() varies (ShotSearch::varied_shots).
inline constexpr std::size_t kVariantCandidates = 3;

/// What plan_shot()'s step 4 tries (shot_planner.hpp); the defaults are plan_shot()'s own.
struct ShotSearch {
  std::vector<double> variant_heights{-0.3, 0.0, 0.3};  ///< tip heights of the variants, ball radii
  std::vector<double> variant_speeds{0.7, 1.0, 1.8};    ///< cue-speed factors of the variants
  /// The best feasible shots by window probability whose variants are
  /// searched.
  std::size_t varied_shots = kVariantCandidates;
  /// Vary a shot even when its window probability leaves nothing to gain
  /// (position play wants the spin and speed that leave the cue ball well).
  bool vary_easy = false;
  /// Engine runs the variants may take beyond the request's budget.
  int variant_runs = 0;
  /// False: no noisy shot at all (no screen, no variants, no estimate): the
  /// feasible shots ranked by window probability, success_probability 0.
  bool noisy = true;
  /// Fill SearchedShots::every (a copy of every shot found).
  bool keep_every = false;
};

struct SearchedShots {
  ShotPlanResult plan;
  /// With ShotSearch::keep_every and noise: every feasible shot and variant
  /// found, the chosen one among them (its success probability as screened,
  /// not as finally estimated). Empty otherwise.
  std::vector<PlannedShot> every;
};

/// plan_shot() with `search` (plan_shot(s, q) is search_shots(s, q, {}).plan).
SearchedShots search_shots(const Scenario& table_state, const PlanRequest& q, const ShotSearch& search);

/// The successes among `shots` noisy repeats of a planned shot under q.noise
/// and q.seed, counted by the planner's rule of success (shot_planner.hpp):
/// shots first_shot, first_shot + 1, ... of the seed's stream.
int noisy_successes(const Scenario& table_state, const PlanRequest& q, int cue_ball, const PlannedShot& shot, int shots,
                    std::uint64_t first_shot);

/// What noisy repeats of a planned shot did (noisy_outcomes()).
struct NoisyOutcomes {
  int hits = 0;                  ///< successes by the planner's rule
  std::vector<Scenario> leaves;  ///< the tables the first successes leave (balls at rest, the pocketed removed)
};

/// noisy_successes(), keeping the tables the first `leaves` successes leave
/// (table_after(), simulation/scenario.hpp), in the stream's order.
NoisyOutcomes noisy_outcomes(const Scenario& table_state, const PlanRequest& q, int cue_ball, const PlannedShot& shot,
                             int shots, std::uint64_t first_shot, int leaves);

/// Sets the shot's success probability to hits / shots, its standard error
/// sqrt(p (1 - p) / shots) and noisy_shots to shots.
void set_estimate(PlannedShot& shot, int hits, int shots);

/// The planner's rule of success (shot_planner.hpp), on what a shot did: the
/// cue ball's first contact is `first_ball` (the target, or a combination's
/// ball A), the target dropped (`target_pocket`: its pocket's index, -1 when
/// it stayed up) into `pocket`, or into any pocket when none is given, and
/// the cue ball stayed up.
inline bool pots_target(int first_contact, int first_ball, int target_pocket, std::optional<int> pocket,
                        bool cue_pocketed) {
  return first_contact == first_ball && (pocket ? target_pocket == *pocket : target_pocket >= 0) && !cue_pocketed;
}

/// The id of the ball the request strikes: PlanRequest::cue_ball, else the
/// scenario's cue ball, else 0 (as plan_shot() takes it).
inline int cue_ball_id(const Scenario& s, const PlanRequest& q) {
  return q.cue_ball ? *q.cue_ball : s.cue ? s.cue->ball : 0;
}

/// The ids of the request's legal targets: PlanRequest::targets, or {target}
/// when it is empty.
inline std::vector<int> target_ids(const PlanRequest& q) {
  return q.targets.empty() ? std::vector<int>{q.target} : q.targets;
}

/// "ball 1" for one target, "any of balls 1, 3, 5" for several.
std::string targets_text(const std::vector<int>& ids);

/// The best window probability of the request's shots on that table, from
/// search_shots() without a noisy shot; 0 when no shot is feasible.
/// `simulations` gains the engine runs spent (a plan with no feasible shot
/// counted at its whole budget: the error does not say what it spent).
double best_window_probability(const Scenario& table_state, const PlanRequest& q, int& simulations);

/// Where plan_shot()'s noisy screen starts in the seed's stream (its final
/// estimate starts at 0).
inline constexpr std::uint64_t kScreenFirstShot = std::uint64_t{1} << 40;

}  // namespace cueball
