// cueball.games: the games layer (include/cueball/games/game.hpp), its
// agents (agents/agent.hpp, agents/match.hpp) and its JSON
// (io/game_json.hpp), as the submodule `games` of the extension (the
// package makes it `cueball.games`). States, actions and records are
// objects with to_json()/from_json() in the CLI's formats, so a state or
// record written by `cueball game` loads here and the other way round;
// rulings and facts are dicts of those same JSON objects.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "cueball/agents/match.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/io/game_json.hpp"
#include "cueball/io/scenario_json.hpp"
#include "cueball/io/shot_facts_json.hpp"
#include "cueball/planning/shot_planner.hpp"

namespace cueball_python {

namespace {

using cueball::Action;
using cueball::GameConfig;
using cueball::GameRecord;
using cueball::GameState;

py::object loads(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

cueball::GameKind game_kind(const std::string& name) {
  const std::optional<cueball::GameKind> kind = cueball::game_kind_from_string(name);
  if (!kind)
    throw cueball::InvalidArgument("kind", "kind = " + cueball::quote_input(name) + " is not a game; allowed: " +
                                               cueball::game_kind_names());
  return *kind;
}

// A GameConfig, or a game's name for its default_config().
GameConfig config_argument(const py::object& config) {
  if (py::isinstance<GameConfig>(config)) return config.cast<GameConfig>();
  if (py::isinstance<py::str>(config)) return cueball::default_config(game_kind(utf8_argument(config, "config")));
  throw ArgumentTypeError("config", wrong_type_message(config, "config", "a GameConfig or a game's name"));
}


double radius_of(const GameConfig& c) { return cueball::preset_table(c.table).ball.radius; }

// An agent by name (agents/agent.hpp, agent_named()), its engine runs a
// decision when given.
cueball::AgentOptions agent_options(const std::string& name, const std::string& field, std::optional<int> simulations,
                                    std::optional<double> seconds) {
  const std::optional<cueball::AgentOptions> agent = cueball::agent_named(name);
  if (!agent)
    throw cueball::InvalidArgument(field, field + " = " + cueball::quote_input(name) + " is not an agent; allowed: " +
                                              cueball::agent_names());
  cueball::AgentOptions o = *agent;
  if (simulations) o.simulations = *simulations;
  if (seconds) o.seconds = *seconds;
  return o;
}

py::object region_object(const std::optional<cueball::PlacementRegion>& r) {
  if (!r) return py::none();
  if (r->kind != cueball::PlacementRegion::Kind::rectangle) return py::str(cueball::to_string(r->kind));
  return py::dict("kind"_a = "rectangle", "x_min"_a = r->x_min, "x_max"_a = r->x_max, "y_min"_a = r->y_min,
                  "y_max"_a = r->y_max);
}

std::vector<std::string> decision_list(const std::vector<cueball::Decision>& ds) {
  std::vector<std::string> out;
  for (const cueball::Decision d : ds) out.emplace_back(cueball::to_string(d));
  return out;
}

// A step of play(): the library's GameStep, its facts and simulation result built on first access.
struct Step {
  cueball::GameStep step;
  py::object facts, result;
};

// A record's step, as in the record JSON.
// An agent's reasoning (games/record.hpp) as a dict: {"summary", "considered":
// [{"what", "estimate", "next_estimate"}]}, an unknown estimate None; None
// when the step has none (a user's action, the random and ghost-ball agents).
py::object reasoning_object(const cueball::Reasoning& r) {
  if (r.summary.empty() && r.considered.empty()) return py::none();
  const auto probability = [](double p) -> py::object { return p >= 0.0 ? py::object(py::float_(p)) : py::none(); };
  py::list considered;
  for (const cueball::ConsideredOption& c : r.considered)
    considered.append(py::dict("what"_a = c.what, "estimate"_a = probability(c.estimate),
                               "next_estimate"_a = probability(c.next_estimate)));
  return py::dict("summary"_a = r.summary, "considered"_a = considered);
}

py::dict recorded_step(const cueball::RecordedStep& s) {
  return py::dict("action"_a = s.action, "seed"_a = s.seed, "ruling"_a = loads(cueball::ruling_to_json(s.ruling)),
                  "state"_a = s.state, "reasoning"_a = reasoning_object(s.reasoning));
}

}  // namespace

void bind_games(py::module_& parent) {
  py::module_ m = parent.def_submodule(
      "games",
      "Games by their rules: 9-ball, 8-ball, 10-ball, snooker and three-cushion (those whose rules have\n"
      "landed; the others raise InvalidArgument 'not available yet').\n\n"
      "    s = games.new_game('nine_ball', seed=1)\n"
      "    while not s.over:\n"
      "        a = games.choose_action(s, agent='random', seed=s.shots)\n"
      "        s = games.play(s, a, seed=s.shots).next\n\n"
      "States, actions and records read and write the JSON of `cueball game` (to_json/from_json);\n"
      "rulings and facts are dicts of the same JSON. Players are 0 and 1; ball ids as the racks'.");

  // ---------------------------------------------------------------- GameConfig
  py::class_<GameConfig> config_class(m, "GameConfig",
                                "How a game is played: the discipline, the table and the variants (default_config()).");
  config_class.def_property_readonly("kind", [](const GameConfig& c) { return std::string(cueball::to_string(c.kind)); })
      .def_readwrite("table", &GameConfig::table, "The table preset's name")
      .def_readwrite("max_shots", &GameConfig::max_shots, "Shots (and decisions) after which the game is truncated")
      .def_readwrite("fouls_to_lose", &GameConfig::fouls_to_lose, "Consecutive fouls that lose (0: off)")
      .def_readwrite("nine_on_break_wins", &GameConfig::nine_on_break_wins, "9-ball: the 9 on a legal break wins")
      .def_readwrite("push_out", &GameConfig::push_out, "9-ball, 10-ball: the push-out after the break")
      .def_readwrite("reds", &GameConfig::reds, "Snooker: 6, 10 or 15 reds")
      .def_readwrite("miss_rule", &GameConfig::miss_rule, "Snooker: the miss rule")
      .def_readwrite("race_to", &GameConfig::race_to, "Three-cushion: points to win")
      .def_property(
          "noise",
          [](const GameConfig& c) {
            const py::object d = loads(cueball::game_config_to_json(c));
            return py::object(d["noise"]);
          },
          [](GameConfig& c, const py::object& noise) {
            if (const auto n = noise_argument(noise, radius_of(c))) c.noise = *n;
          },
          "Execution noise of every shot: a dict of sigmas in the scenario's units; set it to 'none',\n"
          "'tournament' or such a dict")
      .def("to_dict", [](const GameConfig& c) { return loads(cueball::game_config_to_json(c)); },
           "The config as the state file's \"config\" object, with \"kind\"")
      .def_static(
          "from_dict", [](const py::dict& d) { return cueball::game_config_from_json(json_text(d, "config")); }, "d"_a,
          "A config from its dict (every key but 'kind' optional); validated")
      .def("__eq__",
           [](const GameConfig& a, const py::object& b) -> py::object {
             if (!py::isinstance<GameConfig>(b)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
             return py::bool_(cueball::game_config_to_json(a) == cueball::game_config_to_json(b.cast<GameConfig>()));
           })
      .def("__repr__", [](const GameConfig& c) { return "GameConfig(" + cueball::game_config_to_json(c) + ")"; })
      .def(py::pickle([](const GameConfig& c) { return cueball::game_config_to_json(c); },
                      [](const std::string& text) { return cueball::game_config_from_json(text); }));
  config_class.attr("__hash__") = py::none();

  m.def(
      "default_config", [](const std::string& kind) { return cueball::default_config(game_kind(kind)); }, "kind"_a,
      "The config a game is played with unless changed: its table and the variants' defaults.\n"
      "kind: 'nine_ball', 'eight_ball', 'ten_ball', 'snooker' or 'three_cushion'.");

  // ---------------------------------------------------------------- GameState
  py::class_<GameState> state_class(m, "GameState",
                              "The whole state of a game, a value: copy() is a snapshot, == compares, to_json() writes\n"
                              "the state file of `cueball game` (a scenario plus its \"game\" object) bit for bit.");
  state_class.def_property_readonly("kind", [](const GameState& s) { return std::string(cueball::to_string(s.config.kind)); })
      .def_property_readonly("config", [](const GameState& s) { return s.config; })
      .def_property_readonly("table", [](const GameState& s) { return std::make_shared<cueball::Scenario>(s.table); },
                             "The table and the balls at rest, as a Scenario (no cue)")
      .def_property_readonly(
          "balls",
          [](const GameState& s) {
            py::dict d;
            for (const cueball::SimulationBall& b : s.table.balls) d[py::int_(b.id)] = to_tuple(b.state.position);
            return d;
          },
          "{id: (x, y)} of the balls on the table, m")
      .def_property_readonly("phase", [](const GameState& s) { return std::string(cueball::to_string(s.phase)); })
      .def_readonly("to_shoot", &GameState::to_shoot)
      .def_readonly("breaker", &GameState::breaker)
      .def_property_readonly("ball_in_hand", [](const GameState& s) { return region_object(s.ball_in_hand); },
                             "None, the region's name, or a rectangle's dict")
      .def_readonly("cue_must_leave_kitchen", &GameState::cue_must_leave_kitchen)
      .def_property_readonly("scores", [](const GameState& s) { return py::make_tuple(s.scores[0], s.scores[1]); })
      .def_property_readonly("fouls_in_a_row",
                             [](const GameState& s) { return py::make_tuple(s.fouls_in_a_row[0], s.fouls_in_a_row[1]); })
      .def_readonly("on", &GameState::on)
      .def_property_readonly("groups",
                             [](const GameState& s) {
                               return py::make_tuple(cueball::to_string(s.groups[0]), cueball::to_string(s.groups[1]));
                             })
      .def_property_readonly("decisions", [](const GameState& s) { return decision_list(s.decisions); })
      .def_readonly("push_out_available", &GameState::push_out_available)
      .def_readonly("free_ball", &GameState::free_ball)
      .def_readonly("shots", &GameState::shots)
      .def_readonly("over", &GameState::over)
      .def_readonly("winner", &GameState::winner)
      .def_readonly("truncated", &GameState::truncated)
      .def_readonly("end_reason", &GameState::end_reason)
      .def_property_readonly("cue_ball", &GameState::cue_ball, "The ball the player to act strikes")
      .def(
          "to_json", [](const GameState& s, int indent) { return cueball::game_state_to_json(s, indent); }, "indent"_a = 1,
          "The state file's JSON text (indent -1: one line)")
      .def("to_dict", [](const GameState& s) { return loads(cueball::game_state_to_json(s, -1)); })
      .def_static(
          "from_json", [](const std::string& text) { return cueball::game_state_from_json(text); }, "text"_a,
          "Reads and checks a state file's JSON text; InvalidArgument names the path ('state.game.to_shoot')")
      .def("copy", [](const GameState& s) { return s; })
      .def("__copy__", [](const GameState& s) { return s; })
      .def("__deepcopy__", [](const GameState& s, const py::object&) { return s; }, "memo"_a)
      .def("__eq__",
           [](const GameState& a, const py::object& b) -> py::object {
             if (!py::isinstance<GameState>(b)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
             return py::bool_(cueball::game_state_to_json(a, -1) == cueball::game_state_to_json(b.cast<GameState>(), -1));
           })
      .def("__repr__",
           [](const GameState& s) {
             return "GameState(kind='" + std::string(cueball::to_string(s.config.kind)) + "', phase='" +
                    cueball::to_string(s.phase) + "', to_shoot=" + std::to_string(s.to_shoot) + ", shots=" +
                    std::to_string(s.shots) + ", balls=" + std::to_string(s.table.balls.size()) + ")";
           })
      .def(py::pickle([](const GameState& s) { return cueball::game_state_to_json(s, -1); },
                      [](const std::string& text) { return cueball::game_state_from_json(text); }));
  state_class.attr("__hash__") = py::none();

  m.def(
      "new_game",
      [](const py::object& config, std::uint64_t seed) { return cueball::new_game(config_argument(config), seed); },
      "config"_a, "seed"_a = 0,
      "A game ready to break: config is a GameConfig or a game's name (its default_config()); seed\n"
      "seeds the rack's gaps when the config has them.");

  // ---------------------------------------------------------------- Action
  py::class_<Action> action_class(m, "Action",
                            "A shot (the scenario's cue units: speed m/s, aim_deg or target, elevation_deg, side and\n"
                            "height in ball radii; a placement, a call, a push-out, a nomination) or a decision.");
  action_class
      .def(py::init([](double speed, std::optional<double> aim_deg, std::optional<int> target, double elevation_deg,
                       double side, double height, std::optional<std::array<double, 2>> place,
                       std::optional<std::array<int, 2>> call, bool push_out, std::optional<int> nominate,
                       std::optional<std::string> decision) {
             py::dict d;
             if (decision) {
               d["decision"] = *decision;
             } else {
               d["speed"] = speed;
               if (aim_deg) d["aim_deg"] = *aim_deg;
               if (target) d["target"] = *target;
               d["elevation_deg"] = elevation_deg;
               d["side"] = side;
               d["height"] = height;
               if (place) d["place"] = py::make_tuple((*place)[0], (*place)[1]);
               if (call) d["call"] = py::dict("ball"_a = (*call)[0], "pocket"_a = (*call)[1]);
               if (push_out) d["push_out"] = true;
               if (nominate) d["nominate"] = *nominate;
             }
             return cueball::action_from_json(json_text(d, "action"), nullptr, "action");
           }),
           "speed"_a = 3.0, "aim_deg"_a = py::none(), "target"_a = py::none(), "elevation_deg"_a = 0.0, "side"_a = 0.0,
           "height"_a = 0.0, "place"_a = py::none(), "call"_a = py::none(), "push_out"_a = false, "nominate"_a = py::none(),
           "decision"_a = py::none())
      .def_property_readonly("decision",
                             [](const Action& a) -> py::object {
                               return a.decision ? py::object(py::str(cueball::to_string(*a.decision))) : py::none();
                             })
      .def_property_readonly("speed", [](const Action& a) { return a.strike.speed; })
      .def_property_readonly("aim_deg", [](const Action& a) { return a.strike.aim_deg; })
      .def_readonly("target", &Action::aim_at)
      .def_property_readonly("elevation_deg", [](const Action& a) { return a.strike.elevation_deg; })
      .def_property_readonly("side", [](const Action& a) { return a.strike.side; })
      .def_property_readonly("height", [](const Action& a) { return a.strike.height; })
      .def_property_readonly("place",
                             [](const Action& a) -> py::object { return a.place ? py::object(to_tuple(*a.place)) : py::none(); })
      .def_readonly("called_ball", &Action::called_ball)
      .def_readonly("called_pocket", &Action::called_pocket)
      .def_readonly("push_out", &Action::push_out)
      .def_readonly("nominate", &Action::nominate)
      .def(
          "to_json", [](const Action& a, int indent) { return cueball::action_to_json(a, indent); }, "indent"_a = -1,
          "The action as `cueball game shoot --cue` takes it")
      .def("to_dict", [](const Action& a) { return loads(cueball::action_to_json(a)); })
      .def_static(
          "from_json", [](const std::string& text) { return cueball::action_from_json(text); }, "text"_a,
          "An action from its JSON (the pocket of a call by index)")
      .def("__eq__",
           [](const Action& a, const py::object& b) -> py::object {
             if (!py::isinstance<Action>(b)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
             return py::bool_(cueball::action_to_json(a) == cueball::action_to_json(b.cast<Action>()));
           })
      .def("__repr__", [](const Action& a) { return "Action(" + cueball::action_to_json(a) + ")"; });
  action_class.attr("__hash__") = py::none();

  // ---------------------------------------------------------------- legal actions
  m.def(
      "legal_actions",
      [](const GameState& s) {
        const cueball::LegalActions l = cueball::legal_actions(s);
        return py::dict("player"_a = l.player, "cue_ball"_a = l.cue_ball, "shoot"_a = l.shoot, "on"_a = l.on,
                        "ball_in_hand"_a = region_object(l.ball_in_hand), "cue_must_leave_kitchen"_a = l.cue_must_leave_kitchen,
                        "call_required"_a = l.call_required, "callable"_a = l.callable, "push_out"_a = l.push_out,
                        "nominate_required"_a = l.nominate_required, "nominable"_a = l.nominable,
                        "free_ball"_a = l.free_ball, "decisions"_a = decision_list(l.decisions));
      },
      "state"_a,
      "What the player to act may do: a dict {player, cue_ball, shoot, on, ball_in_hand, cue_must_leave_kitchen,\n"
      "call_required, callable, push_out, nominate_required, nominable, free_ball, decisions}.");

  // ---------------------------------------------------------------- play
  py::class_<Step> step_class(m, "GameStep", "One play(): the action, the ruling, the shot's facts and result, the next state.");
  step_class.def_property_readonly("action", [](const Step& s) { return s.step.action; })
      .def_property_readonly("ruling", [](const Step& s) { return loads(cueball::ruling_to_json(s.step.ruling)); },
                             "The ruling as a dict: foul (None or its name), points, turn_over, game_over, winner,\n"
                             "respotted, pocketed, push_out, miss, truncated, reason")
      .def_property_readonly(
          "facts",
          [](Step& s) -> py::object {
            if (s.step.action.decision) return py::none();
            if (!s.facts) s.facts = loads(cueball::shot_facts_to_json(s.step.shot.table, s.step.facts, -1));
            return s.facts;
          },
          "What the shot did (Result.facts' dict), None for a decision")
      .def_property_readonly("next", [](const Step& s) { return s.step.next; }, "The state after it")
      .def_property_readonly(
          "shot",
          [](const Step& s) -> py::object {
            if (s.step.action.decision) return py::none();
            return py::cast(std::make_shared<cueball::Scenario>(s.step.shot));
          },
          "The scenario shot: the balls before it and the strike as played (after the noise); None for a decision")
      .def_property_readonly(
          "result",
          [](Step& s) -> py::object {
            if (s.step.action.decision) return py::none();
            if (!s.result)
              s.result = py::module_::import("cueball._cueball").attr("simulate")(std::make_shared<cueball::Scenario>(s.step.shot));
            return s.result;
          },
          "The shot's simulation Result (simulate(step.shot)); None for a decision")
      .def(
          "to_json", [](const Step& s, int indent) { return cueball::game_step_to_json(s.step, indent); }, "indent"_a = 1,
          "`cueball game shoot --json`'s object: action, ruling, facts, state")
      .def("__repr__", [](const Step& s) { return "GameStep(ruling=" + cueball::ruling_to_json(s.step.ruling) + ")"; });

  m.def(
      "play",
      [](const GameState& s, const Action& a, std::uint64_t seed) {
        Step out;
        {
          py::gil_scoped_release release;
          out.step = cueball::play(s, a, seed);
        }
        return out;
      },
      "state"_a, "action"_a, "seed"_a = 0,
      "Plays the action: places the cue ball, strikes it with the config's noise drawn from seed,\n"
      "simulates and judges. The state is not changed; step.next is the state after it. An illegal\n"
      "action raises InvalidArgument naming the field ('place', 'decision', ...).");

  // ---------------------------------------------------------------- agents
  m.def(
      "choose_action",
      [](const GameState& s, const std::string& agent, std::uint64_t seed, std::optional<int> simulations,
         const py::object& noise, std::optional<double> seconds) {
        cueball::AgentOptions o = agent_options(agent, "agent", simulations, seconds);
        o.noise = noise_argument(noise, s.table.table.ball.radius);
        if (!o.noise) o.noise = s.config.noise;
        py::gil_scoped_release release;
        return cueball::choose_action(o, s, seed);
      },
      "state"_a, "agent"_a = "random", "seed"_a = 0, "simulations"_a = py::none(), "noise"_a = py::none(),
      "seconds"_a = py::none(),
      "The agent's action for the player to act (always legal). agent: 'random', 'ghost_ball',\n"
      "'planner', 'carom_search', 'safety_planner' or 'strongest' (the safety planner with position play);\n"
      "simulations: engine runs a decision (default: the agent's own, 2000; strongest 4000); noise: what the\n"
      "agent plans under (default: the game's); seconds: a wall-clock budget a decision, [0, 3600], planned\n"
      "at doubling budgets from 500 runs up to simulations while the next round fits (not reproducible\n"
      "across machines; the same call with the runs it played at and no seconds is).");

  // ---------------------------------------------------------------- records
  py::class_<GameRecord> record_class(m, "GameRecord",
                                "A whole game: who played, the seed, the start and every step (action, seed, ruling,\n"
                                "state). records_to_json()/records_from_json() read and write `cueball game play --record`.");
  record_class.def_property_readonly("players", [](const GameRecord& r) { return py::make_tuple(r.players[0], r.players[1]); })
      .def_readonly("seed", &GameRecord::seed)
      .def_readonly("start", &GameRecord::start)
      .def_property_readonly(
          "steps",
          [](const GameRecord& r) {
            py::list out;
            for (const cueball::RecordedStep& s : r.steps) out.append(recorded_step(s));
            return out;
          },
          "[{action, seed, ruling, state, reasoning}, ...]: reasoning is the agent's ({summary, considered:\n"
          "[{what, estimate, next_estimate}]}, the chosen option first) or None")
      .def_property_readonly("end", [](const GameRecord& r) { return r.steps.empty() ? r.start : r.steps.back().state; },
                             "The state after the last step")
      .def(
          "tally",
          [](const GameRecord& r) {
            const cueball::GameTally t = cueball::tally(r);
            return py::dict("fouls"_a = py::make_tuple(t.fouls[0], t.fouls[1]), "pots"_a = py::make_tuple(t.pots[0], t.pots[1]),
                            "shots"_a = py::make_tuple(t.shots[0], t.shots[1]));
          },
          "Per player: fouls, object balls pocketed, shots and decisions")
      .def(
          "replay",
          [](const GameRecord& r) -> py::object {
            std::optional<cueball::ReplayDifference> d;
            {
              py::gil_scoped_release release;
              d = cueball::replay_difference(r, 0);
            }
            if (!d) return py::none();
            return py::dict("step"_a = d->step, "path"_a = d->path, "recorded"_a = d->recorded, "replayed"_a = d->replayed);
          },
          "Re-plays every step and compares each ruling and state bit for bit: None when identical,\n"
          "else the first difference {step, path, recorded, replayed}")
      .def("__repr__", [](const GameRecord& r) {
        return "GameRecord(players=('" + r.players[0] + "', '" + r.players[1] + "'), seed=" + std::to_string(r.seed) +
               ", steps=" + std::to_string(r.steps.size()) + ")";
      });

  m.def(
      "play_game",
      [](const py::object& config, const std::array<std::string, 2>& players, std::uint64_t seed,
         std::optional<int> simulations, const py::object& noise, std::optional<double> seconds) {
        GameConfig c = config_argument(config);
        if (const auto n = noise_argument(noise, radius_of(c))) c.noise = *n;
        std::array<cueball::AgentOptions, 2> agents;
        for (std::size_t p = 0; p < 2; ++p) {
          agents[p] = agent_options(players[p], "players[" + std::to_string(p) + "]", simulations, seconds);
          agents[p].noise = c.noise;
        }
        py::gil_scoped_release release;
        return cueball::play_game(c, agents, seed);
      },
      "config"_a, "players"_a = std::array<std::string, 2>{"random", "random"}, "seed"_a = 0, "simulations"_a = py::none(),
      "noise"_a = py::none(), "seconds"_a = py::none(),
      "Plays one game between two agents (players[0] breaks) and records it, as `cueball game play`\n"
      "does with --seed seed: the same seeds, the same game. noise: the game's execution noise\n"
      "(default: the config's), also what the agents plan under; seconds: each decision's wall-clock\n"
      "budget (choose_action).");

  m.def(
      "records_to_json",
      [](const std::vector<GameRecord>& records, int indent) { return cueball::game_records_to_json(records, indent); },
      "records"_a, "indent"_a = -1, "The record file's JSON text (`cueball game replay` checks it)");
  m.def(
      "records_from_json", [](const std::string& text) { return cueball::game_records_from_json(text); }, "text"_a,
      "The games of a record file's JSON text (`cueball game play --record`); checked as state files are");
}

}  // namespace cueball_python
