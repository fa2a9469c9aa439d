// The parameter table: unique names, sane ranges, and parsing as the CLI's --set does it.
#include "core/material/Material.h"
#include "core/material/Parameters.h"
#include "support/TestPaths.h"

#include <QRegularExpression>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

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

// The renderer sets each parameter's uniform from the table, by kind; a name or type that the
// shader does not declare would be dropped silently by GL, so the table is checked against the
// shader source here.
TEST(Parameters, EveryUniformInTheTableIsDeclaredInTheShaderWithItsType) {
  std::ifstream file(test::sourcePath("shaders/include/material_inputs.glsl"));
  ASSERT_TRUE(file) << "material_inputs.glsl not found";
  std::stringstream source;
  source << file.rdbuf();
  const std::string text = source.str();
  int withUniform = 0;
  for (const ParameterSpec& spec : allParameters()) {
    if (spec.uniform.empty()) {
      // Shader-variant switches: choices and flags the renderer turns into #defines.
      EXPECT_TRUE(spec.kind == ParamKind::Choice || spec.kind == ParamKind::Bool) << spec.name;
      continue;
    }
    ++withUniform;
    const char* type = spec.kind == ParamKind::Float  ? "float"
                       : spec.kind == ParamKind::Bool ? "bool"
                                                      : "int";
    // QRegularExpression: GCC 12 warns falsely inside std::regex at -O2.
    const QRegularExpression declaration(
        QStringLiteral("uniform\\s+%1\\s+%2\\s*;")
            .arg(QLatin1String(type))
            .arg(QString::fromUtf8(spec.uniform.data(), qsizetype(spec.uniform.size()))));
    EXPECT_TRUE(declaration.match(QString::fromStdString(text)).hasMatch())
        << spec.name << ": no 'uniform " << type << " " << spec.uniform << ";'";
  }
  EXPECT_GE(withUniform, 15);
}

TEST(Parameters, UseFollowsTechniqueAndShadowMode) {
  const auto inUse = [](ParamId id, Technique technique, ShadowMode shadows) {
    return parameterInUse(parameterSpec(id), technique, shadows, ShadingModel::Classic);
  };
  EXPECT_FALSE(inUse(ParamId::MinSamples, Technique::Parallax, ShadowMode::Soft));
  EXPECT_TRUE(inUse(ParamId::MaxSamples, Technique::Pom, ShadowMode::Off));
  EXPECT_TRUE(inUse(ParamId::RefinementSteps, Technique::Relief, ShadowMode::Off));
  EXPECT_FALSE(inUse(ParamId::RefinementSteps, Technique::Pom, ShadowMode::Off));
  EXPECT_FALSE(inUse(ParamId::ShadowSamples, Technique::Pom, ShadowMode::Off));
  EXPECT_TRUE(inUse(ParamId::ShadowSamples, Technique::Pom, ShadowMode::Hard));
  EXPECT_FALSE(inUse(ParamId::ShadowSoftness, Technique::Pom, ShadowMode::Hard));
  EXPECT_TRUE(inUse(ParamId::ShadowSoftness, Technique::Relief, ShadowMode::Soft));
  EXPECT_TRUE(inUse(ParamId::HeightScale, Technique::Normal, ShadowMode::Off));
  EXPECT_TRUE(inUse(ParamId::MaxTessellation, Technique::Displacement, ShadowMode::Off));
  EXPECT_FALSE(inUse(ParamId::MaxTessellation, Technique::Pom, ShadowMode::Off));
  EXPECT_FALSE(inUse(ParamId::MaxSamples, Technique::Displacement, ShadowMode::Off));
  EXPECT_FALSE(inUse(ParamId::DepthOffset, Technique::Displacement, ShadowMode::Off));
  EXPECT_FALSE(inUse(ParamId::LodFade, Technique::Displacement, ShadowMode::Off));
  EXPECT_TRUE(inUse(ParamId::DepthOffset, Technique::Normal, ShadowMode::Off));
}

TEST(Parameters, EachShadingModelUsesItsOwnTerms) {
  const auto inUse = [](ParamId id, ShadingModel shading) {
    return parameterInUse(parameterSpec(id), Technique::Pom, ShadowMode::Soft, shading);
  };
  EXPECT_TRUE(inUse(ParamId::Shininess, ShadingModel::Classic));
  EXPECT_FALSE(inUse(ParamId::Shininess, ShadingModel::Pbr));
  EXPECT_FALSE(inUse(ParamId::Specular, ShadingModel::Pbr));
  EXPECT_TRUE(inUse(ParamId::Roughness, ShadingModel::Pbr));
  EXPECT_TRUE(inUse(ParamId::Metallic, ShadingModel::Pbr));
  EXPECT_FALSE(inUse(ParamId::Metallic, ShadingModel::Classic));
  EXPECT_TRUE(inUse(ParamId::Shading, ShadingModel::Classic));
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
