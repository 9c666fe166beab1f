// Inside the library: search_shots() as a short driver over one search state
// and a function per step of the method (shot_planner.hpp's header comment;
// the idea of Box2D v3's b2StepContext and its one function per solver
// stage). The steps, in the order search_shots() takes them:
//
//   validate          validate_request()            shot_planner.cpp
//   1-2. candidates   geometric_candidates(), one function per kind and the
//                     path checks                   candidates.cpp
//   3. the exact simulation, per candidate: solve aim, choose speed, windows
//                     search_candidates(), search_candidate()
//                                                   candidate_search.cpp,
//                     over the engine runs of ExactTrials (a trial, the
//                     aim solved, a window's edge)  aim_solver.cpp
//   2b. aim scan      scan_for_candidates()         aim_scan.cpp
//   (none feasible)   throw_no_feasible_shot()      shot_planner.cpp
//   4. noise          keep_most_screened(), then without noise
//                     rank_by_windows(); with it screen_feasible(),
//                     choose_finalists(), estimate_chosen(),
//                     collect_alternatives()        noise_screen.cpp
//                     and between the screens vary_best()
//                                                   variants.cpp
#pragma once

#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/angles.hpp"
#include "planning/shot_search.hpp"

namespace cueball {

namespace planning {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Shots of the brief noisy screen of every feasible shot, and the most
// feasible shots kept.
inline constexpr int kBaseScreenShots = 16;
inline constexpr std::size_t kMaxScreened = 12;
// Spin and speed variants (step 4 of the header): of the
// ShotSearch::varied_shots (kVariantCandidates by default, shot_search.hpp)
// best feasible shots by window probability, each tip height of
// ShotSearch::variant_heights (ball radii: draw, centre, follow) at each
// cue-speed factor of its variant_speeds on the shot's own speed, one more step along the speed
// where the best was at an end, a firm stroke (kVariantFirmFactor x the best's
// speed, kept inside its speed window) at the best, and side kVariantSide
// either way at the best and at the best of each tip height (there with
// the speed chosen for it); a variant's search may take kVariantRuns runs
// or so. A shot whose window probability is kNothingToGain or more is not
// varied. (ShotSearch's defaults: shot_search.hpp).
inline constexpr double kVariantSide = 0.2;
inline constexpr double kVariantFirmFactor = 4.0;
inline constexpr double kNothingToGain = 0.999;
// Window probabilities in one step of this rank by the brief noisy screen.
inline constexpr double kWindowStep = 0.02;
// The aim scan (header, step 2b): kScanAims aims across the cue ball's
// straight hits on the target at each cue speed of kScanSpeeds (m/s),
// centre ball; of the potting runs of aims found, at most kScanCandidates.
inline constexpr int kScanAims = 40;
inline constexpr std::array<double, 2> kScanSpeeds{2.0, 4.0};
inline constexpr std::size_t kScanCandidates = 3;
// The finalists screened on common draws, and the most shots each.
inline constexpr std::size_t kFinalists = 3;
inline constexpr int kFinalistShots = 200;
inline constexpr int kVariantRuns = 60;
// Engine runs one candidate's noise-free search may take.
inline constexpr int kCandidateRuns = 120;
// The screen's noise stream starts at kScreenFirstShot (shot_search.hpp);
// the final estimate's at 0, so `cueball batch` of the written scenario
// with the same seed draws the final estimate's noise.
// Arrival speed of the object ball at the pocket that the first speed aims at, m/s.
inline constexpr double kArrivalSpeed = 1.0;
// The largest step of the aim window's search outwards, degrees: a hole in
// the window wider than this (a jaw that turns the ball out between two
// aims that pot) is not stepped over.
inline constexpr double kAimWindowMostStepDeg = 0.2;
// The target's miss of the pocket's centre the aim is solved to, m.
inline constexpr double kLateralTol = 0.5e-3;
// Where the target through the pocket's centre does not drop: the misses
// tried instead, in steps of kOffsetFraction of the pocket's radius, at most
// kOffsetSteps to either side.
inline constexpr double kOffsetFraction = 0.3;
inline constexpr int kOffsetSteps = 3;
// The largest aim change such a miss is tried at, degrees (the secant's own
// largest step): from a local slope near zero, k steps of the pocket's
// radius would be degrees or turns away, another shot altogether (an aim of
// 1697 degrees was once returned).
inline constexpr double kOffsetMostDeg = 3.0;

inline double angle_deg(Vec2 v) { return std::atan2(v.y, v.x) / kDegree; }

// One candidate as geometry describes it.
struct Candidate {
  ShotKind kind = ShotKind::direct;
  std::string what;         // "bank off <cushion>, then <cushion> into <pocket>", ...
  std::size_t target = 0;   // index of the ball to pot
  std::size_t pocket = 0;
  std::vector<std::size_t> cushions;  // bank: the object ball's, in order; kick: the cue ball's
  std::size_t first_ball = 0;         // index of the ball the cue ball must meet first
  std::optional<std::size_t> intermediate;  // combination: index of ball A
  Vec2 last_leg;            // unit direction of the object ball's last leg into the pocket
  double aim_deg = 0.0;
  double cut_deg = 0.0;     // the cue ball's cut on first_ball
  double combination_cut_deg = 0.0;  // A's cut on the target
  double cue_path = 0.0;    // m
  double middle_path = 0.0; // A's path to the target, m
  double object_path = 0.0; // m
  double ease = 0.0;        // order of the search: larger first
};

// A noise-free engine run and what the planner reads from it.
struct Trial {
  bool simulated = false;
  bool success = false;
  bool touched = false;     // the cue ball's first contact is the intended ball (the target, or A)
  bool short_of_pocket = false;
  double lateral = kNaN;    // signed miss of the pocket centre across the last leg, m
  SimulationResult result;
};

// Thrown by ExactTrials::play when the noise-free search has used its share.
struct BudgetSpent {};

// What a window edge moves: the cue speed or the aim.
enum class WindowAxis { speed, aim };

// The noise-free engine runs of the search (header, step 3), counted against
// a limit: one trial of a strike, the aim solved on them, a window's edge.
class ExactTrials {
 public:
  ExactTrials(const Scenario& s, std::size_t cue, int most_runs)
      : s_(s), cue_(cue), R_(s.settings.parameters.ball.radius), most_runs_(most_runs) {}

  int runs() const { return runs_; }
  // Counts n runs made elsewhere (the aim scan's batch).
  void count(int n) { runs_ += n; }
  // Sets the most runs play() may take (in all).
  void limit(int most_runs) { most_runs_ = most_runs; }

  // The strike played once, noise-free, and read: whether it pots c's target
  // into c's pocket (pots_target()), and the target's signed lateral miss of
  // the pocket's centre across c's last leg. Throws BudgetSpent at the limit.
  Trial play(const ShotAction& a, const Candidate& c);

  // The aim that sends the target through the pocket's centre at this
  // speed (|lateral miss| < kLateralTol), from a.aim_deg: the secant method,
  // bisection once the root is bracketed and the secant step leaves the
  // bracket. It must pot; when `limit` runs do not converge, the potting aim
  // with the smallest miss; nullopt when none potted.
  std::optional<double> solve_aim(ShotAction a, const Candidate& c, bool& short_of_pocket, int limit);

  // The last value of `axis` from `inside` (pots) towards `direction` that
  // still pots: steps doubling from `step` (at most `most_step`) until one
  // misses (or `limit` is passed, which is then the edge), then bisection to `tol`.
  double window_edge(ShotAction a, const Candidate& c, WindowAxis axis, double inside, double direction, double step,
                     double tol, double limit, double most_step = std::numeric_limits<double>::infinity());

 private:
  const Scenario& s_;
  std::size_t cue_;
  double R_;
  int most_runs_;
  int runs_ = 0;
};

// One search of plan_shot(): the request, what was found so far and the
// budget spent. Each step function reads and writes it.
struct SearchState {
  SearchState(const Scenario& scenario, const PlanRequest& request, const ShotSearch& options, std::size_t cue_index,
              std::vector<std::size_t> target_indices)
      : s(scenario), q(request), o(options), cue(cue_index), targets(std::move(target_indices)),
        trials(scenario, cue_index, request.simulations * 3 / 4) {}

  const Scenario& s;
  const PlanRequest& q;
  const ShotSearch& o;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  std::size_t cue;                   // index of the cue ball
  std::vector<std::size_t> targets;  // indices of the balls the plan may pot (PlanRequest::targets)
  ShotPlanResult result;

  // 1-2. Candidates in order of ease.
  std::vector<Candidate> candidates;
  // 3. The exact simulation: at most two fifths of the budget on the search
  // (a candidate started before then may go on to three quarters), the rest
  // for the noise.
  ExactTrials trials;
  std::vector<PlannedShot> feasible;
  std::vector<std::size_t> feasible_of;  // the candidate of each feasible shot
  std::vector<std::size_t> family;       // the feasible shot each shot varies (step 4)

  // 4. Noise.
  int screened_shots = 0;   // noisy shots of the screens
  int finalist_shots = 0;   // shots each finalist is screened with
  int final_reserve = 0;    // shots kept for the final estimate
  bool variants_spent = false;
  int variant_cap = 0;      // engine runs the variants may reach
  std::size_t chosen = 0;   // the feasible shot played
  SearchedShots out;

  int search_budget() const { return q.simulations * 2 / 5; }
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); }
};

// --- validate (shot_planner.cpp) ---

// Checks the scenario and the request; the cue ball's index and the
// targets' (PlanRequest::targets) as SearchState takes them. Throws
// InvalidArgument naming the field.
std::pair<std::size_t, std::vector<std::size_t>> validate_request(const Scenario& s, const PlanRequest& q);

// NoFeasibleShot: a summary of the rejections by reason, then each.
[[noreturn]] void throw_no_feasible_shot(const SearchState& st);

// --- 1-2. candidates (candidates.cpp) ---

// Whether a shot of `kind` at the ball with index `target` may be played
// under PlanRequest::ball_on: the ball on by any kind but a combination,
// another target only by a combination through it; without ball_on, always.
bool kind_allowed(const Scenario& s, const PlanRequest& q, std::size_t target, ShotKind kind);

// The tip heights tried: the request's, or centre ball, then draw, then follow.
std::vector<double> tip_heights(const PlanRequest& q);

// The lowest elevation, in 2 degree steps from level up to
// kMaxPlanElevationDeg, at which the cue clears the balls and the rail.
std::optional<double> clearing_elevation(const Scenario& s, std::size_t cue, double aim_deg, double side,
                                         double height);

// Every candidate of the kinds asked for into each pocket allowed, for each
// target, in order of ease; the others in st.result.rejected with why.
void geometric_candidates(SearchState& st);

// --- 3. the exact simulation (candidate_search.cpp) ---

// One candidate at one tip height: the aim solved, the speed chosen, the
// windows found; nullopt and `why` when it does not pot. `fixed`: a
// variant's cue speed and the aim its solve starts from (the speed is then
// kept, not chosen). May throw BudgetSpent.
std::optional<PlannedShot> search_candidate(SearchState& st, const Candidate& c, double side, double height,
                                            std::string& why,
                                            std::optional<std::pair<double, double>> fixed = std::nullopt);

// Step 3 over every candidate in order: centre ball first, a scratch or a
// miss there tried with draw, then follow; the feasible shots into st.feasible.
void search_candidates(SearchState& st);

// --- 2b. the aim scan (aim_scan.cpp) ---

// Runs of neighbouring aims that pot, found by the scan and not known from
// geometry, searched as candidates (when the kinds and the budget allow).
void scan_for_candidates(SearchState& st);

// --- 4. noise (noise_screen.cpp, variants.cpp) ---

// The success probability the noise-free windows predict (header, step 4).
double window_probability(const PlannedShot& shot, const CueStrikeNoise& noise, const BallParameters& ball,
                          const CueParameters& cue);

// Better first: the window probability in steps of kWindowStep, then the
// brief screen's estimate.
bool better_by_window(const std::vector<PlannedShot>& feasible, std::size_t a, std::size_t b);

// Without noise (ShotSearch::noisy false): the feasible shots ranked by
// window probability into st.out.plan.
void rank_by_windows(SearchState& st);

// At most kMaxScreened feasible shots kept (the rest rejected).
void keep_most_screened(SearchState& st);

// Each feasible shot screened briefly on common draws (when there are two or
// more); the budgets of the finalists' screen and the final estimate set.
void screen_feasible(SearchState& st);

// The ShotSearch::varied_shots best by window probability tried again at other
// tip heights, speeds and sides (unless the request gives the tip height).
void vary_best(SearchState& st);

// The kFinalists best by window probability (and the best by the brief
// screen), screened on the same draws; st.chosen the best of them.
void choose_finalists(SearchState& st);

// The chosen shot measured on fresh draws with the rest of the budget.
void estimate_chosen(SearchState& st);

// The best variant of each other shot, best first, into st.result.alternatives.
void collect_alternatives(SearchState& st);

}  // namespace planning

}  // namespace cueball
