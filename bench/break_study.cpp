// cueball-break-study: why does the built-in 9-ball break pot so few balls,
// and what changes it? (issue 25, item 3; method and results: docs/break.md).
//
// Each cell of a grid (cue-ball spot in the kitchen, cut on the 1, cue
// speed, tip height, rack gap sigma, ball-ball model, ball order) plays
// --shots noisy 9-ball breaks with simulate_many: break k of a cell racks
// with rack_nine_ball(gap_sigma, seed = S + k) (a new rack every break, as
// a referee racks), places the cue ball on the cell's spot and strikes it
// with tournament_noise() (shot_planner.hpp) drawn from (S, k). Per cell it
// reports, each with its binomial standard error sqrt(p (1 - p) / n):
//   pot    an object ball pocketed (any pocket; fouls included)
//   legal  WPA 2.3 (10-ball 9.3): the 1 first (8-ball, 3.3: any ball), no scratch,
//          and a ball pocketed or at least
//          four object balls to a rail (cushion contacts; jaw contacts are
//          not in simulate_many's counts, so `legal` is a slight undercount)
//   made   legal and a ball pocketed: the pro statistic's numerator
//   made|legal  made / legal, the share the WPA statistics quote (~71 %)
//   scratch, wing (a wing ball, the 4 or the 5, in a foot corner pocket), balls
//   (mean object balls pocketed).
// Miscues and event-limit failures count as breaks that make nothing.
//
// Usage: cueball-break-study [--shots N] [--threads T] [--seed S] [--suite NAME]
// suites: default (the built-in break at 7/9/11 m/s), grid (spots x cuts x
// speeds x heights x gaps), order (the frozen rack with its balls given in
// reverse order), model (coulomb_impulse vs mathavan_2014, mirror spots),
// rail (side spots' distance from the rail), sigma (gap sizes), centre (the
// long string and box spots at the top speeds), spot (the 9 on the foot
// spot), final / final9 (the recommended break at 11 / 9 m/s), extras
// (tighter corner pockets, a raised cue), cut9 (the side cut break with the
// 9 on the spot), side (the side break, frozen and on the default gaps, and
// its mirror image), disciplines (8-ball and 10-ball: the side break and its
// neighbours). Output: one line per cell. docs/break.md has the results.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <numbers>
#include <string>
#include <vector>

#include "cueball/planning/shot_planner.hpp"
#include "cueball/simulation/batch.hpp"
#include "cueball/simulation/scenario.hpp"
#include "cueball/table/placement.hpp"
#include "cueball/table/rack.hpp"
#include "cueball/table/table.hpp"

using namespace cueball;

namespace {

struct Cell {
  int game = 9;                 // the rack: 9-ball, 8-ball (15 balls) or 10-ball
  const char* spot = "centre";  // centre, side (near the y = 0 rail), side_top (near y = W)
  double rail_gap = 0.10;       // side spots: centre's distance from the cushion nose line, m
  double cut = 0.0;             // impact offset on the 1, fraction of 2R, + towards the spot's side
  double speed = 9.0;           // m/s
  double height = 0.0;          // ball radii
  double elevation = 0.0;       // degrees
  double gap_sigma = 0.0;       // m
  bool reverse_order = false;   // the balls given to the simulator in reverse id order
  BallCollisionModel model = BallCollisionModel::coulomb_impulse;
  bool nine_on_spot = false;    // the 9 on the foot spot: the rack moved two rows towards the head string
  double corner_mouth = 0.0;    // corner pockets' mouth, m; 0 = pool_9ft's (4 9/16 in)
};

struct Options {
  int shots = 400;
  int threads = 2;
  std::uint64_t seed = 1;
  std::string suite = "default";
};

struct Tally {
  int n = 0, pot = 0, legal = 0, made = 0, scratch = 0, wing = 0, balls = 0;
};

// Everything one cell needs, filled by the steps below in order.
struct CellRun {
  const Cell& cell;
  const Options& options;
  Table table;
  Scenario scenario;
  std::vector<ShotAction> actions;
  std::vector<double> layouts;
  ManyResult result;
  Tally tally;
};

Vec2 cue_spot(const Cell& c, const Table& t) {
  const double x = head_string_x(t) - 0.01;
  if (std::strcmp(c.spot, "side") == 0) return {x, t.ball.radius + c.rail_gap};
  if (std::strcmp(c.spot, "side_top") == 0) return {x, t.width - t.ball.radius - c.rail_gap};
  return {head_string_x(t) - 2.0 * t.ball.radius, 0.5 * t.width};  // rack.hpp's spot
}

// The cell's rack (rack.hpp): WPA 9-ball, 8-ball or 10-ball.
std::vector<PlacedBall> rack_of(const Cell& c, const Table& t, const RackOptions& options = {}) {
  if (c.game == 8) return rack_eight_ball(t, options);
  if (c.game == 10) return rack_ten_ball(t, options);
  return rack_nine_ball(t, options);
}

// Step 1: the table, the frozen rack as the scenario's balls (its order
// reversed when asked), the model and the noise.
void set_scenario(CellRun& run) {
  TableSpec spec = pool_table_9ft_spec();
  if (run.cell.corner_mouth > 0.0) spec.corner_pockets.mouth = run.cell.corner_mouth;
  run.table = build_table(spec);
  run.scenario.table = run.table;
  run.scenario.settings.parameters = default_parameters(run.table);
  run.scenario.settings.ball_collision_model = run.cell.model;
  run.scenario.settings.ball_collision = default_ball_collision(run.cell.model);
  for (const PlacedBall& p : rack_of(run.cell, run.table)) {
    SimulationBall b;
    b.id = p.id;
    b.name = p.name;
    b.state.position = p.position;
    run.scenario.balls.push_back(b);
  }
  if (run.cell.reverse_order) std::reverse(run.scenario.balls.begin() + 1, run.scenario.balls.end());
  ShotStrike cue;
  cue.ball = 0;
  run.scenario.cue = cue;
  run.scenario.noise = tournament_noise();
}

// Step 2: one rack per break (seed S + k) with the cue ball on the spot, and
// the aim at the 1 with the cell's cut.
void set_breaks(CellRun& run) {
  const int n = run.options.shots;
  const double R = run.table.ball.radius;
  const Vec2 cue = cue_spot(run.cell, run.table);
  const std::size_t balls = run.scenario.balls.size();
  run.layouts.resize(static_cast<std::size_t>(n) * balls * 2);
  run.actions.resize(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    RackOptions rack;
    rack.gap_sigma = run.cell.gap_sigma;
    rack.seed = run.options.seed + static_cast<std::uint64_t>(k);
    const std::vector<PlacedBall> placed = rack_of(run.cell, run.table, rack);
    Vec2 one;
    for (std::size_t j = 0; j < balls; ++j) {
      const int id = run.scenario.balls[j].id;
      Vec2 p = cue;
      for (const PlacedBall& q : placed)
        if (q.id == id && id != 0) p = q.position;
      if (id != 0 && run.cell.nine_on_spot) p.x -= 2.0 * std::sqrt(3.0) * (R + 2.0 * run.cell.gap_sigma);
      if (id == 1) one = p;
      run.layouts[(static_cast<std::size_t>(k) * balls + j) * 2] = p.x;
      run.layouts[(static_cast<std::size_t>(k) * balls + j) * 2 + 1] = p.y;
    }
    const Vec2 d = one - cue;
    const double dist = std::sqrt(d.x * d.x + d.y * d.y);
    // A cut towards the spot's own side (the cue ball passes the 1 on the far side).
    const double sign = cue.y < 0.5 * run.table.width ? -1.0 : 1.0;
    const double offset = std::asin(std::min(1.0, run.cell.cut * 2.0 * R / dist));
    ShotAction& a = run.actions[static_cast<std::size_t>(k)];
    a.speed = run.cell.speed;
    a.aim_deg = (std::atan2(d.y, d.x) + sign * offset) * 180.0 / std::numbers::pi;
    a.elevation_deg = run.cell.elevation;
    a.height = run.cell.height;
  }
}

// Step 3: the breaks.
void simulate(CellRun& run) {
  ManyOptions o;
  o.threads = run.options.threads;
  o.seed = run.options.seed;
  o.noise = true;
  run.result = simulate_many(run.scenario, run.actions, run.layouts, o);
}

// Step 4: the WPA 2.3 reading of each break.
void count(CellRun& run) {
  const int balls = run.result.balls;
  Tally& t = run.tally;
  for (int k = 0; k < run.result.shots; ++k) {
    ++t.n;
    if (run.result.miscue[static_cast<std::size_t>(k)] || run.result.failure[static_cast<std::size_t>(k)]) continue;
    int pocketed = 0, to_rail = 0;
    bool scratch = false, wing = false;
    for (int j = 0; j < balls; ++j) {
      const std::size_t e = static_cast<std::size_t>(k * balls + j);
      const int id = run.result.ids[static_cast<std::size_t>(j)];
      const bool down = run.result.pocketed[e] != 0;
      if (id == 0) {
        scratch = down;
        continue;
      }
      if (down) ++pocketed;
      if (down && run.cell.game == 9 && (id == 4 || id == 5)) {
        const int p = run.result.pocket[e];
        if (p == 2 || p == 3) wing = true;  // the foot corners (table.hpp's pocket order)
      }
      if (run.result.cushions[e] > 0) ++to_rail;
    }
    // 9-ball (WPA 2.3) and 10-ball (9.3): the 1 first; 8-ball (3.3): any ball first.
    const bool first_ok = run.cell.game == 8 ? run.result.first_contact[static_cast<std::size_t>(k)] > 0
                                             : run.result.first_contact[static_cast<std::size_t>(k)] == 1;
    const bool legal = first_ok && !scratch && (pocketed > 0 || to_rail >= 4);
    t.pot += pocketed > 0;
    t.balls += pocketed;
    t.scratch += scratch;
    t.wing += wing;
    t.legal += legal;
    t.made += legal && pocketed > 0;
  }
}

std::string share(int k, int n) {
  const double p = n > 0 ? static_cast<double>(k) / n : 0.0;
  const double se = n > 0 ? std::sqrt(p * (1.0 - p) / n) : 0.0;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%5.3f±%5.3f", p, se);
  return buf;
}

void report(const CellRun& run) {
  const Cell& c = run.cell;
  const Tally& t = run.tally;
  std::printf("%d-ball %smouth=%.4f %-8s rail=%.2f cut=%+.2f v=%4.1f h=%+.2f el=%2.0f sigma=%.5f %s %s | pot %s legal %s made %s made|legal %s "
              "scratch %s wing %s balls %.3f | %.0f/s\n",
              c.game, c.nine_on_spot ? "9spot " : "", c.corner_mouth, c.spot, c.rail_gap, c.cut, c.speed, c.height, c.elevation, c.gap_sigma,
              c.model == BallCollisionModel::coulomb_impulse ? "coulomb" : "mathavan",
              c.reverse_order ? "rev" : "fwd", share(t.pot, t.n).c_str(), share(t.legal, t.n).c_str(),
              share(t.made, t.n).c_str(), share(t.made, t.legal).c_str(), share(t.scratch, t.n).c_str(),
              share(t.wing, t.n).c_str(), t.n > 0 ? static_cast<double>(t.balls) / t.n : 0.0,
              run.result.shots_per_second);
  std::fflush(stdout);
}

void run_cell(const Cell& cell, const Options& options) {
  CellRun run{cell, options, {}, {}, {}, {}, {}, {}};
  set_scenario(run);
  set_breaks(run);
  simulate(run);
  count(run);
  report(run);
}

// ------------------------------------------------------------------ suites

void suite_default(const Options& o) {
  // The break a new user tries: the rack's own cue spot, full on the 1, centre ball.
  for (double sigma : {0.0, 0.0001, 0.0005})
    for (double v : {7.0, 9.0, 11.0}) {
      Cell c;
      c.speed = v;
      c.gap_sigma = sigma;
      run_cell(c, o);
    }
}

void suite_grid(const Options& o) {
  for (const char* spot : {"centre", "side", "side_top"})
    for (double cut : {0.0, 0.15, 0.3})
      for (double sigma : {0.0, 0.0001, 0.0005})
        for (double v : {8.0, 11.0})
          for (double h : {-0.2, 0.0, 0.2}) {
            if (std::strcmp(spot, "centre") == 0 && cut != 0.0) continue;
            Cell c;
            c.spot = spot;
            c.cut = cut;
            c.gap_sigma = sigma;
            c.speed = v;
            c.height = h;
            run_cell(c, o);
          }
}

void suite_order(const Options& o) {
  for (const char* spot : {"centre", "side"})
    for (bool rev : {false, true})
      for (double sigma : {0.0, 0.0001}) {
        Cell c;
        c.spot = spot;
        c.reverse_order = rev;
        c.gap_sigma = sigma;
        run_cell(c, o);
      }
}

void suite_model(const Options& o) {
  for (BallCollisionModel m : {BallCollisionModel::coulomb_impulse, BallCollisionModel::mathavan_2014})
    for (const char* spot : {"centre", "side", "side_top"})
      for (double sigma : {0.0, 0.0001}) {
        Cell c;
        c.spot = spot;
        c.model = m;
        c.gap_sigma = sigma;
        run_cell(c, o);
      }
}

void suite_rail(const Options& o) {
  for (double rail : {0.03, 0.06, 0.10, 0.15, 0.20, 0.30})
    for (double sigma : {0.0, 0.0001}) {
      Cell c;
      c.spot = "side";
      c.rail_gap = rail;
      c.gap_sigma = sigma;
      c.speed = 10.0;
      run_cell(c, o);
    }
}

void suite_sigma(const Options& o) {
  for (const char* spot : {"centre", "side"})
    for (double sigma : {0.0, 0.00002, 0.00005, 0.0001, 0.0002, 0.0005, 0.001}) {
      Cell c;
      c.spot = spot;
      c.gap_sigma = sigma;
      c.speed = 10.0;
      run_cell(c, o);
    }
}

// The break on the long string (and off it towards the y = 0 rail, "box"
// spots), at the top speeds, over realistic small gaps.
void suite_centre(const Options& o) {
  for (double sigma : {0.0, 0.000025, 0.00005, 0.0001})
    for (double rail : {0.5 * 1.27 - 0.028575, 0.5 * 1.27 - 0.028575 - 0.1, 0.5 * 1.27 - 0.028575 - 0.2})
      for (double v : {10.0, 11.0, 12.0})
        for (double h : {0.0, 0.1}) {
          Cell c;
          c.spot = "side";  // y = R + rail: the first rail value is the long string
          c.rail_gap = rail;
          c.gap_sigma = sigma;
          c.speed = v;
          c.height = h;
          run_cell(c, o);
        }
}

// The 2016 WPA World Championship racked the 9 on the foot spot.
void suite_spot(const Options& o) {
  for (bool nine : {false, true})
    for (const char* spot : {"centre", "side"})
      for (double sigma : {0.0, 0.000025, 0.0001}) {
        Cell c;
        c.spot = spot;
        c.nine_on_spot = nine;
        c.gap_sigma = sigma;
        c.speed = 11.0;
        run_cell(c, o);
      }
}

// Breaks square on the 1 from a side spot, with the 1 or the 9 on the foot
// spot, over gap scales and speeds.
void side_breaks(const Options& o, const char* spot, std::initializer_list<double> speeds,
                 std::initializer_list<double> sigmas) {
  for (bool nine : {false, true})
    for (double sigma : sigmas)
      for (double v : speeds) {
        Cell c;
        c.spot = spot;
        c.nine_on_spot = nine;
        c.gap_sigma = sigma;
        c.speed = v;
        run_cell(c, o);
      }
}

// The recommended break (games/break_shot.hpp): 10 cm off the y = 0 rail,
// 1 cm behind the head string, square on the apex ball, 11 m/s, centre ball.
void suite_final(const Options& o, double speed = 11.0) { side_breaks(o, "side", {speed}, {0.0, 0.000025, 0.0001}); }

// The side break at three speeds, frozen and on the default gaps, and its
// mirror image (off the y = W rail) at 10 m/s.
void suite_side(const Options& o) {
  side_breaks(o, "side", {9.0, 10.0, 11.0}, {0.0, 0.000025});
  side_breaks(o, "side_top", {10.0}, {0.0, 0.000025});
}

// The cut break from the side that pros use with the 9 on the spot.
void suite_cut9(const Options& o) {
  for (double cut : {0.0, 0.15, 0.3})
    for (double v : {9.0, 11.0}) {
      Cell c;
      c.spot = "side";
      c.cut = cut;
      c.nine_on_spot = true;
      c.gap_sigma = 0.000025;
      c.speed = v;
      run_cell(c, o);
    }
}

// 8-ball and 10-ball (issue 27, item 4): the recommended side break and its
// neighbours (the spot's distance from the rail, the rack's own spot on the
// long string, a cut on the apex ball, the speed), frozen and on the games'
// default gaps (new_game's kDefaultRackGapSigma).
void suite_disciplines(const Options& o) {
  for (int game : {8, 10})
    for (double sigma : {0.0, 0.000025}) {
      auto run = [&](const char* spot, double rail, double cut, double v) {
        run_cell({.game = game, .spot = spot, .rail_gap = rail, .cut = cut, .speed = v, .gap_sigma = sigma}, o);
      };
      run("centre", 0.10, 0.0, 11.0);
      for (double rail : {0.05, 0.10, 0.15, 0.20, 0.25, 0.30}) run("side", rail, 0.0, 11.0);
      for (double cut : {0.15, 0.3}) run("side", 0.10, cut, 11.0);
      for (double v : {9.0, 10.0, 12.0}) run("side", 0.10, 0.0, v);
    }
}

// Tighter corner pockets (pro events: 4-4.25 in) and a raised cue, on the
// recommended break.
void suite_extras(const Options& o) {
  for (bool nine : {false, true})
    for (double mouth : {0.0, 4.25 * 0.0254, 4.0 * 0.0254})
      for (double el : {0.0, 5.0}) {
        Cell c;
        c.spot = "side";
        c.rail_gap = 0.5 * 1.27 - 0.028575;  // the long string
        c.nine_on_spot = nine;
        c.gap_sigma = 0.000025;
        c.speed = 11.0;
        c.corner_mouth = mouth;
        c.elevation = el;
        if (mouth > 0.0 && el > 0.0) continue;
        run_cell(c, o);
      }
}

int usage(const char* why) {
  std::fprintf(stderr, "cueball-break-study: %s\nusage: cueball-break-study [--shots N] [--threads T] [--seed S] "
                       "[--suite default|grid|order|model|rail|sigma|centre|spot|final|final9|extras|cut9|side|disciplines]\n", why);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) return usage(("missing value after " + a).c_str());
    const char* v = argv[++i];
    if (a == "--shots") o.shots = std::atoi(v);
    else if (a == "--threads") o.threads = std::atoi(v);
    else if (a == "--seed") o.seed = std::strtoull(v, nullptr, 10);
    else if (a == "--suite") o.suite = v;
    else return usage(("unknown flag " + a).c_str());
  }
  if (o.shots < 1 || o.shots > kMaxManyShots) return usage("--shots must be in [1, 1000000]");
  if (o.threads < 1 || o.threads > kMaxBatchThreads) return usage("--threads must be in [1, 256]");
  if (o.suite == "default") suite_default(o);
  else if (o.suite == "grid") suite_grid(o);
  else if (o.suite == "order") suite_order(o);
  else if (o.suite == "model") suite_model(o);
  else if (o.suite == "rail") suite_rail(o);
  else if (o.suite == "sigma") suite_sigma(o);
  else if (o.suite == "centre") suite_centre(o);
  else if (o.suite == "spot") suite_spot(o);
  else if (o.suite == "final") suite_final(o);
  else if (o.suite == "final9") suite_final(o, 9.0);  // a cue ball at about 12 m/s (27 mph)
  else if (o.suite == "extras") suite_extras(o);
  else if (o.suite == "side") suite_side(o);
  else if (o.suite == "cut9") suite_cut9(o);
  else if (o.suite == "disciplines") suite_disciplines(o);
  else return usage("unknown --suite (default, grid, order, model, rail, sigma, centre, spot, final, final9, extras, cut9, side, disciplines)");
  return 0;
}
