// Measured cushion impacts as CSV, the data `cueball fit-cushion` and
// fit_cushion() (models/cushion/fit.hpp) take.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "cueball/models/cushion/fit.hpp"

namespace cueball {

/// Fewest residuals a fit needs: two constants and an error estimate (a
/// head-on impact gives one, an oblique one two).
inline constexpr std::size_t kMinFitResiduals = 3;

/// Reads measured impacts: per line either "v0,v_out" (head-on, rolling, no
/// side spin: the paper's experiment) or "v0,alpha_deg,topspin_k,sidespin_k,
/// v_out,beta_deg" (oblique). '#' starts a comment; a UTF-8 byte-order mark at
/// the start is skipped; the first line is a header when none of its cells is
/// a number. Every other line is data: an empty or non-numeric cell is an error
/// naming the file, the line and the cell.
/// `file` names the text in the messages (a quoted file name); `radius` is
/// the ball radius (m) that converts the spins given as K V0 / R. Errors are
/// InvalidArgument whose field is `file` and whose message names the line
/// and the cell.
CushionFitData cushion_fit_data_from_csv(std::string_view csv, const std::string& file, double radius);

}  // namespace cueball
