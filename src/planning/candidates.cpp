// Steps 1-2 of the shot planner (shot_planner.hpp): the candidates that
// geometry gives, one function per kind, and the checks of their straight
// paths.
//
// Sources: ghost-ball aiming and the mirror systems of banks and kicks (D. G.
// Alciatore, "The Illustrated Principles of Pool and Billiards", 2004).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cueball/core/errors.hpp"
#include "planning/search_state.hpp"

namespace cueball::planning {

namespace {

// A cushion's line: where the centre of a ball touching the cushion is (the
// nose line moved in by the contact distance, header comment).
struct CushionLine {
  Vec2 start, along;  // along: unit, start -> end
  double length = 0.0;
  Vec2 normal;        // into the table
  double contact = 0.0;
  CushionLine(const CushionSegment& seg, double R)
      : start(seg.start), along((seg.end - seg.start) / norm(seg.end - seg.start)), length(norm(seg.end - seg.start)),
        normal(inward_normal(seg)), contact(cushion_contact_distance(seg.contact_height, R)) {}
  // Positive on the table's side of the line.
  double signed_distance(Vec2 x) const { return dot(x - start, normal) - contact; }
  Vec2 mirror(Vec2 x) const { return x - 2.0 * signed_distance(x) * normal; }
  // Where a -> b crosses the line (a on the table's side, b beyond it).
  Vec2 crossing(Vec2 a, Vec2 b) const {
    const double sa = signed_distance(a), sb = signed_distance(b);
    return a + sa / (sa - sb) * (b - a);
  }
  // A point of the line that is on the cushion, 3R clear of its ends.
  bool on_cushion(Vec2 x, double R) const {
    const double foot = dot(x - start, along);
    return foot >= 3.0 * R && foot <= length - 3.0 * R;
  }
  // Degrees from the normal at which a ball coming from `from` meets the line at x.
  double incidence_deg(Vec2 from, Vec2 x) const {
    return std::acos(std::clamp(dot((from - x) / norm(from - x), normal), -1.0, 1.0)) / kDegree;
  }
};

// The largest angle from its normal at which a ball may be sent into a cushion, degrees.
constexpr double kMaxIncidenceDeg = 75.0;

Vec2 unit(Vec2 v) { return v / norm(v); }

double angle_between_deg(Vec2 a, Vec2 b) { return std::acos(std::clamp(dot(a, b), -1.0, 1.0)) / kDegree; }

std::string cut_text(double deg) {
  return format_number(std::round(deg * 10) / 10) + " deg > " + format_number(kMaxCutDeg) + " deg";
}

double path_length(const std::vector<Vec2>& legs) {
  double l = 0.0;
  for (std::size_t i = 0; i + 1 < legs.size(); ++i) l += norm(legs[i + 1] - legs[i]);
  return l;
}

// A leg of no length has no direction (a ball frozen to the cushion it
// would be banked off meets that cushion where it is: its bank point is
// the ball itself, and the ghost ball O - 2R u of u = 0/0 is NaN).
bool degenerate(const std::vector<Vec2>& legs) {
  for (std::size_t i = 0; i < legs.size(); ++i) {
    if (!std::isfinite(legs[i].x) || !std::isfinite(legs[i].y)) return true;
    if (i + 1 < legs.size() && !(norm(legs[i + 1] - legs[i]) >= 1e-9)) return true;
  }
  return false;
}

// One target into one pocket: what every kind's geometry reads.
struct Geometry {
  const Scenario& s;
  const PlanRequest& q;
  std::size_t cue, target, pocket;
  double R;
  Vec2 C, O, P;  // the cue ball, the target, the pocket's capture centre
  std::string pocket_name;
  std::string label;  // "ball <id>: " with several targets (PlanRequest::targets), else ""
  std::vector<std::string>& rejected;

  // The cue ball's ghost ball for a ball at b sent towards `towards`.
  Vec2 ghost(Vec2 b, Vec2 towards) const { return b - 2.0 * R * unit(towards - b); }

  // The first ball (other than the cue ball, the target and `also`) whose
  // centre is within 2R of the path a -> b, or "".
  std::string blocker(Vec2 a, Vec2 b, std::optional<std::size_t> also) const {
    for (std::size_t i = 0; i < s.balls.size(); ++i) {
      if (i == cue || i == target || (also && i == *also)) continue;
      if (distance_to_segment(s.balls[i].state.position, a, b) < 2.0 * R) return "ball " + std::to_string(s.balls[i].id);
    }
    return {};
  }

  // Rejects `c` (true) when `ball` meets a cushion more than
  // kMaxIncidenceDeg from its normal.
  bool too_steep(const Candidate& c, const char* ball, double incidence, const char* which) const {
    if (incidence <= kMaxIncidenceDeg) return false;
    rejected.push_back(c.what + ": " + ball + " would meet the cushion at " + format_number(std::round(incidence)) +
                       " deg from its normal (> " + format_number(kMaxIncidenceDeg) + ")" + which);
    return true;
  }
};

// The legs of the cue ball (C -> ... -> its ghost ball of c.first_ball), of
// A (combination: A -> the target's ghost ball) and of the target (O -> ...
// -> P).
struct Legs {
  std::vector<Vec2> cue, middle, object;
};

// The cut angles: the cue ball's on the first ball it meets, A's on the
// target; false (rejected) when either exceeds kMaxCutDeg.
bool cuts_within_limit(const Geometry& g, Candidate& c, const Legs& legs) {
  const std::vector<Vec2>& first_ball_legs = legs.middle.empty() ? legs.object : legs.middle;
  const Vec2 first = unit(first_ball_legs[1] - first_ball_legs[0]);
  const Vec2 w = unit(legs.cue.back() - legs.cue[legs.cue.size() - 2]);
  c.cut_deg = angle_between_deg(w, first);
  if (c.cut_deg > kMaxCutDeg) {
    g.rejected.push_back(c.what + ": cut " + cut_text(c.cut_deg));
    return false;
  }
  if (!legs.middle.empty()) {
    c.combination_cut_deg = angle_between_deg(unit(legs.middle.back() - legs.middle[legs.middle.size() - 2]),
                                              unit(legs.object[1] - legs.object[0]));
    if (c.combination_cut_deg > kMaxCutDeg) {
      g.rejected.push_back(c.what + ": cut of ball " + std::to_string(g.s.balls[*c.intermediate].id) +
                           " on the target " + cut_text(c.combination_cut_deg));
      return false;
    }
  }
  return true;
}

// The swept-circle test of every leg; false (rejected) when one is blocked.
bool paths_clear(const Geometry& g, const Candidate& c, const Legs& legs) {
  for (std::size_t i = 0; i + 1 < legs.cue.size(); ++i) {
    if (const std::string b = g.blocker(legs.cue[i], legs.cue[i + 1], c.intermediate); !b.empty()) {
      g.rejected.push_back(c.what + ": the cue ball's path is blocked by " + b);
      return false;
    }
    // The cue ball must not meet the target first (a combination's
    // target, a kick's target before the cushion).
    const bool last = i + 2 == legs.cue.size();
    if ((c.intermediate || !last) && distance_to_segment(g.O, legs.cue[i], legs.cue[i + 1]) < 2.0 * g.R) {
      g.rejected.push_back(c.what + ": the cue ball's path is blocked by the target");
      return false;
    }
  }
  for (std::size_t i = 0; i + 1 < legs.middle.size(); ++i)
    if (const std::string b = g.blocker(legs.middle[i], legs.middle[i + 1], c.intermediate); !b.empty()) {
      g.rejected.push_back(c.what + ": ball " + std::to_string(g.s.balls[*c.intermediate].id) +
                           "'s path is blocked by " + b);
      return false;
    }
  for (std::size_t i = 0; i + 1 < legs.object.size(); ++i)
    if (const std::string b = g.blocker(legs.object[i], legs.object[i + 1], c.intermediate); !b.empty()) {
      g.rejected.push_back(c.what + ": the object ball's path is blocked by " + b);
      return false;
    }
  return true;
}

// Each cushion halves the ease, a combination's second collision more.
double ease_of(const Candidate& c) {
  double factor = 1.0;
  if (c.kind == ShotKind::bank || c.kind == ShotKind::kick) factor = std::pow(0.5, static_cast<double>(c.cushions.size()));
  if (c.kind == ShotKind::combination) factor = 0.35 * std::cos(c.combination_cut_deg * kDegree);
  return std::cos(c.cut_deg * kDegree) / (c.cue_path + c.middle_path + c.object_path) * factor;
}

// Step 2 for one candidate: its legs checked (a direction, the cuts, the
// paths clear, the cue able to reach the ball), and `c` pushed to `into`
// when they pass, with its aim, paths and ease.
void consider(const Geometry& g, Candidate c, const Legs& legs, std::vector<Candidate>& into) {
  if (degenerate(legs.object) || degenerate(legs.middle)) {
    g.rejected.push_back(c.what + ": the object ball's path has a leg of no length (it touches the cushion)");
    return;
  }
  for (std::size_t i = 0; i + 1 < legs.cue.size(); ++i)
    if (!(norm(legs.cue[i + 1] - legs.cue[i]) >= 1e-9)) {
      g.rejected.push_back(c.what + ": the cue ball is on the ghost ball");
      return;
    }
  if (!cuts_within_limit(g, c, legs) || !paths_clear(g, c, legs)) return;
  c.aim_deg = angle_deg(legs.cue[1] - legs.cue[0]);
  c.cue_path = path_length(legs.cue);
  c.middle_path = path_length(legs.middle);
  c.object_path = path_length(legs.object);
  c.last_leg = unit(legs.object.back() - legs.object[legs.object.size() - 2]);
  // The cue must reach the ball (at some tip height tried).
  bool clear = false;
  for (double height : tip_heights(g.q))
    clear = clear || clearing_elevation(g.s, g.cue, c.aim_deg, g.q.side, height).has_value();
  if (!clear) {
    g.rejected.push_back(c.what + ": the cue is obstructed at every elevation up to " +
                         format_number(kMaxPlanElevationDeg) + " deg");
    return;
  }
  c.ease = ease_of(c);
  into.push_back(c);
}

// direct: the cue ball at the target's ghost ball G = O - 2R u.
void direct_candidate(const Geometry& g, Candidate c, std::vector<Candidate>& out) {
  c.what = g.label + "direct into " + g.pocket_name;
  consider(g, c, {{g.C, g.ghost(g.O, g.P)}, {}, {g.O, g.P}}, out);
}

// kick: G mirrored in each cushion's line (G'), the cue ball aimed at G',
// meeting the line at Y.
void kick_candidates(const Geometry& g, const Candidate& base, const std::vector<std::size_t>& rails,
                     std::vector<Candidate>& out) {
  const Table& table = g.s.table;
  const Vec2 G = g.ghost(g.O, g.P);
  for (std::size_t k : rails) {
    const CushionLine line(table.cushions[k], g.R);
    if (line.signed_distance(g.C) <= 0.0 || line.signed_distance(G) <= 0.0) continue;
    Candidate c = base;
    c.cushions = {k};
    c.what = g.label + "kick off " + cushion_name(table, k) + " into " + g.pocket_name;
    const Vec2 Y = line.crossing(g.C, line.mirror(G));
    if (!line.on_cushion(Y, g.R)) {
      g.rejected.push_back(c.what + ": the cue ball's bank point is not on the cushion");
      continue;
    }
    if (g.too_steep(c, "the cue ball", line.incidence_deg(g.C, Y), "")) continue;
    consider(g, c, {{g.C, Y, G}, {}, {g.O, g.P}}, out);
  }
}

// combination: each other ball A sent to the target's ghost ball G_T, the
// cue ball at A's ghost ball; the kMaxCombinationBalls with the smallest
// combined cut kept.
void combination_candidates(const Geometry& g, const Candidate& base, std::vector<Candidate>& out) {
  const Vec2 GT = g.ghost(g.O, g.P);
  std::vector<Candidate> combinations;
  for (std::size_t i = 0; i < g.s.balls.size(); ++i) {
    if (i == g.cue || i == g.target) continue;
    if (g.q.ball_on && g.s.balls[i].id != *g.q.ball_on) continue;  // it must be met first (PlanRequest::ball_on)
    const Vec2 A = g.s.balls[i].state.position;
    if (norm(GT - A) < 1e-9) continue;
    Candidate c = base;
    c.first_ball = i;
    c.intermediate = i;
    c.what = g.label + "combination via ball " + std::to_string(g.s.balls[i].id) + " into " + g.pocket_name;
    consider(g, c, {{g.C, g.ghost(A, GT)}, {A, GT}, {g.O, g.P}}, combinations);
  }
  // The few with the smallest combined cut.
  std::stable_sort(combinations.begin(), combinations.end(), [](const Candidate& a, const Candidate& b) {
    return a.cut_deg + a.combination_cut_deg < b.cut_deg + b.combination_cut_deg;
  });
  for (std::size_t i = 0; i < combinations.size(); ++i) {
    if (i < kMaxCombinationBalls) out.push_back(combinations[i]);
    else
      g.rejected.push_back(combinations[i].what + ": not among the " + std::to_string(kMaxCombinationBalls) +
                           " with the smallest combined cut");
  }
}

// bank off one cushion: P mirrored in its line (P'), the target sent at P',
// meeting the line at X.
void one_cushion_banks(const Geometry& g, const Candidate& base, const std::vector<std::size_t>& rails,
                       std::vector<Candidate>& out) {
  const Table& table = g.s.table;
  for (std::size_t k : rails) {
    const CushionLine line(table.cushions[k], g.R);
    const double sp = line.signed_distance(g.P), so = line.signed_distance(g.O);
    if (sp < 4.0 * g.R || so <= 0.0) continue;  // the pocket is on this cushion's rail
    Candidate c = base;
    c.cushions = {k};
    c.what = g.label + "bank off " + cushion_name(table, k) + " into " + g.pocket_name;
    const Vec2 X = line.crossing(g.O, line.mirror(g.P));
    if (!line.on_cushion(X, g.R)) {
      g.rejected.push_back(c.what + ": the bank point is not on the cushion");
      continue;
    }
    if (g.too_steep(c, "the object ball", line.incidence_deg(g.O, X), "")) continue;
    consider(g, c, {{g.C, g.ghost(g.O, X)}, {}, {g.O, X, g.P}}, out);
  }
}

// bank off two cushions: P mirrored in the second line (P1), P1 in the
// first (P2); the target sent at P2 meets the first line at X1, the second
// at X2.
void two_cushion_banks(const Geometry& g, const Candidate& base, const std::vector<std::size_t>& rails,
                       std::vector<Candidate>& out) {
  const Table& table = g.s.table;
  for (std::size_t k1 : rails) {
    const CushionLine first(table.cushions[k1], g.R);
    for (std::size_t k2 : rails) {
      const CushionLine second(table.cushions[k2], g.R);
      // Two pieces of one rail (either side of a side pocket) are one line.
      if (k1 == k2 || dot(first.normal, second.normal) > 0.99) continue;
      // P1, P mirrored in the second line; P2, P1 in the first.
      if (second.signed_distance(g.P) < 4.0 * g.R) continue;  // the pocket is on the second cushion's rail
      const Vec2 P1 = second.mirror(g.P);
      if (first.signed_distance(g.O) <= 0.0 || first.signed_distance(P1) <= 0.0 || second.signed_distance(g.O) <= 0.0)
        continue;
      const Vec2 X1 = first.crossing(g.O, first.mirror(P1));
      if (second.signed_distance(X1) <= 0.0) continue;  // the second line would come first
      const Vec2 X2 = second.crossing(X1, P1);
      if (first.signed_distance(X2) <= 0.0) continue;
      Candidate c = base;
      c.cushions = {k1, k2};
      c.what = g.label + "bank off " + cushion_name(table, k1) + ", then " + cushion_name(table, k2) + " into " + g.pocket_name;
      if (!first.on_cushion(X1, g.R) || !second.on_cushion(X2, g.R)) {
        g.rejected.push_back(c.what + ": a bank point is not on its cushion");
        continue;
      }
      if (g.too_steep(c, "the object ball", std::max(first.incidence_deg(g.O, X1), second.incidence_deg(X1, X2)),
                      ", first or second bank"))
        continue;
      consider(g, c, {{g.C, g.ghost(g.O, X1)}, {}, {g.O, X1, X2, g.P}}, out);
    }
  }
}

// Candidates of one kind for one target into one pocket, with the reasons
// others were dropped.
void kind_candidates(const Scenario& s, const PlanRequest& q, std::size_t cue, std::size_t target,
                     std::size_t pocket, ShotKind kind, std::vector<Candidate>& out,
                     std::vector<std::string>& rejected) {
  const Table& table = s.table;
  const Geometry g{s,
                   q,
                   cue,
                   target,
                   pocket,
                   s.settings.parameters.ball.radius,
                   s.balls[cue].state.position,
                   s.balls[target].state.position,
                   table.pockets[pocket].centre,
                   table.pockets[pocket].name,
                   q.targets.size() > 1 ? "ball " + std::to_string(s.balls[target].id) + ": " : "",
                   rejected};
  Candidate base;
  base.kind = kind;
  base.target = target;
  base.pocket = pocket;
  base.first_ball = target;
  // The cushions a ball may be banked or kicked off (not the pocket facings
  // and short pieces).
  std::vector<std::size_t> rails;
  for (std::size_t k = 0; k < table.cushions.size(); ++k)
    if (norm(table.cushions[k].end - table.cushions[k].start) >= 8.0 * g.R) rails.push_back(k);
  switch (kind) {
    case ShotKind::direct: direct_candidate(g, base, out); return;
    case ShotKind::kick: kick_candidates(g, base, rails, out); return;
    case ShotKind::combination: combination_candidates(g, base, out); return;
    case ShotKind::bank:
      one_cushion_banks(g, base, rails, out);
      two_cushion_banks(g, base, rails, out);
      return;
  }
}

}  // namespace

bool kind_allowed(const Scenario& s, const PlanRequest& q, std::size_t target, ShotKind kind) {
  if (!q.ball_on) return true;
  return (s.balls[target].id == *q.ball_on) == (kind != ShotKind::combination);
}

std::vector<double> tip_heights(const PlanRequest& q) {
  if (q.height) return {*q.height};
  return {0.0, -0.3, 0.3};
}

std::optional<double> clearing_elevation(const Scenario& s, std::size_t cue, double aim_deg, double side,
                                         double height) {
  for (int k = 0; 2.0 * k <= kMaxPlanElevationDeg; ++k) {
    const ShotAction probe{1.0, aim_deg, 2.0 * k, side, height};
    if (!cue_obstructed(s.table, s.balls, s.balls[cue].id, to_strike(probe, s.settings.parameters.ball.radius),
                        s.settings.parameters.ball))
      return 2.0 * k;
  }
  return std::nullopt;
}

void geometric_candidates(SearchState& st) {
  const PlanRequest& q = st.q;
  for (std::size_t target : st.targets)
    for (std::size_t k = 0; k < st.s.table.pockets.size(); ++k) {
      if (q.pocket && static_cast<std::size_t>(*q.pocket) != k) continue;
      for (ShotKind kind : kShotKinds)
        if (std::find(q.kinds.begin(), q.kinds.end(), kind) != q.kinds.end() && kind_allowed(st.s, q, target, kind))
          kind_candidates(st.s, q, st.cue, target, k, kind, st.candidates, st.result.rejected);
    }
  std::stable_sort(st.candidates.begin(), st.candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.ease > b.ease; });
}

}  // namespace cueball::planning
