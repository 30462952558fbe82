#include <gtest/gtest.h>

#include <set>
#include <string>

#include "shared/common/error.hpp"
#include "shared/material/material.hpp"
#include "shared/material/stable_neo_hookean.hpp"

namespace altfem {
namespace {

TEST(MaterialFactory, NamesRoundTrip) {
  std::set<std::string> names;
  for (MaterialModel model : all_material_models) {
    const std::string_view name = material_model_name(model);
    names.emplace(name);
    ASSERT_TRUE(material_model_from_name(name).has_value()) << name;
    EXPECT_EQ(*material_model_from_name(name), model);
  }
  EXPECT_EQ(names, (std::set<std::string>{"linear", "corotated_linear", "st_venant_kirchhoff", "neo_hookean",
                                          "stable_neo_hookean"}));
  EXPECT_FALSE(material_model_from_name("neohookean").has_value());
  EXPECT_FALSE(material_model_from_name("").has_value());
}

TEST(MaterialFactory, MakesEveryModelWithItsParameters) {
  const LameParameters expected = lame_parameters(3e6, 0.4);
  for (MaterialModel model : all_material_models) {
    const auto material = make_material(model, 3e6, 0.4, 1200.0);
    EXPECT_EQ(material->model(), model);
    EXPECT_EQ(material->lame().lambda, expected.lambda);
    EXPECT_EQ(material->lame().mu, expected.mu);
    EXPECT_EQ(material->density(), 1200.0);
    EXPECT_EQ(material->is_linear(), model == MaterialModel::linear);
  }
  EXPECT_THROW(make_material(MaterialModel::neo_hookean, 3e6, 0.4, -1.0), InputError);
  EXPECT_THROW(make_material(MaterialModel::neo_hookean, 3e6, 0.6, 1.0), InputError);
}

// Smith et al. 2018's reparametrisation μ' = 4μ/3, λ' = λ + 5μ/6.
TEST(MaterialFactory, StableNeoHookeanReparametrisesLame) {
  const LameParameters lame = lame_parameters(1e6, 0.3);
  const StableNeoHookean material(lame, 1000.0);
  EXPECT_DOUBLE_EQ(material.energy_lame().mu, 4.0 / 3.0 * lame.mu);
  EXPECT_DOUBLE_EQ(material.energy_lame().lambda, lame.lambda + 5.0 / 6.0 * lame.mu);
}

}  // namespace
}  // namespace altfem
