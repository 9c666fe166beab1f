// cueball plan-shot: which strike pots this ball, and how sure is it
// (shot_planner.hpp).
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "common.hpp"
#include "cueball/io/plan_json.hpp"
#include "cueball/io/viewer_json.hpp"
#include "cueball/io/scenario_json.hpp"
#include "cueball/io/result_json.hpp"
#include "cueball/planning/ball_in_hand.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/planning/position_play.hpp"
#include "cueball/simulation/scenario.hpp"
#include "cueball/planning/shot_planner.hpp"
#include "cueball/io/viewer_page.hpp"

namespace cueball::cli {

namespace {

struct PlanShotFlags {
  std::string scenario;
  std::optional<int> ball;
  std::string targets;            // "1,3,5": the legal targets, instead of --ball
  std::optional<int> ball_on;     // PlanRequest::ball_on: the ball the cue ball must meet first
  std::string pocket = "any";
  std::string kinds = "direct,bank";
  std::string noise = "tournament";
  long long seed = 0;
  double simulations = 4000;  // a number, so that 1e9 gets the range error
  std::string scenario_out;
  std::string html;
  SigmaFlags sigma;
  bool json = false;
  bool position = false;
  bool in_hand = false;
  std::string region;             // "x_min,x_max,y_min,y_max", m; empty: anywhere
  std::optional<int> next;        // none: the lowest id left
  double next_simulations = kMinPlanSimulations;
  std::string valuation = "windows";  // PositionRequest::valuation
  std::optional<int> game_ball;       // PositionRequest::game_ball
};

// The viewer page of the planned shot, noise-free, with its aim line and
// ghost ball drawn (aim_overlay_json, io/viewer_json.hpp).
void write_plan_page(const std::string& path, const Scenario& planned, int cue_ball) {
  const SimulationResult r = run_scenario(planned);
  const std::string overlay = aim_overlay_json(r, planned.settings.parameters, cue_ball);
  write_text_file(path, viewer_page(viewer_template(), with_overlay(result_to_json(planned, r, 0.0, -1), overlay)),
                  "--html", "the viewer page");
}

std::string noise_label(const PlanShotFlags& f) {
  return f.noise + (f.sigma.any() ? " noise with the --sigma-* flags" : " noise");
}


std::string describe(const PlannedShot& shot) {
  std::string off;
  for (const std::string& c : shot.cushions) off += (off.empty() ? " off the " : ", then the ") + c;
  if (shot.intermediate_ball >= 0) off = " via ball " + std::to_string(shot.intermediate_ball);
  return std::string(to_string(shot.kind)) + off + " into " + shot.pocket_name;
}

// --ball, or --targets (a comma-separated list of ball ids): one of them.
void set_targets(const PlanShotFlags& f, const Scenario& s, PlanRequest& q) {
  if (f.ball) {
    q.target = *f.ball;
    return;
  }
  std::string ids;
  for (const SimulationBall& b : s.balls) ids += (ids.empty() ? "" : ", ") + std::to_string(b.id);
  std::stringstream parts(f.targets);
  for (std::string part; std::getline(parts, part, ',');) {
    std::size_t used = 0;
    long long id = -1;
    try {
      id = std::stoll(part, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != part.size() || id < 0 || id > 1'000'000'000)
      throw UsageError("--targets = " + quote_input(f.targets) + ": " + quote_input(part) +
                       " is not a ball id; allowed: a comma-separated list of ids of balls on the table (" + ids + ")");
    q.targets.push_back(static_cast<int>(id));
  }
  if (q.targets.empty())
    throw UsageError("--targets = " + quote_input(f.targets) +
                     " names no ball; allowed: a comma-separated list of ids of balls on the table (" + ids + ")");
  q.target = q.targets.front();
}

void run_plan_shot(const PlanShotFlags& f, std::ostream& out, std::ostream& err) {
  if (f.ball && !f.targets.empty())
    throw UsageError("--targets = " + quote_input(f.targets) + " and --ball = " + std::to_string(*f.ball) +
                     " are both given; allowed: one of them");
  if (!f.ball && f.targets.empty())
    throw UsageError("--ball is required: the id of the ball to pot (or --targets, the ids of the legal targets)");
  check_flag("--seed", static_cast<double>(f.seed), 0, 9.0e15, "random seed");
  check_flag("--simulations", f.simulations, kMinPlanSimulations, kMaxPlanSimulations,
             "engine runs the plan may use");
  if (f.simulations != std::floor(f.simulations))
    throw UsageError("--simulations = " + format_number_beside(f.simulations, {std::round(f.simulations)}) + " is not a whole number");
  const Scenario s = f.scenario.empty()
                         ? default_scenario()
                         : scenario_from_document(read_text_file(f.scenario, "the scenario file", kMaxScenarioBytes));
  PlanRequest q;
  set_targets(f, s, q);
  q.seed = static_cast<std::uint64_t>(f.seed);
  q.simulations = static_cast<int>(f.simulations);
  if (f.noise == "none") q.noise = CueStrikeNoise{};
  else if (f.noise == "tournament") q.noise = tournament_noise();
  else if (f.noise == "scenario") q.noise = s.noise;
  else throw UsageError("--noise = " + quote_input(f.noise) + " is not known; allowed: tournament, none, scenario");
  q.noise = with_sigma_flags(f.sigma, q.noise, s.settings.parameters.ball.radius);
  q.call_shot = f.pocket == "called";
  q.ball_on = f.ball_on;
  if (f.pocket != "any" && f.pocket != "called") {
    std::string names;
    for (std::size_t k = 0; k < s.table.pockets.size(); ++k) {
      names += (names.empty() ? "" : ", ") + s.table.pockets[k].name;
      if (s.table.pockets[k].name == f.pocket) q.pocket = static_cast<int>(k);
    }
    if (!q.pocket)
      throw UsageError("--pocket = " + quote_input(f.pocket) + " is not a pocket of " + s.table.name +
                       "; allowed: any, called" + (names.empty() ? "" : ", " + names));
  }
  q.kinds.clear();
  std::stringstream kinds(f.kinds);
  for (std::string kind; std::getline(kinds, kind, ',');) {
    const std::optional<ShotKind> k = shot_kind_from_string(kind);
    if (!k)
      throw UsageError("--kinds = " + quote_input(f.kinds) + ": " + quote_input(kind) +
                       " is not a kind; allowed: a comma-separated list of " + shot_kind_names());
    q.kinds.push_back(*k);
  }
  if (q.kinds.empty())
    throw UsageError("--kinds = " + quote_input(f.kinds) + " names no kind; allowed: a comma-separated list of " +
                     shot_kind_names());

  const bool position_play = f.position || f.in_hand;
  if (!position_play && f.next) throw UsageError("--next = " + std::to_string(*f.next) + " needs --position");
  if (!position_play && f.game_ball)
    throw UsageError("--game-ball = " + std::to_string(*f.game_ball) + " needs --position or --in-hand");
  const std::optional<LeaveValuation> valuation = leave_valuation_from_string(f.valuation);
  if (!valuation)
    throw UsageError("--valuation = " + quote_input(f.valuation) + " is not a valuation; allowed: " +
                     leave_valuation_names());
  if (!position_play && *valuation != LeaveValuation::windows)
    throw UsageError("--valuation = " + quote_input(f.valuation) + " needs --position or --in-hand");
  if (!f.in_hand && !f.region.empty()) throw UsageError("--region = " + quote_input(f.region) + " needs --in-hand");
  std::optional<PlacementRegion> region;
  if (const std::optional<PlacementRegion::Kind> kind = placement_region_from_string(f.region);
      kind && *kind != PlacementRegion::Kind::rectangle) {
    region = PlacementRegion{*kind};
  } else if (!f.region.empty()) {
    std::vector<double> v;
    std::stringstream parts(f.region);
    for (std::string part; std::getline(parts, part, ',');) {
      std::size_t used = 0;
      double x = 0.0;
      try {
        x = std::stod(part, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != part.size() || !std::isfinite(x))
        throw UsageError("--region = " + quote_input(f.region) + ": " + quote_input(part) +
                         " is not a finite number; allowed: x_min,x_max,y_min,y_max in m, or one of " +
                         placement_region_names());
      v.push_back(x);
    }
    if (v.size() != 4)
      throw UsageError("--region = " + quote_input(f.region) + " has " + std::to_string(v.size()) +
                       " numbers; allowed: 4, x_min,x_max,y_min,y_max in m");
    region = PlacementRegion{PlacementRegion::Kind::rectangle, v[0], v[1], v[2], v[3]};
  }
  check_flag("--next-simulations", f.next_simulations, kMinPlanSimulations, kMaxPlanSimulations,
             "engine runs of each next-shot plan");
  if (f.next_simulations != std::floor(f.next_simulations))
    throw UsageError("--next-simulations = " + format_number_beside(f.next_simulations, {std::round(f.next_simulations)}) + " is not a whole number");
  ShotPlanResult plan;
  PositionPlanResult position;
  Scenario on = s;  // the table planned on (with --in-hand, the cue ball at its spot)
  std::optional<BallInHandResult> in_hand;
  try {
    if (position_play) {
      PositionRequest p;
      p.shot = q;
      p.next_target = f.next;
      p.next_simulations = static_cast<int>(f.next_simulations);
      p.valuation = *valuation;
      p.game_ball = f.game_ball;
      if (f.in_hand) {
        in_hand = plan_ball_in_hand(s, BallInHandRequest{p, region});
        position = in_hand->plan;
        on = in_hand->table;
      } else {
        position = plan_shot_for_position(s, p);
      }
      plan = position.plan;
    } else {
      plan = plan_shot(s, q);
    }
  } catch (const InvalidArgument& e) {
    // The library's "target = 4 ..." is the flag's "--ball = 4 ...", "next = ..." is "--next = ...".
    const std::string message = e.what();
    if (e.field() == "target" && message.rfind("target", 0) == 0) throw UsageError("--ball" + message.substr(6));
    if (e.field() == "ball_on" && message.rfind("ball_on", 0) == 0) throw UsageError("--ball-on" + message.substr(7));
    if (e.field() == "targets") throw UsageError("--targets = " + quote_input(f.targets) + ": " + message);
    if (e.field() == "next" && message.rfind("next", 0) == 0) throw UsageError("--next" + message.substr(4));
    if (e.field() == "game_ball" && message.rfind("game_ball", 0) == 0)
      throw UsageError("--game-ball" + message.substr(9));
    if (e.field() == "region") throw UsageError("--region = " + quote_input(f.region) + ": " + message);
    throw;
  }
  if (!f.scenario_out.empty())
    write_text_file(f.scenario_out, scenario_to_json(scenario_with_shot(on, plan.cue_ball, plan.shot, q.noise)) + '\n',
                    "--scenario-out", "the scenario file");
  if (!f.html.empty()) write_plan_page(f.html, scenario_with_shot(on, plan.cue_ball, plan.shot, q.noise), plan.cue_ball);
  if (f.json) {
    out << plan_to_json(on, plan, q.noise, position_play ? &position : nullptr, in_hand ? &*in_hand : nullptr) << '\n';
    return;
  }
  const PlannedShot& b = plan.shot;
  const ShotAction& a = b.strike;
  out << "plan-shot: ball " << b.target << ", " << describe(b) << ": P(success) = " << fixed(b.success_probability, 3)
      << " +- " << fixed(b.success_standard_error, 3) << " (" << b.noisy_shots << " noisy shots, " << noise_label(f)
      << ", seed " << f.seed << ")\n";
  out << "  strike     speed " << fixed(a.speed, 3) << " m/s, aim " << fixed(a.aim_deg, 3) << " deg, elevation "
      << fixed(a.elevation_deg, 1) << " deg, side " << fixed(a.side, 2) << ", height " << fixed(a.height, 2)
      << " (cue ball " << fixed(b.ball_speed, 3) << " m/s)\n";
  out << "  geometry   aim " << fixed(b.geometric_aim_deg, 3) << " deg (cut " << fixed(b.cut_deg, 1)
      << " deg); the exact simulation moves it by " << fixed(a.aim_deg - b.geometric_aim_deg, 3) << " deg\n";
  out << "  windows    aim [" << fixed(b.aim_window_deg[0], 3) << ", " << fixed(b.aim_window_deg[1], 3)
      << "] deg, speed [" << fixed(b.speed_window[0], 2) << ", " << fixed(b.speed_window[1], 2) << "] m/s\n";
  out << "  robot      level cue: tip height " << fixed(b.robot.tip_height * 1000.0, 1) << " mm, cue speed "
      << fixed(b.robot.cue_speed, 3) << " m/s\n";
  const auto leave_line = [&](const Leave& l) {
    std::string line = "leaves the cue ball at (" + fixed(l.cue_ball.x, 3) + ", " + fixed(l.cue_ball.y, 3) + ")";
    if (position.next_target < 0) return line + "; no ball left after this one";
    line += ": ball " + std::to_string(position.next_target) + " next, ";
    const bool by_ghost_ball = f.valuation == to_string(LeaveValuation::ghost_ball);
    line += l.next_feasible ? (by_ghost_ball ? "ghost-ball P = " : "P = ") + fixed(l.next_success_probability, 3) +
                                  " (" + l.next_kind +
                                  (l.next_ball != position.next_target
                                       ? " of ball " + std::to_string(l.next_ball) + " through it"
                                       : std::string()) +
                                  " into " + l.next_pocket + ")"
                            : "no feasible shot";
    if (l.noisy_leaves > 0)
      line += "; from " + std::to_string(l.noisy_leaves) + " noisy leaves " + fixed(l.noisy_next_window, 3);
    return line + "; P(both) = " + fixed(l.score, 3) + " (this pot screened at " + fixed(l.screened_probability, 3) + ")";
  };
  if (in_hand)
    out << "  in hand    the cue ball placed at (" << fixed(in_hand->cue_ball.x, 3) << ", " << fixed(in_hand->cue_ball.y, 3)
        << "): the best of " << in_hand->spots_played << " spots played for position (" << in_hand->spots
        << " behind ghost balls)\n";
  if (position_play) out << "  position   " << leave_line(position.leave) << "\n";
  out << "  cost       " << plan.simulations << (position_play ? " simulations at most, " : " simulations, ")
      << fixed(plan.seconds, 3) << " s\n";
  for (std::size_t k = 0; k < plan.alternatives.size(); ++k) {
    const PlannedShot& alt = plan.alternatives[k];
    out << "  also       " << (f.targets.empty() ? "" : "ball " + std::to_string(alt.target) + ", ") << describe(alt)
        << ": P = " << fixed(alt.success_probability, 3) << " +- "
        << fixed(alt.success_standard_error, 3) << " (" << alt.noisy_shots << " shots), aim "
        << fixed(alt.strike.aim_deg, 3) << " deg, speed " << fixed(alt.strike.speed, 3) << " m/s, height "
        << fixed(alt.strike.height, 2) << "\n";
    if (position_play) out << "             " << leave_line(position.alternative_leaves[k]) << "\n";
  }
  if (!f.scenario_out.empty()) out << "  scenario written to " << f.scenario_out << " (cueball simulate replays it)\n";
  if (!f.html.empty()) out << "  viewer written to " << f.html << " (the shot with its aim line and ghost ball)\n";
  (void)err;
}

}  // namespace

Command add_plan_shot_command(CLI::App& app) {
  auto flags = std::make_shared<PlanShotFlags>();
  CLI::App* sub = app.add_subcommand(
      "plan-shot",
      "Plans the strike that pots ball --ball (or any of --targets): ghost-ball (direct, combination) and mirror-point (bank\n"
      "off one or two cushions, kick) geometry for a first aim, and a scan of aims for pots geometry\n"
      "misses; blocked paths and an obstructed cue skipped, the aim then corrected on the exact\n"
      "simulation (throw, the cloth, the cushions), the aim and speed windows that still pot found,\n"
      "spin and speed variants ranked by the chance that the noise keeps them inside their windows, and\n"
      "the success probability estimated from noisy simulations (--noise tournament: sigma 0.125 deg\n"
      "aim, 0.1 deg elevation, 0.075 m/s speed, 0.5 mm tip). A pot needs the ball in the intended pocket\n"
      "(under the noise, with --pocket any, in any pocket; with --pocket called, a call shot as in 8-ball\n"
      "and 10-ball, only in the pocket each shot aims at), the cue ball touching it first (for a\n"
      "combination: the intermediate ball) and not pocketed. The scenario's own cue strike is\n"
      "ignored. --scenario-out writes the scenario with the planned cue (cueball simulate\n"
      "replays it); --html the viewer page of the planned shot with its aim line and ghost ball. The\n"
      "--sigma-* flags replace single sigmas of the --noise model; --position plays for position;\n"
      "--in-hand places the cue ball too (ball in hand), played for position.\n"
      "Exit status 3 when no shot is feasible.");
  sub->add_option("scenario", flags->scenario, "Scenario JSON file (default: the built-in 9-ball break)");
  sub->add_option("--ball", flags->ball, "Id of the ball to pot (or --targets)");
  sub->add_option("--targets", flags->targets,
                  "Ids of the legal targets, comma-separated (e.g. 1,3,5), instead of --ball: the plan pots any one\n"
                  "of them, the best shot of all");
  sub->add_option("--ball-on", flags->ball_on,
                  "Id of the ball the cue ball must meet first (9-ball's and 10-ball's lowest ball, WPA 6.2): the\n"
                  "ball pots by the kinds asked for but combination, another target only by a combination through\n"
                  "it (give --kinds combination)");
  sub->add_option("--pocket", flags->pocket,
                  "Pocket name (e.g. top-right); any (a pot in any pocket counts, as in 9-ball); or called (any\n"
                  "pocket may be planned, but each shot's pot counts only in its own pocket: a call shot, WPA 1.6)")
      ->capture_default_str();
  sub->add_option("--kinds", flags->kinds,
                  "Kinds of shot to consider, comma-separated: direct, bank (off one or two cushions), kick (the "
                  "cue ball off a cushion first), combination (the cue ball sends another ball into the target)")
      ->capture_default_str();
  sub->add_option("--noise", flags->noise, "Execution noise: tournament, none, or scenario (the scenario's \"noise\")")
      ->capture_default_str();
  sub->add_option("--seed", flags->seed, "Random seed of the noisy estimates")->capture_default_str();
  sub->add_option("--simulations", flags->simulations, "Engine runs the plan may use, [500, 1e6]")
      ->capture_default_str();
  add_sigma_flags(*sub, flags->sigma);
  sub->add_option("--scenario-out", flags->scenario_out, "Write the scenario with the planned cue to this file");
  sub->add_option("--html", flags->html,
                  "Write the viewer page of the planned shot (noise-free) with the aim line and ghost ball");
  sub->add_flag("--json", flags->json, "Print one JSON object");
  sub->add_flag("--position", flags->position,
                "Play for position: among the shots that pot and their spin and speed variants, the one\n"
                "that leaves the best next shot, scored P(this pot) x P(next pot) on the table each leaves");
  sub->add_flag("--in-hand", flags->in_hand,
                "Ball in hand: place the cue ball (its place in the scenario ignored) where the shot, played for\n"
                "position, scores best; spots behind the target's ghost ball for each clear pocket");
  sub->add_option("--region", flags->region,
                  "With --in-hand: where the cue ball may go: x_min,x_max,y_min,y_max in m, or kitchen (behind the\n"
                  "head string), d (snooker's D) or anywhere (the default)");
  sub->add_option("--next", flags->next, "With --position: id of the next ball (default: the lowest id left)");
  sub->add_option("--next-simulations", flags->next_simulations,
                  "With --position: engine runs of each next-shot plan, [500, 1e6]")
      ->capture_default_str();
  sub->add_option("--valuation", flags->valuation,
                  "With --position or --in-hand: how a leave's next shot is valued: windows (the planner's window\n"
                  "search on the exact simulation) or ghost_ball (the best straight pot's chance under the aim\n"
                  "noise from the geometry alone: no engine run, a decision in a fraction of the time)")
      ->capture_default_str();
  sub->add_option("--game-ball", flags->game_ball,
                  "With --valuation ghost_ball: id of a ball whose pot wins at once whichever ball is met first\n"
                  "(9-ball's 9): a leave is also valued by its combination through the next ball");
  return [flags](std::ostream& out, std::ostream& err) { run_plan_shot(*flags, out, err); };
}

}  // namespace cueball::cli
