// ShaderProgram against a real driver: a compile error is reported as the original file and
// line (through the #include resolver), and a failed rebuild keeps the last good program; the
// material program reads every map slot its table declares.
#include "core/material/MapSlot.h"
#include "renderer/OpenGLProbe.h"
#include "renderer/ShaderProgram.h"
#include "renderer/ShaderVariant.h"
#include "support/OffscreenFixture.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>

#include <map>

namespace relief::test {
namespace {

class ShaderProgramWithDriver : public OffscreenTest {};

// The fixture's renderer proves a context can be made; these tests need their own current one.
class CurrentContext {
 public:
  CurrentContext() {
    m_context.setFormat(renderer::requiredSurfaceFormat());
    if (!m_context.create())
      return;
    m_surface.setFormat(m_context.format());
    m_surface.create();
    m_made = m_context.makeCurrent(&m_surface);
  }
  ~CurrentContext() {
    if (m_made)
      m_context.doneCurrent();
  }
  bool made() const { return m_made; }

 private:
  QOpenGLContext m_context;
  QOffscreenSurface m_surface;
  bool m_made = false;
};

TEST_F(ShaderProgramWithDriver, ErrorsPointAtTheIncludedFileAndLine) {
  CurrentContext current;
  ASSERT_TRUE(current.made());

  std::map<std::string, std::string> files = {
      {"ok.vert", "void main() { gl_Position = vec4(0.0); }\n"},
      {"ok.frag", "#include \"parts/colour.glsl\"\nout vec4 c;\nvoid main() { c = colour(); }\n"},
      {"parts/colour.glsl", "vec4 colour() { return vec4(1.0); }\n"},
      {"bad.frag", "#include \"parts/broken.glsl\"\nout vec4 c;\nvoid main() { c = broken(); }\n"},
      {"parts/broken.glsl", "// a helper\n\nvec4 broken() { return undefinedThing; }\n"},
  };
  const renderer::ShaderSourceLoader loader = [&files](const std::string& path) {
    const auto it = files.find(path);
    return it == files.end() ? std::nullopt : std::optional<std::string>(it->second);
  };

  renderer::ShaderProgram program;
  ASSERT_TRUE(program.build("ok.vert", "ok.frag", {}, loader).ok());
  ASSERT_TRUE(program.isValid());
  QOpenGLShaderProgram* good = &program.program();

  core::Status status = program.build("ok.vert", "bad.frag", {}, loader);
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().find("parts/broken.glsl:3"), std::string::npos) << status.error();
  // The previous program is still the one in use.
  EXPECT_TRUE(program.isValid());
  EXPECT_EQ(&program.program(), good);
  program.release();
}

// The samplers and presence flags are declared from core/material/MapSlot.cpp's rows
// (materialTableDefines); a row the shader never reads, or reads under another name, would
// leave the map unbound without an error from GL. An active uniform is one the linked program
// reads, so each slot's sampler and flag must have a location.
TEST_F(ShaderProgramWithDriver, TheMaterialProgramReadsEveryMapSlotsSamplerAndFlag) {
  CurrentContext current;
  ASSERT_TRUE(current.made());

  core::Material material;  // pbr reads every slot (classic ignores metallic)
  material.setParameter(core::ParamId::Shading, double(int(core::ShadingModel::Pbr)));
  std::vector<std::string> defines = renderer::materialTableDefines();
  for (const std::string& define : renderer::materialShaderDefines(
           material, core::DebugView::Shading, renderer::FrameOutput::Display))
    defines.push_back(define);
  renderer::ShaderProgram program;
  const core::Status built = program.build("material.vert", "material.frag", defines);
  ASSERT_TRUE(built.ok()) << built.error();
  for (core::MapSlot slot : core::kAllMapSlots) {
    const std::string sampler(core::mapSlotSampler(slot));
    EXPECT_GE(program.program().uniformLocation(sampler.c_str()), 0)
        << core::mapSlotName(slot) << ": " << sampler << " is not read";
    const std::string flag(core::mapSlotPresenceFlag(slot));
    if (!flag.empty()) {
      EXPECT_GE(program.program().uniformLocation(flag.c_str()), 0)
          << core::mapSlotName(slot) << ": " << flag << " is not read";
    }
  }
  program.release();
}

}  // namespace
}  // namespace relief::test
