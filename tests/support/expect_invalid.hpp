// expect_invalid(field, f): f() must throw cueball::InvalidArgument naming `field`.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "cueball/core/errors.hpp"

namespace cueball::test {

template <class F>
void expect_invalid(const std::string& field, F&& f) {
  try {
    f();
    ADD_FAILURE() << "no InvalidArgument for " << field;
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.field(), field) << e.what();
  }
}

}  // namespace cueball::test
