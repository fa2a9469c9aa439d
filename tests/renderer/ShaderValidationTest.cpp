// Every shader program, expanded exactly as the renderer expands it (from the embedded
// resources), is accepted by glslangValidator, the Khronos reference compiler. This catches
// what llvmpipe tolerates but a stricter driver would reject.
#include "renderer/ShaderProgram.h"
#include "renderer/ShaderVariant.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>

namespace relief::renderer {
namespace {

struct Stage {
  const char* path;
  const char* extension;  // glslangValidator picks the stage from it
};

std::string runValidator(const std::string& file, int& exitCode) {
  const std::string command = "glslangValidator '" + file + "' 2>&1";
  std::string output;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) {
    exitCode = -1;
    return "cannot run glslangValidator";
  }
  std::array<char, 512> buffer{};
  while (fgets(buffer.data(), int(buffer.size()), pipe))
    output += buffer.data();
  const int status = pclose(pipe);
  exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return output;
}

TEST(ShaderValidation, EveryStageCompilesWithGlslang) {
  const Stage stages[] = {{"material.vert", ".vert"},   {"material.tesc", ".tesc"},
                          {"material.tese", ".tese"},   {"material.frag", ".frag"},
                          {"background.vert", ".vert"}, {"background.frag", ".frag"}};
  for (const Stage& stage : stages) {
    core::Result<ResolvedShader> resolved =
        resolveShaderIncludes(stage.path, loadShaderSource, shaderPrelude(materialTableDefines()));
    ASSERT_TRUE(resolved.ok()) << resolved.error();
    const std::string file = test::scratchFolder() + "/expanded_" + stage.path + stage.extension;
    std::ofstream(file) << resolved->source;
    int exitCode = 0;
    const std::string log = runValidator(file, exitCode);
    ASSERT_NE(exitCode, 127) << "glslangValidator is not installed (tools/install-deps.sh)";
    EXPECT_EQ(exitCode, 0) << stage.path << ":\n" << mapShaderLog(log, resolved->lineOrigins);
  }
}

// Expands material.frag with the renderer's defines for `material` (and `hexTiling`, `engine`),
// checks that `expected` is among them and that glslang compiles the result.
void expectVariantCompiles(const core::Material& material, const std::string& expected,
                           const std::string& name, bool hexTiling = false,
                           const core::EngineTraceParams* engine = nullptr) {
  std::vector<std::string> defines = materialTableDefines();
  for (const std::string& define : materialShaderDefines(material, core::DebugView::Shading,
                                                         FrameOutput::Display, hexTiling, engine))
    defines.push_back(define);
  ASSERT_NE(std::find(defines.begin(), defines.end(), expected), defines.end()) << name;
  core::Result<ResolvedShader> resolved =
      resolveShaderIncludes("material.frag", loadShaderSource, shaderPrelude(defines));
  ASSERT_TRUE(resolved.ok()) << resolved.error();
  const std::string file = test::scratchFolder() + "/expanded_" + name + ".frag";
  std::ofstream(file) << resolved->source;
  int exitCode = 0;
  const std::string log = runValidator(file, exitCode);
  EXPECT_EQ(exitCode, 0) << name << ":\n" << mapShaderLog(log, resolved->lineOrigins);
}

// The hex-tiled variant (shaders/include/hex_tiling.glsl) of every technique that takes it, as
// the renderer defines it, including the integer hash and the slope blend.
TEST(ShaderValidation, HexTiledVariantsCompileWithGlslang) {
  core::Material material;
  for (core::Technique technique : core::allTechniques()) {
    if (!core::supportsHexTiling(technique))
      continue;
    material.setTechnique(technique);
    expectVariantCompiles(material, "HEX_TILING",
                          "hex_" + std::string(core::techniqueName(technique)), true);
  }
}

// The curved-silhouette marches (shaders/include/curved_march.glsl) of steep, POM and relief.
TEST(ShaderValidation, CurvedSilhouetteVariantsCompileWithGlslang) {
  core::Material material;
  material.setParameter(core::ParamId::CurvedSilhouettes, 1.0);
  for (core::Technique technique :
       {core::Technique::Steep, core::Technique::Pom, core::Technique::Relief}) {
    material.setTechnique(technique);
    expectVariantCompiles(material, "CURVED_SILHOUETTES",
                          "curved_" + std::string(core::techniqueName(technique)));
  }
}

// Every engine preview's trace (shaders/include/engine_parallax.glsl), as the renderer defines
// it for a marching and a single-step technique.
TEST(ShaderValidation, EnginePreviewVariantsCompileWithGlslang) {
  core::Material material;
  material.setMap(core::MapSlot::Height, std::make_shared<core::Image>(4, 4, 1));
  for (core::Technique technique : {core::Technique::Pom, core::Technique::ParallaxLimited}) {
    material.setTechnique(technique);
    for (const core::EngineInfo& info : core::allEngines()) {
      const core::EngineTraceParams trace = core::engineTrace(material, info.engine);
      expectVariantCompiles(
          material, "ENGINE_PREVIEW",
          "engine_" + std::string(info.name) + "_" + std::string(core::techniqueName(technique)),
          false, &trace);
    }
  }
}

}  // namespace
}  // namespace relief::renderer
