// The ball-ball collision models by name (include/cueball/models/ball_collision/model.hpp).

#include "cueball/models/ball_collision/model.hpp"

#include "cueball/core/errors.hpp"
#include "core/enum_names.hpp"

namespace cueball {

const char* to_string(BallCollisionModel model) {
  switch (model) {
    case BallCollisionModel::coulomb_impulse: return "coulomb_impulse";
    case BallCollisionModel::mathavan_2014: return "mathavan_2014";
  }
  return "?";
}

std::optional<BallCollisionModel> ball_collision_model_from_string(std::string_view name) {
  return value_named(kBallCollisionModels, name);
}

std::string ball_collision_model_names(std::string_view quote) {
  return names_of(kBallCollisionModels, quote);
}

BallCollisionParameters default_ball_collision(BallCollisionModel model) {
  if (model == BallCollisionModel::coulomb_impulse) return ball_collision_alciatore();
  const Mathavan2014Contact paper = mathavan_2014_contact();
  return {paper.restitution, paper.ball_friction, 0.0, 0.0};
}

BallCollisionContact ball_collision_contact(const Parameters& table, BallCollisionModel model,
                                            const BallCollisionParameters& contact) {
  validate(contact);
  BallCollisionContact c;
  c.model = model;
  c.coulomb = contact;
  if (model == BallCollisionModel::mathavan_2014) {
    if (contact.friction_excess != 0.0)
      throw InvalidArgument("friction_excess", contact.friction_excess, "0 (mathavan_2014's friction is constant)");
    if (contact.friction_decay != 0.0)
      throw InvalidArgument("friction_decay", contact.friction_decay,
                            "0 (mathavan_2014's friction is constant; the decay is coulomb_impulse's)");
    c.mathavan = {contact.restitution, contact.friction, table.cloth.sliding_friction};
    require_in_range("friction", c.mathavan.ball_friction, kMathavan2014BallFrictionRange.min,
                     kMathavan2014BallFrictionRange.max, "mathavan_2014's ball-ball friction");
    if (!(c.mathavan.cloth_friction <= kMathavan2014ClothFrictionRange.max))
      throw InvalidArgument("mu_s", c.mathavan.cloth_friction, "[0, 0.5] with the ball-ball model mathavan_2014",
                            "ball-cloth sliding friction");
  }
  return c;
}

std::pair<BallState, BallState> collide(const BallState& a, const BallState& b, const BallParameters& ball,
                                        const BallCollisionContact& contact) noexcept {
  if (contact.model == BallCollisionModel::mathavan_2014) {
    const BallCollisionResult r = mathavan_2014_collision(a, b, ball, contact.mathavan);
    return {r.a, r.b};
  }
  return collide_balls(a, b, ball, contact.coulomb);
}

}  // namespace cueball
