// The Dormand-Prince 5(4) pair's coefficients, shared by the exact impact
// solvers (src/models/cushion/mathavan_2010_exact.cpp, src/models/ball_collision/mathavan_2014.cpp).
//
// Source: J. R. Dormand, P. J. Prince, "A family of embedded Runge-Kutta
// formulae", J. Comput. Appl. Math. 6 (1980) 19-26 (the RK5(4)7M tableau);
// the dense-output weights d of L. F. Shampine, "Some practical Runge-Kutta
// formulas", Math. Comp. 46 (1986) 135-150, as in E. Hairer, S. P. Norsett,
// G. Wanner, "Solving ODEs I" (2nd ed.), section II.6. The seventh stage is
// evaluated at the fifth-order solution (a7j = b_j: first same as last).
#pragma once

namespace cueball::dormand_prince {

inline constexpr double a21 = 1.0 / 5.0;
inline constexpr double a31 = 3.0 / 40.0, a32 = 9.0 / 40.0;
inline constexpr double a41 = 44.0 / 45.0, a42 = -56.0 / 15.0, a43 = 32.0 / 9.0;
inline constexpr double a51 = 19372.0 / 6561.0, a52 = -25360.0 / 2187.0, a53 = 64448.0 / 6561.0, a54 = -212.0 / 729.0;
inline constexpr double a61 = 9017.0 / 3168.0, a62 = -355.0 / 33.0, a63 = 46732.0 / 5247.0, a64 = 49.0 / 176.0,
                        a65 = -5103.0 / 18656.0;
/// The fifth-order weights b_j (= a7j).
inline constexpr double a71 = 35.0 / 384.0, a73 = 500.0 / 1113.0, a74 = 125.0 / 192.0, a75 = -2187.0 / 6784.0,
                        a76 = 11.0 / 84.0;
/// Fifth- minus fourth-order weights: the local error estimate.
inline constexpr double e1 = 71.0 / 57600.0, e3 = -71.0 / 16695.0, e4 = 71.0 / 1920.0, e5 = -17253.0 / 339200.0,
                        e6 = 22.0 / 525.0, e7 = -1.0 / 40.0;
/// Shampine's dense-output weights (the midpoint's).
inline constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                        d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                        d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;

}  // namespace cueball::dormand_prince
