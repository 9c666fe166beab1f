// The cushion commands' JSON (models/cushion/): what `cueball cushion --json`,
// `cueball cushion-sweep --json` and `cueball figures --json` print.
//
// cushion: its report (io/report.hpp), then "history" with --history:
//   [{"P" (N s), "s" (m/s), "phi" (deg), "s_prime" (m/s), "phi_prime" (deg),
//     "v": [x, y, z] (m/s), "w": [x, y, z] (rad/s), "work" (J)}]
// cushion-sweep: {"family", "model", "solver" (mathavan_2010's only),
//   "preset", "rows": [{"v0" (m/s), "alpha_deg", "topspin_k", "sidespin_k",
//   "speed" (m/s), "angle_deg"}] (the CSV's columns) or, for fig12,
//   "history" (as above)}
// figures: {"out", "format", "files": [paths]}
#pragma once

#include <string>
#include <vector>

#include "cueball/io/report.hpp"
#include "cueball/models/cushion/impact.hpp"

namespace cueball {

/// The report, then the impact's "history" over the normal impulse when
/// `history` is given (cushion --history --json). `indent` as in
/// report_to_json.
std::string cushion_report_to_json(const Report& report, const std::vector<CushionImpactSample>* history = nullptr,
                                   int indent = 2);

/// What a sweep swept: the family, the cushion model, the solver ("" : no
/// "solver" key, for a model without one) and the ball's preset.
struct CushionSweepInfo {
  std::string family;
  std::string model;
  std::string solver;
  std::string preset;
};

/// One impact of a sweep: the incoming ball and the rebound speed (m/s) and
/// angle (rad) from the cushion.
struct CushionSweepRow {
  PaperIncidence incoming;
  double speed = 0.0;
  double angle = 0.0;
};

/// The sweep JSON above with its "rows", the spins as multiples of V0/R
/// (`radius` the ball's, m).
std::string cushion_sweep_to_json(const CushionSweepInfo& info, const std::vector<CushionSweepRow>& rows, double radius,
                                  int indent = 2);

/// The sweep JSON above with the "history" of one impact (fig12).
std::string cushion_sweep_history_to_json(const CushionSweepInfo& info, const std::vector<CushionImpactSample>& history,
                                          int indent = 2);

/// The figures JSON above.
std::string figures_to_json(const std::string& out, const std::string& format, const std::vector<std::string>& files,
                            int indent = 2);

}  // namespace cueball
