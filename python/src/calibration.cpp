// include/cueball/calibration/calibrate.hpp: cueball.calibrate, the engine
// fitted to tracked shots (README "Calibrating from tracked shots").
#include "bindings.hpp"

#include <optional>
#include <string>

#include "cueball/calibration/calibrate.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/io/calibration_html.hpp"
#include "cueball/io/tracked_shots_json.hpp"
#include "cueball/models/ball_collision/model.hpp"
#include "cueball/models/cushion/model.hpp"

namespace cueball_python {

namespace {

std::string run_calibration(const std::string& shots_json, double held_out, std::uint64_t seed,
                            const std::optional<std::string>& constants, bool evaluate,
                            const std::optional<std::string>& cushion_model,
                            const std::optional<std::string>& ball_collision_model, int threads, int starts, int max_evaluations,
                            int max_iterations, int restarts, int spin_profile, int bootstrap, bool html, std::string& page) {
  using namespace cueball;
  const TrackedShots shots = tracked_shots_from_json(shots_json);
  FitModel start = constants ? fit_model_from_json(*constants, shots) : default_fit_model(shots);
  if (cushion_model) {
    const auto model = cushion_model_from_string(*cushion_model);
    if (!model)
      throw InvalidArgument("cushion_model", "cushion_model = " + quote_input(*cushion_model) +
                                                 " is not known; allowed: " + cushion_model_names());
    if (*model != start.settings.cushion.model) start.settings.cushion = default_cushion_settings(*model);
  }
  if (ball_collision_model) {
    const auto model = ball_collision_model_from_string(*ball_collision_model);
    if (!model)
      throw InvalidArgument("ball_collision_model", "ball_collision_model = " + quote_input(*ball_collision_model) +
                                                        " is not known; allowed: " + ball_collision_model_names());
    if (*model != start.settings.ball_collision_model)
      start.settings.ball_collision_model = *model, start.settings.ball_collision = default_ball_collision(*model);
  }
  if (evaluate && !constants)
    throw InvalidArgument("evaluate", "evaluate=True needs constants= (the constants to evaluate)");
  if (starts < 1 || starts > 64) throw InvalidArgument("starts", starts, "[1, 64]", "refined starts per strike fit");
  CalibrationOptions o;
  o.held_out = evaluate ? 0.0 : held_out;
  o.seed = seed;
  o.evaluate_only = evaluate;
  o.threads = threads;
  o.strike.starts = starts;
  o.constants.max_evaluations = max_evaluations;
  o.constants.max_iterations = max_iterations;
  o.constants.restarts = restarts;
  o.constants.spin_profile = spin_profile;
  o.bootstrap.replicates = bootstrap;
  o.bootstrap.seed = seed;
  const CalibrationReport report = calibrate(shots, start, o);
  if (html) page = calibration_report_html(report, shots.table, shot_drawings(shots, report));
  return calibration_report_to_json(report, -1);
}

}  // namespace

void bind_calibration(py::module_& m) {
  m.def(
      "calibrate",
      [](const std::string& shots, double held_out, std::uint64_t seed, const std::optional<std::string>& constants,
         bool evaluate, const std::optional<std::string>& cushion_model,
         const std::optional<std::string>& ball_collision_model, int threads, int starts, int max_evaluations,
         int max_iterations, int restarts, int spin_profile, int bootstrap, bool html) {
        std::string report, page;
        {
          py::gil_scoped_release release;
          report = run_calibration(shots, held_out, seed, constants, evaluate, cushion_model, ball_collision_model, threads, starts,
                                   max_evaluations, max_iterations, restarts, spin_profile, bootstrap, html, page);
        }
        py::object out = py::module_::import("json").attr("loads")(report);
        if (html) out["html"] = page;
        return out;
      },
      "shots"_a, py::kw_only(), "held_out"_a = 0.25, "seed"_a = 0, "constants"_a = py::none(), "evaluate"_a = false,
      "cushion_model"_a = py::none(), "ball_collision_model"_a = py::none(), "threads"_a = 1, "starts"_a = 32,
      "max_evaluations"_a = 300, "max_iterations"_a = 20,
      "restarts"_a = 2, "spin_profile"_a = 7, "bootstrap"_a = 0, "html"_a = false,
      "Fits the engine to tracked shots (README 'Calibrating from tracked shots'): shots is the JSON text of\n"
      "a tracked-shots document; constants the JSON text of a scenario whose parameters and cushion to start\n"
      "from (with evaluate=True: to use, fitting strikes only); ball_collision_model the ball-ball model played\n"
      "(not fitted; 'mathavan_2014' fits the recorded carom match best). Returns the report as `cueball calibrate\n"
      "--json` prints it (a dict: constants, uncertainty, summary, shots). spin_profile=N: points of the profile\n"
      "over mu_sp after the first simplex (0: none). bootstrap=N: the constants'\n"
      "spread over N bootstrap replicates of the training shots; html=True: the HTML report's page in the dict's \"html\".\n"
      "Releases the GIL.");
}

}  // namespace cueball_python
