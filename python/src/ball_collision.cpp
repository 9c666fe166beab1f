// include/cueball/models/ball_collision/coulomb_impulse.hpp: the collision of two balls.
#include "bindings.hpp"

#include <optional>
#include <string>
#include <utility>

#include "cueball/models/ball_collision/coulomb_impulse.hpp"
#include "cueball/models/ball_collision/mathavan_2014.hpp"
#include "cueball/core/errors.hpp"

namespace cueball_python {

namespace {

using cueball::BallCollisionParameters;
using cueball::BallState;

// The kernels trust their input: the ball, the contact and both states.
void check_collision(const BallState& a, const BallState& b, const cueball::Parameters& p,
                     const BallCollisionParameters& contact) {
  cueball::validate(p);
  cueball::validate(contact);
  for (const auto& [name, state] : {std::pair{"a", &a}, std::pair{"b", &b}}) {
    try {
      cueball::validate(*state);
    } catch (const cueball::InvalidArgument& e) {
      throw cueball::InvalidArgument(std::string(name) + "." + e.field(), std::string(name) + ": " + e.what());
    }
  }
}

py::arg_v contact_arg() {
  return py::arg_v("contact", cueball::ball_collision_alciatore(), "ball_collision_alciatore()");
}

}  // namespace

void bind_ball_collision(py::module_& m) {
  using cueball::BallCollisionResult;
  using cueball::Parameters;

  py::class_<BallCollisionParameters> params(
      m, "BallCollisionParameters",
      "The ball-ball contact: restitution e (Newton, along the line of centres, [0, 1]); friction\n"
      "mu(u) = friction + friction_excess * exp(-friction_decay * u) at incoming slip speed u (m/s;\n"
      "friction_decay in s/m, [0, 100]; friction + friction_excess <= 1).");
  params
      .def(py::init([](double restitution, double friction, double friction_excess, double friction_decay) {
             return BallCollisionParameters{restitution, friction, friction_excess, friction_decay};
           }),
           "restitution"_a, "friction"_a = 0.0, "friction_excess"_a = 0.0, "friction_decay"_a = 0.0)
      .def_readwrite("restitution", &BallCollisionParameters::restitution, "e, [0, 1]")
      .def_readwrite("friction", &BallCollisionParameters::friction, "mu at high slip speed, [0, 1]")
      .def_readwrite("friction_excess", &BallCollisionParameters::friction_excess, "extra mu at zero slip, [0, 1]")
      .def_readwrite("friction_decay", &BallCollisionParameters::friction_decay, "c, s/m, [0, 100]");
  add_value_semantics(
      params, "BallCollisionParameters", {"restitution", "friction", "friction_excess", "friction_decay"},
      [](const BallCollisionParameters& c) {
        return py::make_tuple(c.restitution, c.friction, c.friction_excess, c.friction_decay);
      },
      [](const py::tuple& t) {
        return BallCollisionParameters{t[0].cast<double>(), t[1].cast<double>(), t[2].cast<double>(),
                                       t[3].cast<double>()};
      });
  m.def("ball_collision_alciatore", &cueball::ball_collision_alciatore,
        "e = 0.95 with Alciatore's friction fit mu(u) = 9.951e-3 + 0.108 exp(-1.088 u) (TP A.14): the\n"
        "simulator's default.");
  m.def(
      "ball_collision_frictionless",
      [](double restitution) {
        cueball::check_range(cueball::kBallRestitutionRange, restitution);
        return cueball::ball_collision_frictionless(restitution);
      },
      "restitution"_a, "No friction: the impulse along the line of centres only, spins unchanged.");
  m.def(
      "ball_friction",
      [](const BallCollisionParameters& c, double slip_speed) {
        cueball::validate(c);
        cueball::require_in_range("slip_speed", slip_speed, 0.0, 2.0 * cueball::kMaxSpeed, "contact slip speed, m/s");
        return cueball::ball_friction(c, slip_speed);
      },
      "contact"_a, "slip_speed"_a, "mu at contact slip speed slip_speed >= 0, m/s.");
  m.def(
      "balls_approaching", [](const BallState& a, const BallState& b) { return cueball::balls_approaching(a, b); },
      "a"_a, "b"_a, "True if the centres are closing: (r_b - r_a) . (v_b - v_a) < 0.");

  py::class_<BallCollisionResult> result(
      m, "BallCollisionResult",
      "The outcome of one collision: the states a and b just after it (positions unchanged) and the\n"
      "impulses on b (N s) along n = (r_b - r_a)/|r_b - r_a|, t = z x n and z (on a the opposite).");
  result.def_readonly("a", &BallCollisionResult::a)
      .def_readonly("b", &BallCollisionResult::b)
      .def_readonly("normal_impulse", &BallCollisionResult::normal_impulse, "m p_n >= 0, N s, on b along n")
      .def_readonly("tangential_impulse", &BallCollisionResult::tangential_impulse, "m p_t, N s, on b along t")
      .def_readonly("vertical_impulse", &BallCollisionResult::vertical_impulse,
                    "m p_z, N s, on b; taken up by the bed (changes only the spins)")
      .def_readonly("friction", &BallCollisionResult::friction, "mu used")
      .def_readonly("slip_speed", &BallCollisionResult::slip_speed, "incoming contact slip speed, m/s")
      .def_readonly("gripped", &BallCollisionResult::gripped, "the slip stopped during the impact");
  add_repr(result, "BallCollisionResult",
           {"a", "b", "normal_impulse", "tangential_impulse", "vertical_impulse", "friction", "slip_speed", "gripped"},
           [](const BallCollisionResult& r) {
             return py::make_tuple(r.a, r.b, r.normal_impulse, r.tangential_impulse, r.vertical_impulse, r.friction,
                                   r.slip_speed, r.gripped);
           });
  m.def(
      "mathavan_2014_collision",
      [](const BallState& a, const BallState& b, const Parameters& p, double restitution, double ball_friction,
         std::optional<double> cloth_friction) {
        check_collision(a, b, p, cueball::ball_collision_frictionless(0.0));
        const cueball::Mathavan2014Contact c{restitution, ball_friction,
                                             cloth_friction ? *cloth_friction : p.cloth.sliding_friction};
        cueball::validate(c);
        return cueball::mathavan_2014_collision(a, b, p.ball, c);
      },
      "a"_a, "b"_a, params_arg(), "restitution"_a = cueball::mathavan_2014_contact().restitution,
      "ball_friction"_a = cueball::mathavan_2014_contact().ball_friction, "cloth_friction"_a = py::none(),
      "The collision by Mathavan et al. (2014): the cloth's friction acts at both balls' table contacts\n"
      "during the impact (cloth_friction, default the params' mu_s), energetic restitution e_b and a\n"
      "constant ball-ball friction mu_b (the paper's 0.89 and 0.05 by default), solved exactly.");

  m.def(
      "resolve_ball_collision",
      [](const BallState& a, const BallState& b, const Parameters& p, const BallCollisionParameters& contact) {
        check_collision(a, b, p, contact);
        return cueball::resolve_ball_collision(a, b, p.ball, contact);
      },
      "a"_a, "b"_a, params_arg(), contact_arg(),
      "The collision of two identical balls touching (only the direction r_b - r_a is used) and\n"
      "approaching: Newton restitution along the line of centres, Coulomb friction across it, with\n"
      "the spins (throw, spin transfer). A pair not approaching comes back unchanged with zero impulses.\n"
      "Uses params.ball.radius (and the mass for the impulses). Returns a BallCollisionResult.");
  m.def(
      "collide_balls",
      [](const BallState& a, const BallState& b, const Parameters& p, const BallCollisionParameters& contact) {
        check_collision(a, b, p, contact);
        return cueball::collide_balls(a, b, p.ball, contact);
      },
      "a"_a, "b"_a, params_arg(), contact_arg(), "resolve_ball_collision's two states (a, b) only.");
}

}  // namespace cueball_python
