// Meshes from files: UVs required, tangents from the file kept (with their handedness), or
// computed after reference 004 when the file has none; clear errors for bad files.
#include "core/mesh/MeshImport.h"
#include "support/TestPaths.h"

#include <QByteArray>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <gtest/gtest.h>

#include <fstream>
#include <vector>

namespace relief::core {
namespace {

std::string writeFile(const std::string& name, const std::string& text) {
  const std::string path = test::scratchFolder() + "/" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

constexpr const char* kQuadObj =
    "v -1 0 1\nv 1 0 1\nv 1 0 -1\nv -1 0 -1\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "vn 0 1 0\n"
    "f 1/1/1 2/2/1 3/3/1 4/4/1\n";

TEST(MeshImport, ObjWithUvsGetsComputedTangents) {
  Result<ImportedMesh> imported = importMesh(writeFile("quad.obj", kQuadObj));
  ASSERT_TRUE(imported.ok()) << imported.error();
  EXPECT_FALSE(imported->tangentsFromFile);
  EXPECT_EQ(imported->mesh.triangleCount(), 2u);
  for (const Vertex& v : imported->mesh.vertices) {
    EXPECT_NEAR(v.tangent.x, 1.0f, 1e-5f);  // u runs along +X
    EXPECT_EQ(v.tangent.w, 1.0f);
    EXPECT_NEAR(v.normal.y, 1.0f, 1e-5f);
    // UV 0..1 over 2 units each way (core::Vertex::uvScale, for the parallax marches' depth).
    EXPECT_NEAR(v.uvScale.x, 2.0f, 1e-5f);
    EXPECT_NEAR(v.uvScale.y, 2.0f, 1e-5f);
  }
}

TEST(MeshImport, MeshWithoutUvsIsRefusedWithAReason) {
  const std::string path = writeFile("nouv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  Result<ImportedMesh> imported = importMesh(path);
  ASSERT_FALSE(imported.ok());
  EXPECT_NE(imported.error().find("nouv.obj"), std::string::npos) << imported.error();
  EXPECT_NE(imported.error().find("texture coordinates"), std::string::npos) << imported.error();
}

TEST(MeshImport, UnreadableFilesAreRefusedWithTheirName) {
  EXPECT_NE(importMesh(test::scratchFolder() + "/absent.obj").error().find("absent.obj"),
            std::string::npos);
  Result<ImportedMesh> garbage = importMesh(writeFile("garbage.glb", "definitely not glTF"));
  ASSERT_FALSE(garbage.ok());
  EXPECT_NE(garbage.error().find("garbage.glb"), std::string::npos) << garbage.error();
}

// A one-triangle glTF 2.0 file with a TANGENT attribute whose w is -1 (mirrored UVs).
std::string gltfWithTangents() {
  const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 0, -1};
  const std::vector<float> normals = {0, 1, 0, 0, 1, 0, 0, 1, 0};
  const std::vector<float> uvs = {1, 0, 0, 0, 1, 1};  // u runs toward -X: mirrored
  const std::vector<float> tangents = {-1, 0, 0, -1, -1, 0, 0, -1, -1, 0, 0, -1};
  QByteArray buffer;
  std::vector<QJsonObject> views;
  auto append = [&](const std::vector<float>& values) {
    const auto offset = buffer.size();
    buffer.append(reinterpret_cast<const char*>(values.data()),
                  qsizetype(values.size() * sizeof(float)));
    views.push_back(QJsonObject{{"buffer", 0},
                                {"byteOffset", offset},
                                {"byteLength", qint64(values.size() * sizeof(float))}});
  };
  append(positions);
  append(normals);
  append(uvs);
  append(tangents);
  QJsonArray bufferViews;
  for (const QJsonObject& view : views)
    bufferViews.append(view);
  auto accessor = [](int view, const char* type, QJsonArray min = {}, QJsonArray max = {}) {
    QJsonObject object{{"bufferView", view}, {"componentType", 5126}, {"count", 3}, {"type", type}};
    if (!min.isEmpty()) {
      object["min"] = min;
      object["max"] = max;
    }
    return object;
  };
  const QJsonObject gltf{
      {"asset", QJsonObject{{"version", "2.0"}}},
      {"buffers", QJsonArray{QJsonObject{{"byteLength", buffer.size()},
                                         {"uri", "data:application/octet-stream;base64," +
                                                     QString::fromLatin1(buffer.toBase64())}}}},
      {"bufferViews", bufferViews},
      {"accessors", QJsonArray{accessor(0, "VEC3", {0, 0, -1}, {1, 0, 0}), accessor(1, "VEC3"),
                               accessor(2, "VEC2"), accessor(3, "VEC4")}},
      {"meshes",
       QJsonArray{QJsonObject{
           {"primitives", QJsonArray{QJsonObject{{"attributes", QJsonObject{{"POSITION", 0},
                                                                            {"NORMAL", 1},
                                                                            {"TEXCOORD_0", 2},
                                                                            {"TANGENT", 3}}}}}}}}},
      {"nodes", QJsonArray{QJsonObject{{"mesh", 0}}}},
      {"scenes", QJsonArray{QJsonObject{{"nodes", QJsonArray{0}}}}},
      {"scene", 0},
  };
  return QJsonDocument(gltf).toJson().toStdString();
}

TEST(MeshImport, TangentsInTheFileAreKeptWithTheirHandedness) {
  Result<ImportedMesh> imported = importMesh(writeFile("tangents.gltf", gltfWithTangents()));
  ASSERT_TRUE(imported.ok()) << imported.error();
  EXPECT_TRUE(imported->tangentsFromFile);
  ASSERT_EQ(imported->mesh.vertices.size(), 3u);
  for (const Vertex& v : imported->mesh.vertices) {
    EXPECT_NEAR(v.tangent.x, -1.0f, 1e-5f);
    EXPECT_EQ(v.tangent.w, -1.0f);
    // The file's tangents are kept, and the texel size is still measured: one unit a UV unit.
    EXPECT_NEAR(v.uvScale.x, 1.0f, 1e-5f);
    EXPECT_NEAR(v.uvScale.y, 1.0f, 1e-5f);
  }
}

}  // namespace
}  // namespace relief::core
