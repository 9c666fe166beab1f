// ShotFacts (src/simulation/shot_facts.cpp): each fact built from a crafted
// shot whose answer follows from its geometry, and every fact of a 9-ball
// break checked against the simulator's own events and trajectories.
#include "cueball/io/scenario_json.hpp"
#include "cueball/io/result_json.hpp"
#include "cueball/simulation/shot_facts.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "cueball/simulation/batch.hpp"
#include "cueball/simulation/scenario.hpp"
#include "cueball/table/rack.hpp"

namespace cueball {
namespace {

constexpr double R = 0.028575;  // pool ball radius, m

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// Balls on "pool_9ft" and a cue strike of ball 0 (JSON "cue" members).
Scenario shot(const std::vector<std::pair<int, Vec2>>& balls, const std::string& cue) {
  std::string json = R"({"table": "pool_9ft", "balls": [)";
  for (std::size_t i = 0; i < balls.size(); ++i)
    json += (i ? ", " : "") + std::string(R"({"id": )") + std::to_string(balls[i].first) + R"(, "position": [)" +
            num(balls[i].second.x) + ", " + num(balls[i].second.y) + "]}";
  return scenario_from_json(json + R"(], "cue": {"ball": 0, )" + cue + "}}");
}

ShotFacts facts_of(const Scenario& s, SimulationResult& r) {
  r = run_scenario(s);
  return shot_facts(s.table, s.settings.parameters, r, s.cue->ball);
}

TEST(ShotFacts, DirectPotNamesTheFirstContactAndThePotWithItsPocketAndTime) {
  const Scenario s = shot({{0, {1.94, 0.67}}, {1, {2.24, 0.97}}}, R"("target": 1, "speed": 1.5, "height": -0.2)");
  SimulationResult r;
  const ShotFacts f = facts_of(s, r);
  EXPECT_EQ(f.cue_ball, 0);
  EXPECT_EQ(f.first_contact, 1);
  EXPECT_EQ(f.first_contact_simultaneous, -1);
  ASSERT_FALSE(f.contacts.empty());
  EXPECT_EQ(f.contacts.front().ball + f.contacts.front().other, 1);  // 0 and 1
  EXPECT_DOUBLE_EQ(f.contacts.front().time, f.first_contact_time);
  ASSERT_EQ(f.pots.size(), 1u);
  EXPECT_EQ(f.pots[0].ball, 1);
  ASSERT_TRUE(r.balls[1].pocketed);
  EXPECT_EQ(f.pots[0].pocket, r.balls[1].pocket);
  EXPECT_EQ(s.table.pockets[static_cast<std::size_t>(f.pots[0].pocket)].name, "top-right");
  EXPECT_DOUBLE_EQ(f.pots[0].time, r.balls[1].pocket_time);
  EXPECT_GT(f.pots[0].time, f.first_contact_time);
  EXPECT_TRUE(f.pocketed(1));
  EXPECT_FALSE(f.pocketed(0));
  EXPECT_EQ(f.pocket_of(0), -1);
  EXPECT_EQ(f.balls_touched_by_cue(), std::vector<int>{1});
  ASSERT_EQ(f.cue_cushions_before_contact.size(), 1u);
  EXPECT_EQ(f.cue_cushions_before_contact[0].cushions, 0);
}

TEST(ShotFacts, KickCountsTheCueBallsCushionBeforeItsContact) {
  // Straight down onto the bottom rail; the rebound comes straight back up
  // into ball 1, above the cue ball's start.
  const Scenario s = shot({{0, {1.0, 0.3}}, {1, {1.0, 0.9}}}, R"("aim_deg": -90, "speed": 2.0)");
  SimulationResult r;
  const ShotFacts f = facts_of(s, r);
  ASSERT_FALSE(f.cushions.empty());
  EXPECT_EQ(f.cushions[0].ball, 0);
  EXPECT_FALSE(f.cushions[0].after_first_contact);
  EXPECT_EQ(s.table.cushions[static_cast<std::size_t>(f.cushions[0].cushion)].name, "bottom rail, left of the side pocket");
  EXPECT_EQ(f.first_contact, 1);
  EXPECT_LT(f.cushions[0].time, f.first_contact_time);
  ASSERT_FALSE(f.cue_cushions_before_contact.empty());
  EXPECT_EQ(f.cue_cushions_before_contact[0].ball, 1);
  EXPECT_EQ(f.cue_cushions_before_contact[0].cushions, 1);
  EXPECT_EQ(f.cushion_count(0) - f.cushion_count_after_first_contact(0), 1);
  for (const CushionHit& c : f.cushions) EXPECT_EQ(c.after_first_contact, c.time > f.first_contact_time);
}

TEST(ShotFacts, NoContactLeavesFirstContactEmpty) {
  const Scenario s = shot({{0, {1.0, 0.3}}, {1, {2.0, 0.9}}}, R"("aim_deg": 0, "speed": 0.5)");
  SimulationResult r;
  const ShotFacts f = facts_of(s, r);
  EXPECT_EQ(f.first_contact, -1);
  EXPECT_TRUE(std::isnan(f.first_contact_time));
  EXPECT_TRUE(f.contacts.empty());
  EXPECT_TRUE(f.cue_cushions_before_contact.empty());
  for (const CushionHit& c : f.cushions) EXPECT_FALSE(c.after_first_contact);
}

TEST(ShotFacts, TwoBallsMetAtOneInstantAreFlaggedSimultaneous) {
  // Two touching balls straddling the cue ball's line: it meets both at once.
  const double y = 0.635;
  const Scenario s = shot({{0, {1.0, y}}, {1, {2.0, y + R}}, {2, {2.0, y - R}}}, R"("aim_deg": 0, "speed": 2.0)");
  SimulationResult r;
  const ShotFacts f = facts_of(s, r);
  ASSERT_NE(f.first_contact, -1);
  EXPECT_TRUE((f.first_contact == 1 && f.first_contact_simultaneous == 2) ||
              (f.first_contact == 2 && f.first_contact_simultaneous == 1))
      << f.first_contact << " " << f.first_contact_simultaneous;
  // ...and the pair touching at the start is frozen.
  ASSERT_EQ(f.frozen_balls.size(), 1u);
  EXPECT_EQ(f.frozen_balls[0].ball, 1);
  EXPECT_EQ(f.frozen_balls[0].other, 2);
}

TEST(ShotFacts, ContactsAMillisecondApartAreNotSimultaneous) {
  const double y = 0.635;
  const Scenario s = shot({{0, {1.0, y}}, {1, {2.0, y + R}}, {2, {2.003, y - R - 1e-3}}}, R"("aim_deg": 0, "speed": 2.0)");
  SimulationResult r;
  const ShotFacts f = facts_of(s, r);
  EXPECT_EQ(f.first_contact, 1);
  EXPECT_EQ(f.first_contact_simultaneous, -1);
  EXPECT_TRUE(f.frozen_balls.empty());
}

// A draw shot that crosses the head string and comes back within its one
// sliding segment: the crossings must come from the path, not from the
// segments' end points (which lie on the same side).
TEST(ShotFacts, HeadStringCrossingsFollowThePathWithinASegment) {
  const Table table = preset_table("pool_9ft");
  const Parameters p = pool_parameters();
  const double line = head_string_x(table);
  SimulationBall cue{0, "cue", {}};
  cue.state.position = {line - 0.01, 0.635};
  cue.state.velocity = {0.3, 0.0};
  cue.state.angular_velocity = {0.0, -6.0 * 0.3 / p.ball.radius, 0.0};  // heavy backspin
  SimulationSettings settings;
  settings.parameters = p;
  const SimulationResult r = simulate(table, {cue}, settings);
  const ShotFacts f = shot_facts(table, p, r, 0);
  ASSERT_GE(r.balls[0].segments.size(), 2u);
  const double slide_end = r.balls[0].segments[1].start_time;
  ASSERT_EQ(f.head_string_crossings.size(), 2u);
  EXPECT_FALSE(f.head_string_crossings[0].toward_head);
  EXPECT_TRUE(f.head_string_crossings[1].toward_head);
  for (const HeadStringCrossing& c : f.head_string_crossings) {
    EXPECT_EQ(c.ball, 0);
    EXPECT_LT(c.time, slide_end);
    EXPECT_NEAR(r.state_at(0, c.time, p).position.x, line, 1e-12);
  }
  EXPECT_LT(f.head_string_crossings[0].time, f.head_string_crossings[1].time);
  // The segment's ends are both on the head side.
  EXPECT_LT(r.balls[0].segments[1].state.position.x, line);
}

TEST(ShotFacts, CrossingsAlternateAndLieOnTheString) {
  const Scenario s = shot({{0, {0.4, 0.5}}}, R"("aim_deg": 10, "speed": 3.0)");
  SimulationResult r;
  const ShotFacts f = facts_of(s, r);
  const double line = head_string_x(s.table);
  ASSERT_GE(f.head_string_crossings.size(), 2u);
  EXPECT_FALSE(f.head_string_crossings[0].toward_head);
  for (std::size_t k = 0; k < f.head_string_crossings.size(); ++k) {
    const HeadStringCrossing& c = f.head_string_crossings[k];
    EXPECT_EQ(c.toward_head, k % 2 == 1);
    EXPECT_NEAR(r.state_at(0, c.time, s.settings.parameters).position.x, line, 1e-9);
  }
}

TEST(ShotFacts, FrozenToACushionAtTheStart) {
  const Table table = preset_table("pool_9ft");
  const Parameters p = pool_parameters();
  const double d = cushion_contact_distance(table.cushions[0].contact_height, p.ball.radius);
  SimulationBall a{3, "3", {}}, b{4, "4", {}};
  a.state.position = {1.0, d};          // touching the bottom rail
  b.state.position = {1.8, d + 1e-4};   // 0.1 mm off it
  SimulationSettings settings;
  settings.parameters = p;
  const SimulationResult r = simulate(table, {a, b}, settings);
  const ShotFacts f = shot_facts(table, p, r, 3);
  ASSERT_EQ(f.frozen_to_cushion.size(), 1u);
  EXPECT_EQ(f.frozen_to_cushion[0].ball, 3);
  EXPECT_EQ(cushion_name(table, static_cast<std::size_t>(f.frozen_to_cushion[0].cushion)),
            "bottom rail, left of the side pocket");
  EXPECT_TRUE(f.frozen_balls.empty());
}

// A ball sent along the top rail into the corner pocket's jaws: the jaw
// contacts are facts of their own, not cushions (WPA 6.3 counts rails).
TEST(ShotFacts, JawContactsAreNamedAndAreNotCushions) {
  const Table table = preset_table("pool_9ft");
  const Parameters p = pool_parameters();
  SimulationBall ball{0, "cue", {}};
  ball.state.position = {2.0, 1.20};
  ball.state.velocity = {1.0, 0.0};
  SimulationSettings settings;
  settings.parameters = p;
  const SimulationResult r = simulate(table, {ball}, settings);
  const ShotFacts f = shot_facts(table, p, r, 0);
  ASSERT_GE(f.jaws.size(), 2u);
  EXPECT_EQ(jaw_name(table, static_cast<std::size_t>(f.jaws[0].jaw)), "top-right pocket, right jaw");
  EXPECT_EQ(jaw_name(table, static_cast<std::size_t>(f.jaws[1].jaw)), "top-right pocket, top jaw");
  EXPECT_LT(f.jaws[0].time, f.jaws[1].time);
  for (const JawHit& j : f.jaws) EXPECT_EQ(j.ball, 0);
  ASSERT_FALSE(f.cushions.empty());
  EXPECT_GT(f.cushions[0].time, f.jaws[1].time);  // the right rail after the jaws
  EXPECT_EQ(f.cushion_count(0), static_cast<int>(f.cushions.size()));
  EXPECT_TRUE(f.pots.empty());
}

// Every fact of the 9-ball break, against the events and trajectories.
TEST(ShotFacts, BreakFactsAgreeWithEventsTrajectoriesAndShotOutcome) {
  const Scenario s = default_scenario();
  SimulationResult r;
  const ShotFacts f = facts_of(s, r);
  std::size_t ball_ball = 0, cushion = 0, jaw = 0, pocket = 0;
  for (const Event& e : r.events) {
    ball_ball += e.type == EventType::ball_ball;
    cushion += e.type == EventType::ball_cushion;
    jaw += e.type == EventType::ball_jaw;
    pocket += e.type == EventType::ball_pocket;
  }
  EXPECT_EQ(f.contacts.size(), ball_ball);
  EXPECT_EQ(f.cushions.size(), cushion);
  EXPECT_EQ(f.jaws.size(), jaw);
  EXPECT_EQ(f.pots.size(), pocket);
  EXPECT_EQ(f.first_contact, 1);  // aimed at the 1
  for (const BallTrajectory& b : r.balls) {
    EXPECT_EQ(f.pocketed(b.id), b.pocketed) << b.id;
    if (b.pocketed) {
      EXPECT_EQ(f.pocket_of(b.id), b.pocket);
    }
  }
  for (std::size_t k = 1; k < f.pots.size(); ++k) EXPECT_LE(f.pots[k - 1].time, f.pots[k].time);
  for (std::size_t k = 1; k < f.cue_cushions_before_contact.size(); ++k)
    EXPECT_LE(f.cue_cushions_before_contact[k - 1].cushions, f.cue_cushions_before_contact[k].cushions);
  // The rack is frozen: every ball touches at least one other.
  EXPECT_GE(f.frozen_balls.size(), 8u);
  // ShotOutcome reads the same facts.
  ShotOutcome o;
  outcome_from_result(r, 0, o);
  EXPECT_EQ(o.first_contact, f.first_contact);
  for (std::size_t i = 0; i < r.balls.size(); ++i) {
    EXPECT_EQ(o.cushions[i], f.cushion_count(r.balls[i].id));
    EXPECT_EQ(o.cushions[i] - o.cushions_before_contact[i], f.cushion_count_after_first_contact(r.balls[i].id));
  }
  const std::vector<int> railed = f.balls_to_cushion_after_first_contact();
  EXPECT_FALSE(railed.empty());
  for (int id : railed) EXPECT_GT(f.cushion_count_after_first_contact(id), 0);
}

// A batch worker's reused record: after another shot's facts, the same as fresh.
TEST(ShotFacts, IntoAReusedRecordGivesTheFreshFacts) {
  const Scenario brk = default_scenario();
  const SimulationResult a = run_scenario(brk);
  const Scenario kick = shot({{0, {1.0, 0.3}}, {1, {1.0, 0.9}}}, R"("aim_deg": -90, "speed": 2.0)");
  const SimulationResult b = run_scenario(kick);
  ShotFacts reused;
  shot_facts_into(a, 0, reused);
  ASSERT_FALSE(reused.contacts.empty());
  shot_facts_into(b, 0, reused);
  const ShotFacts fresh = shot_facts(b, 0);
  EXPECT_EQ(reused.first_contact, fresh.first_contact);
  EXPECT_EQ(reused.first_contact_time, fresh.first_contact_time);
  EXPECT_EQ(reused.first_contact_simultaneous, fresh.first_contact_simultaneous);
  EXPECT_EQ(reused.contacts.size(), fresh.contacts.size());
  EXPECT_EQ(reused.cushions.size(), fresh.cushions.size());
  EXPECT_EQ(reused.pots.size(), fresh.pots.size());
  EXPECT_EQ(reused.jaws.size(), fresh.jaws.size());
  EXPECT_EQ(reused.cue_cushions_before_contact.size(), fresh.cue_cushions_before_contact.size());
  // A shot without a contact after one with: first_contact is reset.
  const SimulationResult none = run_scenario(shot({{0, {1.0, 0.3}}, {1, {2.0, 0.9}}}, R"("aim_deg": 0, "speed": 0.5)"));
  shot_facts_into(none, 0, reused);
  EXPECT_EQ(reused.first_contact, -1);
  EXPECT_TRUE(std::isnan(reused.first_contact_time));
  EXPECT_TRUE(reused.contacts.empty());
}

TEST(ShotFacts, ResultJsonCarriesTheFacts) {
  const Scenario s = default_scenario();
  const SimulationResult r = run_scenario(s);
  const nlohmann::json j = nlohmann::json::parse(result_to_json(s, r));
  ASSERT_TRUE(j.contains("facts"));
  const nlohmann::json& f = j["facts"];
  for (const char* key : {"first_contact", "contacts", "pots", "cushions", "cue_cushions_before_contact", "jaws",
                          "head_string_crossings", "frozen_at_start"})
    EXPECT_TRUE(f.contains(key)) << key;
  EXPECT_EQ(f["first_contact"]["ball"], 1);
  const ShotFacts facts = shot_facts(s.table, s.settings.parameters, r, 0);
  ASSERT_EQ(f["pots"].size(), facts.pots.size());
  for (std::size_t k = 0; k < facts.pots.size(); ++k)
    EXPECT_EQ(f["pots"][k]["pocket"], s.table.pockets[static_cast<std::size_t>(facts.pots[k].pocket)].name);
  ASSERT_EQ(f["cushions"].size(), facts.cushions.size());
  ASSERT_FALSE(facts.cushions.empty());
  EXPECT_EQ(f["cushions"][0]["cushion_name"], cushion_name(s.table, static_cast<std::size_t>(facts.cushions[0].cushion)));
  EXPECT_EQ(f["frozen_at_start"]["balls"].size(), facts.frozen_balls.size());
}

}  // namespace
}  // namespace cueball
