// include/cueball/simulation/batch.hpp: noisy batches of one shot.
#include "bindings.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include "cueball/simulation/batch.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/simulation/scenario.hpp"

namespace cueball_python {

namespace {

// [x, y] as a list: the object json.loads makes of the CLI's output.
py::list to_list(cueball::Vec2 v) {
  py::list l;
  l.append(v.x);
  l.append(v.y);
  return l;
}

py::dict batch_dict(const cueball::Scenario& s, const cueball::BatchResult& r) {
  py::dict probability;
  py::list balls;
  for (std::size_t i = 0; i < r.balls.size(); ++i) {
    const cueball::BallOutcome& b = r.balls[i];
    probability[py::int_(b.id)] = b.pocketed_probability;
    balls.append(py::dict("id"_a = b.id, "name"_a = s.balls[i].name, "pocketed_probability"_a = b.pocketed_probability,
                          "mean_position"_a = to_list(b.mean_position), "position_std"_a = to_list(b.position_std)));
  }
  const double events_per_shot = r.simulated > 0 ? static_cast<double>(r.events) / r.simulated : 0.0;
  return py::dict("shots"_a = r.shots, "simulated"_a = r.simulated, "miscues"_a = r.miscues, "failures"_a = r.failures,
                  "speed_reflected"_a = r.speed_reflected, "elevation_reflected"_a = r.elevation_reflected,
                  "seconds"_a = r.seconds, "shots_per_second"_a = r.shots_per_second,
                  "events_per_shot"_a = events_per_shot, "pocketed_probability"_a = probability, "balls"_a = balls);
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
      "events_per_shot, pocketed_probability {ball id (int): probability} and balls [{id, name, pocketed_probability, mean_position, position_std}].\n"
      "Releases the GIL while simulating.");
}

}  // namespace cueball_python
