#include "shared/quadrature/witherden_vincent.hpp"

#include "shared/common/error.hpp"

#include "quadrature_checks.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <string>

namespace altfem {
namespace {

using testing::Shape;
namespace fs = std::filesystem;

const fs::path shipped_tables = fs::path(ALTFEM_SOURCE_DIR) / "data" / "quadrature";

struct DomainCase {
  ReferenceDomain domain;
  Shape shape;
  int table_count;  // files shipped in data/quadrature/<domain> (data/README.md)
};

const DomainCase domain_cases[] = {
    {ReferenceDomain::quadrilateral, Shape::box, 11},
    {ReferenceDomain::triangle, Shape::simplex, 19},
    {ReferenceDomain::hexahedron, Shape::box, 6},
    {ReferenceDomain::tetrahedron, Shape::simplex, 9},
};

// Reads every shipped file independently of the library's folder scan, maps the simplices
// {x_i >= −1, Σ x_i <= 2 − d} onto the unit simplex, and checks exactness up to the
// strength in the file name, positive weights and strictly interior points, except for
// the two tables known to have points on the boundary (reference_rules.cpp skips them).
TEST(WitherdenVincent, EveryShippedTableIsExactPositiveAndInterior) {
  for (const DomainCase& c : domain_cases) {
    const int dimension = reference_dimension(c.domain);
    std::map<int, Eigen::Index> point_counts;  // strength → points, from the files
    for (const auto& entry : fs::directory_iterator(shipped_tables / std::string(reference_domain_name(c.domain)))) {
      const std::string stem = entry.path().stem().string();
      const int strength = std::stoi(stem.substr(0, stem.find('-')));
      const int points = std::stoi(stem.substr(stem.find('-') + 1));
      QuadratureRule rule = read_quadrature_table(entry.path(), dimension, strength);
      ASSERT_EQ(rule.points.rows(), points) << entry.path();
      if (c.shape == Shape::simplex) {
        rule.points = (rule.points.array() + 1.0) / 2.0;
        rule.weights /= std::exp2(dimension);
      }
      EXPECT_NEAR(std::accumulate(rule.weights.begin(), rule.weights.end(), 0.0), reference_measure(c.domain), 1e-14)
          << entry.path();
      EXPECT_TRUE(testing::exact_to_degree(rule, c.shape, strength)) << entry.path();
      const std::string name = std::string(reference_domain_name(c.domain)) + "/" + entry.path().filename().string();
      if (name == "hex/3-6.txt" || name == "tri/16-55.txt") {
        EXPECT_FALSE(testing::positive_and_interior(rule, c.shape)) << name;
        EXPECT_TRUE(testing::positive_and_in_closure(rule, c.shape)) << name;
      } else {
        EXPECT_TRUE(testing::positive_and_interior(rule, c.shape)) << name;
      }
      point_counts[strength] = points;
    }
    EXPECT_EQ(static_cast<int>(point_counts.size()), c.table_count) << reference_domain_name(c.domain);

    // The library's cached, mapped rules are the same tables, sorted by strength.
    const std::vector<QuadratureRule>& rules = witherden_vincent_rules(c.domain);
    ASSERT_EQ(rules.size(), point_counts.size()) << reference_domain_name(c.domain);
    auto expected = point_counts.begin();
    for (const QuadratureRule& rule : rules) {
      EXPECT_EQ(rule.strength, expected->first);
      EXPECT_EQ(rule.points.rows(), expected->second);
      EXPECT_TRUE(testing::exact_to_degree(rule, c.shape, rule.strength)) << reference_domain_name(c.domain);
      EXPECT_TRUE(testing::positive_and_in_closure(rule, c.shape)) << reference_domain_name(c.domain);
      ++expected;
    }
  }
}

TEST(WitherdenVincent, CachedRulesAreLoadedOnce) {
  EXPECT_EQ(&witherden_vincent_rules(ReferenceDomain::tetrahedron),
            &witherden_vincent_rules(ReferenceDomain::tetrahedron));
}

class MalformedTable : public ::testing::Test {
protected:
  const fs::path folder = fs::path(ALTFEM_BINARY_DIR) / "unit_quadrature_tables";
  void SetUp() override { fs::create_directories(folder); }

  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path file = folder / name;
    std::ofstream(file) << text;
    return file;
  }

  // The InputError's message is one line naming the file and `where`.
  static void expect_input_error(const fs::path& file, const std::string& where) {
    try {
      read_quadrature_table(file, 3, 1);
      ADD_FAILURE() << file << " was accepted";
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find(file.string()), std::string::npos) << message;
      EXPECT_NE(message.find(where), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
};

TEST_F(MalformedTable, MissingFile) { expect_input_error(folder / "no-such-table.txt", "cannot open"); }

TEST_F(MalformedTable, WrongNumberOfColumns) {
  expect_input_error(write("columns.txt", "0 0 0 1\n\n0.1 0.2 0.5\n"), "line 3: expected 4 numbers");
}

TEST_F(MalformedTable, NotANumber) {
  expect_input_error(write("number.txt", "0 0 0 1\n0.1 0.2x 0.1 1\n"), "line 2: expected a finite number, got '0.2x'");
  expect_input_error(write("nan.txt", "0 0 nan 1\n"), "line 1: expected a finite number");
}

TEST_F(MalformedTable, NonPositiveWeight) {
  expect_input_error(write("weight.txt", "0 0 0 1\n0 0 0 -0.5\n"), "line 2: expected a positive weight");
}

TEST_F(MalformedTable, Empty) {
  expect_input_error(write("empty.txt", "\n \n"), "expected quadrature points, got none");
}

TEST_F(MalformedTable, ReadsAWellFormedTable) {
  const QuadratureRule rule = read_quadrature_table(write("good.txt", " -0.5 0.25 +1e-1\t2 \r\n\n"), 3, 4);
  ASSERT_EQ(rule.points.rows(), 1);
  EXPECT_EQ(rule.points(0, 0), -0.5);
  EXPECT_EQ(rule.points(0, 1), 0.25);
  EXPECT_EQ(rule.points(0, 2), 0.1);
  EXPECT_EQ(rule.weights(0), 2.0);
  EXPECT_EQ(rule.strength, 4);
}

}  // namespace
}  // namespace altfem
