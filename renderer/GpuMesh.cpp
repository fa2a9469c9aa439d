// GpuMesh; see GpuMesh.h.
#include "renderer/GpuMesh.h"

#include <algorithm>

#include <cstddef>

namespace relief::renderer {

GpuMesh::GpuMesh() = default;

void GpuMesh::upload(QOpenGLExtraFunctions& gl, const core::Mesh& mesh) {
  if (!m_vao.isCreated())
    m_vao.create();
  QOpenGLVertexArrayObject::Binder binder(&m_vao);
  if (!m_vertices.isCreated())
    m_vertices.create();
  if (!m_indices.isCreated())
    m_indices.create();
  m_vertices.bind();
  m_vertices.allocate(mesh.vertices.data(), int(mesh.vertices.size() * sizeof(core::Vertex)));
  m_indices.bind();
  m_indices.allocate(mesh.indices.data(), int(mesh.indices.size() * sizeof(std::uint32_t)));
  m_indexCount = int(mesh.indices.size());

  const auto stride = GLsizei(sizeof(core::Vertex));
  auto attribute = [&](GLuint location, GLint size, std::size_t offset) {
    gl.glEnableVertexAttribArray(location);
    gl.glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, stride,
                             reinterpret_cast<const void*>(offset));
  };
  attribute(kAttribPosition, 3, offsetof(core::Vertex, position));
  attribute(kAttribNormal, 3, offsetof(core::Vertex, normal));
  attribute(kAttribUv, 2, offsetof(core::Vertex, uv));
  attribute(kAttribTangent, 4, offsetof(core::Vertex, tangent));
  attribute(kAttribUvScale, 2, offsetof(core::Vertex, uvScale));
}

void GpuMesh::draw(QOpenGLExtraFunctions& gl, GLenum mode, int primitivesPerDraw) {
  if (m_indexCount == 0)
    return;
  QOpenGLVertexArrayObject::Binder binder(&m_vao);
  const int batch = std::max(3 * primitivesPerDraw, 3);
  for (int first = 0; first < m_indexCount; first += batch) {
    gl.glDrawElements(mode, std::min(batch, m_indexCount - first), GL_UNSIGNED_INT,
                      reinterpret_cast<const void*>(std::size_t(first) * sizeof(GLuint)));
  }
}

void GpuMesh::release() {
  m_vertices.destroy();
  m_indices.destroy();
  m_vao.destroy();
  m_indexCount = 0;
}

}  // namespace relief::renderer
