// include/cueball/simulation/simulator.hpp: whole shots. simulate() returns a Result
// that holds the library's SimulationResult (and the scenario it ran) and
// builds NumPy arrays from it on demand; no JSON on the way unless asked for
// (to_dict(), to_json(): the library's result_to_json, the CLI's bytes).
#include "bindings.hpp"
#include "cueball/io/viewer_page.hpp"

#include <pybind11/numpy.h>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cueball/io/result_json.hpp"
#include "cueball/physics/cloth_motion.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/simulation/scenario.hpp"
#include "cueball/simulation/shot_facts.hpp"
#include "cueball/simulation/simulator.hpp"
#include "cueball/io/shot_facts_json.hpp"

namespace cueball_python {

namespace {

constexpr cueball::EventType kEventTypes[] = {
    cueball::EventType::cue_strike,   cueball::EventType::slide_to_roll, cueball::EventType::roll_to_spin,
    cueball::EventType::roll_to_rest, cueball::EventType::spin_stop,     cueball::EventType::ball_ball,
    cueball::EventType::ball_cushion, cueball::EventType::ball_jaw,      cueball::EventType::ball_pocket};
constexpr cueball::MotionPhase kPhases[] = {cueball::MotionPhase::sliding, cueball::MotionPhase::rolling,
                                            cueball::MotionPhase::spinning, cueball::MotionPhase::stationary};

// A shot's result: the scenario run and the library's result; the arrays of
// events, balls and segments are built on first access and kept.
struct Result {
  std::shared_ptr<const cueball::Scenario> scenario;
  cueball::SimulationResult result;
  double sample_rate = 0.0;  // to_dict()'s and to_json()'s default
  py::object events, balls, segments, facts;
};

using Index = py::ssize_t;

Index ssize(std::size_t n) { return static_cast<Index>(n); }

// A C-contiguous array of shape `shape`, and a pointer to its first element.
template <class T>
std::pair<py::array_t<T>, T*> new_array(std::vector<Index> shape) {
  py::array_t<T> a(shape);
  T* data = a.mutable_data();
  return {std::move(a), data};
}

void put(double* at, cueball::Vec2 v) {
  at[0] = v.x;
  at[1] = v.y;
}
void put(double* at, cueball::Vec3 v) {
  at[0] = v.x;
  at[1] = v.y;
  at[2] = v.z;
}

py::dict events_dict(const Result& r) {
  const std::vector<cueball::Event>& events = r.result.events;
  const Index n = ssize(events.size());
  auto [time, t] = new_array<double>({n});
  auto [type, ty] = new_array<std::int8_t>({n});
  auto [ball, b] = new_array<std::int32_t>({n});
  auto [other, o] = new_array<std::int32_t>({n});
  auto [cushion, c] = new_array<std::int32_t>({n});
  auto [jaw, j] = new_array<std::int32_t>({n});
  auto [pocket, q] = new_array<std::int32_t>({n});
  for (std::size_t i = 0; i < events.size(); ++i) {
    const cueball::Event& e = events[i];
    t[i] = e.time;
    ty[i] = static_cast<std::int8_t>(e.type);
    b[i] = e.ball;
    o[i] = e.type == cueball::EventType::ball_ball ? e.other : -1;
    c[i] = e.type == cueball::EventType::ball_cushion ? e.other : -1;
    j[i] = e.type == cueball::EventType::ball_jaw ? e.other : -1;
    q[i] = e.type == cueball::EventType::ball_pocket ? e.other : -1;
  }
  return py::dict("time"_a = time, "type"_a = type, "ball"_a = ball, "other"_a = other, "cushion"_a = cushion,
                  "jaw"_a = jaw, "pocket"_a = pocket);
}

py::dict balls_dict(const Result& r) {
  const std::vector<cueball::BallTrajectory>& balls = r.result.balls;
  const Index n = ssize(balls.size());
  auto [id, ids] = new_array<std::int32_t>({n});
  auto [pocketed, pd] = new_array<bool>({n});
  auto [pocket, pk] = new_array<std::int32_t>({n});
  auto [pocket_time, pt] = new_array<double>({n});
  auto [position, x] = new_array<double>({n, 2});
  auto [velocity, v] = new_array<double>({n, 2});
  auto [spin, w] = new_array<double>({n, 3});
  py::list names;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const cueball::BallTrajectory& ball = balls[i];
    ids[i] = ball.id;
    names.append(ball.name);
    pd[i] = ball.pocketed;
    pk[i] = ball.pocketed ? ball.pocket : -1;
    pt[i] = ball.pocketed ? ball.pocket_time : std::nan("");
    put(x + 2 * i, ball.final_state.position);
    put(v + 2 * i, ball.final_state.velocity);
    put(w + 3 * i, ball.final_state.angular_velocity);
  }
  return py::dict("id"_a = id, "name"_a = names, "pocketed"_a = pocketed, "pocket"_a = pocket,
                  "pocket_time"_a = pocket_time, "position"_a = position, "velocity"_a = velocity,
                  "angular_velocity"_a = spin);
}

py::list segments_list(const Result& r) {
  const cueball::Parameters& p = r.scenario->settings.parameters;
  py::list out;
  for (const cueball::BallTrajectory& ball : r.result.balls) {
    const Index k = ssize(ball.segments.size());
    auto [time, t] = new_array<double>({k});
    auto [position, x] = new_array<double>({k, 2});
    auto [velocity, v] = new_array<double>({k, 2});
    auto [spin, w] = new_array<double>({k, 3});
    auto [phase, ph] = new_array<std::int8_t>({k});
    for (std::size_t i = 0; i < ball.segments.size(); ++i) {
      const cueball::TrajectorySegment& s = ball.segments[i];
      t[i] = s.start_time;
      put(x + 2 * i, s.state.position);
      put(v + 2 * i, s.state.velocity);
      put(w + 3 * i, s.state.angular_velocity);
      ph[i] = static_cast<std::int8_t>(cueball::motion_phase(s.state, p));
    }
    out.append(py::dict("time"_a = time, "position"_a = position, "velocity"_a = velocity,
                        "angular_velocity"_a = spin, "phase"_a = phase));
  }
  return out;
}

// Every ball's state at each of `times` (seconds, finite, >= 0), evaluated
// without the GIL: arrays (n_balls, n_times, ...).
py::dict states_dict(const Result& r, py::array_t<double> times) {
  const Index n_times = times.size();
  const Index n_balls = ssize(r.result.balls.size());
  auto [position, x] = new_array<double>({n_balls, n_times, 2});
  auto [velocity, v] = new_array<double>({n_balls, n_times, 2});
  auto [spin, w] = new_array<double>({n_balls, n_times, 3});
  auto [phase, ph] = new_array<std::int8_t>({n_balls, n_times});
  const double* t = times.data();
  const cueball::Parameters& p = r.scenario->settings.parameters;
  {
    py::gil_scoped_release release;
    std::size_t at = 0;
    for (std::size_t i = 0; i < r.result.balls.size(); ++i) {
      for (Index k = 0; k < n_times; ++k, ++at) {
        const cueball::BallState s = r.result.state_at(i, t[k], p);
        put(x + 2 * at, s.position);
        put(v + 2 * at, s.velocity);
        put(w + 3 * at, s.angular_velocity);
        ph[at] = static_cast<std::int8_t>(cueball::motion_phase(s, p));
      }
    }
  }
  return py::dict("time"_a = times, "position"_a = position, "velocity"_a = velocity, "angular_velocity"_a = spin,
                  "phase"_a = phase);
}

// A 1-D float64 copy of `times` (a number, a sequence or an array of any real
// dtype), every value finite and >= 0.
py::array_t<double> checked_times(const py::object& times) {
  if (py::isinstance<py::str>(times) || py::isinstance<py::bytes>(times))
    throw ArgumentTypeError("times", wrong_type_message(times, "times", "a number or a 1-D array of numbers (seconds)"));
  py::array_t<double> a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(times);
  if (!a) {
    PyErr_Clear();
    throw ArgumentTypeError("times", wrong_type_message(times, "times", "a number or a 1-D array of numbers (seconds)"));
  }
  if (a.ndim() > 1)
    throw cueball::InvalidArgument("times", "times has " + std::to_string(a.ndim()) +
                                                " dimensions; allowed: a number or a 1-D array of times, s");
  py::array_t<double> out(std::vector<Index>{a.size()});
  double* o = out.mutable_data();
  const double* in = a.data();
  for (Index k = 0; k < a.size(); ++k) {
    if (!(std::isfinite(in[k]) && in[k] >= 0.0))
      throw cueball::InvalidArgument("times[" + std::to_string(k) + "]", in[k], "[0, infinity)", "time, s");
    o[k] = in[k];
  }
  return out;
}

// The sampling rate's range, and at most kMaxSamples states (the limit of the
// result's JSON samples), checked before anything is allocated.
void check_sample_rate(const Result& r, double rate, bool zero_allowed) {
  cueball::require_in_range("sample_rate", rate, zero_allowed ? 0.0 : 1e-9, 1e4,
                            zero_allowed ? "sampling rate, Hz (0: none)" : "sampling rate, Hz");
  if (rate == 0.0) return;
  const double states = (std::floor(r.result.end_time * rate) + 1.0) * static_cast<double>(r.result.balls.size());
  if (!(states <= cueball::kMaxSamples))
    throw cueball::InvalidArgument("sample_rate", "sample_rate = " + cueball::format_number(rate) +
                                                      " Hz over the shot's " + cueball::format_number(r.result.end_time) +
                                                      " s and " + std::to_string(r.result.balls.size()) + " balls gives " +
                                                      cueball::format_number(states) +
                                                      " sampled states; allowed: at most " +
                                                      cueball::format_number(cueball::kMaxSamples));
}

std::string result_json(const Result& r, std::optional<double> sample_rate, int indent) {
  const double rate = sample_rate ? *sample_rate : r.sample_rate;
  check_sample_rate(r, rate, true);
  py::gil_scoped_release release;
  return cueball::result_to_json(*r.scenario, r.result, rate, indent);
}

py::tuple names_tuple(bool events) {
  py::list names;
  if (events) {
    for (cueball::EventType t : kEventTypes) names.append(cueball::to_string(t));
  } else {
    for (cueball::MotionPhase ph : kPhases) names.append(cueball::to_string(ph));
  }
  return py::tuple(names);
}

}  // namespace

void bind_simulation(py::module_& m) {
  // The codes of events["type"] and of the phase arrays are the library's
  // enum values: check that they are the positions in these tuples.
  for (std::size_t i = 0; i < std::size(kEventTypes); ++i)
    if (static_cast<std::size_t>(kEventTypes[i]) != i) throw std::logic_error("EventType codes out of order");
  for (std::size_t i = 0; i < std::size(kPhases); ++i)
    if (static_cast<std::size_t>(kPhases[i]) != i) throw std::logic_error("MotionPhase codes out of order");
  m.attr("EVENT_TYPES") = names_tuple(true);
  m.attr("PHASES") = names_tuple(false);

  py::class_<Result> result(
      m, "Result",
      "A simulated shot (simulate()): NumPy arrays built from the library's result on first access.\n"
      "Units SI (m, s, rad). Ball arrays are in the scenario's ball order (the order of to_dict()'s\n"
      "'balls'); events in the order resolved. to_dict() / to_json() give the documented JSON form,\n"
      "the bytes `cueball simulate --json` prints.");
  result
      .def_property_readonly(
          "end_time", [](const Result& r) { return r.result.end_time; },
          "s: every ball is at rest or pocketed from then on")
      .def_property_readonly(
          "events",
          [](Result& r) {
            if (!r.events) r.events = events_dict(r);
            return r.events;
          },
          "dict of 1-D arrays, one entry per event: time (float64, s), type (int8, an index into\n"
          "EVENT_TYPES), ball (int32, the ball's id), other (int32, the other ball's id in a ball_ball\n"
          "event, else -1), cushion, jaw, pocket (int32, the index into the table's cushions, jaws or\n"
          "pockets (pocket_names) in a ball_cushion, ball_jaw or ball_pocket event, else -1)")
      .def_property_readonly(
          "balls",
          [](Result& r) {
            if (!r.balls) r.balls = balls_dict(r);
            return r.balls;
          },
          "dict of arrays, one row per ball: id (int32), name (list of str), pocketed (bool),\n"
          "pocket (int32, index into pocket_names, -1 if not pocketed), pocket_time (float64, s, NaN\n"
          "if not pocketed), and the final state: position (n, 2) m, velocity (n, 2) m/s,\n"
          "angular_velocity (n, 3) rad/s")
      .def_property_readonly(
          "segments",
          [](Result& r) {
            if (!r.segments) r.segments = segments_list(r);
            return r.segments;
          },
          "per ball (list, ball order), its closed-form trajectory: a dict of arrays, one row per\n"
          "segment: time (start, s), position (k, 2), velocity (k, 2), angular_velocity (k, 3) at the\n"
          "start, phase (int8, index into PHASES). Between starts the state is evolve(start, t - time).")
      .def_property_readonly(
          "facts",
          [](Result& r) {
            if (!r.facts) {
              const cueball::Scenario& s = *r.scenario;
              const cueball::ShotFacts f =
                  cueball::shot_facts(s.table, s.settings.parameters, r.result, s.cue ? s.cue->ball : -1);
              r.facts = py::module_::import("json").attr("loads")(cueball::shot_facts_to_json(s.table, f, -1));
            }
            return r.facts;
          },
          "What the shot did (the result JSON's \"facts\"; ShotFacts, shot_facts.hpp), a dict: cue_ball,\n"
          "first_contact {ball, time, simultaneous} (None: no contact), contacts [{time, balls}],\n"
          "pots [{time, ball, pocket (name)}], cushions [{time, ball, cushion, cushion_name,\n"
          "after_first_contact}], cue_cushions_before_contact [{time, ball, cushions}], jaws [{time,\n"
          "ball, jaw, jaw_name}], head_string_crossings [{time, ball, toward_head}], frozen_at_start\n"
          "{balls: [[id, id]], cushions: [{ball, cushion, cushion_name}]}. Lists in event order.")
      .def_property_readonly(
          "scenario", [](const Result& r) { return std::const_pointer_cast<cueball::Scenario>(r.scenario); },
          "the Scenario that ran (the same object when simulate() was given one): simulate(result.scenario)\n"
          "reproduces this result bit for bit")
      .def_property_readonly(
          "cue_obstructed", [](const Result& r) { return cueball::cue_strike_obstructed(*r.scenario); },
          "True when the scenario's cue strike is obstructed (the cue, aligned for it, passes through\n"
          "another ball or below the rail; the result JSON's \"cue_obstructed\"); False without a cue.\n"
          "The shot is simulated all the same.")
      .def_property_readonly(
          "pocket_names",
          [](const Result& r) {
            py::list names;
            for (const cueball::Pocket& q : r.scenario->table.pockets) names.append(q.name);
            return names;
          },
          "the table's pocket names, indexed by events['pocket'] and balls['pocket']")
      .def_property_readonly(
          "cushion_names",
          [](const Result& r) {
            py::list names;
            for (std::size_t i = 0; i < r.scenario->table.cushions.size(); ++i)
              names.append(cueball::cushion_name(r.scenario->table, i));
            return names;
          },
          "the table's cushion names (as the result JSON's events give them), indexed by events['cushion']")
      .def_property_readonly(
          "jaw_names",
          [](const Result& r) {
            py::list names;
            for (std::size_t j = 0; j < r.scenario->table.jaws.size(); ++j) names.append(cueball::jaw_name(r.scenario->table, j));
            return names;
          },
          "the table's jaw names (as the result JSON's events give them), indexed by events['jaw']")
      .def(
          "table_after",
          [](const Result& r) { return std::make_shared<cueball::Scenario>(cueball::table_after(*r.scenario, r.result)); },
          "The table this shot leaves, as a Scenario to plan or play the next shot on: the same table and\n"
          "settings, every ball not pocketed at rest where it stopped, no cue strike (result.scenario is\n"
          "the table before the shot).")
      .def(
          "state_at", [](const Result& r, const py::object& times) { return states_dict(r, checked_times(times)); },
          "times"_a,
          "Every ball's state at each time (s; a number or a 1-D array, finite, >= 0; after end_time the\n"
          "final states): dict with time (n_times,), position (n_balls, n_times, 2) m, velocity\n"
          "(n_balls, n_times, 2) m/s, angular_velocity (n_balls, n_times, 3) rad/s, phase\n"
          "(n_balls, n_times) int8 indices into PHASES. A pocketed ball is at its capture point, at\n"
          "rest, from its pocket_time on. Releases the GIL while evaluating.")
      .def(
          "sample",
          [](const Result& r, double rate) {
            check_sample_rate(r, rate, false);
            const auto count = static_cast<Index>(std::floor(r.result.end_time * rate)) + 1;
            py::array_t<double> times(std::vector<Index>{count});
            double* t = times.mutable_data();
            for (Index k = 0; k < count; ++k) t[k] = static_cast<double>(k) / rate;
            return states_dict(r, times);
          },
          "rate"_a,
          "state_at() at the times k / rate, k = 0, 1, ... up to end_time (rate in Hz, (0, 1e4], at most\n"
          "200000 states in all): the times and states of to_dict(sample_rate=rate)['samples'].")
      .def(
          "to_dict",
          [](const Result& r, std::optional<double> sample_rate) {
            return py::module_::import("json").attr("loads")(result_json(r, sample_rate, -1));
          },
          "sample_rate"_a = py::none(),
          "The documented result JSON as Python objects (json.loads of `cueball simulate --json`):\n"
          "table, parameters, end_time, events, balls and, with a sample rate > 0 (Hz; default the\n"
          "sample_rate given to simulate()), samples.")
      .def(
          "to_json",
          [](const Result& r, std::optional<double> sample_rate, int indent) {
            if (indent < -1 || indent > 16)
              throw cueball::InvalidArgument("indent", indent, "[-1, 16]", "spaces per level, -1: one line");
            return result_json(r, sample_rate, indent);
          },
          "sample_rate"_a = py::none(), "indent"_a = 1,
          "The documented result JSON text, as `cueball simulate --json` prints it (indent 1; -1 puts\n"
          "it on one line).")
      .def(
          "to_html",
          [](const Result& r, std::optional<double> sample_rate) {
            return cueball::viewer_page(cueball::viewer_template(), result_json(r, sample_rate, -1));
          },
          "sample_rate"_a = py::none(),
          "The shot as a self-contained HTML viewer page (the bytes of `cueball simulate --html`).")
      .def("__repr__", [](const Result& r) {
        return "Result(balls=" + std::to_string(r.result.balls.size()) + ", events=" +
               std::to_string(r.result.events.size()) + ", end_time=" +
               py::repr(py::float_(r.result.end_time)).cast<std::string>() + ")";
      });

  m.def(
      "viewer_page",
      [](const std::string& document) { return cueball::viewer_page(cueball::viewer_template(), document); },
      "document"_a,
      "The self-contained HTML viewer page with `document` filled in: a result's JSON (Result.to_json)\n"
      "or a game document (cueball.games, cueball.rl render()), as `cueball view` writes it.");

  m.def(
      "simulate",
      [](const py::object& scenario, double sample_rate) {
        const ScenarioInput input = scenario_input(scenario);
        Result r;
        {
          py::gil_scoped_release release;
          cueball::require_in_range("sample_rate", sample_rate, 0.0, 1e4, "sampling rate, Hz (0: none)");
          std::shared_ptr<const cueball::Scenario> s = load_scenario(input);
          r.result = cueball::run_scenario(*s);
          r.scenario = std::move(s);
        }
        r.sample_rate = sample_rate;
        check_sample_rate(r, sample_rate, true);
        return r;
      },
      "scenario"_a = py::none(), "sample_rate"_a = 0.0,
      "Simulates a whole shot, event by event, until every ball is at rest or pocketed, and returns\n"
      "a Result (events, balls, segments as NumPy arrays; state_at(times), sample(rate); to_dict()\n"
      "and to_json(), the form of `cueball simulate --json`). sample_rate (Hz, [0, 1e4]) is the\n"
      "default of to_dict() and to_json() (0: no samples). scenario: None (the built-in 9-ball\n"
      "break), the scenario's JSON text (a str starting with '{'), a dict of the same, or a path\n"
      "(any other str, or a pathlib.Path) to a scenario file; see the README's 'Scenario format'.\n"
      "Releases the GIL while simulating.");

  m.def(
      "_time_run_scenario",
      [](const py::object& scenario, long long repetitions) {
        if (repetitions < 1 || repetitions > 1000000)
          throw cueball::InvalidArgument("repetitions", static_cast<double>(repetitions), "[1, 1e6]",
                                         "runs to time");
        const ScenarioInput input = scenario_input(scenario);
        py::gil_scoped_release release;
        const std::shared_ptr<const cueball::Scenario> scenario_ptr = load_scenario(input);
        const cueball::Scenario& s = *scenario_ptr;
        std::size_t events = 0;
        const auto start = std::chrono::steady_clock::now();
        for (long long k = 0; k < repetitions; ++k) events += cueball::run_scenario(s).events.size();
        const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
        if (events == 0) throw std::logic_error("no events");  // keeps the runs from being optimised away
        return elapsed.count() / static_cast<double>(repetitions);
      },
      "scenario"_a = py::none(), "repetitions"_a = 100,
      "Benchmark hook: seconds per run of the library's run_scenario() on the scenario (loaded once),\n"
      "timed in C++ over `repetitions` runs without the GIL.");
}

}  // namespace cueball_python
