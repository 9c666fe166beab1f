// The learner's observation (rl/environment.hpp): a fixed-size float array
// per discipline, its names, and its mirror image about the long string.
#include <algorithm>
#include <string>

#include "cueball/planning/shot_planner.hpp"
#include "cueball/rl/environment.hpp"

namespace cueball {

namespace {

// Offsets of the game fields after the balls (kEnvGameFields of them).
enum GameField : int {
  kPlayer = 0,
  kPhaseBreak,
  kPhasePlay,
  kPhaseDecision,
  kBallInHand,
  kRegionAnywhere,
  kRegionKitchen,
  kRegionD,
  kCueMustLeaveKitchen,
  kCallRequired,
  kNominateRequired,
  kPushOutAvailable,
  kFreeBall,
  kScore,
  kOpponentScore,
  kFouls,
  kOpponentFouls,
  kGroup,
  kDecisions,  // 7 flags
  kShots = kDecisions + 7,
  kNoise,      // 5: speed, aim, elevation, side, height
  kFieldsEnd = kNoise + 5,
};
static_assert(kFieldsEnd == kEnvGameFields, "kEnvGameFields must count the game fields");

constexpr const char* kFieldNames[kEnvGameFields] = {
    "player",        "phase.break",    "phase.play",       "phase.decision",     "ball_in_hand",
    "region.anywhere", "region.kitchen", "region.d",       "cue_must_leave_kitchen", "call_required",
    "nominate_required", "push_out_available", "free_ball", "score",           "opponent_score",
    "fouls",         "opponent_fouls", "group",            "decision.play",      "decision.pass",
    "decision.rerack_and_break", "decision.rerack_opponent_breaks", "decision.respot_eight", "decision.rerack",
    "decision.restore", "shots",        "noise.speed",      "noise.aim",          "noise.elevation",
    "noise.side",    "noise.height"};

constexpr const char* kBallFeatureNames[kEnvBallFeatures] = {"x", "y", "present", "on", "value"};

std::size_t at(int i) { return static_cast<std::size_t>(i); }

// The value feature of ball `id` for the player to act.
double ball_value(const GameState& state, int player, int id) {
  switch (state.config.kind) {
    case GameKind::nine_ball:
    case GameKind::ten_ball: return id / 15.0;
    case GameKind::eight_ball: return id >= 1 && id <= 7 ? 1.0 : id >= 9 ? -1.0 : 0.0;
    case GameKind::snooker: return id >= 16 ? (id - 14) / 7.0 : id >= 1 ? 1.0 / 7.0 : 0.0;
    case GameKind::three_cushion: {
      return id == player ? 1.0 : id == 2 ? 0.0 : -1.0;
    }
  }
  return 0.0;
}

double score_scale(const GameState& state) {
  switch (state.config.kind) {
    case GameKind::snooker: return 147.0;
    case GameKind::three_cushion: return std::max(1, state.config.race_to);
    default: return 1.0;
  }
}

double group_value(Group g) { return g == Group::solids ? 1.0 : g == Group::stripes ? -1.0 : 0.0; }

double noise_ratio(double sigma, double reference) { return reference > 0.0 ? sigma / reference : 0.0; }

}  // namespace

int env_ball_count(GameKind game) {
  switch (game) {
    case GameKind::nine_ball: return 10;
    case GameKind::ten_ball: return 11;
    case GameKind::eight_ball: return 16;
    case GameKind::snooker: return 22;
    case GameKind::three_cushion: return 3;
  }
  return 0;
}

int env_observation_size(GameKind game) { return env_ball_count(game) * kEnvBallFeatures + kEnvGameFields; }

std::vector<std::string> env_observation_names(GameKind game) {
  std::vector<std::string> names;
  for (int id = 0; id < env_ball_count(game); ++id)
    for (const char* f : kBallFeatureNames) names.push_back("ball" + std::to_string(id) + "." + f);
  for (const char* f : kFieldNames) names.emplace_back(f);
  return names;
}

void write_observation(const GameState& state, int player, const CueStrikeNoise& noise, float* out) {
  const int balls = env_ball_count(state.config.kind);
  std::fill(out, out + env_observation_size(state.config.kind), 0.0f);
  const Table& t = state.table.table;
  const LegalActions legal = legal_actions(state);
  for (const SimulationBall& b : state.table.balls) {
    if (b.id < 0 || b.id >= balls) continue;
    float* f = out + b.id * kEnvBallFeatures;
    f[0] = static_cast<float>(2.0 * b.state.position.x / t.length - 1.0);
    f[1] = static_cast<float>(2.0 * b.state.position.y / t.width - 1.0);
    f[2] = 1.0f;
  }
  for (const int id : legal.on)
    if (id >= 0 && id < balls) out[id * kEnvBallFeatures + 3] = 1.0f;
  const int me = player == 1 ? 1 : 0;
  for (int id = 0; id < balls; ++id) out[id * kEnvBallFeatures + 4] = static_cast<float>(ball_value(state, me, id));

  float* g = out + balls * kEnvBallFeatures;
  const int them = 1 - me;
  g[kPlayer] = static_cast<float>(me);
  g[kPhaseBreak] = state.phase == GamePhase::break_shot ? 1.0f : 0.0f;
  g[kPhasePlay] = state.phase == GamePhase::play ? 1.0f : 0.0f;
  g[kPhaseDecision] = state.phase == GamePhase::decision ? 1.0f : 0.0f;
  if (legal.ball_in_hand) {
    g[kBallInHand] = 1.0f;
    const PlacementRegion::Kind k = legal.ball_in_hand->kind;
    g[k == PlacementRegion::Kind::behind_head_string ? kRegionKitchen
      : k == PlacementRegion::Kind::inside_d         ? kRegionD
                                                     : kRegionAnywhere] = 1.0f;
  }
  g[kCueMustLeaveKitchen] = legal.cue_must_leave_kitchen ? 1.0f : 0.0f;
  g[kCallRequired] = legal.call_required ? 1.0f : 0.0f;
  g[kNominateRequired] = legal.nominate_required ? 1.0f : 0.0f;
  g[kPushOutAvailable] = legal.push_out ? 1.0f : 0.0f;
  g[kFreeBall] = legal.free_ball ? 1.0f : 0.0f;
  if (state.config.kind == GameKind::snooker || state.config.kind == GameKind::three_cushion) {
    g[kScore] = static_cast<float>(state.scores[at(me)] / score_scale(state));
    g[kOpponentScore] = static_cast<float>(state.scores[at(them)] / score_scale(state));
  }
  g[kFouls] = static_cast<float>(state.fouls_in_a_row[at(me)] / 3.0);
  g[kOpponentFouls] = static_cast<float>(state.fouls_in_a_row[at(them)] / 3.0);
  g[kGroup] = static_cast<float>(group_value(state.groups[at(me)]));
  for (const Decision d : legal.decisions) g[kDecisions + static_cast<int>(d)] = 1.0f;
  g[kShots] = static_cast<float>(state.shots / static_cast<double>(std::max(1, state.config.max_shots)));
  const CueStrikeNoise ref = tournament_noise();
  g[kNoise + 0] = static_cast<float>(noise_ratio(noise.speed, ref.speed));
  g[kNoise + 1] = static_cast<float>(noise_ratio(noise.aim, ref.aim));
  g[kNoise + 2] = static_cast<float>(noise_ratio(noise.elevation, ref.elevation));
  g[kNoise + 3] = static_cast<float>(noise_ratio(noise.side_offset, ref.side_offset));
  g[kNoise + 4] = static_cast<float>(noise_ratio(noise.height_offset, ref.height_offset));
}

void mirror_observation(GameKind game, float* observation) {
  for (int id = 0; id < env_ball_count(game); ++id) {
    float& y = observation[id * kEnvBallFeatures + 1];
    if (observation[id * kEnvBallFeatures + 2] != 0.0f) y = -y;
  }
}

}  // namespace cueball
