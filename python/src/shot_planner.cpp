// plan_shot: which strike pots this ball, and how sure is it
// (include/cueball/planning/shot_planner.hpp). The plan comes back as the dict of
// `cueball plan-shot --json` (json.loads of plan_to_json, io/plan_json.hpp: the
// same writer, so the same keys and values), plus each shot's scenario with
// its planned cue as a Scenario object.
#include <array>
#include <memory>
#include <optional>
#include <variant>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "cueball/io/plan_json.hpp"
#include "cueball/io/scenario_json.hpp"
#include "cueball/planning/ball_in_hand.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/planning/position_play.hpp"
#include "cueball/planning/shot_planner.hpp"

namespace cueball_python {

namespace {

using cueball::PlannedShot;
using cueball::Scenario;

// noise: a model's name, or a dict of sigmas in the units of the scenario's
// "noise" (read by the scenario's own reader: the same keys, ranges and errors).
cueball::CueStrikeNoise noise_model(const py::object& noise, const Scenario& s) {
  if (py::isinstance<py::dict>(noise))
    return cueball::noise_from_json(json_text(noise, "noise"), s.settings.parameters.ball.radius, "noise");
  if (!py::isinstance<py::str>(noise))
    throw ArgumentTypeError("noise", wrong_type_message(noise, "noise",
                                                       "'tournament', 'none', 'scenario' or a dict of sigmas (speed, "
                                                       "aim_deg, elevation_deg, side, height)"));
  const std::string name = utf8_argument(noise, "noise");
  if (name == "tournament") return cueball::tournament_noise();
  if (name == "none") return {};
  if (name == "scenario") return s.noise;
  throw cueball::InvalidArgument("noise", "noise = '" + name + "' is not known; allowed: 'tournament', 'none', 'scenario' or a dict of sigmas");
}

std::vector<cueball::ShotKind> shot_kinds(const std::vector<std::string>& names) {
  std::vector<cueball::ShotKind> kinds;
  for (const std::string& k : names) {
    const std::optional<cueball::ShotKind> kind = cueball::shot_kind_from_string(k);
    if (!kind)
      throw cueball::InvalidArgument("kinds", "kinds: '" + k + "' is not a kind; allowed: " +
                                                  cueball::shot_kind_names("'"));
    kinds.push_back(*kind);
  }
  if (kinds.empty())
    throw cueball::InvalidArgument("kinds", "kinds names no kind; allowed: " + cueball::shot_kind_names("'"));
  return kinds;
}

std::optional<int> pocket_index(const py::object& pocket, const Scenario& s) {
  if (pocket.is_none()) return std::nullopt;
  if (py::isinstance<py::str>(pocket)) {
    const std::string name = utf8_argument(pocket, "pocket");
    if (name == "any" || name == "called") return std::nullopt;
    std::string names;
    for (std::size_t k = 0; k < s.table.pockets.size(); ++k) {
      if (s.table.pockets[k].name == name) return static_cast<int>(k);
      names += ", '" + s.table.pockets[k].name + "'";
    }
    throw cueball::InvalidArgument("pocket", "pocket = '" + name + "' is not a pocket of " + s.table.name +
                                                 "; allowed: 'any', 'called'" + names + " or an index");
  }
  return cast_argument<int>(pocket, "pocket", "a pocket's name, 'any', 'called' or an index");  // plan_shot checks the index's range
}

// region=: a name (placement.hpp: "kitchen", "d", "anywhere", ...) or a
// rectangle (x_min, x_max, y_min, y_max), m.
cueball::PlacementRegion placement_region(const std::variant<std::string, std::array<double, 4>>& region) {
  if (const auto* r = std::get_if<std::array<double, 4>>(&region))
    return {cueball::PlacementRegion::Kind::rectangle, (*r)[0], (*r)[1], (*r)[2], (*r)[3]};
  const std::string& name = std::get<std::string>(region);
  const std::optional<cueball::PlacementRegion::Kind> kind = cueball::placement_region_from_string(name);
  if (!kind || *kind == cueball::PlacementRegion::Kind::rectangle)
    throw cueball::InvalidArgument("region", "region = " + cueball::quote_input(name) + " is not known; allowed: (x_min, x_max, y_min, y_max) in m, or one of " +
                                                 cueball::placement_region_names());
  return {*kind};
}

// target or targets (one of them) into the request.
void set_targets(std::optional<int> target, const std::optional<std::vector<int>>& targets, cueball::PlanRequest& q) {
  if (target && targets)
    throw cueball::InvalidArgument("targets", "targets and target = " + std::to_string(*target) +
                                                  " are both given; allowed: one of them");
  if (!target && !targets)
    throw cueball::InvalidArgument("target", "target is required: the id of the ball to pot (or targets, the ids of the legal targets)");
  if (target) {
    q.target = *target;
    return;
  }
  if (targets->empty()) throw cueball::InvalidArgument("targets", "targets is empty; allowed: one or more ball ids");
  q.targets = *targets;
  q.target = targets->front();
}

}  // namespace

void bind_shot_planner(py::module_& m) {
  m.def(
      "plan_shot",
      [](const py::object& scenario, std::optional<int> target, std::optional<std::vector<int>> targets,
         std::optional<int> cue_ball, const py::object& pocket, const std::vector<std::string>& kinds,
         const py::object& noise, std::uint64_t seed, long long simulations, double side, std::optional<double> height,
         bool position, std::optional<int> next, std::optional<std::vector<std::vector<int>>> next_targets,
         long long next_simulations, bool in_hand,
         std::optional<std::variant<std::string, std::array<double, 4>>> region, const std::string& valuation,
         std::optional<int> ball_on, std::optional<int> game_ball) {
        if (simulations < cueball::kMinPlanSimulations || simulations > cueball::kMaxPlanSimulations)
          throw cueball::InvalidArgument("simulations", static_cast<double>(simulations),
                                         "[" + std::to_string(cueball::kMinPlanSimulations) + ", " +
                                             cueball::format_number(cueball::kMaxPlanSimulations) + "]",
                                         "engine runs the plan may use");
        const ScenarioInput input = scenario_input(scenario);
        const std::shared_ptr<const Scenario> s = load_scenario(input);
        cueball::PlanRequest q;
        q.cue_ball = cue_ball;
        set_targets(target, targets, q);
        q.pocket = pocket_index(pocket, *s);
        q.call_shot = py::isinstance<py::str>(pocket) && pocket.cast<std::string>() == "called";
        q.ball_on = ball_on;
        q.kinds = shot_kinds(kinds);
        q.noise = noise_model(noise, *s);
        q.seed = seed;
        q.simulations = static_cast<int>(simulations);
        q.side = side;
        q.height = height;
        const bool position_play = position || in_hand;
        if (!position_play && next)
          throw cueball::InvalidArgument("next", "next = " + std::to_string(*next) + " needs position=True");
        if (!position_play && game_ball)
          throw cueball::InvalidArgument("game_ball", "game_ball = " + std::to_string(*game_ball) + " needs position=True");
        if (!position_play && next_targets)
          throw cueball::InvalidArgument("next_targets", "next_targets needs position=True");
        if (!in_hand && region) throw cueball::InvalidArgument("region", "region needs in_hand=True");
        const std::optional<cueball::LeaveValuation> leave_valuation = cueball::leave_valuation_from_string(valuation);
        if (!leave_valuation)
          throw cueball::InvalidArgument("valuation", "valuation = " + cueball::quote_input(valuation) +
                                                          " is not known; allowed: " + cueball::leave_valuation_names());
        if (!position_play && *leave_valuation != cueball::LeaveValuation::windows)
          throw cueball::InvalidArgument("valuation", "valuation = " + cueball::quote_input(valuation) +
                                                          " needs position=True or in_hand=True");
        if (next_simulations < cueball::kMinPlanSimulations || next_simulations > cueball::kMaxPlanSimulations)
          throw cueball::InvalidArgument("next_simulations", static_cast<double>(next_simulations),
                                         "[" + std::to_string(cueball::kMinPlanSimulations) + ", " +
                                             cueball::format_number(cueball::kMaxPlanSimulations) + "]",
                                         "engine runs of each next-shot plan");
        cueball::ShotPlanResult plan;
        cueball::PositionPlanResult played;
        std::optional<cueball::BallInHandResult> placed;
        {
          py::gil_scoped_release release;
          if (position_play) {
            cueball::PositionRequest p;
            p.shot = q;
            p.next_target = next;
            if (next_targets) p.next_targets = *next_targets;
            p.next_simulations = static_cast<int>(next_simulations);
            p.valuation = *leave_valuation;
            p.game_ball = game_ball;
            if (in_hand) {
              cueball::BallInHandRequest h{p, std::nullopt};
              if (region) h.region = placement_region(*region);
              placed = cueball::plan_ball_in_hand(*s, h);
              played = placed->plan;
            } else {
              played = cueball::plan_shot_for_position(*s, p);
            }
            plan = played.plan;
          } else {
            plan = cueball::plan_shot(*s, q);
          }
        }
        const Scenario& on = placed ? placed->table : *s;
        // The CLI's plan-shot --json (io/plan_json.hpp), and each shot's Scenario.
        py::dict out = json_loads(cueball::plan_to_json(on, plan, q.noise, position_play ? &played : nullptr,
                                                        placed ? &*placed : nullptr, -1));
        const auto scenario_of = [&](const PlannedShot& shot) {
          return std::make_shared<Scenario>(cueball::scenario_with_shot(on, plan.cue_ball, shot, q.noise));
        };
        out["scenario"] = scenario_of(plan.shot);
        const py::list alternatives = out["alternatives"];
        for (std::size_t k = 0; k < plan.alternatives.size(); ++k)
          alternatives[k].cast<py::dict>()["scenario"] = scenario_of(plan.alternatives[k]);
        return out;
      },
      "scenario"_a, "target"_a = py::none(), py::kw_only(), "targets"_a = py::none(), "cue_ball"_a = py::none(),
      "pocket"_a = "any",
      "kinds"_a = std::vector<std::string>{"direct", "bank"}, "noise"_a = "tournament", "seed"_a = 0,
      "simulations"_a = 4000, "side"_a = 0.0, "height"_a = py::none(), "position"_a = false, "next"_a = py::none(),
      "next_targets"_a = py::none(), "next_simulations"_a = cueball::kMinPlanSimulations, "in_hand"_a = false, "region"_a = py::none(),
      "valuation"_a = "windows", "ball_on"_a = py::none(), "game_ball"_a = py::none(),
      "Plans the strike that pots ball `target` (cueball plan-shot, shot_planner.hpp), or any ball of\n"
      "`targets` (a list of ids, the legal targets: plan-shot --targets; give one of the two; each\n"
      "shot's dict says its `target`): ghost-ball\n"
      "(direct, combination) and mirror-point (bank off one or two cushions, kick) geometry for a\n"
      "first aim, blocked paths and an obstructed cue skipped, the aim then solved on the exact simulation (throw, the cloth, the\n"
      "cushion), the aim and speed windows that still pot, and the success probability from noisy\n"
      "simulations. scenario: as simulate()'s (its own cue strike is ignored; None: the built-in\n"
      "rack); pocket: 'any', 'called' (a call shot, WPA 1.6: each shot's pot counts only in the pocket\n"
      "it aims at, as 8-ball and 10-ball score it), a pocket's name or index; kinds: any of 'direct', 'bank', 'kick',\n"
      "'combination'; ball_on: the id of the ball the cue ball must meet first (9-ball's and 10-ball's\n"
      "lowest, WPA 6.2: another target is then played only by a combination through it; plan-shot\n"
      "--ball-on); noise: 'tournament'\n"
      "(sigma 0.125 deg aim, 0.1 deg elevation, 0.075 m/s, 0.5 mm tip), 'none', 'scenario' (the\n"
      "scenario's own \"noise\") or a dict of sigmas as the scenario's \"noise\" takes them (speed m/s,\n"
      "aim_deg, elevation_deg, side and height in ball radii; missing keys 0); simulations: the budget of engine runs, [500, 1e6]; side, height:\n"
      "tip offsets in ball radii (height None: centre ball, then draw, then follow; then draw, centre and follow at three speeds and side either way, ranked by their windows and screened under noise; given: that height only). Returns the dict\n"
      "of `cueball plan-shot --json`, json.loads of the same writer (io/plan_json.hpp): the same keys and\n"
      "values, pairs as lists (cue in the scenario's units, target, kind, pocket, cushion (the first;\n"
      "only when the shot has one), cushions (in order), intermediate_ball (a combination's; else None),\n"
      "success_probability, success_standard_error, noisy_shots, window_probability, aim_window_deg,\n"
      "speed_window (m/s), robot {tip_height m, cue_speed m/s}, ball_speed, geometric_aim_deg, cut_deg,\n"
      "combination_cut_deg (combinations only), predicted, simulations, seconds, alternatives, rejected);\n"
      "Python adds one key the CLI's JSON has not: `scenario` (also in each alternative), the Scenario\n"
      "with the planned cue (simulate() replays the plan). position=True\n"
      "plays for position (position_play.hpp; cueball plan-shot --position): every shot and its\n"
      "variants at five tip heights and six speeds, the leaves scored by window probabilities, the three\n"
      "best screened and the next ball planned on the table each leaves; the one played maximises\n"
      "P(pot, screened) x P(next ball's pot), its success_probability then measured on fresh draws;\n"
      "next: the next ball's id (None: the lowest id left); next_targets: the next shots' legal targets\n"
      "in turn, a list of lists of ids (9-ball [[2], [3], ...]; 8-ball [[9, ..., 15], [8]]: the next shot\n"
      "pots any ball of the first list left on the table; instead of next); next_simulations: each next plan's budget;\n"
      "valuation: how a leave's next shot is valued, 'windows' (the planner's window search) or 'ghost_ball' (the\n"
      "best straight pot's chance under the aim noise from the geometry alone, no engine run; position_play.hpp);\n"
      "each shot's dict then has `position` (next, cue_ball, next_feasible, next_success_probability,\n"
      "next_kind, next_pocket, next_ball, screened_probability, score). in_hand=True: ball in hand (ball_in_hand.hpp;\n"
      "plan-shot --in-hand), the cue ball placed (its place in the scenario ignored) where the shot, played for\n"
      "position, scores best, inside region (a rectangle (x_min, x_max, y_min, y_max) m, or 'kitchen', 'd',\n"
      "'anywhere') when given; the dict then has\n"
      "`in_hand` (cue_ball, spots, spots_played) and `scenario` has the cue ball at its spot. Raises\n"
      "NoFeasibleShot when no candidate pots. Releases the GIL while planning.");
}

}  // namespace cueball_python
