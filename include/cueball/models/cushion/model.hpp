// The ball-cushion models by name: one is chosen once, at the API boundary
// (SimulationSettings::cushion, a scenario's "cushion": {"model": ...}), its
// constants are validated and built once per contact height
// (cushion_contact()), and the simulator's hot path dispatches on the name
// with a switch (cushion_rebound()): plain structs and functions, no class
// hierarchy.
//
//   mathavan_2010      cushion_impact.hpp (src/cushion/mathavan_2010*.cpp): the
//                      impact integrated over the normal impulse with friction
//                      at the cushion and at the bed; solver "exact" (the
//                      default) or the paper's Euler scheme ("paper").
//   han_2005           cushion/han_2005.hpp: one impulse at the cushion, closed
//                      form, the bed not involved.
//   stronge_compliant  cushion/stronge_compliant.hpp: Stronge's compliant
//                      contact (normal and tangential springs: slip, stick and
//                      slip reversal in closed form), applied at the ball's
//                      equator as pooltool does; the bed not involved.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "cueball/models/cushion/han_2005.hpp"
#include "cueball/models/cushion/rebound.hpp"
#include "cueball/models/cushion/stronge_compliant.hpp"
#include "cueball/models/cushion/impact.hpp"
#include "cueball/core/parameters.hpp"

namespace cueball {

enum class CushionModel { mathavan_2010, han_2005, stronge_compliant };

/// Every model, in the order of the names.
inline constexpr std::array kCushionModels{CushionModel::mathavan_2010, CushionModel::han_2005,
                                           CushionModel::stronge_compliant};

/// "mathavan_2010", "han_2005", "stronge_compliant".
const char* to_string(CushionModel model);

/// The model of that name, if there is one (the caller names its field in the error).
std::optional<CushionModel> cushion_model_from_string(std::string_view name);

/// The names, comma-separated, each between `quote`s: for messages and help texts.
std::string cushion_model_names(std::string_view quote = "\"");

/// "exact" or "paper" (the Euler scheme of Mathavan 2010).
const char* to_string(CushionSolver solver);
std::optional<CushionSolver> cushion_solver_from_string(std::string_view name);

/// Most Euler steps per impact in a simulation (some 4 ms an impact; a
/// single impact, cushion_impact(), takes more).
inline constexpr int kMaxCushionPaperSteps = 100000;

/// The cushion of a simulation: the model and its constants. The contact
/// height comes from each cushion and jaw of the table.
struct CushionSettings {
  CushionModel model = CushionModel::mathavan_2010;
  /// mathavan_2010: e_e, the energetic coefficient (16b), (0, 1];
  /// han_2005: Newton's coefficient e along the common normal, [0, 1];
  /// stronge_compliant: Stronge's energetic e, (0, 1].
  double restitution = 0.98;
  /// mathavan_2010: mu_w, [0, tan(theta)]; han_2005 and stronge_compliant: mu, [0, 1].
  double friction = 0.14;
  /// stronge_compliant only: Omega, the ratio of the tangential to the normal
  /// natural frequency of the contact (S3), (1, 1000].
  double frequency_ratio = 1.8;
  /// mathavan_2010 only: the exact solver (default) or the paper's Euler scheme.
  CushionSolver solver = CushionSolver::exact;
  /// mathavan_2010 with solver paper: N, the Euler steps per impact, [1, kMaxCushionPaperSteps].
  int paper_steps = 5000;
  /// mathavan_2010 with solver exact: the local error per Runge-Kutta step,
  /// relative to the largest incoming velocity (CushionImpactOptions::
  /// exact_tolerance), [1e-11, 1e-7]. The default 1e-8 keeps the accuracy
  /// goal (1e-6 of that velocity from the N -> infinity limit); 1e-7 is for
  /// planners' inner loops: on the 6,158 sliding impacts of one plan_shot
  /// (README, "Cushion models") it takes 29% less time a sliding impact, and
  /// is 1e-7 of that velocity from the reference at the median, 8e-7 at the
  /// 99.9th percentile, 6.8e-6 at worst (6 impacts beyond 1e-6, where a slip
  /// passes close to zero). Rolling balls are looked up in the same table.
  double exact_tolerance = CushionImpactOptions{}.exact_tolerance;
  friend bool operator==(const CushionSettings&, const CushionSettings&) = default;
};

/// Each model's own constants, as its source gives them: mathavan_2010 the
/// authors' fit (e_e = 0.98, mu_w = 0.14, section 3.5, fitted with their
/// Euler scheme and equally close with the exact solver); han_2005 e = 0.85,
/// mu = 0.2 (cushion/han_2005.hpp); stronge_compliant pooltool's e = 0.85,
/// mu = 0.2, Omega = 1.8 (cushion/stronge_compliant.hpp).
CushionSettings default_cushion_settings(CushionModel model);

/// The chosen model's constants for one contact height, validated: what the
/// simulator keeps per cushion and jaw.
struct CushionContact {
  CushionModel model = CushionModel::mathavan_2010;
  CushionImpactModel mathavan;
  CushionImpactOptions mathavan_options;
  Han2005Cushion han;
  StrongeCompliantCushion stronge;
};

/// Validates `settings` (InvalidArgument names "cushion_restitution",
/// "cushion_friction", "cushion_paper_steps", "cushion_exact_tolerance",
/// "cushion_frequency_ratio" or
/// the model's constant) and builds the contact at height h (which
/// stronge_compliant, applied at the equator, does not use).
CushionContact cushion_contact(const Parameters& table, const CushionSettings& settings, double contact_height);

/// The ball just after the impact, by the contact's model. `ball` moves into
/// the cushion (yG' > 0, zG' = 0). Throws InfeasibleShot where mathavan_2010
/// has no rebound (the ball wedges between cushion and bed).
CushionRebound cushion_rebound(const IncomingBall& ball, const CushionContact& contact);

}  // namespace cueball
