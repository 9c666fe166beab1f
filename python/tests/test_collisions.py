"""Ball-ball collisions (conservation laws, the closed forms of the
frictionless impact, the 90 degree rule, mirror symmetry) and the cushion fit
(it recovers the constants that made synthetic rebounds)."""

import math
import pickle
import unittest

import numpy as np

import cueball

P = cueball.pool_parameters()
R = P.ball.radius


def pair(cut_deg, speed=2.0, spin_a=(0.0, 0.0, 0.0), spin_b=(0.0, 0.0, 0.0)):
    """Ball a moving along +x at `speed` hits b at cut angle `cut_deg` (b's centre is 2R away at that angle)."""
    c = math.radians(cut_deg)
    a = cueball.BallState((0.0, 0.0), (speed, 0.0), spin_a)
    b = cueball.BallState((2 * R * math.cos(c), 2 * R * math.sin(c)), (0.0, 0.0), spin_b)
    return a, b


def energy(*states):
    return sum(cueball.kinetic_energy(s, P) for s in states)


def mirrored(s):
    """The state mirrored in the plane y = 0: (x, -y), (vx, -vy), (-wx, wy, -wz)."""
    (x, y), (vx, vy), (wx, wy, wz) = s.position, s.velocity, s.angular_velocity
    return cueball.BallState((x, -y), (vx, -vy), (-wx, wy, -wz))


class BallCollisionTest(unittest.TestCase):
    def test_frictionless_head_on_exchanges_the_velocities(self):
        a, b = pair(0.0, speed=1.7)
        after_a, after_b = cueball.collide_balls(a, b, contact=cueball.ball_collision_frictionless(1.0))
        self.assertEqual(after_a.velocity, (0.0, 0.0))
        self.assertEqual(after_b.velocity, (1.7, 0.0))
        self.assertEqual(after_a.position, a.position)  # positions unchanged
        for e in (0.0, 0.5, 0.93):
            with self.subTest(e=e):
                r = cueball.resolve_ball_collision(a, b, contact=cueball.ball_collision_frictionless(e))
                self.assertAlmostEqual(r.a.velocity[0], (1 - e) / 2 * 1.7, delta=1e-15)
                self.assertAlmostEqual(r.b.velocity[0], (1 + e) / 2 * 1.7, delta=1e-15)
                self.assertAlmostEqual(r.normal_impulse, P.ball.mass * (1 + e) / 2 * 1.7, delta=1e-15)
                self.assertEqual((r.tangential_impulse, r.vertical_impulse), (0.0, 0.0))

    def test_the_90_degree_rule(self):
        # Elastic, frictionless, no spin: the balls leave at right angles, b along the line of centres.
        for cut in (10.0, 30.0, 55.0):
            a, b = pair(cut)
            after_a, after_b = cueball.collide_balls(a, b, contact=cueball.ball_collision_frictionless(1.0))
            self.assertAlmostEqual(float(np.dot(after_a.velocity, after_b.velocity)), 0.0, delta=1e-12)
            self.assertAlmostEqual(math.degrees(math.atan2(after_b.velocity[1], after_b.velocity[0])), cut, delta=1e-9)

    def test_momentum_is_conserved_and_energy_never_grows(self):
        rng = np.random.default_rng(12)
        for _ in range(200):
            cut = rng.uniform(-80.0, 80.0)
            a, b = pair(cut, rng.uniform(0.1, 8.0), tuple(rng.uniform(-150, 150, 3)), tuple(rng.uniform(-50, 50, 3)))
            e = rng.uniform(0.0, 1.0)
            contact = cueball.BallCollisionParameters(e, rng.uniform(0.0, 0.3), rng.uniform(0.0, 0.5), rng.uniform(0, 5))
            r = cueball.resolve_ball_collision(a, b, P, contact)
            before = np.add(a.velocity, b.velocity)
            np.testing.assert_allclose(np.add(r.a.velocity, r.b.velocity), before, atol=1e-12)
            self.assertLessEqual(energy(r.a, r.b), energy(a, b) * (1 + 1e-12))
            self.assertGreaterEqual(r.normal_impulse, 0.0)
            # Angular momentum about the contact point: each ball's spin changes by
            # the torque of the friction impulse, the same for both (B4).
            dwa = np.subtract(r.a.angular_velocity, a.angular_velocity)
            dwb = np.subtract(r.b.angular_velocity, b.angular_velocity)
            np.testing.assert_allclose(dwa, dwb, atol=1e-9)

    def test_alciatore_friction_throws_the_object_ball(self):
        a, b = pair(30.0, speed=1.0)
        r = cueball.resolve_ball_collision(a, b)  # the defaults: pool ball, Alciatore's contact
        self.assertGreater(r.friction, 0.0)
        self.assertAlmostEqual(r.friction, cueball.ball_friction(cueball.ball_collision_alciatore(), r.slip_speed),
                               delta=1e-15)
        # A stun shot: Alciatore's TP A.14 throw angle, with the slip v sin(phi) and mu(v_rel).
        phi = math.radians(30.0)
        v_rel = math.sin(phi)
        mu = cueball.ball_friction(cueball.ball_collision_alciatore(), v_rel)
        expected = math.atan(min(mu * math.cos(phi) / v_rel, 1 / 7) * math.tan(phi))
        self.assertAlmostEqual(r.slip_speed, v_rel, delta=1e-15)
        throw = phi - math.atan2(r.b.velocity[1], r.b.velocity[0])  # off the line of centres, towards a's path
        self.assertAlmostEqual(throw, expected, delta=1e-12)
        self.assertAlmostEqual(math.degrees(throw), 4.15, delta=0.01)
        self.assertFalse(r.gripped)
        self.assertEqual(cueball.ball_friction(cueball.ball_collision_alciatore(), 0.0), 0.009951 + 0.108)

    def test_mirror_symmetry_and_the_roles_of_a_and_b(self):
        a, b = pair(25.0, 3.0, (5.0, 40.0, -30.0), (1.0, -2.0, 7.0))
        r = cueball.resolve_ball_collision(a, b)
        m = cueball.resolve_ball_collision(mirrored(a), mirrored(b))
        for got, expected in ((m.a, mirrored(r.a)), (m.b, mirrored(r.b))):
            np.testing.assert_allclose(got.velocity, expected.velocity, atol=1e-12)
            np.testing.assert_allclose(got.angular_velocity, expected.angular_velocity, atol=1e-9)
        swapped = cueball.resolve_ball_collision(b, a)
        np.testing.assert_allclose(swapped.a.velocity, r.b.velocity, atol=1e-12)
        np.testing.assert_allclose(swapped.b.velocity, r.a.velocity, atol=1e-12)

    def test_separating_balls_do_not_collide(self):
        a, b = pair(20.0)
        self.assertTrue(cueball.balls_approaching(a, b))
        away = cueball.BallState(a.position, (-1.0, 0.0))
        self.assertFalse(cueball.balls_approaching(away, b))
        r = cueball.resolve_ball_collision(away, b)
        self.assertEqual((r.a, r.b, r.normal_impulse), (away, b, 0.0))

    def test_bad_input_names_the_field(self):
        a, b = pair(10.0)
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.collide_balls(a, b, contact=cueball.BallCollisionParameters(1.5))
        self.assertEqual(caught.exception.field, "restitution")
        self.assertIn("[0, 1]", str(caught.exception))
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.collide_balls(a, b, contact=cueball.BallCollisionParameters(0.9, 0.6, 0.6))
        self.assertEqual(caught.exception.field, "friction_excess")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.ball_collision_frictionless(-0.1)
        self.assertEqual(caught.exception.field, "restitution")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.resolve_ball_collision(cueball.BallState(velocity=(math.nan, 0.0)), b)
        self.assertEqual(caught.exception.field, "a.velocity")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.resolve_ball_collision(a, cueball.BallState(b.position, angular_velocity=(0.0, 0.0, 1e9)))
        self.assertTrue(caught.exception.field.startswith("b."), caught.exception.field)

    def test_numpy_and_value_semantics(self):
        contact = cueball.BallCollisionParameters(np.float32(0.5), np.float64(0.1))
        self.assertEqual(pickle.loads(pickle.dumps(contact)), contact)
        a = cueball.BallState(np.zeros(2), np.array([1.0, 0.0]))
        b = cueball.BallState(np.array([2 * R, 0.0]))
        after_a, after_b = cueball.collide_balls(a, b, P, contact)
        self.assertAlmostEqual(after_b.velocity[0], 0.75, delta=1e-7)


class CushionFitTest(unittest.TestCase):
    """tests/test_cushion_fit.cpp's synthetic data, made with cushion_impact (the paper's snooker ball)."""

    p = cueball.snooker_parameters()
    e, mu = 0.95, 0.18

    def impact(self, v0, alpha_deg, kt, ks):
        R = self.p.ball.radius
        return cueball.cushion_impact(v0, math.radians(alpha_deg), kt * v0 / R, ks * v0 / R, params=self.p,
                                      restitution=self.e, friction=self.mu)

    def data(self, oblique, sigma_speed=0.0, sigma_angle=0.0):
        rng = np.random.default_rng(20100901)
        head_on = [cueball.HeadOnRebound(v0, self.impact(v0, 90.0, 1.0, 0.0).rebound_speed + sigma_speed * rng.normal())
                   for v0 in (0.4, 0.6, 0.8, 1.0, 1.2, 1.4)]
        rebounds = []
        if oblique:
            R = self.p.ball.radius
            for alpha in (20.0, 35.0, 50.0, 65.0):
                for kt, ks in ((1.0, 0.0), (1.0, 1.0), (0.0, -1.0)):
                    r = self.impact(0.9, alpha, kt, ks)
                    incidence = cueball.PaperIncidence(0.9, math.radians(alpha), kt * 0.9 / R, ks * 0.9 / R)
                    rebounds.append(cueball.ObliqueRebound(incidence, r.rebound_speed + sigma_speed * rng.normal(),
                                                           r.rebound_angle + sigma_angle * rng.normal()))
        return cueball.CushionFitData(head_on, rebounds)

    def test_recovers_known_constants_from_noisy_data(self):
        fit = cueball.fit_cushion(self.data(True, 0.003, math.radians(0.2)), params=self.p)
        self.assertFalse(fit.poorly_separated)
        self.assertGreater(fit.restitution_sigma, 0.0)
        self.assertLess(fit.restitution_sigma, 0.02)
        self.assertLess(fit.friction_sigma, 0.02)
        self.assertAlmostEqual(fit.restitution, self.e, delta=max(4 * fit.restitution_sigma, 0.002))
        self.assertAlmostEqual(fit.friction, self.mu, delta=max(4 * fit.friction_sigma, 0.002))
        self.assertLessEqual(fit.residual, fit.grid_residual)
        self.assertEqual(fit.residuals, 6 + 2 * 12)

    def test_exact_data_give_the_constants_back(self):
        fit = cueball.fit_cushion(self.data(True), self.p, cueball.CushionFitOptions(grid_step=0.05))
        self.assertAlmostEqual(fit.restitution, self.e, delta=1e-6)
        self.assertAlmostEqual(fit.friction, self.mu, delta=1e-6)
        self.assertLess(fit.residual, 1e-12)

    def test_head_on_data_alone_fix_one_combination_only(self):
        fit = cueball.fit_cushion(self.data(False), self.p, cueball.CushionFitOptions(grid_step=0.05))
        self.assertTrue(fit.poorly_separated)
        self.assertGreater(abs(fit.correlation), 0.98)
        # The fitted pair lies on the curve of the true ratio V_out / V0, wherever along it
        # (the C++ test's tolerance).
        ratio = cueball.cushion_impact(1.0, math.pi / 2, params=self.p, restitution=fit.restitution,
                                       friction=fit.friction).rebound_speed
        self.assertAlmostEqual(ratio, self.impact(1.0, 90.0, 1.0, 0.0).rebound_speed, delta=0.004)

    def test_bad_data_name_the_field(self):
        with self.assertRaises(cueball.InvalidArgument):
            cueball.fit_cushion(cueball.CushionFitData())
        bad = cueball.CushionFitData([cueball.HeadOnRebound(1.0, 0.9), cueball.HeadOnRebound(0.5, -1.0),
                                      cueball.HeadOnRebound(0.7, 0.6)])
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.fit_cushion(bad)
        self.assertEqual(caught.exception.field, "head_on[1].rebound_speed")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.CushionFitOptions(solver="rk4")
        self.assertEqual(caught.exception.field, "solver")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.fit_cushion(self.data(False), options=cueball.CushionFitOptions(grid_step=0.9))
        self.assertEqual(caught.exception.field, "grid_step")

    def test_values_pickle(self):
        d = self.data(True)
        self.assertEqual(pickle.loads(pickle.dumps(d)), d)
        o = cueball.CushionFitOptions("paper", 100, 0.02, np.float32(0.03))
        self.assertEqual(pickle.loads(pickle.dumps(o)), o)
        self.assertEqual(o.solver, "paper")


if __name__ == "__main__":
    unittest.main()
