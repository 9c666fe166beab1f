// Benchmarks of whole shots (src/simulation/simulator.cpp): the built-in 9-ball break
// under each ball-ball model and under each cushion model, a one-ball shot
// with five cushion hits under each cushion model (the exact one also at the
// planners' tolerance 1e-7), what ShotFacts cost beside the simulation
// they read (BM_ShotFacts), and batch throughput on one and
// two threads (their ratio is the parallel speed-up), and simulate_many of
// the same noisy breaks against simulate_batch (their throughput ratio, the
// two run alternately in one process). Counters report events and
// microseconds per shot. BM_OneBallCushionsExactVsHan times the five-rail shot
// under the exact cushion and under han_2005 alternately (their ratio),
// BM_BreakExactVsHan the built-in and the frozen 9-ball breaks;
// BM_OneBallCushionsBudget and BM_BreakBudget time the same shots' cushion
// impacts alone (what the sliding ones may cost for a ratio of 1.5).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "cueball/io/scenario_json.hpp"
#include "cueball/simulation/batch.hpp"
#include "cueball/simulation/scenario.hpp"
#include "cueball/simulation/shot_facts.hpp"

namespace {

using namespace cueball;

void run_shot(benchmark::State& st, const Scenario& s) {
  const std::vector<SimulationBall> balls = balls_after_strike(s);
  std::size_t events = 0;
  for (auto _ : st) {
    const SimulationResult r = simulate(s.table, balls, s.settings);
    events = r.events.size();
    benchmark::DoNotOptimize(r.end_time);
  }
  st.counters["events"] = static_cast<double>(events);
  st.counters["us_per_shot"] = benchmark::Counter(static_cast<double>(st.iterations()) * 1e-6,
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// The built-in break under each ball-ball model (ball_collision_model.hpp),
// each with its own constants.
void BM_NineBallBreak(benchmark::State& st, BallCollisionModel model) {
  Scenario s = default_scenario();
  s.settings.ball_collision_model = model;
  s.settings.ball_collision = default_ball_collision(model);
  run_shot(st, s);
}
BENCHMARK_CAPTURE(BM_NineBallBreak, coulomb_impulse, BallCollisionModel::coulomb_impulse)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_NineBallBreak, mathavan_2014, BallCollisionModel::mathavan_2014)->Unit(benchmark::kMicrosecond);

// The 9-ball and 15-ball breaks (cue 9 m/s, full on the apex ball) on a
// frozen rack, whose touching balls are one cluster resolved at once
// (contact_cluster.hpp), and on a rack with gap_sigma = 0.025 mm, where
// every contact is a pair: side by side, their ratio is what the cluster
// costs.
void BM_Break(benchmark::State& st) {
  const char* rack = st.range(0) == 9 ? "nine_ball" : "eight_ball";
  const std::string gap = st.range(1) == 0 ? "0" : "2.5e-5";
  const Scenario s = scenario_from_json(std::string(R"({"table": "pool_9ft", "rack": {"type": ")") + rack +
                                        R"(", "gap_sigma": )" + gap + R"(, "seed": 3}, "cue": {"ball": 0, "target": 1, "speed": 9.0}})");
  run_shot(st, s);
}
BENCHMARK(BM_Break)->ArgsProduct({{9, 15}, {0, 1}})->ArgNames({"balls", "gaps"})->Unit(benchmark::kMicrosecond);

// The same break without re-validating the table and balls: what a batch or
// a planner pays per shot once its scenario has been validated.
void BM_NineBallBreakUnchecked(benchmark::State& st) {
  const Scenario s = default_scenario();
  const std::vector<SimulationBall> balls = balls_after_strike(s);
  for (auto _ : st) benchmark::DoNotOptimize(simulate_unchecked(s.table, balls, s.settings).end_time);
  st.counters["us_per_shot"] = benchmark::Counter(static_cast<double>(st.iterations()) * 1e-6,
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_NineBallBreakUnchecked)->Unit(benchmark::kMicrosecond);

// The same break under each cushion model (ball-ball model coulomb_impulse):
// what the exact cushion costs a break, against the closed forms of Han 2005
// and Stronge (issue 14's in-process proxy for a simulator with a simple
// cushion).
void BM_NineBallBreakCushion(benchmark::State& st, CushionModel model, double exact_tolerance = 1e-8) {
  Scenario s = default_scenario();
  s.settings.cushion = default_cushion_settings(model);
  s.settings.cushion.exact_tolerance = exact_tolerance;
  const SimulationResult r = run_scenario(s);
  st.counters["cushion_hits"] = static_cast<double>(std::count_if(
      r.events.begin(), r.events.end(), [](const Event& e) { return e.type == EventType::ball_cushion; }));
  run_shot(st, s);
}
BENCHMARK_CAPTURE(BM_NineBallBreakCushion, mathavan_2010, CushionModel::mathavan_2010)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_NineBallBreakCushion, mathavan_2010_tolerance_1e-7, CushionModel::mathavan_2010, 1e-7)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_NineBallBreakCushion, han_2005, CushionModel::han_2005)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_NineBallBreakCushion, stronge_compliant, CushionModel::stronge_compliant)
    ->Unit(benchmark::kMicrosecond);

// One ball around the (pocketless) carom table with running side: five
// rails under each cushion model (cushion_model.hpp), 13 events. The shot's
// time is mostly its cushion impacts: the ratios between the models are
// what a model costs a planner's inner loop.
Scenario five_rails() {
  return scenario_from_json(R"({"table": "carom_10ft",
      "balls": [{"id": 0, "position": [0.7, 0.4]}],
      "cue": {"ball": 0, "aim_deg": 27, "speed": 3.0, "side": 0.3, "height": 0.2}})");
}
void BM_OneBallCushions(benchmark::State& st, CushionSettings cushion) {
  Scenario s = five_rails();
  s.settings.cushion = cushion;
  const SimulationResult r = run_scenario(s);
  st.counters["cushion_hits"] = static_cast<double>(
      std::count_if(r.events.begin(), r.events.end(), [](const Event& e) { return e.type == EventType::ball_cushion; }));
  run_shot(st, s);
}
CushionSettings mathavan_tolerance(double exact_tolerance) {
  CushionSettings c;
  c.exact_tolerance = exact_tolerance;
  return c;
}
CushionSettings mathavan_paper(int steps) {
  CushionSettings c;
  c.solver = CushionSolver::paper;
  c.paper_steps = steps;
  return c;
}
BENCHMARK_CAPTURE(BM_OneBallCushions, mathavan_2010, default_cushion_settings(CushionModel::mathavan_2010))
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_OneBallCushions, mathavan_2010_tolerance_1e-7, mathavan_tolerance(1e-7))
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_OneBallCushions, mathavan_2010_paper_N1000, mathavan_paper(1000))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_OneBallCushions, han_2005, default_cushion_settings(CushionModel::han_2005))
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_OneBallCushions, stronge_compliant, default_cushion_settings(CushionModel::stronge_compliant))
    ->Unit(benchmark::kMicrosecond);

// Seconds that `run` takes `shots` times in a row (so that the clock's reads
// do not count).
template <class Run>
double seconds_of(int shots, const Run& run) {
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < shots; ++i) run();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The scenario under han_2005 (with its own constants) instead of its cushion.
Scenario under_han(Scenario s) {
  s.settings.cushion = default_cushion_settings(CushionModel::han_2005);
  return s;
}

// A shot under the default cushion (mathavan_2010, exact) and under
// han_2005, alternately in each iteration, `shots` of each in a row.
// Counters: microseconds a shot under each, and their ratio.
void exact_vs_han(benchmark::State& st, const Scenario& exact, int shots) {
  const Scenario han = under_han(exact);
  const std::vector<SimulationBall> balls = balls_after_strike(exact);
  auto play = [&](const Scenario& s) { benchmark::DoNotOptimize(simulate(s.table, balls, s.settings).end_time); };
  double exact_s = 0.0, han_s = 0.0;
  for (auto _ : st) {
    exact_s += seconds_of(shots, [&] { play(exact); });
    han_s += seconds_of(shots, [&] { play(han); });
  }
  const double n = static_cast<double>(st.iterations()) * shots;
  st.counters["exact_us"] = 1e6 * exact_s / n;
  st.counters["han_us"] = 1e6 * han_s / n;
  st.counters["exact_over_han"] = exact_s / han_s;
}

// The five-rail shot (issue 29: the exact cushion at the price of a closed
// form; goal exact_over_han <= 1.5).
void BM_OneBallCushionsExactVsHan(benchmark::State& st) { exact_vs_han(st, five_rails(), 64); }
BENCHMARK(BM_OneBallCushionsExactVsHan)->Unit(benchmark::kMillisecond);

// Issue 29's budget: a shot's cushion and jaw impacts under the exact model
// are solved alone, as the simulator passes them to cushion_rebound() (the
// ball an ulp before the event, in the impact frame), alternately with the
// shot under each model, `shots` of each in a row. Counters: the shot under
// each model and its events; its impacts the Runge-Kutta solver takes
// (sliding_us, a shot's worth) and those the rolling-ball table answers
// (rolling_us); the ratio to
// han_2005 the shot would keep were its sliding impacts free
// (free_sliding_over_han); and what a ratio of 1.5 (the five rails' goal)
// leaves them (sliding_budget_us = 1.5 han_us - (exact_us - sliding_us)).
struct RecordedImpact {
  IncomingBall ball;
  CushionContact contact;
};

// The impact of event e as the simulator passed it to cushion_rebound(), or
// none where that call does not give the velocity the shot left the event
// with (to 1e-9 m/s: the ball is taken an ulp before the event).
std::optional<RecordedImpact> recorded_impact(const Scenario& s, const SimulationResult& shot, const Event& e) {
  const auto index = static_cast<std::size_t>(
      std::find_if(shot.balls.begin(), shot.balls.end(), [&](const BallTrajectory& b) { return b.id == e.ball; }) -
      shot.balls.begin());
  const BallState b = shot.state_at(index, std::nextafter(e.time, 0.0), s.settings.parameters);
  Vec2 n;  // the wall's inward normal at the contact
  double height = 0.0;
  if (e.type == EventType::ball_cushion) {
    const CushionSegment& c = s.table.cushions[static_cast<std::size_t>(e.other)];
    n = perp((c.end - c.start) / norm(c.end - c.start));
    height = c.contact_height;
  } else {
    const JawArc& j = s.table.jaws[static_cast<std::size_t>(e.other)];
    n = (b.position - j.centre) / norm(b.position - j.centre);
    height = j.contact_height;
  }
  const CushionImpactFrame frame(n);
  RecordedImpact r{{}, cushion_contact(s.settings.parameters, s.settings.cushion, height)};
  r.ball.velocity = frame.to_frame(b.velocity, 0.0);
  r.ball.angular_velocity = frame.to_frame(horizontal(b.angular_velocity), b.angular_velocity.z);
  const Vec2 after = shot.state_at(index, e.time, s.settings.parameters).velocity;
  if (!(norm(frame.from_frame(cushion_rebound(r.ball, r.contact).velocity) - after) < 1e-9)) return std::nullopt;
  return r;
}

void cushion_budget(benchmark::State& st, const Scenario& exact, int shots) {
  const Scenario han = under_han(exact);
  const std::vector<SimulationBall> balls = balls_after_strike(exact);
  const SimulationResult shot = simulate(exact.table, balls, exact.settings);
  st.counters["exact_events"] = static_cast<double>(shot.events.size());
  st.counters["han_events"] = static_cast<double>(simulate(han.table, balls, han.settings).events.size());
  std::vector<RecordedImpact> sliding, rolling;
  for (const Event& e : shot.events) {
    if (e.type != EventType::ball_cushion && e.type != EventType::ball_jaw) continue;
    std::optional<RecordedImpact> r = recorded_impact(exact, shot, e);
    if (!r) {
      st.SkipWithError("an impact solved alone does not give the shot's rebound");
      return;
    }
    const bool looked_up =
        solve_cushion_impact_unchecked(r->ball, r->contact.mathavan, r->contact.mathavan_options).solver_steps == 0;
    (looked_up ? rolling : sliding).push_back(*r);
  }
  auto play = [&](const Scenario& s) { benchmark::DoNotOptimize(simulate(s.table, balls, s.settings).end_time); };
  auto rebounds = [](const std::vector<RecordedImpact>& impacts) {
    for (const RecordedImpact& i : impacts) benchmark::DoNotOptimize(cushion_rebound(i.ball, i.contact).velocity.x);
  };
  double exact_s = 0.0, han_s = 0.0, sliding_s = 0.0, rolling_s = 0.0;
  for (auto _ : st) {
    exact_s += seconds_of(shots, [&] { play(exact); });
    han_s += seconds_of(shots, [&] { play(han); });
    sliding_s += seconds_of(shots, [&] { rebounds(sliding); });
    rolling_s += seconds_of(shots, [&] { rebounds(rolling); });
  }
  const double us = 1e6 / (static_cast<double>(st.iterations()) * shots);
  st.counters["exact_us"] = exact_s * us;
  st.counters["han_us"] = han_s * us;
  st.counters["sliding_impacts"] = static_cast<double>(sliding.size());
  st.counters["rolling_impacts"] = static_cast<double>(rolling.size());
  st.counters["sliding_us"] = sliding_s * us;
  st.counters["rolling_us"] = rolling_s * us;
  st.counters["free_sliding_over_han"] = (exact_s - sliding_s) / han_s;
  st.counters["sliding_budget_us"] = (1.5 * han_s - (exact_s - sliding_s)) * us;
}

void BM_OneBallCushionsBudget(benchmark::State& st) { cushion_budget(st, five_rails(), 64); }
BENCHMARK(BM_OneBallCushionsBudget)->Unit(benchmark::kMillisecond);

// The built-in 9-ball break (frozen:0, BM_NineBallBreakCushion's) and the
// frozen 9-ball break of BM_Break (frozen:1), the same way.
Scenario nine_ball_break(bool frozen) {
  return frozen ? scenario_from_json(R"({"table": "pool_9ft",
      "rack": {"type": "nine_ball", "gap_sigma": 0, "seed": 3}, "cue": {"ball": 0, "target": 1, "speed": 9.0}})")
                : default_scenario();
}
void BM_BreakExactVsHan(benchmark::State& st) { exact_vs_han(st, nine_ball_break(st.range(0) != 0), 2); }
BENCHMARK(BM_BreakExactVsHan)->Arg(0)->Arg(1)->ArgNames({"frozen"})->Unit(benchmark::kMillisecond);

// The same breaks' budget (cushion_budget() above).
void BM_BreakBudget(benchmark::State& st) { cushion_budget(st, nine_ball_break(st.range(0) != 0), 2); }
BENCHMARK(BM_BreakBudget)->Arg(0)->Arg(1)->ArgNames({"frozen"})->Unit(benchmark::kMillisecond);

// simulate() in a loop over one scenario against simulate_unchecked() of the
// same shot, alternately in each iteration (issue 29: validation that costs
// nothing in a loop; goal checked_over_unchecked <= 1.1): the one-ball
// five-rail shot (arg 0), the 9-ball break (arg 1) and a planner's cut shot
// among three other balls (arg 2).
void BM_SimulateLoop(benchmark::State& st) {
  const Scenario s = st.range(0) == 0 ? scenario_from_json(R"({"table": "carom_10ft",
      "balls": [{"id": 0, "position": [0.7, 0.4]}],
      "cue": {"ball": 0, "aim_deg": 27, "speed": 3.0, "side": 0.3, "height": 0.2}})")
                     : st.range(0) == 1 ? default_scenario()
                                        : scenario_from_json(R"({"table": "pool_9ft",
      "balls": [{"id": 0, "position": [0.8, 0.4]}, {"id": 1, "position": [1.6, 0.7]}, {"id": 2, "position": [1.2, 1.0]},
                {"id": 3, "position": [2.0, 0.3]}, {"id": 4, "position": [0.5, 1.0]}],
      "cue": {"ball": 0, "aim_deg": 18, "speed": 2.0}})");
  const std::vector<SimulationBall> balls = balls_after_strike(s);
  double checked_s = 0.0, unchecked_s = 0.0;
  for (auto _ : st) {
    const auto t0 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(simulate(s.table, balls, s.settings).end_time);
    const auto t1 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(simulate_unchecked(s.table, balls, s.settings).end_time);
    const auto t2 = std::chrono::steady_clock::now();
    checked_s += std::chrono::duration<double>(t1 - t0).count();
    unchecked_s += std::chrono::duration<double>(t2 - t1).count();
  }
  const double n = static_cast<double>(st.iterations());
  st.counters["checked_us"] = 1e6 * checked_s / n;
  st.counters["unchecked_us"] = 1e6 * unchecked_s / n;
  st.counters["checked_over_unchecked"] = checked_s / unchecked_s;
}
BENCHMARK(BM_SimulateLoop)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

void BM_BatchBreaks(benchmark::State& st) {
  static const Scenario s = default_scenario();
  const int threads = static_cast<int>(st.range(0));
  double shots = 0.0;
  for (auto _ : st) {
    const BatchResult r = simulate_batch(s, {200, threads, 1});
    shots += r.shots;
  }
  st.counters["shots_per_second"] = benchmark::Counter(shots, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_BatchBreaks)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// N noisy breaks through simulate_many (one action per shot, all the
// break's nominal strike, the scenario's noise) against simulate_batch of
// the same N breaks, alternately in each iteration: many_over_batch is the
// ratio of their throughputs (1 = no cost for returning every outcome).
std::vector<ShotAction> nominal_breaks(const Scenario& s, int n) {
  const CueStrike nominal = resolved_strike(s, s.cue->strike);
  const double degree = std::numbers::pi / 180.0;
  return std::vector<ShotAction>(static_cast<std::size_t>(n),
                                 ShotAction{nominal.speed, nominal.aim / degree, nominal.elevation / degree, 0.0, 0.0});
}

void BM_ManyVsBatchBreaks(benchmark::State& st) {
  static const Scenario s = default_scenario();
  const int threads = static_cast<int>(st.range(0));
  constexpr int kShots = 512;
  const std::vector<ShotAction> actions = nominal_breaks(s, kShots);
  double batch_seconds = 0.0, many_seconds = 0.0, shots = 0.0;
  for (auto _ : st) {
    auto t0 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(simulate_batch(s, {kShots, threads, 1}).events);
    auto t1 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(simulate_many(s, actions, {}, {threads, 1, true}).events.data());
    auto t2 = std::chrono::steady_clock::now();
    batch_seconds += std::chrono::duration<double>(t1 - t0).count();
    many_seconds += std::chrono::duration<double>(t2 - t1).count();
    shots += kShots;
  }
  st.counters["batch_shots_per_s"] = shots / batch_seconds;
  st.counters["many_shots_per_s"] = shots / many_seconds;
  st.counters["many_over_batch"] = batch_seconds / many_seconds;
}
BENCHMARK(BM_ManyVsBatchBreaks)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The same N noisy breaks through simulate_many without a present mask and
// with one that keeps every ball (the absent-ball path: the present balls
// gathered, their outcome spread back over the scenario's columns),
// alternately in each iteration: masked_over_plain is the ratio of their
// throughputs (1 = the mask costs nothing). The arrays are the same.
void BM_ManyMaskedVsPlain(benchmark::State& st) {
  static const Scenario s = default_scenario();
  constexpr int kShots = 512;
  const std::vector<ShotAction> actions = nominal_breaks(s, kShots);
  const std::vector<std::uint8_t> every_ball(kShots * s.balls.size(), 1);
  double plain_seconds = 0.0, masked_seconds = 0.0;
  for (auto _ : st) {
    auto t0 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(simulate_many(s, actions, {}, {1, 1, true}).events.data());
    auto t1 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(simulate_many(s, actions, {}, {1, 1, true}, every_ball).events.data());
    auto t2 = std::chrono::steady_clock::now();
    plain_seconds += std::chrono::duration<double>(t1 - t0).count();
    masked_seconds += std::chrono::duration<double>(t2 - t1).count();
  }
  st.counters["masked_over_plain"] = plain_seconds / masked_seconds;
}
BENCHMARK(BM_ManyMaskedVsPlain)->Unit(benchmark::kMillisecond)->UseRealTime();

// What a shot's facts cost beside its simulation (shot_facts.hpp), timed
// alternately in one process: the events-only facts that every batch shot's
// outcome reads (outcome_from_result, into storage it reuses) and the full facts a game rule reads
// (head-string crossings on the exact paths, frozen balls). Counters are the
// ratios to one simulate_unchecked() of the same shot: the built-in break
// (arg 0) and a planner's cut shot among three other balls (arg 1).
void BM_ShotFacts(benchmark::State& st) {
  const Scenario s = st.range(0) == 0 ? default_scenario() : scenario_from_json(R"({"table": "pool_9ft",
      "balls": [{"id": 0, "position": [0.8, 0.4]}, {"id": 1, "position": [1.6, 0.7]}, {"id": 2, "position": [1.2, 1.0]},
                {"id": 3, "position": [2.0, 0.3]}, {"id": 4, "position": [0.5, 1.0]}],
      "cue": {"ball": 0, "aim_deg": 18, "speed": 2.0}})");
  const std::vector<SimulationBall> balls = balls_after_strike(s);
  const Parameters& p = s.settings.parameters;
  double simulate_s = 0.0, events_s = 0.0, full_s = 0.0;
  ShotFacts reused;  // as a batch's worker keeps it (outcome_from_result)
  for (auto _ : st) {
    const auto t0 = std::chrono::steady_clock::now();
    const SimulationResult r = simulate_unchecked(s.table, balls, s.settings);
    const auto t1 = std::chrono::steady_clock::now();
    shot_facts_into(r, 0, reused);
    benchmark::DoNotOptimize(reused.contacts.size());
    const auto t2 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(shot_facts(s.table, p, r, 0).head_string_crossings.size());
    const auto t3 = std::chrono::steady_clock::now();
    simulate_s += std::chrono::duration<double>(t1 - t0).count();
    events_s += std::chrono::duration<double>(t2 - t1).count();
    full_s += std::chrono::duration<double>(t3 - t2).count();
  }
  const double n = static_cast<double>(st.iterations());
  st.counters["simulate_us"] = 1e6 * simulate_s / n;
  st.counters["events_facts_us"] = 1e6 * events_s / n;
  st.counters["full_facts_us"] = 1e6 * full_s / n;
  st.counters["events_facts_over_simulate"] = events_s / simulate_s;
  st.counters["full_facts_over_simulate"] = full_s / simulate_s;
}
BENCHMARK(BM_ShotFacts)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace
