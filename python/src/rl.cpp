// cueball.rl's native part: the learning environment of rl/environment.hpp
// as the private submodule _cueball._rl (classes Table and VectorTables),
// which python/cueball/rl.py wraps in the Gymnasium and PettingZoo APIs.
// Options arrive as plain values that rl.py has already parsed; the library
// validates them (InvalidArgument naming the field).
#include <pybind11/numpy.h>

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/io/game_json.hpp"
#include "cueball/io/game_viewer_json.hpp"
#include "cueball/io/scenario_json.hpp"
#include "cueball/planning/shot_planner.hpp"
#include "cueball/rl/environment.hpp"

namespace cueball_python {

namespace {

using cueball::EnvAction;
using cueball::EnvOptions;
using cueball::EnvStepResult;
using cueball::EnvTable;

template <class E>
E named(std::optional<E> value, const std::string& field, const std::string& name, const std::string& allowed) {
  if (!value)
    throw cueball::InvalidArgument(field, field + " = " + cueball::quote_input(name) + " is not known; allowed: " + allowed);
  return *value;
}

// The options rl.py parsed (python/cueball/rl.py, _native_options()).
EnvOptions make_options(const std::string& game, const std::optional<std::string>& opponent,
                        std::optional<int> simulations, std::optional<double> seconds,
                        const py::object& noise, std::array<double, 2> noise_scale, const py::dict& reward,
                        const std::string& form, const std::string& break_policy, int seat, int max_shots,
                        double max_speed) {
  EnvOptions o;
  o.game = named(cueball::game_kind_from_string(game), "game", game, cueball::game_kind_names());
  // An agent by name (agent_named(): a kind, at the environment's quick
  // budget unless `simulations` is given, or "strongest" at its own).
  if (opponent && *opponent == "strongest") {
    o.opponent.agent = named(cueball::agent_named(*opponent), "opponent", *opponent, cueball::agent_names());
    if (simulations) o.opponent.agent->simulations = *simulations;
  } else if (opponent) {
    o.opponent.kind = named(cueball::agent_kind_from_string(*opponent), "opponent", *opponent, cueball::agent_names());
  } else {
    o.opponent.kind.reset();
  }
  if (simulations) o.opponent.simulations = *simulations;
  // A wall-clock budget a decision (AgentOptions::seconds; rl.py checked
  // that an opponent is named and the range): the opponent's options in full.
  if (seconds && o.opponent.kind && !o.opponent.agent) o.opponent.agent = cueball::opponent_agent(o.opponent);
  if (seconds && o.opponent.agent) o.opponent.agent->seconds = *seconds;
  const cueball::GameState probe = cueball::new_game(cueball::default_config(o.game), 0);
  if (const auto n = noise_argument(noise, probe.table.table.ball.radius)) o.noise.base = *n;
  o.noise.scale_min = noise_scale[0];
  o.noise.scale_max = noise_scale[1];
  o.reward = cueball::RewardTerms{};
  for (const auto& [key, value] : reward) {
    const std::string k = key.cast<std::string>();
    const double w = cast_argument<double>(value, "reward." + k, "a number");
    if (k == "win") o.reward.win = w;
    else if (k == "points") o.reward.points = w;
    else if (k == "pots") o.reward.pots = w;
    else if (k == "fouls") o.reward.fouls = w;
    else if (k == "illegal") o.reward.illegal = w;
    else
      throw cueball::InvalidArgument("reward", "reward term " + cueball::quote_input(k) +
                                                   " is not known; allowed: win, points, pots, fouls, illegal");
  }
  o.form = named(cueball::action_form_from_string(form), "action", form, "raw, target");
  o.break_policy = named(cueball::break_policy_from_string(break_policy), "break", break_policy, "recommended, agent");
  o.seat = seat;
  o.max_shots = max_shots;
  o.max_speed = max_speed;
  cueball::validate(o);
  return o;
}

py::array_t<float> observation_array(const std::vector<float>& v) {
  py::array_t<float> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

py::dict ruling_dict(const cueball::Ruling& r) { return json_loads(cueball::ruling_to_json(r, -1)).cast<py::dict>(); }

py::dict masks_dict(const cueball::ActionMasks& m) {
  auto bytes = [](const auto& v) {
    py::array_t<bool> a(static_cast<py::ssize_t>(v.size()));
    for (std::size_t i = 0; i < v.size(); ++i) a.mutable_data()[i] = v[i] != 0;
    return a;
  };
  py::dict d;
  d["ball"] = bytes(m.ball);
  d["pocket"] = bytes(m.pocket);
  d["decision"] = bytes(m.decision);
  d["push_out"] = bytes(m.push_out);
  return d;
}

py::dict terms_dict(const cueball::RewardTerms& t) {
  return py::dict("win"_a = t.win, "points"_a = t.points, "pots"_a = t.pots, "fouls"_a = t.fouls,
                  "illegal"_a = t.illegal);
}

EnvAction env_action(const std::array<double, 5>& strike, const std::array<double, 2>& place, int ball, int pocket,
                     int decision, int push_out) {
  EnvAction a;
  a.strike = strike;
  a.place = place;
  a.ball = ball;
  a.pocket = pocket;
  a.decision = decision;
  a.push_out = push_out;
  return a;
}

// One table, as rl.CueballEnv and rl.TwoPlayerEnv drive it.
struct NativeTable {
  EnvOptions options;
  EnvTable table;
};

py::tuple step_table(NativeTable& t, const EnvAction& a) {
  EnvStepResult r;
  {
    py::gil_scoped_release release;
    r = cueball::env_step(t.options, t.table, a);
  }
  py::list rulings;
  for (const cueball::Ruling& ruling : r.rulings) rulings.append(ruling_dict(ruling));
  py::dict info("player"_a = r.player, "rewards"_a = py::make_tuple(r.rewards[0], r.rewards[1]),
                "terms"_a = py::make_tuple(terms_dict(r.terms[0]), terms_dict(r.terms[1])),
                "illegal"_a = r.illegal.empty() ? py::object(py::none()) : py::object(py::str(r.illegal)),
                "rulings"_a = rulings, "players"_a = r.players);
  return py::make_tuple(observation_array(t.table.observation), r.reward, r.terminated, r.truncated, info);
}

// Many tables (rl.VectorEnv).
struct NativeVector {
  cueball::VectorEnvironment env;
};

template <class T>
py::array_t<T> column(std::size_t n) {
  return py::array_t<T>(static_cast<py::ssize_t>(n));
}

py::array_t<float> matrix(const std::vector<float>& v, std::size_t rows) {
  const std::size_t cols = rows ? v.size() / rows : 0;
  py::array_t<float> a({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(cols)});
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

py::dict vector_masks(const cueball::VectorEnvironment& env) {
  const std::size_t n = env.tables.size();
  const std::size_t balls = static_cast<std::size_t>(cueball::env_ball_count(env.options.game));
  const std::size_t pockets = env.tables.empty() ? 1 : std::max<std::size_t>(1, env.tables[0].state.table.table.pockets.size());
  py::array_t<bool> ball({n, balls}), pocket({n, pockets}), decision({n, std::size_t{cueball::kEnvDecisionChoices}}),
      push_out({n, std::size_t{2}});
  bool* b = ball.mutable_data();
  bool* p = pocket.mutable_data();
  bool* d = decision.mutable_data();
  bool* u = push_out.mutable_data();
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < n; ++i) {
      const cueball::ActionMasks m = cueball::action_masks(env.tables[i].state);
      for (std::size_t k = 0; k < balls; ++k) b[i * balls + k] = m.ball[k] != 0;
      for (std::size_t k = 0; k < pockets && k < m.pocket.size(); ++k) p[i * pockets + k] = m.pocket[k] != 0;
      for (std::size_t k = 0; k < m.decision.size(); ++k) d[i * m.decision.size() + k] = m.decision[k] != 0;
      for (std::size_t k = 0; k < 2; ++k) u[i * 2 + k] = m.push_out[k] != 0;
    }
  }
  return py::dict("ball"_a = ball, "pocket"_a = pocket, "decision"_a = decision, "push_out"_a = push_out);
}

py::tuple step_vector(NativeVector& v, const py::array_t<double, py::array::c_style | py::array::forcecast>& strike,
                      const py::array_t<double, py::array::c_style | py::array::forcecast>& place,
                      const py::array_t<long long, py::array::c_style | py::array::forcecast>& ball,
                      const py::array_t<long long, py::array::c_style | py::array::forcecast>& pocket,
                      const py::array_t<long long, py::array::c_style | py::array::forcecast>& decision,
                      const py::array_t<long long, py::array::c_style | py::array::forcecast>& push_out) {
  const std::size_t n = v.env.tables.size();
  auto check = [n](const py::array& a, const char* field, py::ssize_t width) {
    const bool ok = width == 0 ? (a.ndim() == 1 && static_cast<std::size_t>(a.shape(0)) == n)
                               : (a.ndim() == 2 && static_cast<std::size_t>(a.shape(0)) == n && a.shape(1) == width);
    if (!ok)
      throw cueball::InvalidArgument(field, std::string(field) + " must have shape (" + std::to_string(n) +
                                                (width ? ", " + std::to_string(width) : std::string(",")) + ")");
  };
  check(strike, "action['strike']", 5);
  check(place, "action['place']", 2);
  check(ball, "action['ball']", 0);
  check(pocket, "action['pocket']", 0);
  check(decision, "action['decision']", 0);
  check(push_out, "action['push_out']", 0);
  std::vector<EnvAction> actions(n);
  const double* s = strike.data();
  const double* p = place.data();
  for (std::size_t i = 0; i < n; ++i) {
    std::array<double, 5> st{s[5 * i], s[5 * i + 1], s[5 * i + 2], s[5 * i + 3], s[5 * i + 4]};
    actions[i] = env_action(st, {p[2 * i], p[2 * i + 1]}, static_cast<int>(ball.data()[i]),
                            static_cast<int>(pocket.data()[i]), static_cast<int>(decision.data()[i]),
                            static_cast<int>(push_out.data()[i]));
  }
  {
    py::gil_scoped_release release;
    cueball::vector_step(v.env, actions);
  }
  auto reward = column<double>(n);
  auto terminated = column<bool>(n);
  auto truncated = column<bool>(n);
  auto illegal = column<bool>(n);
  auto player = column<long long>(n);
  for (std::size_t i = 0; i < n; ++i) {
    const EnvStepResult& r = v.env.results[i];
    reward.mutable_data()[i] = r.reward;
    terminated.mutable_data()[i] = r.terminated;
    truncated.mutable_data()[i] = r.truncated;
    illegal.mutable_data()[i] = !r.illegal.empty();
    player.mutable_data()[i] = r.player;
  }
  return py::make_tuple(matrix(v.env.observations, n), reward, terminated, truncated, illegal, player,
                        matrix(v.env.final_observations, n));
}

}  // namespace

void bind_rl(py::module_& m) {
  py::module_ rl = m.def_submodule("_rl", "cueball.rl's native part (rl/environment.hpp); use cueball.rl");
  rl.def("observation_names", [](const std::string& game) {
    return cueball::env_observation_names(named(cueball::game_kind_from_string(game), "game", game, cueball::game_kind_names()));
  });
  rl.def("ball_count", [](const std::string& game) {
    return cueball::env_ball_count(named(cueball::game_kind_from_string(game), "game", game, cueball::game_kind_names()));
  });
  rl.attr("min_speed") = cueball::kEnvMinSpeed;
  rl.attr("max_cut_offset_deg") = cueball::kEnvMaxCutOffsetDeg;
  rl.attr("max_elevation_deg") = cueball::kEnvMaxElevationDeg;
  rl.attr("decision_choices") = cueball::kEnvDecisionChoices;

  py::class_<NativeTable>(rl, "Table")
      .def(py::init([](const std::string& game, const std::optional<std::string>& opponent, std::optional<int> simulations,
                       std::optional<double> seconds, const py::object& noise, std::array<double, 2> noise_scale,
                       const py::dict& reward, const std::string& form, const std::string& break_policy, int seat,
                       int max_shots, double max_speed, bool record) {
        NativeTable t;
        t.options = make_options(game, opponent, simulations, seconds, noise, noise_scale, reward, form, break_policy, seat,
                                 max_shots, max_speed);
        t.table.record_steps = record;
        return t;
      }))
      .def("reset",
           [](NativeTable& t, std::optional<std::uint64_t> seed) {
             {
               py::gil_scoped_release release;
               cueball::env_reset(t.options, t.table, seed);
             }
             return observation_array(t.table.observation);
           })
      .def("reset_from",
           [](NativeTable& t, const cueball::GameState& start) {
             {
               py::gil_scoped_release release;
               cueball::env_reset_from(t.options, t.table, start);
             }
             return observation_array(t.table.observation);
           })
      .def("step",
           [](NativeTable& t, std::array<double, 5> strike, std::array<double, 2> place, int ball, int pocket,
              int decision, int push_out) {
             return step_table(t, env_action(strike, place, ball, pocket, decision, push_out));
           })
      .def("observe",
           [](const NativeTable& t, int player) {
             std::vector<float> v(static_cast<std::size_t>(cueball::env_observation_size(t.options.game)));
             cueball::write_observation(t.table.state, player, t.table.noise, v.data());
             return observation_array(v);
           })
      .def("masks", [](const NativeTable& t) { return masks_dict(cueball::action_masks(t.table.state)); })
      .def_property_readonly("state", [](const NativeTable& t) { return t.table.state; })
      .def_property_readonly("status",
                             [](const NativeTable& t) {  // (over, truncated, to_shoot, viewer): no state copy
                               const cueball::GameState& s = t.table.state;
                               return py::make_tuple(s.over, s.truncated, s.to_shoot, t.table.viewer());
                             })
      .def_property_readonly("learner", [](const NativeTable& t) { return t.table.learner; })
      .def_property_readonly("episode", [](const NativeTable& t) { return t.table.episode; })
      .def_property_readonly("game_seed", [](const NativeTable& t) { return t.table.game_seed; })
      .def_property_readonly("pockets",
                             [](const NativeTable& t) { return t.table.state.table.table.pockets.size(); })
      .def_property_readonly("noise",
                             [](const NativeTable& t) {
                               const cueball::CueStrikeNoise& n = t.table.noise;
                               const double r = t.table.state.table.table.ball.radius;
                               return py::dict("speed"_a = n.speed, "aim_deg"_a = n.aim * 180.0 / 3.14159265358979323846,
                                               "elevation_deg"_a = n.elevation * 180.0 / 3.14159265358979323846,
                                               "side"_a = n.side_offset / r, "height"_a = n.height_offset / r);
                             })
      .def("shots",
           [](const NativeTable& t) {
             std::vector<std::string> out;
             for (const cueball::GameStep& g : t.table.history)
               if (g.shot.cue) out.push_back(cueball::scenario_to_json(g.shot, -1));
             return out;
           })
      .def("viewer_json", [](const NativeTable& t, const std::array<std::string, 2>& players) {
        return cueball::game_viewer_json(t.table.start, t.table.history, players, -1);
      })
      .def("mirror_action",
           [](const NativeTable& t, std::array<double, 5> strike, std::array<double, 2> place, int ball, int pocket,
              int decision, int push_out) {
             const EnvAction a =
                 cueball::mirror_action(t.table.state.table.table, env_action(strike, place, ball, pocket, decision, push_out));
             return py::make_tuple(a.strike, a.place, a.ball, a.pocket, a.decision, a.push_out);
           })
      .def("mirror_observation", [](const NativeTable& t, const py::array_t<float, py::array::c_style | py::array::forcecast>& obs) {
        const auto size = static_cast<py::ssize_t>(cueball::env_observation_size(t.options.game));
        if (obs.ndim() != 1 || obs.shape(0) != size)
          throw cueball::InvalidArgument("observation", "observation must have shape (" + std::to_string(size) + ",)");
        py::array_t<float> out(size);
        std::copy(obs.data(), obs.data() + size, out.mutable_data());
        cueball::mirror_observation(t.options.game, out.mutable_data());
        return out;
      });

  py::class_<NativeVector>(rl, "VectorTables")
      .def(py::init([](const std::string& game, const std::optional<std::string>& opponent, std::optional<int> simulations,
                       std::optional<double> seconds, const py::object& noise, std::array<double, 2> noise_scale,
                       const py::dict& reward, const std::string& form, const std::string& break_policy, int seat,
                       int max_shots, double max_speed, int n, int threads, std::uint64_t seed) {
        const EnvOptions o = make_options(game, opponent, simulations, seconds, noise, noise_scale, reward, form, break_policy,
                                          seat, max_shots, max_speed);
        NativeVector v;
        py::gil_scoped_release release;
        v.env = cueball::make_vector_environment(o, n, threads, seed);
        return v;
      }))
      .def("reset",
           [](NativeVector& v, std::optional<std::uint64_t> seed) {
             {
               py::gil_scoped_release release;
               cueball::vector_reset(v.env, seed);
             }
             return matrix(v.env.observations, v.env.tables.size());
           })
      .def("step", &step_vector)
      .def("masks", [](const NativeVector& v) { return vector_masks(v.env); })
      .def_property_readonly("size", [](const NativeVector& v) { return v.env.tables.size(); })
      .def_property_readonly("pockets", [](const NativeVector& v) {
        return v.env.tables.empty() ? std::size_t{1} : std::max<std::size_t>(1, v.env.tables[0].state.table.table.pockets.size());
      });
}

}  // namespace cueball_python
