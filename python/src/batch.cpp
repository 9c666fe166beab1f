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

void bind_batch(py::module_& m) {
  m.def(
      "simulate_batch",
      [](const py::object& scenario, long long shots, long long threads, std::uint64_t seed) {
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
        cueball::BatchResult r;
        {
          py::gil_scoped_release release;
          s = load_scenario(input);
          // A worker's error (e.g. InvalidArgument) is rethrown here, in this thread.
          r = cueball::simulate_batch(
              *s, cueball::BatchOptions{static_cast<int>(shots), static_cast<int>(threads), seed});
        }
        return batch_dict(*s, r);
      },
      "scenario"_a = py::none(), "shots"_a = 1000, "threads"_a = 1, "seed"_a = 0,
      "Simulates `shots` copies of the scenario's shot with Gaussian execution noise on the cue\n"
      "strike (the scenario's \"noise\"), on `threads` threads; deterministic for a seed whatever\n"
      "the number of threads; memory does not grow with `shots` (at most 1e8). A noisy cue speed\n"
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
