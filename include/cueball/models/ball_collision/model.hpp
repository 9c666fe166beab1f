// The ball-ball collision models by name: chosen once at the API boundary
// (SimulationSettings::ball_collision_model, a scenario's "ball_collision":
// {"model": ...}), validated and built once per simulation
// (ball_collision_contact()), dispatched with a switch in the simulator's hot
// path (collide()).
//
//   coulomb_impulse  ball_collision.hpp (src/models/ball_collision/coulomb_impulse.cpp):
//                    Newton restitution and Coulomb friction integrated over
//                    the normal impulse at the ball-ball contact (B1-B8), with
//                    Alciatore's speed-dependent friction; the cloth takes no
//                    part during the impact. The default.
//   mathavan_2014    ball_collision/mathavan_2014.hpp: the same contact with
//                    the cloth's friction acting at both balls' table contacts
//                    during the impact (M1-M11), solved exactly; constant
//                    ball-ball friction, energetic restitution.
// Why coulomb_impulse is the default: against Mathavan et al.'s own Tables 1
// and 2 (five cut shots of a rolling cue ball) it is within 1.2 % (the cue
// ball's deflection 29.12 deg against 29.47 at the 18 deg cut), mathavan_2014
// within 0.2 %; but mathavan_2014 costs some 11 times as much per collision
// (bench_ball_collision, bench_simulator's break under each model), and its
// constant ball-ball friction cannot follow the measured fall of friction
// with slip speed (Alciatore's fit to Marlow's data, TP A.14), which moves
// the throw of a cut shot by more than 1 %: coulomb_impulse has both.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "cueball/models/ball_collision/coulomb_impulse.hpp"
#include "cueball/models/ball_collision/mathavan_2014.hpp"
#include "cueball/core/parameters.hpp"

namespace cueball {

enum class BallCollisionModel { coulomb_impulse, mathavan_2014 };

/// Every model, in the order of the names.
inline constexpr std::array kBallCollisionModels{BallCollisionModel::coulomb_impulse, BallCollisionModel::mathavan_2014};

/// "coulomb_impulse", "mathavan_2014".
const char* to_string(BallCollisionModel model);

/// The model of that name, if there is one (the caller names its field in the error).
std::optional<BallCollisionModel> ball_collision_model_from_string(std::string_view name);

/// The names, comma-separated, each between `quote`s.
std::string ball_collision_model_names(std::string_view quote = "\"");

/// Each model's own constants: coulomb_impulse Alciatore's (e = 0.95 and his
/// friction fit, ball_collision_alciatore()); mathavan_2014 the paper's
/// e_b = 0.89 and a constant mu_b = 0.05 (friction_excess 0).
BallCollisionParameters default_ball_collision(BallCollisionModel model);

/// The chosen model's constants, validated: what the simulator keeps.
struct BallCollisionContact {
  BallCollisionModel model = BallCollisionModel::coulomb_impulse;
  BallCollisionParameters coulomb;
  Mathavan2014Contact mathavan;
};

/// Validates `contact` (validate(BallCollisionParameters)) and, for
/// mathavan_2014, that its friction is constant (friction_excess = 0 and
/// friction_decay = 0, InvalidArgument "friction_excess" or
/// "friction_decay") and within the model's range
/// ("friction"), with the cloth's mu_s as the friction at the table
/// contacts ("mu_s" when above the model's 0.5).
BallCollisionContact ball_collision_contact(const Parameters& table, BallCollisionModel model,
                                            const BallCollisionParameters& contact);

/// The states of a and b just after their collision by the contact's model
/// (resolve_ball_collision's conventions: touching, approaching; otherwise
/// unchanged).
std::pair<BallState, BallState> collide(const BallState& a, const BallState& b, const BallParameters& ball,
                                        const BallCollisionContact& contact) noexcept;

}  // namespace cueball
