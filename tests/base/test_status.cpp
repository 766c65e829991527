// Status and Expected<T>: every code has its own name, an Expected holds a value or an error, and
// an Expected made from an OK status (no value, no error: a bug in the caller) is an Internal error.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "core/base/status.h"

namespace gr {
namespace {

TEST(Status, EveryCodeHasItsOwnName) {
  const std::vector<std::pair<StatusCode, std::string>> names = {
      {StatusCode::Ok, "Ok"},
      {StatusCode::InvalidInput, "InvalidInput"},
      {StatusCode::NonManifold, "NonManifold"},
      {StatusCode::Degenerate, "Degenerate"},
      {StatusCode::NotConverged, "NotConverged"},
      {StatusCode::Cancelled, "Cancelled"},
      {StatusCode::OutOfMemory, "OutOfMemory"},
      {StatusCode::Internal, "Internal"},
  };
  std::set<std::string> seen;
  for (const auto& [code, name] : names) {
    EXPECT_EQ(toString(code), name);
    EXPECT_TRUE(seen.insert(toString(code)).second) << "two codes named " << toString(code);
  }
  // The list above is every code: Internal is the last enumerator.
  EXPECT_EQ(static_cast<int>(StatusCode::Internal) + 1, static_cast<int>(names.size()));
}

TEST(Status, HelpersSetTheirCode) {
  EXPECT_EQ(invalidInput("x").code, StatusCode::InvalidInput);
  EXPECT_EQ(nonManifold("x").code, StatusCode::NonManifold);
  EXPECT_EQ(degenerate("x").code, StatusCode::Degenerate);
  EXPECT_EQ(cancelled().code, StatusCode::Cancelled);
  const Status oom = outOfMemory("out of memory");
  EXPECT_EQ(oom.code, StatusCode::OutOfMemory);
  EXPECT_EQ(oom.message, "out of memory");
  EXPECT_FALSE(oom);
  const Status bug = internalError("internal error: broken invariant");
  EXPECT_EQ(bug.code, StatusCode::Internal);
  EXPECT_EQ(bug.message, "internal error: broken invariant");
  EXPECT_FALSE(bug);
  EXPECT_TRUE(Status::ok());
  EXPECT_EQ(Status::ok().code, StatusCode::Ok);
}

TEST(Expected, FromAValueHoldsItAndAnOkStatus) {
  const Expected<int> e = 42;
  ASSERT_TRUE(e.hasValue());
  EXPECT_TRUE(static_cast<bool>(e));
  EXPECT_EQ(*e, 42);
  EXPECT_EQ(e.value(), 42);
  EXPECT_EQ(e.status().code, StatusCode::Ok);
  EXPECT_TRUE(e.status().isOk());
  EXPECT_TRUE(e.status().message.empty());
}

TEST(Expected, FromAnErrorHoldsTheError) {
  const Expected<std::vector<int>> e = nonManifold("edge 3-7 has three faces");
  EXPECT_FALSE(e.hasValue());
  EXPECT_FALSE(static_cast<bool>(e));
  EXPECT_EQ(e.status().code, StatusCode::NonManifold);
  EXPECT_EQ(e.status().message, "edge 3-7 has three faces");
}

TEST(Expected, FromAnOkStatusIsAnInternalError) {
  const Expected<int> e = Status::ok();
  EXPECT_FALSE(e.hasValue()) << "an OK status with no value must not read as a success";
  EXPECT_FALSE(static_cast<bool>(e));
  EXPECT_EQ(e.status().code, StatusCode::Internal);
  EXPECT_EQ(e.status().message, "an Expected was given an OK status and no value (a bug)");
  // The same through a function returning Expected (the way the bug would happen).
  const auto passOn = [](Status s) -> Expected<double> { return s; };
  EXPECT_EQ(passOn(Status{}).status().code, StatusCode::Internal);
  EXPECT_EQ(passOn(degenerate("face 2")).status().code, StatusCode::Degenerate);
}

}  // namespace
}  // namespace gr
