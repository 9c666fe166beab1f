// The measured-impacts reader (src/io/cushion_fit_data.cpp): what it accepts,
// the units it converts, and the line and cell each error names.
#include "cueball/io/cushion_fit_data.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "cueball/core/errors.hpp"

namespace cueball {
namespace {

constexpr double R = 0.028575;

std::string error_of(const std::string& csv) {
  try {
    (void)cushion_fit_data_from_csv(csv, "\"data.csv\"", R);
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.field(), "\"data.csv\"");
    return e.what();
  }
  return "no error";
}

TEST(CushionFitData, ReadsHeadOnAndObliqueRowsWithAHeaderCommentsAndABom) {
  const CushionFitData d = cushion_fit_data_from_csv(
      "\xEF\xBB\xBFv0,v_out\n# a comment\n1.0,0.8\n\n2.0,1.6  # trailing\n1.5,30,0.5,-0.25,1.2,40\n", "\"data.csv\"", R);
  ASSERT_EQ(d.head_on.size(), 2u);
  EXPECT_EQ(d.head_on[1].incoming_speed, 2.0);
  EXPECT_EQ(d.head_on[1].rebound_speed, 1.6);
  ASSERT_EQ(d.oblique.size(), 1u);
  const ObliqueRebound& o = d.oblique[0];
  EXPECT_EQ(o.incidence.speed, 1.5);
  EXPECT_DOUBLE_EQ(o.incidence.angle, 30.0 * std::numbers::pi / 180.0);
  EXPECT_DOUBLE_EQ(o.incidence.topspin, 0.5 * 1.5 / R);    // K V0 / R
  EXPECT_DOUBLE_EQ(o.incidence.sidespin, -0.25 * 1.5 / R);
  EXPECT_DOUBLE_EQ(o.rebound_angle, 40.0 * std::numbers::pi / 180.0);
}

TEST(CushionFitData, ErrorsNameTheLineAndTheCell) {
  EXPECT_EQ(error_of("1,0.8\n2,abc\n3,2\n"), "\"data.csv\":2: cell 2 = \"abc\" is not a number; expected v0,v_out or "
                                             "v0,alpha_deg,topspin_k,sidespin_k,v_out,beta_deg");
  EXPECT_EQ(error_of("1,0.8\n40,1\n3,2\n"),
            "\"data.csv\":2: v0 = 40 is outside the allowed range [1e-06, 30] (incoming speed, m/s)");
  EXPECT_NE(error_of("1,0.8\n1,2,3\n3,2\n").find("\"data.csv\":2: expected 2 numbers"), std::string::npos);
  EXPECT_NE(error_of("1,0.8\n2,1.6\n").find("too few"), std::string::npos);  // 2 residuals < kMinFitResiduals
  EXPECT_NE(error_of("1,0.8\n2,inf\n3,2\n").find("cell 2"), std::string::npos);
  // A header only on the first line: a later all-text line is an error.
  EXPECT_NE(error_of("1,0.8\nv0,v_out\n3,2\n").find("\"data.csv\":2: cell 1"), std::string::npos);
}

}  // namespace
}  // namespace cueball
