// Camera framing: after frame(), every corner of the mesh's bounds projects inside the view.
#include "core/mesh/MeshPrimitives.h"
#include "core/view/OrbitCamera.h"

#include <gtest/gtest.h>

namespace relief::core {
namespace {

TEST(OrbitCamera, FrameKeepsEveryCornerInView) {
  for (PrimitiveShape shape : allPrimitiveShapes()) {
    const Mesh mesh = makePrimitive(shape);
    const Bounds bounds = mesh.bounds();
    for (float aspect : {0.6f, 1.0f, 16.0f / 9.0f}) {
      for (float yaw : {0.0f, 25.0f, 90.0f, 200.0f}) {
        for (float pitch : {-60.0f, 0.0f, 35.0f, 89.0f}) {
          OrbitCamera camera;
          camera.yawDeg = yaw;
          camera.pitchDeg = pitch;
          camera.frame(bounds, aspect);
          const glm::mat4 viewProjection = camera.projectionMatrix(aspect) * camera.viewMatrix();
          for (const Vertex& vertex : mesh.vertices) {
            const glm::vec4 clip = viewProjection * glm::vec4(vertex.position, 1.0f);
            ASSERT_GT(clip.w, 0.0f);
            EXPECT_LE(std::abs(clip.x / clip.w), 1.0f) << mesh.name << " yaw " << yaw;
            EXPECT_LE(std::abs(clip.y / clip.w), 1.0f) << mesh.name << " pitch " << pitch;
            EXPECT_LE(std::abs(clip.z / clip.w), 1.0f) << mesh.name;
          }
        }
      }
    }
  }
}

TEST(OrbitCamera, PositionFollowsYawAndPitch) {
  OrbitCamera camera;
  camera.distance = 2.0f;
  camera.yawDeg = 0.0f;
  camera.pitchDeg = 0.0f;
  EXPECT_NEAR(camera.position().z, 2.0f, 1e-6f);
  camera.yawDeg = 90.0f;
  EXPECT_NEAR(camera.position().x, 2.0f, 1e-6f);
  camera.pitchDeg = 89.0f;
  EXPECT_GT(camera.position().y, 1.99f);
}

}  // namespace
}  // namespace relief::core
