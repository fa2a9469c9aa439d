// MaterialRenderer; see MaterialRenderer.h.
#include "renderer/MaterialRenderer.h"

#include <glm/gtc/type_ptr.hpp>

#include <QMatrix4x4>
#include <QVector3D>

namespace relief::renderer {
namespace {

using core::MapSlot;
using core::ParamId;

constexpr int kFirstMapUnit = 0;

QMatrix4x4 toQt(const glm::mat4& m) {
  // QMatrix4x4's float constructor takes row-major values; glm stores columns.
  return QMatrix4x4(glm::value_ptr(glm::transpose(m)));
}

QVector3D toQt(const glm::vec3& v) {
  return QVector3D(v.x, v.y, v.z);
}

}  // namespace

MaterialRenderer::MaterialRenderer() = default;

MaterialRenderer::~MaterialRenderer() {
  // Resources must have been released while the context was current.
  Q_ASSERT(!m_initialized);
}

core::Status MaterialRenderer::initialize() {
  initializeOpenGLFunctions();
  if (core::Status status = m_materialProgram.build("material.vert", "material.frag"); !status) {
    return status;
  }
  if (core::Status status = m_backgroundProgram.build("background.vert", "background.frag");
      !status) {
    return status;
  }
  glGenVertexArrays(1, &m_emptyVao);
  m_textures.sync(m_material);
  m_initialized = true;
  return {};
}

void MaterialRenderer::releaseResources() {
  if (!m_initialized)
    return;
  m_mesh.release();
  m_textures.release();
  m_materialProgram.release();
  m_backgroundProgram.release();
  glDeleteVertexArrays(1, &m_emptyVao);
  m_emptyVao = 0;
  m_initialized = false;
}

void MaterialRenderer::setMesh(const core::Mesh& mesh) {
  m_mesh.upload(*this, mesh);
}

void MaterialRenderer::setMaterial(const core::Material& material) {
  m_material = material;
  if (m_initialized)
    m_textures.sync(m_material);
}

std::string MaterialRenderer::rendererDescription() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return std::string(renderer ? renderer : "unknown renderer") + ", OpenGL " +
         (version ? version : "unknown");
}

void MaterialRenderer::render(const RenderView& view, int width, int height, unsigned framebuffer) {
  Q_ASSERT(m_initialized);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, width, height);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glClearDepthf(1.0f);
  glClear(GL_DEPTH_BUFFER_BIT);

  drawBackground(view);

  QOpenGLShaderProgram& program = m_materialProgram.program();
  program.bind();
  setMaterialUniforms(program, view, float(width) / float(std::max(height, 1)));
  m_textures.bind(kFirstMapUnit);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  // Both sides are drawn: an open mesh (the plane) must not vanish when orbiting below it.
  glDisable(GL_CULL_FACE);
  m_mesh.draw(*this);
  program.release();
  glDisable(GL_DEPTH_TEST);
}

void MaterialRenderer::drawBackground(const RenderView& view) {
  QOpenGLShaderProgram& program = m_backgroundProgram.program();
  program.bind();
  program.setUniformValue("uTopColor", toQt(view.backgroundTop));
  program.setUniformValue("uBottomColor", toQt(view.backgroundBottom));
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(m_emptyVao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  program.release();
}

void MaterialRenderer::setMaterialUniforms(QOpenGLShaderProgram& program, const RenderView& view,
                                           float aspect) {
  const glm::mat4 model(1.0f);
  const glm::mat4 viewProjection = view.camera.projectionMatrix(aspect) * view.camera.viewMatrix();
  program.setUniformValue("uModel", toQt(model));
  program.setUniformValue("uViewProjection", toQt(viewProjection));
  program.setUniformValue("uNormalMatrix", toQt(model).normalMatrix());  // inverse transpose
  program.setUniformValue("uCameraPosition", toQt(view.camera.position()));
  program.setUniformValue("uLightDirection", toQt(view.light.direction()));
  program.setUniformValue("uLightColor", toQt(view.light.color * view.light.intensity));
  program.setUniformValue("uAmbient", view.light.ambient);

  program.setUniformValue("uTiling", m_material.parameterf(ParamId::Tiling));
  program.setUniformValue("uNormalStrength", m_material.parameterf(ParamId::NormalStrength));
  program.setUniformValue("uNormalYDown", m_material.parameterFlag(ParamId::NormalYDown));
  program.setUniformValue("uSpecular", m_material.parameterf(ParamId::Specular));
  program.setUniformValue("uShininess", m_material.parameterf(ParamId::Shininess));

  program.setUniformValue("uColorMap", kFirstMapUnit + int(MapSlot::Color));
  program.setUniformValue("uNormalMap", kFirstMapUnit + int(MapSlot::Normal));
  program.setUniformValue("uHeightMap", kFirstMapUnit + int(MapSlot::Height));
  program.setUniformValue("uOcclusionMap", kFirstMapUnit + int(MapSlot::AmbientOcclusion));
  program.setUniformValue("uRoughnessMap", kFirstMapUnit + int(MapSlot::Roughness));
}

}  // namespace relief::renderer
