// Racks (see include/cueball/table/rack.hpp).
//
// Sources: WPA World Standardized Rules (8-Ball and 9-Ball racking; head
// string, foot spot, diamonds at eighths of the length); WPBSA Rules of
// Snooker, section 1 (baulk line 737 mm, D radius 292 mm, black spot 324 mm
// from the top cushion, pink midway between the centre spot and the top
// cushion) and section 2 (positions of the balls: the reds in a triangle, the
// apex red as near to the pink as possible without touching it, the base
// parallel to and nearest the top cushion).
#include "cueball/table/rack.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "cueball/core/errors.hpp"
#include "cueball/core/random.hpp"

namespace cueball {

namespace {

// WPBSA standard table and markings, m.
constexpr double kSnookerLength = 3.569;
constexpr double kSnookerWidth = 1.778;
constexpr double kBaulkLine = 0.737;
constexpr double kDRadius = 0.292;
constexpr double kBlackSpotFromTop = 0.324;

struct Site {
  int row;  // 0 at the apex, growing away from it (towards +x)
  int col;  // 0..row across the row
};

struct RackBall {
  int id;
  std::string name;
  Site site;
};

// Two independent standard normals (Box-Muller) in the rack's own order of
// draws: radius from 1 - unit() (in (0, 1]), then angle.
Vec2 normal_pair(RandomStream& rng) {
  const double u1 = 1.0 - rng.unit();
  const double u2 = rng.unit();
  const double r = std::sqrt(-2.0 * std::log(u1));
  const double a = 2.0 * std::numbers::pi * u2;
  return {r * std::cos(a), r * std::sin(a)};
}

std::string format_number(double v) {
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

// Places a triangular-lattice rack with its apex site (0, 0) at `apex`, rows
// growing along +x. Spacing 2R (+ 4 sigma with random gaps); every ball but
// the apex moves by a random vector of length <= 2 sigma (see rack.hpp).
std::vector<PlacedBall> place(const std::vector<RackBall>& balls, Vec2 apex, double radius,
                              const RackOptions& options) {
  const double sigma = options.gap_sigma;
  const double spacing = 2.0 * radius + 4.0 * sigma;
  const double row_step = 0.5 * std::numbers::sqrt3 * spacing;
  RandomStream jitter(options.seed);
  std::vector<PlacedBall> out;
  out.reserve(balls.size());
  for (const RackBall& b : balls) {
    Vec2 p{apex.x + b.site.row * row_step, apex.y + (b.site.col - 0.5 * b.site.row) * spacing};
    if (sigma > 0.0 && !(b.site.row == 0 && b.site.col == 0)) {
      Vec2 u = sigma * normal_pair(jitter);
      const double len = norm(u);
      if (len > 2.0 * sigma) u = u * (2.0 * sigma / len);
      p = p + u;
    }
    out.push_back({b.id, b.name, p});
  }
  return out;
}

// Every ball must be placeable and no two may overlap (a custom table may be
// too small for the rack). Errors name the field "rack" (the scenario's
// "rack" object; the rack functions have no other input that can be wrong
// for a valid table), give the offending ball's position or the pair's
// distance, and what the rack needs. `object_balls` are the ones placed on
// the lattice, whose apex is at x = 3L/4 on the long string for every rack.
void check_fits(const Table& table, const std::vector<PlacedBall>& balls, const std::vector<PlacedBall>& lattice,
                const char* type, bool cue_behind_head_string) {
  const double R = table.ball.radius;
  double d = 0.0;  // the closest a ball's centre comes to a cushion nose
  for (const CushionSegment& c : table.cushions) d = std::max(d, cushion_contact_distance(c.contact_height, R));
  const std::string head = std::string("rack: the ") + type + " rack does not fit on table '" + table.name +
                           "' (length " + format_number(table.length) + " m, width " + format_number(table.width) +
                           " m): ";
  for (const PlacedBall& b : balls) {
    if (ball_on_table(table, b.position)) continue;
    // What a rectangular table needs: the lattice's reach beyond x = 3L/4
    // and either side of y = W/2, plus the contact distance to the noses.
    double along = 0.0, across = 0.0;
    for (const PlacedBall& l : lattice) {
      along = std::max(along, l.position.x - 0.75 * table.length);
      across = std::max(across, std::abs(l.position.y - 0.5 * table.width));
    }
    double need_length = 4.0 * (along + d);
    if (cue_behind_head_string) need_length = std::max(need_length, 4.0 * (2.0 * R + d));
    const double need_width = 2.0 * (across + d);
    throw InvalidArgument(
        "rack", head + "ball '" + b.name + "' at (" + format_number(b.position.x) + ", " + format_number(b.position.y) +
                    ") m is off the playing surface, over a pocket or overlaps a cushion: every centre must lie in [" +
                    format_number(d) + ", " + format_number(table.length - d) + "] x [" + format_number(d) + ", " +
                    format_number(table.width - d) + "] m, clear of jaws and pockets. On a rectangular table this rack "
                    "needs length >= " + format_number(need_length) + " m and width >= " + format_number(need_width) +
                    " m");
  }
  const double min_distance = 2.0 * R - kPlacementTolerance;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    for (std::size_t k = i + 1; k < balls.size(); ++k) {
      const double apart = norm(balls[i].position - balls[k].position);
      if (apart < min_distance) {
        throw InvalidArgument("rack", head + "balls '" + balls[i].name + "' and '" + balls[k].name +
                                          "' overlap: their centres are " + format_number(apart) +
                                          " m apart, at least 2R = " + format_number(2.0 * R) + " m needed");
      }
    }
  }
}

Vec2 pool_cue_ball(const Table& table) {
  // On the long string, one ball diameter behind the head string.
  return {head_string_x(table) - 2.0 * table.ball.radius, 0.5 * table.width};
}

std::vector<PlacedBall> rack_pool(const Table& table, const RackOptions& options,
                                  const std::vector<RackBall>& balls, const char* type) {
  validate(table);
  validate(options);
  std::vector<PlacedBall> out{{0, "cue", pool_cue_ball(table)}};
  const std::vector<PlacedBall> lattice = place(balls, foot_spot(table), table.ball.radius, options);
  out.insert(out.end(), lattice.begin(), lattice.end());
  check_fits(table, out, lattice, type, true);
  return out;
}

}  // namespace

void validate(const RackOptions& options) {
  require_in_range("gap_sigma", options.gap_sigma, 0.0, kMaxGapSigma, "scale of the random gaps in a rack, m");
}

SnookerSpots snooker_spots(const Table& table) {
  const double L = table.length, W = table.width;
  const double along = L / kSnookerLength;
  SnookerSpots s;
  s.baulk_line_x = kBaulkLine * along;
  s.d_radius = kDRadius * (W / kSnookerWidth);
  s.black = {L - kBlackSpotFromTop * along, 0.5 * W};
  s.blue = {0.5 * L, 0.5 * W};
  s.pink = {0.5 * (s.blue.x + L), 0.5 * W};
  s.brown = {s.baulk_line_x, 0.5 * W};
  s.yellow = {s.baulk_line_x, 0.5 * W - s.d_radius};
  s.green = {s.baulk_line_x, 0.5 * W + s.d_radius};
  return s;
}

std::vector<PlacedBall> rack_nine_ball(const Table& table, const RackOptions& options) {
  // Diamond 1-2-3-2-1: the 1 at the apex (foot spot), the 9 in the centre.
  const std::vector<RackBall> balls{
      {1, "1", {0, 0}}, {2, "2", {1, 0}}, {3, "3", {1, 1}}, {4, "4", {2, 0}}, {9, "9", {2, 1}},
      {5, "5", {2, 2}}, {6, "6", {3, 1}}, {7, "7", {3, 2}}, {8, "8", {4, 2}},
  };
  return rack_pool(table, options, balls, "nine_ball");
}

std::vector<PlacedBall> rack_eight_ball(const Table& table, const RackOptions& options) {
  // Rows of 1..5; the 8 in the middle of the third row; back corners 5
  // (solid) and 12 (stripe).
  const std::vector<RackBall> balls{
      {1, "1", {0, 0}},   {9, "9", {1, 0}},   {2, "2", {1, 1}},   {10, "10", {2, 0}}, {8, "8", {2, 1}},
      {3, "3", {2, 2}},   {11, "11", {3, 0}}, {7, "7", {3, 1}},   {14, "14", {3, 2}}, {4, "4", {3, 3}},
      {5, "5", {4, 0}},   {13, "13", {4, 1}}, {15, "15", {4, 2}}, {6, "6", {4, 3}},   {12, "12", {4, 4}},
  };
  return rack_pool(table, options, balls, "eight_ball");
}

std::vector<PlacedBall> rack_snooker(const Table& table, const RackOptions& options) {
  return rack_snooker_with_reds(table, 15, options);
}

std::vector<PlacedBall> rack_snooker_with_reds(const Table& table, int reds_in_rack, const RackOptions& options) {
  validate(table);
  validate(options);
  if (reds_in_rack != 6 && reds_in_rack != 10 && reds_in_rack != 15)
    throw InvalidArgument("reds", std::to_string(reds_in_rack) + " is not one of 6, 10, 15");
  const SnookerSpots s = snooker_spots(table);
  const double R = table.ball.radius;
  // A full triangle of 3, 4 or 5 rows (1+2+3 = 6, +4 = 10, +5 = 15 reds).
  const int rows = reds_in_rack == 6 ? 3 : reds_in_rack == 10 ? 4 : 5;
  std::vector<RackBall> reds;
  int id = 1;
  for (int row = 0; row < rows; ++row) {
    for (int col = 0; col <= row; ++col, ++id) reds.push_back({id, "red" + std::to_string(id), {row, col}});
  }
  // In the D, between the brown and yellow spots.
  std::vector<PlacedBall> out{{0, "cue", {s.baulk_line_x - s.d_radius / 3.0, 0.5 * table.width - 0.5 * s.d_radius}}};
  const Vec2 apex{s.pink.x + 2.0 * R + kPinkApexGap, s.pink.y};
  const std::vector<PlacedBall> lattice = place(reds, apex, R, options);
  out.insert(out.end(), lattice.begin(), lattice.end());
  out.push_back({16, "yellow", s.yellow});
  out.push_back({17, "green", s.green});
  out.push_back({18, "brown", s.brown});
  out.push_back({19, "blue", s.blue});
  out.push_back({20, "pink", s.pink});
  out.push_back({21, "black", s.black});
  check_fits(table, out, lattice, "snooker", false);
  return out;
}


std::vector<PlacedBall> rack_ten_ball(const Table& table, const RackOptions& options) {
  // Rows of 1..4 (WPA 9.2): the 1 at the apex on the foot spot, the 10 in the
  // middle of the third row, the others in a fixed order (the rule book asks
  // for no pattern; a fixed one keeps a seed's rack reproducible).
  const std::vector<RackBall> balls{
      {1, "1", {0, 0}}, {2, "2", {1, 0}}, {3, "3", {1, 1}}, {4, "4", {2, 0}}, {10, "10", {2, 1}},
      {5, "5", {2, 2}}, {6, "6", {3, 0}}, {7, "7", {3, 1}}, {8, "8", {3, 2}}, {9, "9", {3, 3}},
  };
  return rack_pool(table, options, balls, "ten_ball");
}

}  // namespace cueball
