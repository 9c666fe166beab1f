// libFuzzer target: cueball::scenario_from_json on arbitrary bytes, and the
// simulator (bounded) on every scenario that parses.
//
// Checked for every input:
//   * scenario_from_json returns or throws InvalidArgument (field and message
//     non-empty); nothing else escapes, nothing crashes (ASan, UBSan).
// and for every accepted scenario:
//   * its table survives table_to_json -> table_from_json exactly (table.hpp);
//   * run_scenario, capped at kMaxEvents events (and on a table of more than
//     kMaxExactHeights contact heights by the paper's cushion solver), returns or throws
//     SimulationError (the event limit); events are in time order with finite
//     times; every ball's final state is finite;
//   * result_to_json writes the result (and a few samples) without throwing.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "cueball/io/scenario_json.hpp"
#include "cueball/io/result_json.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/simulation/scenario.hpp"
#include "cueball/simulation/simulator.hpp"
#include "cueball/io/table_json.hpp"
#include "cueball/table/table.hpp"
#include "fuzz_common.hpp"

namespace {

using cueball_fuzz::check;

// Keeps one input well under a second even for a full rack.
constexpr int kMaxEvents = 2000;
// The exact cushion solver builds a rolling-ball table on the first rolling
// impact at each contact height (a set of constants; up to ~0.2 s in Release,
// several times that under ASan and coverage): a table of many heights runs
// the paper scheme instead (capped below), so an input builds at most this many.
constexpr std::size_t kMaxExactHeights = 3;

bool finite(cueball::Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }
bool finite(cueball::Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void check_table_round_trip(const cueball::Table& table) {
  const std::string text = cueball::table_to_json(table);
  cueball::Table back;
  try {
    back = cueball::table_from_json(text, "table");
  } catch (const cueball::InvalidArgument& e) {
    cueball_fuzz::fail("table_to_json wrote a table that table_from_json rejects", e.what() + ("\n" + text));
  }
  check(back == table, "table_from_json(table_to_json(t)) != t", text);
}

void check_result(const cueball::Scenario& s, const cueball::SimulationResult& r) {
  check(std::isfinite(r.end_time) && r.end_time >= 0.0, "end_time not finite", std::to_string(r.end_time));
  check(r.balls.size() == s.balls.size(), "result has a different ball count");
  double last = 0.0;
  for (const cueball::Event& e : r.events) {
    check(std::isfinite(e.time) && e.time >= last, "event times not finite or not in order",
          std::to_string(last) + " then " + std::to_string(e.time) + " (" + cueball::to_string(e.type) + ")");
    last = e.time;
  }
  check(last <= r.end_time, "an event after end_time");
  for (const cueball::BallTrajectory& b : r.balls) {
    const cueball::BallState& f = b.final_state;
    check(finite(f.position) && finite(f.velocity) && finite(f.angular_velocity), "non-finite final state",
          "ball " + std::to_string(b.id));
    check(!b.segments.empty(), "ball without trajectory segments", "ball " + std::to_string(b.id));
  }
  (void)cueball::result_to_json(s, r);
  // Samples: at most ~50 per ball whatever end_time is.
  if (r.end_time > 0.0) (void)cueball::result_to_json(s, r, 50.0 / std::max(r.end_time, 1.0));
}

void run_bounded(cueball::Scenario s) {
  s.settings.max_events = std::min(s.settings.max_events, kMaxEvents);
  // The paper's Euler scheme costs its N per impact: kept short here too.
  s.settings.cushion.paper_steps = std::min(s.settings.cushion.paper_steps, 200);
  std::vector<double> heights;
  for (const cueball::CushionSegment& c : s.table.cushions) heights.push_back(c.contact_height);
  for (const cueball::JawArc& j : s.table.jaws) heights.push_back(j.contact_height);
  std::sort(heights.begin(), heights.end());
  const auto distinct = static_cast<std::size_t>(std::unique(heights.begin(), heights.end()) - heights.begin());
  if (distinct > kMaxExactHeights && s.settings.cushion.model == cueball::CushionModel::mathavan_2010)
    s.settings.cushion.solver = cueball::CushionSolver::paper;
  try {
    check_result(s, cueball::run_scenario(s));
  } catch (const cueball::SimulationError& e) {
    if (cueball_fuzz::verbose()) std::fprintf(stderr, "scenario: simulation stopped: %s\n", e.what());
  } catch (const cueball::InvalidArgument& e) {
    // scenario_from_json accepted it, so running it must not be "invalid".
    cueball_fuzz::fail("run_scenario rejected a scenario that scenario_from_json accepted",
                       "[" + e.field() + "] " + e.what());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    cueball::Scenario s;
    try {
      s = cueball::scenario_from_json(text);
    } catch (const cueball::InvalidArgument& e) {
      cueball_fuzz::check_rejection(e, "scenario");
      return 0;
    }
    if (cueball_fuzz::verbose())
      std::fprintf(stderr, "scenario: accepted (%zu balls, table %s)\n", s.balls.size(), s.table.name.c_str());
    check_table_round_trip(s.table);
    run_bounded(std::move(s));
  } catch (const std::exception& e) {
    cueball_fuzz::unexpected(e, "scenario_from_json/run_scenario");
  }
  return 0;
}
