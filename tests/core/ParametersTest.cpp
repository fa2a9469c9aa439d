// The parameter table: unique names, sane ranges, and parsing as the CLI's --set does it.
#include "core/Material.h"
#include "core/Parameters.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>

namespace relief::core {
namespace {

TEST(Parameters, TableIsConsistent) {
  std::set<std::string_view> names;
  for (std::size_t i = 0; i < allParameters().size(); ++i) {
    const ParameterSpec& spec = allParameters()[i];
    EXPECT_EQ(std::size_t(spec.id), i) << spec.name;
    EXPECT_TRUE(names.insert(spec.name).second) << "duplicate " << spec.name;
    EXPECT_LT(spec.minimum, spec.maximum) << spec.name;
    EXPECT_GE(spec.defaultValue, spec.minimum) << spec.name;
    EXPECT_LE(spec.defaultValue, spec.maximum) << spec.name;
    EXPECT_FALSE(spec.unit.empty()) << spec.name;
    EXPECT_FALSE(spec.description.empty()) << spec.name;
    EXPECT_EQ(findParameter(spec.name), spec.id);
  }
  EXPECT_EQ(allParameters().size(), kParamCount);
}

TEST(Parameters, ParsesNumbersAndBooleansAndRejectsNonsense) {
  const ParameterSpec& tiling = parameterSpec(ParamId::Tiling);
  EXPECT_EQ(parseOptionValue(tiling, "2.5").value(), 2.5);
  EXPECT_FALSE(parseOptionValue(tiling, "abc").ok());
  EXPECT_FALSE(parseOptionValue(tiling, "2.5x").ok());
  EXPECT_FALSE(parseOptionValue(tiling, "nan").ok());
  Result<double> outside = parseOptionValue(tiling, "1000");
  ASSERT_FALSE(outside.ok());
  EXPECT_NE(outside.error().find("tiling"), std::string::npos) << outside.error();

  const ParameterSpec& yDown = parameterSpec(ParamId::NormalYDown);
  EXPECT_EQ(parseOptionValue(yDown, "true").value(), 1.0);
  EXPECT_EQ(parseOptionValue(yDown, "OFF").value(), 0.0);
  EXPECT_FALSE(parseOptionValue(yDown, "maybe").ok());
}

TEST(Parameters, MaterialClampsAndReplacesNonFiniteValues) {
  Material material;
  material.setParameter(ParamId::Tiling, 1e9);
  EXPECT_EQ(material.parameter(ParamId::Tiling), parameterSpec(ParamId::Tiling).maximum);
  material.setParameter(ParamId::Tiling, std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(material.parameter(ParamId::Tiling), parameterSpec(ParamId::Tiling).defaultValue);
  material.setParameter(ParamId::NormalYDown, 0.7);
  EXPECT_EQ(material.parameter(ParamId::NormalYDown), 1.0);
}

}  // namespace
}  // namespace relief::core
