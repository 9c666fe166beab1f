// src/rl/observation.cpp: the observation's layout, its values and its mirror.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cueball/planning/shot_planner.hpp"
#include "cueball/rl/environment.hpp"
#include "game_actions.hpp"

namespace cueball {
namespace {

std::vector<float> observe(const GameState& s, int player, const CueStrikeNoise& noise = {}) {
  std::vector<float> v(static_cast<std::size_t>(env_observation_size(s.config.kind)), -7.0f);
  write_observation(s, player, noise, v.data());
  return v;
}

float field(const std::vector<float>& v, GameKind kind, const std::string& name) {
  const std::vector<std::string> names = env_observation_names(kind);
  const auto at = std::find(names.begin(), names.end(), name);
  EXPECT_NE(at, names.end()) << name;
  return v[static_cast<std::size_t>(at - names.begin())];
}

TEST(Observation, EveryDisciplineHasAFixedSizeAndANameForEveryEntry) {
  for (const GameKind kind : kGameKinds) {
    const int size = env_observation_size(kind);
    EXPECT_EQ(size, env_ball_count(kind) * kEnvBallFeatures + kEnvGameFields);
    const std::vector<std::string> names = env_observation_names(kind);
    ASSERT_EQ(static_cast<int>(names.size()), size);
    EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size());
    const GameState s = new_game(default_config(kind), 3);
    for (const float x : observe(s, 0)) EXPECT_TRUE(std::isfinite(x));
    for (const SimulationBall& b : s.table.balls) EXPECT_LT(b.id, env_ball_count(kind));
  }
  EXPECT_EQ(env_ball_count(GameKind::snooker), 22);
}

TEST(Observation, BallsAreNormalisedAndFlagged) {
  GameState s = test::rotation_in_play(GameKind::nine_ball, {{0, {0.635, 0.3175}}, {1, {1.905, 0.9525}}, {9, {2.2, 0.3}}});
  const std::vector<float> v = observe(s, 0);
  const GameKind k = GameKind::nine_ball;
  EXPECT_FLOAT_EQ(field(v, k, "ball0.x"), -0.5f);
  EXPECT_FLOAT_EQ(field(v, k, "ball0.y"), -0.5f);
  EXPECT_FLOAT_EQ(field(v, k, "ball1.x"), 0.5f);
  EXPECT_FLOAT_EQ(field(v, k, "ball1.y"), 0.5f);
  EXPECT_EQ(field(v, k, "ball1.present"), 1.0f);
  EXPECT_EQ(field(v, k, "ball1.on"), 1.0f);
  EXPECT_EQ(field(v, k, "ball9.on"), 0.0f);
  EXPECT_EQ(field(v, k, "ball4.present"), 0.0f);
  EXPECT_EQ(field(v, k, "ball4.x"), 0.0f);
  EXPECT_FLOAT_EQ(field(v, k, "ball9.value"), 9.0f / 15.0f);
  EXPECT_EQ(field(v, k, "phase.play"), 1.0f);
  EXPECT_EQ(field(v, k, "ball_in_hand"), 0.0f);
  s.ball_in_hand = PlacementRegion{PlacementRegion::Kind::behind_head_string};
  EXPECT_EQ(field(observe(s, 0), k, "region.kitchen"), 1.0f);
}

// The point of view: scores and fouls are the viewer's first; three-cushion's
// cue balls are +1 (own) and -1 (the opponent's).
TEST(Observation, IsFromTheViewersPointOfView) {
  GameState s = new_game(default_config(GameKind::three_cushion));
  s.scores = {4, 7};
  s.fouls_in_a_row = {0, 0};
  const GameKind k = GameKind::three_cushion;
  const std::vector<float> p0 = observe(s, 0);
  const std::vector<float> p1 = observe(s, 1);
  EXPECT_FLOAT_EQ(field(p0, k, "score"), 4.0f / 15.0f);
  EXPECT_FLOAT_EQ(field(p1, k, "score"), 7.0f / 15.0f);
  EXPECT_FLOAT_EQ(field(p1, k, "opponent_score"), 4.0f / 15.0f);
  EXPECT_EQ(field(p0, k, "ball0.value"), 1.0f);
  EXPECT_EQ(field(p0, k, "ball1.value"), -1.0f);
  EXPECT_EQ(field(p1, k, "ball1.value"), 1.0f);
  EXPECT_EQ(field(p1, k, "ball2.value"), 0.0f);
  EXPECT_EQ(field(p1, k, "player"), 1.0f);
}

TEST(Observation, SnookerValuesAndTheNoiseOverTournamentNoise) {
  const GameState s = new_game(default_config(GameKind::snooker));
  const GameKind k = GameKind::snooker;
  CueStrikeNoise half = tournament_noise();
  half.aim *= 0.5;
  const std::vector<float> v = observe(s, 0, half);
  EXPECT_FLOAT_EQ(field(v, k, "ball1.value"), 1.0f / 7.0f);
  EXPECT_FLOAT_EQ(field(v, k, "ball21.value"), 1.0f);  // the black
  EXPECT_FLOAT_EQ(field(v, k, "ball16.value"), 2.0f / 7.0f);  // the yellow
  EXPECT_FLOAT_EQ(field(v, k, "noise.aim"), 0.5f);
  EXPECT_FLOAT_EQ(field(v, k, "noise.speed"), 1.0f);
  EXPECT_EQ(field(v, k, "region.d"), 1.0f);
}

// The mirror negates y of the balls on the table and nothing else; twice is
// the identity.
TEST(Observation, TheMirrorNegatesYOfTheBallsOnTheTable) {
  const GameState s = new_game(default_config(GameKind::eight_ball), 4);
  std::vector<float> v = observe(s, 0);
  const std::vector<float> original = v;
  mirror_observation(GameKind::eight_ball, v.data());
  for (std::size_t i = 0; i < v.size(); ++i) {
    const bool is_y = i < 16 * kEnvBallFeatures && i % kEnvBallFeatures == 1;
    EXPECT_EQ(v[i], is_y ? -original[i] : original[i]) << i;
  }
  mirror_observation(GameKind::eight_ball, v.data());
  EXPECT_EQ(v, original);
}

}  // namespace
}  // namespace cueball
