// The #include resolver: expansion order, include-once, errors that name file and line, and
// driver logs mapped back to the original file and line.
#include "renderer/ShaderIncludeResolver.h"

#include <gtest/gtest.h>

#include <map>

namespace relief::renderer {
namespace {

ShaderSourceLoader loaderFor(std::map<std::string, std::string> files) {
  return [files = std::move(files)](const std::string& path) -> std::optional<std::string> {
    const auto it = files.find(path);
    if (it == files.end())
      return std::nullopt;
    return it->second;
  };
}

TEST(ShaderIncludeResolver, ExpandsNestedIncludesInPlace) {
  const auto loader = loaderFor({
      {"main.frag", "// main\n#include \"lib/a.glsl\"\nvoid main() {}\n"},
      {"lib/a.glsl", "#include \"b.glsl\"\nfloat a;\n"},
      {"lib/b.glsl", "float b;\n"},
  });
  core::Result<ResolvedShader> resolved =
      resolveShaderIncludes("main.frag", loader, "#version 410 core\n");
  ASSERT_TRUE(resolved.ok()) << resolved.error();
  EXPECT_EQ(resolved->source, "#version 410 core\n// main\nfloat b;\nfloat a;\nvoid main() {}\n");
  ASSERT_EQ(resolved->lineOrigins.size(), 5u);
  EXPECT_EQ(resolved->lineOrigins[0].file, "<prelude>");
  EXPECT_EQ(resolved->lineOrigins[1].file, "main.frag");
  EXPECT_EQ(resolved->lineOrigins[1].line, 1);
  EXPECT_EQ(resolved->lineOrigins[2].file, "lib/b.glsl");
  EXPECT_EQ(resolved->lineOrigins[2].line, 1);
  EXPECT_EQ(resolved->lineOrigins[3].file, "lib/a.glsl");
  EXPECT_EQ(resolved->lineOrigins[3].line, 2);
  EXPECT_EQ(resolved->lineOrigins[4].file, "main.frag");
  EXPECT_EQ(resolved->lineOrigins[4].line, 3);
}

TEST(ShaderIncludeResolver, IncludesEachFileOnce) {
  const auto loader = loaderFor({
      {"main.frag", "#include \"a.glsl\"\n#include \"b.glsl\"\n#include \"./a.glsl\"\n"},
      {"a.glsl", "A\n"},
      {"b.glsl", "#include \"a.glsl\"\nB\n"},
  });
  core::Result<ResolvedShader> resolved = resolveShaderIncludes("main.frag", loader);
  ASSERT_TRUE(resolved.ok()) << resolved.error();
  EXPECT_EQ(resolved->source, "A\nB\n");
}

TEST(ShaderIncludeResolver, ReportsMissingFilesAndCyclesWithTheirLocation) {
  const auto missing = loaderFor({{"main.frag", "x\ny\n#include \"gone.glsl\"\n"}});
  core::Result<ResolvedShader> first = resolveShaderIncludes("main.frag", missing);
  ASSERT_FALSE(first.ok());
  EXPECT_NE(first.error().find("main.frag:3"), std::string::npos) << first.error();
  EXPECT_NE(first.error().find("gone.glsl"), std::string::npos) << first.error();

  const auto cycle =
      loaderFor({{"a.glsl", "#include \"b.glsl\"\n"}, {"b.glsl", "#include \"a.glsl\"\n"}});
  core::Result<ResolvedShader> second = resolveShaderIncludes("a.glsl", cycle);
  ASSERT_FALSE(second.ok());
  EXPECT_NE(second.error().find("cycle"), std::string::npos) << second.error();
  EXPECT_NE(second.error().find("b.glsl:1"), std::string::npos) << second.error();

  EXPECT_FALSE(resolveShaderIncludes("nothing.frag", missing).ok());
}

TEST(ShaderIncludeResolver, MapsDriverLogsToFileAndLine) {
  std::vector<SourceLocation> origins = {
      {"<prelude>", 1}, {"main.frag", 1}, {"include/lighting.glsl", 7}, {"main.frag", 2}};
  // Mesa (llvmpipe, radeonsi, iris).
  EXPECT_EQ(mapShaderLog("0:3(12): error: `foo' undeclared\n", origins),
            "include/lighting.glsl:7: error: `foo' undeclared\n");
  // NVIDIA.
  EXPECT_EQ(mapShaderLog("0(4) : error C1008: undefined variable \"x\"\n", origins),
            "main.frag:2: error C1008: undefined variable \"x\"\n");
  // AMD and Intel on Windows.
  EXPECT_EQ(mapShaderLog("ERROR: 0:3: 'bar' : undeclared identifier\n", origins),
            "ERROR: include/lighting.glsl:7: 'bar' : undeclared identifier\n");
  // Out-of-range and unrecognised lines pass through unchanged.
  EXPECT_EQ(mapShaderLog("0:99(1): error: x\nlinker said no\n", origins),
            "0:99(1): error: x\nlinker said no\n");
  EXPECT_EQ(mapShaderLog("0:99999999999999999999(1): error\n", origins),
            "0:99999999999999999999(1): error\n");
}

}  // namespace
}  // namespace relief::renderer
