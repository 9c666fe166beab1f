// include/cueball/simulator.hpp: whole shots.
#include "bindings.hpp"

#include <optional>
#include <string>
#include "cueball/errors.hpp"
#include "cueball/scenario.hpp"

namespace cueball_python {

void bind_simulation(py::module_& m) {
  m.def(
      "simulate",
      [](const py::object& scenario, double sample_rate) {
        const std::optional<std::string> text = scenario_text(scenario);
        std::string json;
        {
          py::gil_scoped_release release;
          cueball::require_in_range("sample_rate", sample_rate, 0.0, 1e4, "sampling rate, Hz (0: none)");
          const cueball::Scenario s = load_scenario(text);
          json = cueball::result_to_json(s, cueball::run_scenario(s), sample_rate, -1);
        }
        return py::module_::import("json").attr("loads")(json);
      },
      "scenario"_a = py::none(), "sample_rate"_a = 0.0,
      "Simulates a whole shot, event by event, until every ball is at rest or pocketed, and returns\n"
      "the result as `cueball simulate --json` prints it (json.loads of it): table, parameters,\n"
      "end_time, events, balls (final states, pocketing, trajectory segments) and, with\n"
      "sample_rate > 0 (Hz), samples. scenario: None (the built-in 9-ball break), the scenario's\n"
      "JSON text (a str starting with '{'), a dict of the same, or a path (any other str, or a\n"
      "pathlib.Path) to a scenario file; see the README's\n"
      "'Scenario format'. Releases the GIL while simulating.");
}

}  // namespace cueball_python
