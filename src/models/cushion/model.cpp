// The cushion models by name (include/cueball/models/cushion/model.hpp).

#include "cueball/models/cushion/model.hpp"

#include <cmath>

#include "cueball/core/errors.hpp"
#include "core/enum_names.hpp"
#include "mathavan_2010_equations.hpp"

namespace cueball {

const char* to_string(CushionModel model) {
  switch (model) {
    case CushionModel::mathavan_2010: return "mathavan_2010";
    case CushionModel::han_2005: return "han_2005";
    case CushionModel::stronge_compliant: return "stronge_compliant";
  }
  return "?";
}

std::optional<CushionModel> cushion_model_from_string(std::string_view name) {
  return value_named(kCushionModels, name);
}

std::string cushion_model_names(std::string_view quote) {
  return names_of(kCushionModels, quote);
}

const char* to_string(CushionSolver solver) { return solver == CushionSolver::paper ? "paper" : "exact"; }

std::optional<CushionSolver> cushion_solver_from_string(std::string_view name) {
  if (name == "exact") return CushionSolver::exact;
  if (name == "paper") return CushionSolver::paper;
  return std::nullopt;
}

CushionSettings default_cushion_settings(CushionModel model) {
  CushionSettings s;
  s.model = model;
  if (model == CushionModel::han_2005) {
    s.restitution = kHan2005Restitution;
    s.friction = kHan2005Friction;
  } else if (model == CushionModel::stronge_compliant) {
    const StrongeCompliantConstants k;
    s.restitution = k.restitution;
    s.friction = k.friction;
    s.frequency_ratio = k.frequency_ratio;
  }
  return s;
}

CushionContact cushion_contact(const Parameters& table, const CushionSettings& settings, double contact_height) {
  CushionContact c;
  c.model = settings.model;
  switch (settings.model) {
    case CushionModel::mathavan_2010:
      require_in_range("cushion_restitution", settings.restitution, 1e-9, 1.0, "Mathavan e_e");
      require_in_range("cushion_friction", settings.friction, 0.0, 1.0, "Mathavan mu_w");
      if (settings.paper_steps < 1 || settings.paper_steps > kMaxCushionPaperSteps)
        throw InvalidArgument("cushion_paper_steps", settings.paper_steps, "[1, " + std::to_string(kMaxCushionPaperSteps) + "]",
                              "Euler steps per impact");
      require_in_range("cushion_exact_tolerance", settings.exact_tolerance, kMinExactTolerance, kMaxExactTolerance,
                       "the exact solver's local error per step");
      c.mathavan = cushion_impact_model(table, {settings.restitution, settings.friction, contact_height});
      c.mathavan_options.solver = settings.solver;
      c.mathavan_options.paper_steps = settings.paper_steps;
      c.mathavan_options.exact_tolerance = settings.exact_tolerance;
      break;
    case CushionModel::han_2005:
      validate(table);
      require_in_range("cushion_restitution", settings.restitution, 0.0, 1.0, "Han 2005 e");
      require_in_range("cushion_friction", settings.friction, 0.0, 1.0, "Han 2005 mu");
      c.han = han_2005_cushion(table.ball, settings.restitution, settings.friction, contact_height);
      validate(c.han);  // the contact height: sin_theta
      break;
    case CushionModel::stronge_compliant: {
      validate(table);
      require_in_range("cushion_restitution", settings.restitution, 1e-9, 1.0, "Stronge's energetic e");
      require_in_range("cushion_friction", settings.friction, 0.0, 1.0, "mu");
      if (!(settings.frequency_ratio > 1.0 && settings.frequency_ratio <= 1000.0))
        throw InvalidArgument("cushion_frequency_ratio", settings.frequency_ratio, "(1, 1000]",
                              "Omega, tangential over normal natural frequency");
      StrongeCompliantConstants k;
      k.restitution = settings.restitution;
      k.friction = settings.friction;
      k.frequency_ratio = settings.frequency_ratio;
      c.stronge = stronge_compliant_cushion(table.ball, k);
      break;
    }
  }
  return c;
}

CushionRebound cushion_rebound(const IncomingBall& ball, const CushionContact& contact) {
  switch (contact.model) {
    case CushionModel::mathavan_2010: return mathavan_2010::rebound(ball, contact.mathavan, contact.mathavan_options);
    case CushionModel::han_2005: return han_2005_rebound(ball, contact.han);
    case CushionModel::stronge_compliant: return stronge_compliant_rebound(ball, contact.stronge);
  }
  return {ball.velocity, ball.angular_velocity};
}

}  // namespace cueball
