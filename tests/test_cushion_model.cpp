// Tests of the cushion models by name (src/models/cushion/model.cpp): names, each
// model's own constants, validation under the simulation's field names, the
// dispatch against each model's kernel, a scenario's "cushion" object, and
// the simulator's rebound under each model.
#include "cueball/io/scenario_json.hpp"
#include "cueball/models/cushion/model.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cueball/core/errors.hpp"
#include "cueball/simulation/scenario.hpp"
#include "cueball/simulation/simulator.hpp"
#include "cueball/table/table.hpp"

namespace cueball {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string field_of(const auto& call) {
  try {
    call();
  } catch (const InvalidArgument& e) {
    return e.field() + ": " + e.what();
  }
  return "no error";
}

TEST(CushionModel, NamesRoundTrip) {
  for (const CushionModel m : kCushionModels)
    EXPECT_EQ(cushion_model_from_string(to_string(m)), m);
  EXPECT_FALSE(cushion_model_from_string("mathavan").has_value());
  EXPECT_EQ(cushion_model_names(), "\"mathavan_2010\", \"han_2005\", \"stronge_compliant\"");
  EXPECT_EQ(cushion_solver_from_string("paper"), CushionSolver::paper);
  EXPECT_FALSE(cushion_solver_from_string("euler").has_value());
}

TEST(CushionModel, EachModelHasItsOwnConstants) {
  const CushionSettings m = default_cushion_settings(CushionModel::mathavan_2010);
  EXPECT_EQ(m.restitution, 0.98);
  EXPECT_EQ(m.friction, 0.14);
  EXPECT_EQ(m.solver, CushionSolver::exact);
  const CushionSettings h = default_cushion_settings(CushionModel::han_2005);
  EXPECT_EQ(h.model, CushionModel::han_2005);
  EXPECT_EQ(h.restitution, 0.85);
  EXPECT_EQ(h.friction, 0.2);
  const CushionSettings k = default_cushion_settings(CushionModel::stronge_compliant);
  EXPECT_EQ(k.restitution, 0.85);
  EXPECT_EQ(k.frequency_ratio, 1.8);  // pooltool's omega_ratio
  // The simulator's default is Mathavan 2010's.
  EXPECT_EQ(SimulationSettings{}.cushion.model, CushionModel::mathavan_2010);
}

TEST(CushionModel, ValidationNamesTheSimulationField) {
  const Parameters p = pool_parameters();
  const double h = 1.4 * p.ball.radius;
  CushionSettings s = default_cushion_settings(CushionModel::han_2005);
  s.friction = 1.5;
  EXPECT_EQ(field_of([&] { (void)cushion_contact(p, s, h); }).rfind("cushion_friction: ", 0), 0u);
  s = default_cushion_settings(CushionModel::han_2005);
  s.restitution = -0.1;
  EXPECT_EQ(field_of([&] { (void)cushion_contact(p, s, h); }).rfind("cushion_restitution: ", 0), 0u);
  s = default_cushion_settings(CushionModel::mathavan_2010);
  s.solver = CushionSolver::paper;
  s.paper_steps = 0;
  EXPECT_EQ(field_of([&] { (void)cushion_contact(p, s, h); }).rfind("cushion_paper_steps: ", 0), 0u);
  s = default_cushion_settings(CushionModel::mathavan_2010);
  s.exact_tolerance = 1e-6;  // looser than the solver's range
  EXPECT_EQ(field_of([&] { (void)cushion_contact(p, s, h); }).rfind("cushion_exact_tolerance: ", 0), 0u);
  s = default_cushion_settings(CushionModel::mathavan_2010);
  s.friction = 0.9;  // above tan(theta)
  EXPECT_EQ(field_of([&] { (void)cushion_contact(p, s, h); }).rfind("mu_w: ", 0), 0u);
  s = default_cushion_settings(CushionModel::stronge_compliant);
  s.frequency_ratio = 1.0;
  EXPECT_EQ(field_of([&] { (void)cushion_contact(p, s, h); }).rfind("cushion_frequency_ratio: ", 0), 0u);
}

TEST(CushionModel, DispatchGivesEachModelsOwnKernel) {
  const Parameters p = pool_parameters();
  const double h = 1.4 * p.ball.radius;
  const IncomingBall in = incoming_ball({1.2, 40.0 * kPi / 180.0, 0.8 * 1.2 / p.ball.radius, -0.6 * 1.2 / p.ball.radius});

  CushionSettings s = default_cushion_settings(CushionModel::mathavan_2010);
  const CushionRebound exact = cushion_rebound(in, cushion_contact(p, s, h));
  const CushionImpactResult direct = cushion_impact(in, p, {0.98, 0.14, h});
  EXPECT_EQ(exact.velocity.x, direct.velocity.x);
  EXPECT_EQ(exact.angular_velocity.z, direct.angular_velocity.z);

  s.solver = CushionSolver::paper;
  s.paper_steps = 400;
  const CushionRebound paper = cushion_rebound(in, cushion_contact(p, s, h));
  CushionImpactOptions o;
  o.solver = CushionSolver::paper;
  o.paper_steps = 400;
  EXPECT_EQ(paper.velocity.y, cushion_impact(in, p, {0.98, 0.14, h}, o).velocity.y);
  EXPECT_NE(paper.velocity.y, exact.velocity.y);  // N = 400 is visibly coarse

  // The exact solver at another tolerance: the same answer as
  // cushion_impact() at that tolerance, within the default's accuracy of the
  // default's (the ball slides: topspin K = 0.8, so the Runge-Kutta solve, not
  // the table). A tighter one, 1e-9: the planners' 1e-7 takes the very steps
  // of the default on this impact, whose slips stay large throughout (where
  // the default's steps are loosened 10x, to 1e-7; mathavan_2010_exact.cpp).
  s = default_cushion_settings(CushionModel::mathavan_2010);
  s.exact_tolerance = 1e-9;
  const CushionRebound tight = cushion_rebound(in, cushion_contact(p, s, h));
  o = CushionImpactOptions{};
  o.exact_tolerance = 1e-9;
  const CushionImpactResult tight_direct = cushion_impact(in, p, {0.98, 0.14, h}, o);
  EXPECT_EQ(tight.velocity.x, tight_direct.velocity.x);
  EXPECT_EQ(tight.angular_velocity.z, tight_direct.angular_velocity.z);
  EXPECT_NE(tight.velocity.x, exact.velocity.x);  // more steps: a different rounding
  EXPECT_NEAR(tight.velocity.x, exact.velocity.x, 1e-6 * 1.2);
  EXPECT_NEAR(tight.velocity.y, exact.velocity.y, 1e-6 * 1.2);
  EXPECT_NEAR(p.ball.radius * tight.angular_velocity.z, p.ball.radius * exact.angular_velocity.z, 1e-6 * 1.2);

  s = default_cushion_settings(CushionModel::han_2005);
  const CushionRebound han = cushion_rebound(in, cushion_contact(p, s, h));
  const CushionRebound han_direct = han_2005_rebound(in, han_2005_cushion(p.ball, 0.85, 0.2, h));
  EXPECT_EQ(han.velocity.x, han_direct.velocity.x);
  EXPECT_EQ(han.velocity.y, han_direct.velocity.y);
  EXPECT_GT(std::abs(han.velocity.y - exact.velocity.y), 0.05);  // two different models

  s = default_cushion_settings(CushionModel::stronge_compliant);
  s.frequency_ratio = 2.5;
  const CushionRebound stronge = cushion_rebound(in, cushion_contact(p, s, h));
  StrongeCompliantConstants k;
  k.frequency_ratio = 2.5;
  const CushionRebound stronge_direct = stronge_compliant_rebound(in, stronge_compliant_cushion(p.ball, k));
  EXPECT_EQ(stronge.velocity.x, stronge_direct.velocity.x);
  EXPECT_EQ(stronge.angular_velocity.z, stronge_direct.angular_velocity.z);
}

// The simulator's path (cushion_rebound, which skips the rest of
// CushionImpactResult) gives solve_cushion_impact_unchecked()'s velocity and
// spin to the bit: rolling balls (the table), sliding ones (the Runge-Kutta
// solve), the paper's scheme, and a contact that records the history (the
// Runge-Kutta solve even for a rolling ball).
TEST(CushionModel, SimulatorPathIsTheSolversAnswerToTheBit) {
  const Parameters p = pool_parameters();
  const double h = 1.4 * p.ball.radius;
  const double r = p.ball.radius;
  std::vector<IncomingBall> balls;
  for (int i = 0; i < 40; ++i) {
    const double v = 0.3 + 0.07 * i;
    const double alpha = (2.0 + 2.2 * i) * kPi / 180.0;
    balls.push_back(incoming_ball({v, alpha, v / r, (0.05 * i - 1.0) * v / r}));        // rolling
    balls.push_back(incoming_ball({v, alpha, (0.04 * i - 0.6) * v / r, 0.3 * v / r}));  // sliding
  }
  for (const bool paper : {false, true}) {
    for (const bool history : {false, true}) {
      CushionSettings s = default_cushion_settings(CushionModel::mathavan_2010);
      if (paper) {
        s.solver = CushionSolver::paper;
        s.paper_steps = 300;
      }
      CushionContact c = cushion_contact(p, s, h);
      c.mathavan_options.record_history = history;
      for (const IncomingBall& in : balls) {
        const CushionRebound fast = cushion_rebound(in, c);
        const CushionImpactResult full = solve_cushion_impact_unchecked(in, c.mathavan, c.mathavan_options);
        EXPECT_EQ(fast.velocity.x, full.velocity.x) << paper << history;
        EXPECT_EQ(fast.velocity.y, full.velocity.y) << paper << history;
        EXPECT_EQ(fast.velocity.z, full.velocity.z) << paper << history;
        EXPECT_EQ(fast.angular_velocity.x, full.angular_velocity.x) << paper << history;
        EXPECT_EQ(fast.angular_velocity.y, full.angular_velocity.y) << paper << history;
        EXPECT_EQ(fast.angular_velocity.z, full.angular_velocity.z) << paper << history;
      }
    }
  }
}

TEST(CushionModel, ScenarioChoosesTheModelByName) {
  const Scenario s = scenario_from_json(R"({"cushion": {"model": "han_2005"}, "balls": [{"id": 0, "position": [1, 0.6]}]})");
  EXPECT_EQ(s.settings.cushion.model, CushionModel::han_2005);
  EXPECT_EQ(s.settings.cushion.restitution, 0.85);  // the model's own constants
  const Scenario t = scenario_from_json(
      R"({"cushion": {"model": "mathavan_2010", "solver": "paper", "paper_steps": 800, "friction": 0.2},
          "balls": [{"id": 0, "position": [1, 0.6]}]})");
  EXPECT_EQ(t.settings.cushion.solver, CushionSolver::paper);
  EXPECT_EQ(t.settings.cushion.paper_steps, 800);
  EXPECT_EQ(t.settings.cushion.friction, 0.2);
  EXPECT_EQ(t.settings.cushion.restitution, 0.98);
  // It writes back what it read.
  const Scenario back = scenario_from_json(scenario_to_json(t));
  EXPECT_EQ(back.settings.cushion.solver, CushionSolver::paper);
  EXPECT_EQ(back.settings.cushion.paper_steps, 800);
  EXPECT_EQ(scenario_from_json(scenario_to_json(s)).settings.cushion.model, CushionModel::han_2005);
  const Scenario k = scenario_from_json(
      R"({"cushion": {"model": "stronge_compliant", "frequency_ratio": 3}, "balls": [{"id": 0, "position": [1, 0.6]}]})");
  EXPECT_EQ(k.settings.cushion.frequency_ratio, 3.0);
  EXPECT_EQ(scenario_from_json(scenario_to_json(k)).settings.cushion.frequency_ratio, 3.0);
  // The exact solver's tolerance: read, written back, and left out at its default.
  const Scenario loose = scenario_from_json(
      R"({"cushion": {"exact_tolerance": 1e-7}, "balls": [{"id": 0, "position": [1, 0.6]}]})");
  EXPECT_EQ(loose.settings.cushion.exact_tolerance, 1e-7);
  EXPECT_EQ(scenario_from_json(scenario_to_json(loose)).settings.cushion.exact_tolerance, 1e-7);
  EXPECT_EQ(scenario_to_json(t).find("exact_tolerance"), std::string::npos);

  const auto error = [](const char* json) {
    return field_of([&] { (void)scenario_from_json(json); });
  };
  const std::string unknown = error(R"({"cushion": {"model": "stronge"}, "balls": [{"id": 0, "position": [1, 0.6]}]})");
  EXPECT_EQ(unknown.rfind("scenario.cushion.model: ", 0), 0u) << unknown;
  EXPECT_NE(unknown.find("mathavan_2010, han_2005, stronge_compliant"), std::string::npos) << unknown;
  const std::string solver = error(R"({"cushion": {"model": "han_2005", "solver": "paper"}, "balls": [{"id": 0, "position": [1, 0.6]}]})");
  EXPECT_EQ(solver.rfind("scenario.cushion.solver: ", 0), 0u) << solver;
  const std::string omega = error(R"({"cushion": {"frequency_ratio": 2}, "balls": [{"id": 0, "position": [1, 0.6]}]})");
  EXPECT_NE(omega.find("applies to the model \"stronge_compliant\" only"), std::string::npos) << omega;
  const std::string steps = error(R"({"cushion": {"solver": "paper", "paper_steps": 100001}, "balls": [{"id": 0, "position": [1, 0.6]}]})");
  EXPECT_EQ(steps.rfind("scenario.cushion.paper_steps", 0), 0u) << steps;
  EXPECT_NE(steps.find("100000"), std::string::npos) << steps;
  const std::string tolerance = error(R"({"cushion": {"exact_tolerance": 1e-6}, "balls": [{"id": 0, "position": [1, 0.6]}]})");
  EXPECT_EQ(tolerance.rfind("scenario.cushion.exact_tolerance: ", 0), 0u) << tolerance;
  EXPECT_NE(tolerance.find("1e-07"), std::string::npos) << tolerance;
  const std::string not_han =
      error(R"({"cushion": {"model": "han_2005", "exact_tolerance": 1e-7}, "balls": [{"id": 0, "position": [1, 0.6]}]})");
  EXPECT_NE(not_han.find("applies to the model \"mathavan_2010\" only"), std::string::npos) << not_han;
  const std::string mu = error(R"({"cushion": {"model": "han_2005", "friction": 2}, "balls": [{"id": 0, "position": [1, 0.6]}]})");
  EXPECT_EQ(mu.rfind("scenario.cushion.friction: ", 0), 0u) << mu;
  // Issue 24: each solver's key with the other solver was accepted and ignored.
  const std::string paper_tolerance =
      error(R"({"cushion": {"solver": "paper", "exact_tolerance": 1e-7}, "balls": [{"id": 0, "position": [1, 0.6]}]})");
  EXPECT_EQ(paper_tolerance, "scenario.cushion.exact_tolerance: scenario.cushion.exact_tolerance applies to the solver "
                             "\"exact\" only, not to \"paper\"");
  const std::string exact_steps = error(R"({"cushion": {"paper_steps": 100}, "balls": [{"id": 0, "position": [1, 0.6]}]})");
  EXPECT_EQ(exact_steps, "scenario.cushion.paper_steps: scenario.cushion.paper_steps applies to the solver \"paper\" "
                         "only, not to \"exact\"");
  // What the writer writes reads back: each solver's own key only.
  SimulationSettings paper;
  paper.cushion.solver = CushionSolver::paper;
  paper.cushion.exact_tolerance = 1e-7;  // not the paper solver's: left out
  Scenario with_paper = t;
  with_paper.settings = paper;
  const std::string written = scenario_to_json(with_paper);
  EXPECT_EQ(written.find("exact_tolerance"), std::string::npos) << written;
  EXPECT_EQ(scenario_from_json(written).settings.cushion.solver, CushionSolver::paper);
}

TEST(CushionModel, SimulatorReboundsByTheChosenModel) {
  // A ball rolling straight into the right cushion of the 9-ft table: its
  // state just after the cushion event is the model's rebound of its state
  // just before (the cushion frame: X = -y, Y = +x, Z up).
  const Table table = pool_table_9ft();
  const Parameters p = pool_parameters();
  const double R = p.ball.radius, v = 1.5;
  const std::vector<SimulationBall> balls{{0, "0", {{table.length - 0.3, table.width / 2}, {v, 0.0}, {0.0, v / R, 0.0}}}};
  for (const CushionModel model : kCushionModels) {
    SimulationSettings s;
    s.cushion = default_cushion_settings(model);
    const SimulationResult r = simulate(table, balls, s);
    const auto hit = std::find_if(r.events.begin(), r.events.end(), [](const Event& e) { return e.type == EventType::ball_cushion; });
    ASSERT_NE(hit, r.events.end());
    const BallState before = r.state_at(0, hit->time - 1e-12, p);
    const BallState after = r.state_at(0, hit->time, p);
    const IncomingBall in{{-before.velocity.y, before.velocity.x, 0.0},
                          {-before.angular_velocity.y, before.angular_velocity.x, before.angular_velocity.z}};
    const CushionRebound expected = cushion_rebound(in, cushion_contact(p, s.cushion, table.cushions[static_cast<std::size_t>(hit->other)].contact_height));
    SCOPED_TRACE(to_string(model));
    EXPECT_NEAR(after.velocity.x, expected.velocity.y, 1e-9);
    EXPECT_NEAR(after.velocity.y, -expected.velocity.x, 1e-9);
    EXPECT_NEAR(after.angular_velocity.x, expected.angular_velocity.y, 1e-6);
    EXPECT_LT(after.velocity.x, 0.0);
  }
}

TEST(CushionModel, ExactToleranceReachesTheSimulation) {
  // The benchmark's one-ball shot round the carom table (a corner double hit
  // while the ball still slides, solved by Runge-Kutta): at another
  // tolerance the shot has the same events and ends within a micrometre. A
  // tighter one, 1e-9: at the planners' 1e-7 its one sliding impact, whose
  // slips stay large, takes the very steps of the default (loosened 10x
  // there, to 1e-7; mathavan_2010_exact.cpp).
  const auto shot = [](const std::string& cushion) {
    return R"({"table": "carom_10ft", "balls": [{"id": 0, "position": [0.7, 0.4]}],
        "cue": {"ball": 0, "aim_deg": 27, "speed": 3.0, "side": 0.3, "height": 0.2})" + cushion + "}";
  };
  const std::string tight_json = shot(R"(, "cushion": {"exact_tolerance": 1e-9})");
  const std::string default_json = shot("");
  const SimulationResult tight = run_scenario(scenario_from_json(tight_json));
  const SimulationResult exact = run_scenario(scenario_from_json(default_json));
  ASSERT_EQ(tight.events.size(), exact.events.size());
  for (std::size_t i = 0; i < exact.events.size(); ++i) EXPECT_EQ(tight.events[i].type, exact.events[i].type) << i;
  const Vec2 a = tight.balls[0].final_state.position;
  const Vec2 b = exact.balls[0].final_state.position;
  EXPECT_NE(a.x, b.x);  // the setting reaches the solver
  EXPECT_LT(std::hypot(a.x - b.x, a.y - b.y), 1e-6);
}

}  // namespace
}  // namespace cueball
