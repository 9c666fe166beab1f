// include/cueball/simulation/batch.hpp: noisy batches of one shot.
#include "bindings.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include "cueball/io/batch_json.hpp"
#include "cueball/simulation/batch.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/simulation/scenario.hpp"

namespace cueball_python {

namespace {

// What `cueball batch --json` prints (io/batch_json.hpp: one writer for
// both), as Python objects; pocketed_probability's keys, JSON's strings,
// become the balls' ids as ints.
py::dict batch_dict(const cueball::Scenario& s, const cueball::BatchResult& r) {
  py::dict d = json_loads(cueball::batch_result_to_json(s, r, -1));
  py::dict probability;
  for (const auto& [id, p] : d["pocketed_probability"].cast<py::dict>()) probability[py::int_(py::reinterpret_borrow<py::object>(id))] = p;
  d["pocketed_probability"] = probability;
  return d;
}

}  // namespace

std::shared_ptr<const cueball::Scenario> with_noise_argument(std::shared_ptr<const cueball::Scenario> s,
                                                             const py::object& noise) {
  const char* allowed = "None or 'scenario' (the scenario's), True, False, 'none', 'tournament' or a dict of sigmas";
  if (!(noise.is_none() || py::isinstance<py::bool_>(noise) || py::isinstance<py::str>(noise) ||
        py::isinstance<py::dict>(noise)))
    throw ArgumentTypeError("noise", wrong_type_message(noise, "noise", allowed));
  const std::string name = py::isinstance<py::str>(noise) ? utf8_argument(noise, "noise") : std::string();
  if (py::isinstance<py::str>(noise) && name != "scenario" && name != "none" && name != "tournament")
    throw cueball::InvalidArgument("noise", "noise = " + cueball::quote_input(name) + " is not known; allowed: " + allowed);
  const bool scenarios = noise.is_none() || (py::isinstance<py::bool_>(noise) && noise.cast<bool>()) || name == "scenario";
  if (scenarios) {
    if (s->noise == cueball::CueStrikeNoise{} &&
        PyErr_WarnEx(PyExc_UserWarning,
                     "the scenario has no execution noise (its \"noise\" is all zero): every shot is the nominal "
                     "strike. Pass noise='tournament' or a dict of sigmas, or noise='none' if identical shots are meant.",
                     2) != 0)  // 2: the caller's line (every function is wrapped in _arguments.py's call)
      throw py::error_already_set();
    return s;
  }
  auto copy = std::make_shared<cueball::Scenario>(*s);
  if (py::isinstance<py::bool_>(noise))
    copy->noise = {};  // False
  else
    copy->noise = *noise_argument(noise, s->settings.parameters.ball.radius);  // not None here
  return copy;
}

void bind_batch(py::module_& m) {
  m.def(
      "simulate_batch",
      [](const py::object& scenario, long long shots, long long threads, std::uint64_t seed, const py::object& noise) {
        // Taken as long long so that a huge count gets the range error naming it.
        if (shots < 1 || shots > cueball::kMaxBatchShots)
          throw cueball::InvalidArgument("shots", static_cast<double>(shots),
                                         "[1, " + cueball::format_number(cueball::kMaxBatchShots) + "]",
                                         "number of shots");
        if (threads < 1 || threads > cueball::kMaxBatchThreads)
          throw cueball::InvalidArgument("threads", static_cast<double>(threads),
                                         "[1, " + std::to_string(cueball::kMaxBatchThreads) + "]", "worker threads");
        const ScenarioInput input = scenario_input(scenario);
        std::shared_ptr<const cueball::Scenario> s;
        {
          py::gil_scoped_release release;
          s = load_scenario(input);
        }
        s = with_noise_argument(s, noise);
        cueball::BatchResult r;
        {
          py::gil_scoped_release release;
          // A worker's error (e.g. InvalidArgument) is rethrown here, in this thread.
          r = cueball::simulate_batch(
              *s, cueball::BatchOptions{static_cast<int>(shots), static_cast<int>(threads), seed});
        }
        return batch_dict(*s, r);
      },
      "scenario"_a = py::none(), "shots"_a = 1000, "threads"_a = 1, "seed"_a = 0, "noise"_a = py::none(),
      "Simulates `shots` copies of the scenario's shot with Gaussian execution noise on the cue\n"
      "strike, on `threads` threads; deterministic for a seed whatever the number of threads; memory\n"
      "does not grow with `shots` (at most 1e8). `noise`: None or 'scenario' the scenario's \"noise\"\n"
      "(a UserWarning when it is all zero: every shot would be the same), 'none', 'tournament'\n"
      "(tournament_noise()), or a dict of sigmas in the scenario's units (speed m/s, aim_deg,\n"
      "elevation_deg, side and height ball radii; missing keys 0). A noisy cue speed\n"
      "above 12 m/s or elevation below 0 is reflected at the limit (2 cap - v, -e) and counted; a\n"
      "noisy tip offset beyond the miscue limit (0.5 R) is a miscue, counted and not simulated. An\n"
      "error in any shot raises the same exception a single run of it would (the lowest-numbered\n"
      "shot's, whatever `threads`). Returns the keys of `cueball batch --json`: shots, simulated,\n"
      "miscues, failures, speed_reflected, elevation_reflected, seconds, shots_per_second,\n"
      "events_per_shot, pocketed_probability {ball id (int): probability} and balls [{id, name, pocketed_probability, mean_position, position_std}],\n"
      "from the CLI's own writer (batch_result_to_json: json.loads of its output, the ids as ints).\n"
      "Releases the GIL while simulating.");
}

}  // namespace cueball_python
