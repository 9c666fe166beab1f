// Pocket windows measured on the engine; see pocket_windows.hpp.
#include "cueball/planning/pocket_windows.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numbers>
#include <optional>

#include "cueball/table/table.hpp"

namespace cueball {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr std::size_t kMaxCached = 4;
// A roll starts at least this clear of every cushion, m: a line that grazes
// a rail from its start is left out, where touching or not would be a
// rounding's choice.
constexpr double kStartClearance = 1e-3;

std::size_t directions() { return static_cast<std::size_t>(std::lround(360.0 / kPocketWindowAngleStepDeg)); }

// One roll's context: the table, its settings and the pocket's centre.
struct Roll {
  const Scenario& s;
  std::size_t pocket;
  Vec2 centre;
  double R;
};

// Whether the ball rolled along direction d on the line `offset` to its
// left of the pocket's centre drops into the pocket; nullopt when the
// line's start is not on the table.
std::optional<bool> pots(const Roll& r, Vec2 d, double offset) {
  const Vec2 left = perp(d);
  const Vec2 start = r.centre - kPocketWindowDistance * d + offset * left;
  if (!ball_on_table(r.s.table, start, r.R + kStartClearance)) return std::nullopt;
  SimulationBall ball;
  ball.state.position = start;
  ball.state.velocity = kPocketWindowSpeed * d;
  ball.state.angular_velocity = Vec3{-ball.state.velocity.y / r.R, ball.state.velocity.x / r.R, 0.0};
  const SimulationResult result = simulate_unchecked(r.s.table, {ball}, r.s.settings);
  return result.balls.front().pocketed && result.balls.front().pocket == static_cast<int>(r.pocket);
}

// The edge between a potting offset `in` and one that does not `out`
// (which may be a line off the table), bisected to the tolerance: the last
// potting offset found.
double edge(const Roll& r, Vec2 d, double in, double out) {
  while (std::abs(out - in) > kPocketWindowEdgeTolerance) {
    const double mid = 0.5 * (in + out);
    if (pots(r, d, mid).value_or(false)) in = mid;
    else out = mid;
  }
  return in;
}

// The window along direction d: the first and last potting offsets of the
// scan, each edge bisected outwards.
void measure(const Roll& r, Vec2 d, double& low, double& high) {
  const double reach = r.s.table.pockets[r.pocket].radius + 2.0 * r.R;
  const int steps = static_cast<int>(std::ceil(reach / kPocketWindowScanStep));
  int first = steps + 1, last = -steps - 1;
  for (int k = -steps; k <= steps; ++k)
    if (pots(r, d, k * kPocketWindowScanStep).value_or(false)) {
      first = std::min(first, k);
      last = std::max(last, k);
    }
  if (first > last) {  // no window: low > high
    low = 0.0;
    high = -1.0;
    return;
  }
  low = edge(r, d, first * kPocketWindowScanStep, (first - 1) * kPocketWindowScanStep);
  high = edge(r, d, last * kPocketWindowScanStep, (last + 1) * kPocketWindowScanStep);
}

PocketWindows build(const Scenario& s) {
  PocketWindows w;
  const double R = s.settings.parameters.ball.radius;
  const std::size_t n = directions();
  for (std::size_t p = 0; p < s.table.pockets.size(); ++p) {
    const Roll r{s, p, s.table.pockets[p].centre, R};
    PocketWindow pw;
    pw.low.resize(n);
    pw.high.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      const double a = static_cast<double>(k) * kPocketWindowAngleStepDeg * kDeg;
      measure(r, Vec2{std::cos(a), std::sin(a)}, pw.low[k], pw.high[k]);
    }
    w.pockets.push_back(std::move(pw));
  }
  return w;
}

struct Entry {
  Table table;
  SimulationSettings settings;
  std::shared_ptr<const PocketWindows> windows;
};

struct Cache {
  std::mutex mutex;
  std::vector<Entry> entries;  // least recently used first
};

Cache& cache() {
  static Cache* const c = new Cache;  // never destroyed: threads may outlive static destruction
  return *c;
}

}  // namespace

std::shared_ptr<const PocketWindows> pocket_windows(const Scenario& table) {
  Cache& c = cache();
  const std::lock_guard<std::mutex> lock(c.mutex);
  const auto it = std::find_if(c.entries.begin(), c.entries.end(), [&](const Entry& e) {
    return e.settings == table.settings && e.table == table.table;
  });
  if (it != c.entries.end()) {
    std::rotate(it, it + 1, c.entries.end());
  } else {
    c.entries.push_back({table.table, table.settings, std::make_shared<const PocketWindows>(build(table))});
    if (c.entries.size() > kMaxCached) c.entries.erase(c.entries.begin());
  }
  return c.entries.back().windows;
}

namespace {

// The two measured directions either side of `direction` and the fraction
// of the way from the first to the second.
struct Bracket {
  std::size_t k0, k1;
  double f;
};

Bracket bracket(std::size_t n, Vec2 direction) {
  double a = std::atan2(direction.y, direction.x) / kDeg / kPocketWindowAngleStepDeg;
  if (a < 0.0) a += static_cast<double>(n);
  const auto k0 = static_cast<std::size_t>(std::floor(a)) % n;
  return {k0, (k0 + 1) % n, a - std::floor(a)};
}

}  // namespace

double pocket_window_half_width(const PocketWindows& windows, std::size_t pocket, Vec2 direction) {
  if (pocket >= windows.pockets.size()) return 0.0;
  const PocketWindow& w = windows.pockets[pocket];
  const auto half = [&](std::size_t k) { return std::max(0.0, 0.5 * (w.high[k] - w.low[k])); };  // 0: closed
  const Bracket b = bracket(w.low.size(), direction);
  return (1.0 - b.f) * half(b.k0) + b.f * half(b.k1);
}

double pocket_window_middle(const PocketWindows& windows, std::size_t pocket, Vec2 direction) {
  if (pocket >= windows.pockets.size()) return 0.0;
  const PocketWindow& w = windows.pockets[pocket];
  const Bracket b = bracket(w.low.size(), direction);
  const bool open0 = w.low[b.k0] <= w.high[b.k0], open1 = w.low[b.k1] <= w.high[b.k1];
  const double c0 = 0.5 * (w.low[b.k0] + w.high[b.k0]), c1 = 0.5 * (w.low[b.k1] + w.high[b.k1]);
  if (open0 && open1) return (1.0 - b.f) * c0 + b.f * c1;
  if (open0) return c0;
  if (open1) return c1;
  return 0.0;
}

}  // namespace cueball
