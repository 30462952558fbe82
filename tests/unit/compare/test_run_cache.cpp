// The run cache key: equal resolved options give equal hashes, any change a different one.
#include <gtest/gtest.h>

#include "shared/compare/run_hash.hpp"

namespace altfem {
namespace {

using nlohmann::json;

TEST(RunHash, DependsOnOptionsAndMethodButNotOnKeyOrderNameOrCompareBlock) {
  const json a = json::parse(R"({"name": "a", "material": {"poisson_ratio": 0.3, "youngs_modulus": 1e6}})");
  const json b = json::parse(R"({"material": {"youngs_modulus": 1e6, "poisson_ratio": 0.3}, "name": "b",
                                 "compare": {"methods": ["fem"]}})");
  const json c = json::parse(R"({"material": {"youngs_modulus": 1e6, "poisson_ratio": 0.31}})");
  EXPECT_EQ(run_hash("fem", a), run_hash("fem", b));
  EXPECT_NE(run_hash("fem", a), run_hash("fem", c));
  EXPECT_NE(run_hash("fem", a), run_hash("dg", a));
  EXPECT_EQ(run_hash("fem", a).size(), 16u);
  EXPECT_EQ(run_hash("fem", a).find_first_not_of("0123456789abcdef"), std::string::npos);
}

TEST(RunHash, IsFnv1aOfTheCanonicalText) {
  // FNV-1a 64 of "m\nnull" computed by hand from its definition.
  std::uint64_t hash = 14695981039346656037ull;
  for (const unsigned char c : std::string("m\nnull")) hash = (hash ^ c) * 1099511628211ull;
  char expected[17];
  std::snprintf(expected, sizeof expected, "%016llx", static_cast<unsigned long long>(hash));
  EXPECT_EQ(run_hash("m", json()), expected);
}

}  // namespace
}  // namespace altfem
