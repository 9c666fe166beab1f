// Mathavan, Jackson & Parkin (2010), the ball-cushion impact: the `paper`
// solver, the authors' algorithm (section 3.4). Explicit Euler in the normal
// impulse P_I with the fixed step dP_I = (1 + e_e) M yG'(0) / N, the work of
// the normal force (16a) by the trapezoid rule, stopping at the first step
// past the end of compression (16c) and past the end of restitution (16b).
// It reproduces the published numbers; the paper's constants (e_e = 0.98,
// mu_w = 0.14) were fitted with it. The equations, the scaled units and the
// state are in mathavan_2010_equations.hpp.
//
// Source: S. Mathavan, M. R. Jackson, R. M. Parkin, Proc. IMechE Part C 224
// (2010), section 3.4 and equations (7), (10), (14)-(17) as numbered there.
#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

#include "mathavan_2010_equations.hpp"

namespace cueball::mathavan_2010 {

namespace {

// Friction of the paper's scheme: Coulomb at each slipping contact (7), (10);
// zero where a slip speed is zero (15a), (15b).
Friction paper_friction(const Coefficients& k, const State& y, double zero_slip) {
  Friction f{};
  const Vec2 si = cushion_slip(k, y);
  const double s = length(si);
  if (s > zero_slip) f.cushion = -k.mu_w / s * si;  // (7a), (7b): cos Phi = s_x/s, sin Phi = s_y'/s
  const Vec2 sc = bed_slip(y);
  const double sp = length(sc);
  if (sp > zero_slip) f.bed = -k.mu_s * bed_normal_rate(k, f) / sp * sc;  // (10a), (10b) with (8)
  return f;
}

}  // namespace

Outcome solve_paper(const Coefficients& k, State y, int n_steps, const Units& units,
                    std::vector<CushionImpactSample>* history) {
  const double dp = (1.0 + k.e) / n_steps;  // dP_I = (1 + e_e) M V0 sin(alpha) / N (section 3.4)
  const double zero_slip = 1e-14 * velocity_scale(y);
  const long long max_steps = static_cast<long long>(kMaxScaledImpulse / dp) + 1;
  if (history) {
    history->reserve(static_cast<std::size_t>(1.15 * n_steps) + 2);
    history->push_back(sample(k, units, 0.0, y));
  }
  Outcome out;
  bool compressing = true;
  double work_target = 0.0;
  for (long long n = 1;; ++n) {
    if (n > max_steps) wedged();
    const Friction f = paper_friction(k, y, zero_slip);
    const State d = rates(k, y, f);
    const double z_before = -y[kVy] * k.c;  // z_I' = -yG' cos(theta) (16c note)
    for (std::size_t i = kVx; i <= kUz; ++i) y[i] += d[i] * dp;  // (17a) and the five like it
    const double z_after = -y[kVy] * k.c;
    y[kWork] += dp * 0.5 * (z_before + z_after);  // trapezoid rule (16a)
    const double p = static_cast<double>(n) * dp;
    if (history) history->push_back(sample(k, units, p, y));
    if (compressing) {
      if (y[kVy] <= 0.0) {  // z_I' = 0 reached: end of compression (16c)
        compressing = false;
        out.compression_impulse = p;
        out.compression_work = y[kWork];
        work_target = (1.0 - k.e * k.e) * y[kWork];  // W(P_I^f) = (1 - e_e^2) W(P_I^c) (16b)
      }
    } else if (y[kWork] >= work_target) {  // first step past (16b)
      out.total_impulse = p;
      out.steps = static_cast<int>(std::min<long long>(n, std::numeric_limits<int>::max()));
      out.events = 2;
      out.final_state = y;
      return out;
    }
  }
}

}  // namespace cueball::mathavan_2010
