// include/cueball/physics/cloth_motion.hpp: the ball on the cloth in closed form.
#include "bindings.hpp"

#include <cmath>
#include <string>
#include "cueball/physics/cloth_motion.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/core/parameters.hpp"

namespace cueball_python {

namespace {

const char* transition_name(cueball::Transition t) {
  switch (t) {
    case cueball::Transition::sliding_ends: return "sliding_ends";
    case cueball::Transition::rolling_ends: return "rolling_ends";
    case cueball::Transition::vertical_spin_ends: return "vertical_spin_ends";
    case cueball::Transition::none: break;
  }
  return "none";
}

// The kernels of cloth_motion.hpp trust their input: validate it here.
void check_state(const cueball::BallState& s, const cueball::Parameters& p) {
  cueball::validate(p);
  cueball::validate(s);
}

void check_time(const char* field, double t) {
  if (!(std::isfinite(t) && t >= 0.0)) throw cueball::InvalidArgument(field, t, "[0, infinity)", "time, s");
}

void check_straight_shot(double v0, double w0, double side_spin, const cueball::Parameters& p) {
  cueball::validate(p);
  cueball::require_in_range("v0", v0, 0.0, cueball::kMaxSpeed, "initial speed along +x, m/s");
  cueball::require_in_range("w0", w0, -cueball::kMaxAngularSpeed, cueball::kMaxAngularSpeed, "initial topspin, rad/s");
  cueball::require_in_range("side_spin", side_spin, -cueball::kMaxAngularSpeed, cueball::kMaxAngularSpeed,
                            "initial side spin w_z, rad/s");
}

}  // namespace

void bind_cloth_motion(py::module_& m) {
  using cueball::BallState;
  using cueball::Parameters;

  py::class_<BallState> state(m, "BallState",
                              "Kinematic state of a ball on the bed. position (x, y), m: the centre projected on\n"
                              "the bed; velocity (vx, vy), m/s; angular_velocity (wx, wy, wz), rad/s, wz > 0\n"
                              "anticlockwise seen from above. Not validated until used.");
  state
      .def(py::init([](const Pair& position, const Pair& velocity, const Triple& angular_velocity) {
             return BallState{to_vec2(position), to_vec2(velocity), to_vec3(angular_velocity)};
           }),
           "position"_a = Pair{0.0, 0.0}, "velocity"_a = Pair{0.0, 0.0}, "angular_velocity"_a = Triple{0.0, 0.0, 0.0})
      .def_property(
          "position", [](const BallState& s) { return to_tuple(s.position); },
          [](BallState& s, const Pair& v) { s.position = to_vec2(v); }, "(x, y), m")
      .def_property(
          "velocity", [](const BallState& s) { return to_tuple(s.velocity); },
          [](BallState& s, const Pair& v) { s.velocity = to_vec2(v); }, "(vx, vy), m/s")
      .def_property(
          "angular_velocity", [](const BallState& s) { return to_tuple(s.angular_velocity); },
          [](BallState& s, const Triple& v) { s.angular_velocity = to_vec3(v); }, "(wx, wy, wz), rad/s");
  add_value_semantics(
      state, "BallState", {"position", "velocity", "angular_velocity"},
      [](const BallState& s) {
        return py::make_tuple(to_tuple(s.position), to_tuple(s.velocity), to_tuple(s.angular_velocity));
      },
      [](const py::tuple& t) {
        return BallState{to_vec2(t[0].cast<Pair>()), to_vec2(t[1].cast<Pair>()), to_vec3(t[2].cast<Triple>())};
      });

  m.def(
      "slip_velocity",
      [](const BallState& s, const Parameters& p) {
        check_state(s, p);
        return to_tuple(cueball::slip_velocity(s, p.ball.radius));
      },
      "state"_a, params_arg(), "Contact-point slip u = v + R z^ x w (paper 001 eq. 1), (ux, uy) m/s.");
  m.def(
      "motion_phase",
      [](const BallState& s, const Parameters& p) {
        check_state(s, p);
        return std::string(cueball::to_string(cueball::motion_phase(s, p)));
      },
      "state"_a, params_arg(), "'sliding', 'rolling', 'spinning' or 'stationary', from the kinematics.");
  m.def(
      "next_transition",
      [](const BallState& s, const Parameters& p) {
        check_state(s, p);
        const cueball::NextTransition next = cueball::next_transition(s, p);
        return py::make_tuple(next.time, transition_name(next.kind));
      },
      "state"_a, params_arg(),
      "(time, kind): seconds until the equations of motion next change, and what changes:\n"
      "'sliding_ends', 'rolling_ends', 'vertical_spin_ends', or 'none' (time = inf, stationary).");
  m.def(
      "phase_end_time",
      [](const BallState& s, const Parameters& p) {
        check_state(s, p);
        return cueball::phase_end_time(s, p);
      },
      "state"_a, params_arg(),
      "Seconds until the path changes (end of sliding or rolling), ignoring vertical spin; inf at rest.");
  m.def(
      "evolve",
      [](const BallState& s, double dt, const Parameters& p) {
        check_state(s, p);
        check_time("dt", dt);
        return cueball::evolve(s, dt, p);
      },
      "state"_a, "dt"_a, params_arg(),
      "The state after dt >= 0 seconds, in closed form across every phase transition.");
  m.def(
      "kinetic_energy",
      [](const BallState& s, const Parameters& p) {
        check_state(s, p);
        return cueball::kinetic_energy(s, p.ball);
      },
      "state"_a, params_arg(), "Translational plus rotational kinetic energy (I = 2/5 m R^2), J.");

  py::class_<cueball::StraightShot> shot(m, "StraightShot",
                                         "A straight shot along +x from x = 0 (paper 001 eqs 19-24).");
  shot.def_readonly("t1", &cueball::StraightShot::t1, "end of sliding, s (eq. 19)")
      .def_readonly("x1", &cueball::StraightShot::x1, "position at the end of sliding, m (eq. 21)")
      .def_readonly("v1", &cueball::StraightShot::v1, "velocity at the end of sliding, m/s, signed along +x (eq. 20)")
      .def_readonly("t2", &cueball::StraightShot::t2, "the ball stops translating, s (eq. 22 with v2 = 0)")
      .def_readonly("x2", &cueball::StraightShot::x2, "rest position, m (eq. 24)")
      .def_readonly("t_spin", &cueball::StraightShot::t_spin, "vertical spin reaches zero, s (0 without side spin)");
  add_repr(shot, "StraightShot", {"t1", "x1", "v1", "t2", "x2", "t_spin"}, [](const cueball::StraightShot& s) {
    return py::make_tuple(s.t1, s.x1, s.v1, s.t2, s.x2, s.t_spin);
  });
  m.def(
      "straight_shot",
      [](double v0, double w0, double side_spin, const Parameters& p) {
        check_straight_shot(v0, w0, side_spin, p);
        return cueball::straight_shot(v0, w0, side_spin, p);
      },
      "v0"_a, "w0"_a = 0.0, "side_spin"_a = 0.0, params_arg(),
      "A ball struck along +x with speed v0 (m/s), topspin w0 (rad/s; R w0 = v0 natural roll, 0 stun,\n"
      "< 0 draw) and side spin w_z (rad/s): when sliding ends and where the ball stops.");
  m.def(
      "straight_shot_state",
      [](double v0, double w0, double side_spin, double t, const Parameters& p) {
        check_straight_shot(v0, w0, side_spin, p);
        check_time("t", t);
        return cueball::straight_shot_state(v0, w0, side_spin, t, p);
      },
      "v0"_a, "w0"_a = 0.0, "side_spin"_a = 0.0, "t"_a = 0.0, params_arg(),
      "The state of straight_shot(v0, w0, side_spin) at time t >= 0, s.");

  m.attr("MAX_SPEED") = cueball::kMaxSpeed;
  m.attr("MAX_ANGULAR_SPEED") = cueball::kMaxAngularSpeed;
}

}  // namespace cueball_python
