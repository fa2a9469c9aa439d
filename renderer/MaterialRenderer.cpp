// MaterialRenderer; see MaterialRenderer.h.
#include "renderer/MaterialRenderer.h"

#include "core/compression/Compressor.h"
#include "core/shading/EnvironmentMaps.h"
#include "core/shading/SplitSumLut.h"
#include "renderer/CompressedUpload.h"
#include "renderer/ShaderVariant.h"

#include <glm/gtc/type_ptr.hpp>

#include <QGenericMatrix>
#include <QMatrix4x4>
#include <QOpenGLFramebufferObject>
#include <QOpenGLTexture>
#include <QVector2D>
#include <QVector3D>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace relief::renderer {
namespace {

using core::MapSlot;
using core::ParamId;

constexpr int kFirstMapUnit = 0;
constexpr int kPyramidUnit = kFirstMapUnit + int(core::kMapSlotCount);  // the exact tracers'
constexpr int kConeMapUnit = kPyramidUnit + 1;                          // the cone technique's
constexpr int kSplitSumUnit = kConeMapUnit + 1;                         // pbr shading's table
constexpr int kEnvironmentSpecularUnit = kSplitSumUnit + 1;             // and its environment
constexpr int kEnvironmentIrradianceUnit = kEnvironmentSpecularUnit + 1;
constexpr int kEnvironmentSourceUnit = kEnvironmentIrradianceUnit + 1;  // the sharp background
// 32 x 32 entries of 4096 samples: the table varies smoothly, so 32 entries a side interpolate
// well; 4096 samples keep grazing entries within 0.3% (core/shading tests). Built at start-up in
// about 40 ms.
constexpr int kSplitSumSize = 32;
constexpr int kSplitSumSamples = 4096;

QMatrix4x4 toQt(const glm::mat4& m) {
  // QMatrix4x4's float constructor takes row-major values; glm stores columns.
  return QMatrix4x4(glm::value_ptr(glm::transpose(m)));
}

QVector3D toQt(const glm::vec3& v) {
  return QVector3D(v.x, v.y, v.z);
}

bool isPbr(const core::Material& material) {
  return core::ShadingModel(int(material.parameter(ParamId::Shading))) == core::ShadingModel::Pbr;
}

std::string joined(const std::vector<std::string>& parts) {
  std::string key;
  for (const std::string& part : parts)
    key += part + ";";
  return key;
}

}  // namespace

MaterialRenderer::MaterialRenderer() = default;

MaterialRenderer::~MaterialRenderer() {
  // Resources must have been released while the context was current.
  Q_ASSERT(!m_initialized);
}

core::Status MaterialRenderer::initialize() {
  initializeOpenGLFunctions();
  const std::map<core::Background, std::string> backgroundDefines = {
      {core::Background::Color, "BACKGROUND_COLOR"},
      {core::Background::Environment, "BACKGROUND_ENVIRONMENT"},
      {core::Background::Blurred, "BACKGROUND_BLURRED"},
  };
  for (const auto& [background, define] : backgroundDefines) {
    if (core::Status status =
            m_backgroundPrograms[background].build("background.vert", "background.frag", {define});
        !status) {
      return status;
    }
  }
  if (core::Status status = m_environment.initialize(); !status)
    return status;
  // The default variant up front, so a broken shader shows at start-up, not at first draw.
  std::string error;
  if (!programFor(m_material, FrameSettings{}, error))
    return core::makeError(error);
  glGenVertexArrays(1, &m_emptyVao);
  createSplitSumTable();
  m_initialized = true;
  return {};
}

void MaterialRenderer::createSplitSumTable() {
  const core::Image table = core::makeSplitSumLut(kSplitSumSize, kSplitSumSamples);
  // Row 0 (smoothest) at t = 0: uploaded as is, no flip, unlike the maps. The table's four
  // channels go up whole (A and B in red and green): 16 KiB, not worth repacking.
  m_splitSumTable = std::make_unique<QOpenGLTexture>(QOpenGLTexture::Target2D);
  m_splitSumTable->setFormat(QOpenGLTexture::RGBA32F);
  m_splitSumTable->setSize(kSplitSumSize, kSplitSumSize);
  m_splitSumTable->setMipLevels(1);
  m_splitSumTable->allocateStorage(QOpenGLTexture::RGBA, QOpenGLTexture::Float32);
  m_splitSumTable->setData(QOpenGLTexture::RGBA, QOpenGLTexture::Float32, table.data());
  m_splitSumTable->setMinMagFilters(QOpenGLTexture::Linear, QOpenGLTexture::Linear);
  m_splitSumTable->setWrapMode(QOpenGLTexture::ClampToEdge);
}

void MaterialRenderer::releaseResources() {
  if (!m_initialized)
    return;
  m_mesh.release();
  m_textures.release();
  m_materialPrograms.clear();
  m_backgroundPrograms.clear();
  m_environment.release();
  m_reducedTarget.reset();
  m_splitSumTable.reset();
  glDeleteVertexArrays(1, &m_emptyVao);
  m_emptyVao = 0;
  m_initialized = false;
}

void MaterialRenderer::setMesh(const core::Mesh& mesh) {
  m_mesh.upload(*this, mesh);
  m_meshBounds = mesh.bounds();
  m_meshWorldPerUv = float(core::worldUnitsPerUv(mesh));
}

void MaterialRenderer::setMaterial(const core::Material& material) {
  m_material = material;
}

std::string MaterialRenderer::rendererDescription() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return std::string(renderer ? renderer : "unknown renderer") + ", OpenGL " +
         (version ? version : "unknown");
}

int MaterialRenderer::maxImageSize() {
  GLint renderbufferMax = 0;
  GLint viewportMax[2] = {0, 0};
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbufferMax);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewportMax);
  return std::min({renderbufferMax, viewportMax[0], viewportMax[1]});
}

ShaderProgram* MaterialRenderer::programFor(const core::Material& material,
                                            const FrameSettings& frame, std::string& error) {
  const std::optional<core::EngineTraceParams> engine = engineTraceFor(material, frame);
  const std::vector<std::string> defines = materialShaderDefines(
      material, frame.debugView, frame.output, frame.tiles.hex, engine ? &*engine : nullptr);
  std::unique_ptr<ShaderProgram>& program = m_materialPrograms[joined(defines)];
  if (!program) {
    ShaderStagePaths paths{"material.vert", "material.frag", {}, {}};
    if (usesTessellation(material, frame.output, engine.has_value())) {
      paths.tessellationControl = "material.tesc";
      paths.tessellationEvaluation = "material.tese";
    }
    std::vector<std::string> allDefines = materialTableDefines();
    allDefines.insert(allDefines.end(), defines.begin(), defines.end());
    auto built = std::make_unique<ShaderProgram>();
    if (core::Status status = built->build(paths, allDefines); !status) {
      m_materialPrograms.erase(joined(defines));
      error = status.error();
      return nullptr;
    }
    program = std::move(built);
  }
  return program.get();
}

core::Status MaterialRenderer::render(const FrameSettings& frame, int width, int height,
                                      unsigned framebuffer) {
  Q_ASSERT(m_initialized);
  prepareEnvironment(frame);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, width, height);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  if (m_rowWindow) {
    glEnable(GL_SCISSOR_TEST);
    scissor(0, 0, width, height);
  }
  glDepthMask(GL_TRUE);
  glClearDepthf(1.0f);
  if (frame.output == FrameOutput::Display) {
    glClear(GL_DEPTH_BUFFER_BIT);
    drawBackground(frame.view, width, height);
  } else {
    // Data outputs: alpha 0 marks pixels the mesh does not cover.
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }

  std::string error;
  core::Material standInA, standInB;
  const core::Material& materialA = drawable(m_material, standInA);
  ShaderProgram* programA = programFor(materialA, frame, error);
  if (!programA)
    return core::makeError(error);
  if (!frame.split) {
    drawMaterial(*programA, materialA, frame, width, height);
  } else {
    // A left of the divider, B right of it, the same camera for both.
    const int divider =
        std::clamp(int(std::lround(frame.split->dividerFraction * float(width))), 0, width);
    const core::Material& materialB = drawable(frame.split->material, standInB);
    ShaderProgram* programB = programFor(materialB, frame, error);
    if (!programB)
      return core::makeError(error);
    glEnable(GL_SCISSOR_TEST);
    scissor(0, 0, divider, height);
    drawMaterial(*programA, materialA, frame, width, height);
    scissor(divider, 0, width - divider, height);
    drawMaterial(*programB, materialB, frame, width, height);
    glDisable(GL_SCISSOR_TEST);
  }
  if (frame.split) {
    m_textures.releaseUnused({&m_material, &frame.split->material});
  } else {
    m_textures.releaseUnused({&m_material});
  }
  return {};
}

std::optional<core::EngineTraceParams> MaterialRenderer::engineTraceFor(
    const core::Material& material, const FrameSettings& frame) {
  if (!frame.engine)
    return std::nullopt;
  return core::engineTrace(material, *frame.engine);
}

const core::Material& MaterialRenderer::drawable(const core::Material& material,
                                                 core::Material& standIn) const {
  if (coneMapReady(material))
    return material;
  standIn = material;
  standIn.setTechnique(core::Technique::Quadtree);
  return standIn;
}

void MaterialRenderer::drawMaterial(ShaderProgram& shader, const core::Material& material,
                                    const FrameSettings& frame, int width, int height) {
  QOpenGLShaderProgram& program = shader.program();
  program.bind();
  setUniforms(program, material, frame, width, height);
  for (MapSlot slot : core::kAllMapSlots) {
    m_textures.texture(material, slot, frame.mipChains[std::size_t(slot)])
        .bind(unsigned(kFirstMapUnit + int(slot)));
  }
  const std::optional<core::EngineTraceParams> engine = engineTraceFor(material, frame);
  if (engine) {
    program.setUniformValue("uEngineDepth", float(engine->depth));
    program.setUniformValue("uEngineMinSteps", float(engine->minSteps));
    program.setUniformValue("uEngineMaxSteps", float(engine->maxSteps));
    program.setUniformValue("uEngineReferencePlane", float(engine->referencePlane));
    program.setUniformValue("uEngineLodThreshold", float(engine->lodThreshold));
  }
  if (!engine && core::isExactTracing(material.technique())) {
    QOpenGLTexture& pyramid = m_textures.heightPyramid(material);
    pyramid.bind(unsigned(kPyramidUnit));
    program.setUniformValue("uHeightPyramid", kPyramidUnit);
    program.setUniformValue("uHeightPyramidLevels", pyramid.mipLevels());
  }
  if (!engine && material.technique() == core::Technique::Cone) {
    m_textures.coneMap(material).bind(unsigned(kConeMapUnit));
    program.setUniformValue("uConeMap", kConeMapUnit);
  }
  m_splitSumTable->bind(unsigned(kSplitSumUnit));
  program.setUniformValue("uSplitSumLut", kSplitSumUnit);
  if (isPbr(material))
    bindEnvironment(program, frame.view.environment);
  for (MapSlot slot : core::kAllMapSlots) {
    if (const std::string_view flag = core::mapSlotPresenceFlag(slot); !flag.empty())
      program.setUniformValue(flag.data(), material.hasMap(slot));
  }
  // A natively uploaded two-channel normal (BC5, EAC RG11, DXT5nm swizzled) has no Z texel.
  const auto& normal = material.map(MapSlot::Normal).compressed;
  program.setUniformValue(
      "uNormalTwoChannel",
      normal && core::isTwoChannelNormalFormat(normal->format) &&
          m_textures.uploadedNatively(material, MapSlot::Normal).value_or(false));
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glClear(GL_DEPTH_BUFFER_BIT);
  // Both sides are drawn: an open mesh (the plane) must not vanish when orbiting below it.
  glDisable(GL_CULL_FACE);
  if (usesTessellation(material, frame.output, engine.has_value())) {
    // Tessellated draws are issued a few patches at a time. Mesa's llvmpipe (22.3, Debian 12)
    // silently drops the rest of a draw that generates too many triangles (512 patches at
    // level 32, about 520k triangles, lost the later patches; at level 16 all were drawn), and
    // it tessellates big draws slowly: the plane at 16 segments per edge took 216 ms a frame
    // in draws of up to 65536 generated triangles, 93 ms at 16384, 60 at 4096, 64 at 1024.
    // A patch at level n makes about n^2 triangles; at most kTrianglesPerDraw per call costs a
    // GPU one draw call per few patches.
    constexpr int kTrianglesPerDraw = 1 << 12;
    const int level = int(material.parameter(core::ParamId::MaxTessellation));
    glPatchParameteri(GL_PATCH_VERTICES, 3);
    m_mesh.draw(*this, GL_PATCHES, std::max(kTrianglesPerDraw / (level * level), 1));
  } else {
    m_mesh.draw(*this, GL_TRIANGLES);
  }
  program.release();
  glDisable(GL_DEPTH_TEST);
}

std::string MaterialRenderer::compressedUploadSummary(const core::Material& material) {
  std::string summary;
  for (MapSlot slot : core::kAllMapSlots) {
    const auto& compressed = material.map(slot).compressed;
    if (!compressed)
      continue;
    const bool native = m_textures.uploadedNatively(material, slot).value_or(false);
    if (!summary.empty())
      summary += "; ";
    summary +=
        std::string(core::mapSlotLabel(slot)) + " " +
        std::string(core::textureFormatInfo(compressed->format).label) +
        (native                                  ? " uploaded natively"
         : !m_textures.nativeCompressedUploads() ? " decoded by Relief (Preferences)"
                                                 : " decoded by Relief (the driver lacks " +
                                                       formatRequirement(compressed->format) + ")");
  }
  return summary;
}

void MaterialRenderer::prepareEnvironment(const FrameSettings& frame) {
  const bool shownBehind = frame.output == FrameOutput::Display &&
                           frame.view.environment.background != core::Background::Color;
  const bool lights = isPbr(m_material) || (frame.split && isPbr(frame.split->material));
  if (!shownBehind && !lights)
    return;
  core::Result<std::shared_ptr<const core::Image>> radiance =
      core::environmentRadiance(frame.view.environment.source);
  m_environmentError.clear();
  if (!radiance) {
    m_environmentError = radiance.error();
    radiance = core::environmentRadiance(
        std::string(core::builtInEnvironmentName(core::BuiltInEnvironment::Uniform)));
  }
  m_environment.prepare(radiance.value());
}

void MaterialRenderer::bindEnvironment(QOpenGLShaderProgram& program,
                                       const core::Environment& environment) {
  m_environment.specular().bind(unsigned(kEnvironmentSpecularUnit));
  m_environment.irradiance().bind(unsigned(kEnvironmentIrradianceUnit));
  program.setUniformValue("uEnvironmentSpecular", kEnvironmentSpecularUnit);
  program.setUniformValue("uEnvironmentIrradiance", kEnvironmentIrradianceUnit);
  program.setUniformValue("uEnvironmentMaxLevel", float(EnvironmentLight::kSpecularLevels - 1));
  program.setUniformValue("uEnvironmentIntensity", environment.intensity);
  const glm::mat3 rotation = environment.worldToEnvironment();
  program.setUniformValue("uEnvironmentRotation",
                          QMatrix3x3(glm::value_ptr(glm::transpose(rotation))));
}

void MaterialRenderer::drawBackground(const RenderView& view, int width, int height) {
  const core::Background background = view.environment.background;
  QOpenGLShaderProgram& program = m_backgroundPrograms.at(background).program();
  program.bind();
  if (background == core::Background::Color) {
    program.setUniformValue("uTopColor", toQt(view.backgroundTop));
    program.setUniformValue("uBottomColor", toQt(view.backgroundBottom));
  } else {
    bindEnvironment(program, view.environment);
    const float aspect = float(width) / float(std::max(height, 1));
    const glm::mat4 viewProjection =
        view.camera.projectionMatrix(aspect) * view.camera.viewMatrix();
    program.setUniformValue("uInverseViewProjection", toQt(glm::inverse(viewProjection)));
    program.setUniformValue("uCameraPosition", toQt(view.camera.position()));
    m_environment.source().bind(unsigned(kEnvironmentSourceUnit));
    program.setUniformValue("uEnvironmentSource", kEnvironmentSourceUnit);
    program.setUniformValue(
        "uEnvironmentSourceSize",
        QVector2D(float(m_environment.source().width()), float(m_environment.source().height())));
    program.setUniformValue("uPixelAngle",
                            glm::radians(view.camera.fovYDeg) / float(std::max(height, 1)));
    program.setUniformValue("uExposure", view.display.exposureScale());
    program.setUniformValue("uToneMapper", int(view.display.toneMapper));
  }
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(m_emptyVao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  program.release();
}

void MaterialRenderer::setUniforms(QOpenGLShaderProgram& program, const core::Material& material,
                                   const FrameSettings& frame, int width, int height) {
  const RenderView& view = frame.view;
  const float aspect = float(width) / float(std::max(height, 1));
  const glm::mat4 model(1.0f);
  const glm::mat4 viewProjection = view.camera.projectionMatrix(aspect) * view.camera.viewMatrix();
  program.setUniformValue("uModel", toQt(model));
  program.setUniformValue("uViewProjection", toQt(viewProjection));
  program.setUniformValue("uNormalMatrix", toQt(model).normalMatrix());  // inverse transpose
  program.setUniformValue("uCameraPosition", toQt(view.camera.position()));
  program.setUniformValue("uLightDirection", toQt(view.light.direction()));
  program.setUniformValue("uLightColor", toQt(view.light.color * view.light.intensity));
  program.setUniformValue("uAmbient", view.light.ambient);
  program.setUniformValue("uExposure", view.display.exposureScale());
  program.setUniformValue("uToneMapper", int(view.display.toneMapper));
  program.setUniformValue("uViewportSize", QVector2D(float(width), float(height)));
  program.setUniformValue("uWorldPerUv", m_meshWorldPerUv);
  const float radius = m_meshBounds.sphereRadius;
  program.setUniformValue(
      "uDepthDisplayRange",
      QVector2D(std::max(view.camera.distance - radius, 0.0f), view.camera.distance + radius));

  // Every parameter with a uniform, from the table (core/material/Parameters.cpp).
  for (const core::ParameterSpec& spec : core::allParameters()) {
    if (spec.uniform.empty())
      continue;
    const double value = material.parameter(spec.id) * spec.uniformScale;
    const char* name = spec.uniform.data();  // literals in the table: NUL-terminated
    switch (spec.kind) {
      case core::ParamKind::Float:
        program.setUniformValue(name, float(value));
        break;
      case core::ParamKind::Int:
      case core::ParamKind::Choice:
        program.setUniformValue(name, int(value));
        break;
      case core::ParamKind::Bool:
        program.setUniformValue(name, value != 0.0);
        break;
    }
  }

  program.setUniformValue(
      "uTiling", float(material.parameter(ParamId::Tiling) * std::max(frame.tiles.repeats, 1) *
                       std::max(frame.tiles.distance, 1)));
  program.setUniformValue("uTileSeams", frame.tiles.seams);

  const bool packed = material.parameterFlag(ParamId::HeightInNormalAlpha);
  const core::Image* heightSource = material.image(packed ? MapSlot::Normal : MapSlot::Height);
  program.setUniformValue("uHeightMapSize", heightSource ? QVector2D(float(heightSource->width()),
                                                                     float(heightSource->height()))
                                                         : QVector2D(1.0f, 1.0f));
  program.setUniformValue("uHeightQuantum", heightQuantum(heightSource));

  for (MapSlot slot : core::kAllMapSlots)
    program.setUniformValue(core::mapSlotSampler(slot).data(), kFirstMapUnit + int(slot));
}

// The step between a height map's stored levels, in normalised height: self-shadow rays start
// above it (shaders/include/self_shadow.glsl). Float maps, and maps of unknown origin (made in
// memory by a generator), have none.
float MaterialRenderer::heightQuantum(const core::Image* height) {
  const int bits = height ? height->sourceBitsPerChannel() : 0;
  if (bits < 1 || bits > 16)
    return 0.0f;
  return 1.0f / float((1 << bits) - 1);
}

std::pair<int, int> MaterialRenderer::reducedSize(int width, int height, float scale) {
  return {std::max(int(std::lround(float(width) * scale)), 1),
          std::max(int(std::lround(float(height) * scale)), 1)};
}

core::Status MaterialRenderer::renderReduced(const FrameSettings& frame, int width, int height,
                                             float scale, unsigned framebuffer) {
  if (scale >= 1.0f)
    return render(frame, width, height, framebuffer);
  if (frame.output != FrameOutput::Display || !(scale > 0.0f))
    return core::makeError("reduced-resolution frames are drawn for display only, at a scale > 0");
  const auto [reducedWidth, reducedHeight] = reducedSize(width, height, scale);
  if (!m_reducedTarget || m_reducedTarget->size() != QSize(reducedWidth, reducedHeight)) {
    // RGBA8 like the window's framebuffer: the shaders write display-encoded colour, so the
    // stretch filters the same values the full frame would show.
    QOpenGLFramebufferObjectFormat format;
    format.setAttachment(QOpenGLFramebufferObject::Depth);
    format.setInternalTextureFormat(GL_RGBA8);
    m_reducedTarget =
        std::make_unique<QOpenGLFramebufferObject>(reducedWidth, reducedHeight, format);
  }
  if (!m_reducedTarget->isValid()) {
    m_reducedTarget.reset();
    return core::makeError("cannot create a " + std::to_string(reducedWidth) + "x" +
                           std::to_string(reducedHeight) + " framebuffer (out of GPU memory?)");
  }
  if (core::Status status = render(frame, reducedWidth, reducedHeight, m_reducedTarget->handle());
      !status) {
    return status;
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, m_reducedTarget->handle());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
  glBlitFramebuffer(0, 0, reducedWidth, reducedHeight, 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                    GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  return {};
}

// A scissor box limited to renderRows' rows, when it is drawing.
void MaterialRenderer::scissor(int x, int y, int width, int height) {
  if (m_rowWindow) {
    const int bottom = std::max(y, m_rowWindow->first);
    const int top = std::min(y + height, m_rowWindow->second);
    y = bottom;
    height = std::max(top - bottom, 0);
  }
  glScissor(x, y, width, height);
}

core::Status MaterialRenderer::renderRows(const FrameSettings& frame, int width, int height,
                                          int firstRow, int endRow) {
  if (!m_refineTarget || m_refineTarget->size() != QSize(width, height)) {
    QOpenGLFramebufferObjectFormat format;
    format.setAttachment(QOpenGLFramebufferObject::Depth);
    format.setInternalTextureFormat(GL_RGBA8);  // as the window's and the reduced frame's
    m_refineTarget = std::make_unique<QOpenGLFramebufferObject>(width, height, format);
  }
  if (!m_refineTarget->isValid()) {
    m_refineTarget.reset();
    return core::makeError("cannot create a " + std::to_string(width) + "x" +
                           std::to_string(height) + " framebuffer (out of GPU memory?)");
  }
  m_rowWindow = std::pair(firstRow, endRow);
  core::Status status = render(frame, width, height, m_refineTarget->handle());
  m_rowWindow.reset();
  glDisable(GL_SCISSOR_TEST);
  return status;
}

void MaterialRenderer::showRefined(int width, int height, int refinedFrom, unsigned framebuffer) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
  if (m_reducedTarget) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, m_reducedTarget->handle());
    glBlitFramebuffer(0, 0, m_reducedTarget->width(), m_reducedTarget->height(), 0, 0, width,
                      height, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  }
  if (m_refineTarget && m_refineTarget->size() == QSize(width, height) && refinedFrom < height) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, m_refineTarget->handle());
    glBlitFramebuffer(0, refinedFrom, width, height, 0, refinedFrom, width, height,
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
}

core::Result<core::Image> MaterialRenderer::renderToImage(
    const FrameSettings& frame, int width, int height, float scale,
    std::optional<FrameRefinement> refinement) {
  const int limit = maxImageSize();
  if (width < 1 || height < 1 || width > limit || height > limit) {
    return core::makeError("cannot render " + std::to_string(width) + "x" + std::to_string(height) +
                           ": sizes must be 1 to " + std::to_string(limit) + " pixels on this GPU");
  }
  const bool display = frame.output == FrameOutput::Display;
  QOpenGLFramebufferObjectFormat format;
  format.setAttachment(QOpenGLFramebufferObject::Depth);
  format.setInternalTextureFormat(display ? GL_RGBA8 : GL_RGBA32F);
  QOpenGLFramebufferObject fbo(width, height, format);
  if (!fbo.isValid()) {
    return core::makeError("cannot create a " + std::to_string(width) + "x" +
                           std::to_string(height) + " framebuffer (out of GPU memory?)");
  }
  if (core::Status status = renderReduced(frame, width, height, scale, fbo.handle()); !status) {
    return core::makeError(status.error());
  }
  if (refinement && scale < 1.0f) {
    int refinedFrom = height;
    for (int band = 0; band < refinement->bands && refinedFrom > 0; ++band) {
      const int first = std::max(refinedFrom - refinement->bandRows, 0);
      if (core::Status status = renderRows(frame, width, height, first, refinedFrom); !status)
        return core::makeError(status.error());
      refinedFrom = first;
    }
    showRefined(width, height, refinedFrom, fbo.handle());
  }

  core::Image image(width, height, 4, display ? core::ColorSpace::Srgb : core::ColorSpace::Linear);
  image.setSourceBitsPerChannel(display ? 8 : 32);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.handle());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  if (display) {
    std::vector<unsigned char> rgba(image.valueCount());
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    for (std::size_t i = 0; i < rgba.size(); ++i)
      image.data()[i] = float(rgba[i]) / 255.0f;
  } else {
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, image.data());
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  // GL rows start at the bottom; Image rows start at the top.
  const std::size_t rowValues = std::size_t(width) * 4;
  for (int y = 0; y < height / 2; ++y) {
    std::swap_ranges(image.pixel(0, y), image.pixel(0, y) + rowValues,
                     image.pixel(0, height - 1 - y));
  }
  return image;
}

core::Result<FrameTimes> MaterialRenderer::timeFrames(const FrameSettings& frame, int width,
                                                      int height, const FrameTiming& timing) {
  QOpenGLFramebufferObject fbo(width, height, QOpenGLFramebufferObject::Depth);
  if (!fbo.isValid())
    return core::makeError("cannot create a " + std::to_string(width) + "x" +
                           std::to_string(height) + " framebuffer (out of GPU memory?)");
  std::vector<double> times;
  const auto drawOne = [&]() -> core::Result<double> {
    const auto start = std::chrono::steady_clock::now();
    if (core::Status status = render(frame, width, height, fbo.handle()); !status)
      return core::makeError(status.error());
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
  };
  if (core::Result<double> first = drawOne(); !first)  // compiles and uploads: not timed
    return core::makeError(first.error());
  const int minFrames = std::max(timing.minFrames, 1);
  const int maxFrames = std::max(timing.maxFrames, minFrames);
  const auto start = std::chrono::steady_clock::now();
  while (int(times.size()) < maxFrames) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (int(times.size()) >= minFrames && elapsed >= timing.minSeconds)
      break;
    core::Result<double> milliseconds = drawOne();
    if (!milliseconds)
      return core::makeError(milliseconds.error());
    times.push_back(milliseconds.value());
  }
  return summarizeFrameTimes(std::move(times));
}

}  // namespace relief::renderer
