// GltfExport; see GltfExport.h. Layout choices the glTF 2.0 specification requires: texture
// coordinates have their origin at the image's top-left (v is flipped), accessors are 4-byte
// aligned, POSITION has min and max, normal textures are +Y up (OpenGL), colour textures sRGB.
#include "core/exporters/GltfExport.h"

#include "core/base/AtomicFile.h"
#include "core/exporters/EngineConversion.h"
#include "core/exporters/PackageExport.h"
#include "core/image/ImageIO.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cstring>
#include <filesystem>
#include <vector>

namespace relief::core::inline exporters {
namespace {

constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

class BinaryBuilder {
 public:
  // Appends values as a buffer view and an accessor; returns the accessor's index.
  template <class T>
  int add(const std::vector<T>& values, int componentType, const char* type, int count, int target,
          QJsonArray& views, QJsonArray& accessors, QJsonObject extra = {}) {
    while (m_bytes.size() % 4)
      m_bytes.push_back('\0');
    const std::size_t offset = m_bytes.size();
    const std::size_t length = values.size() * sizeof(T);
    m_bytes.resize(offset + length);
    std::memcpy(m_bytes.data() + offset, values.data(), length);
    views.append(QJsonObject{{"buffer", 0},
                             {"byteOffset", qint64(offset)},
                             {"byteLength", qint64(length)},
                             {"target", target}});
    QJsonObject accessor{{"bufferView", views.size() - 1},
                         {"componentType", componentType},
                         {"count", count},
                         {"type", type}};
    for (auto it = extra.begin(); it != extra.end(); ++it)
      accessor.insert(it.key(), it.value());
    accessors.append(accessor);
    return int(accessors.size() - 1);
  }
  const std::string& bytes() const { return m_bytes; }

 private:
  std::string m_bytes;
};

// The mesh's vertices and indices in one binary buffer, with their views and accessors.
struct GltfMeshBuffers {
  BinaryBuilder binary;
  QJsonArray views, accessors;
  int position = 0, normal = 0, tangent = 0, uv = 0, indices = 0;  // accessor indices
};

// Tiling is baked into the texture coordinates (core glTF has no UV transform).
GltfMeshBuffers meshBuffers(const Mesh& mesh, float tiling) {
  std::vector<float> positions, normals, tangents, uvs;
  glm::vec3 low = mesh.vertices.front().position, high = low;
  for (const Vertex& v : mesh.vertices) {
    positions.insert(positions.end(), {v.position.x, v.position.y, v.position.z});
    normals.insert(normals.end(), {v.normal.x, v.normal.y, v.normal.z});
    tangents.insert(tangents.end(), {v.tangent.x, v.tangent.y, v.tangent.z, v.tangent.w});
    uvs.insert(uvs.end(), {v.uv.x * tiling, 1.0f - v.uv.y * tiling});
    low = glm::min(low, v.position);
    high = glm::max(high, v.position);
  }
  GltfMeshBuffers out;
  const int count = int(mesh.vertices.size());
  out.position = out.binary.add(
      positions, kFloat, "VEC3", count, kArrayBuffer, out.views, out.accessors,
      {{"min", QJsonArray{low.x, low.y, low.z}}, {"max", QJsonArray{high.x, high.y, high.z}}});
  out.normal =
      out.binary.add(normals, kFloat, "VEC3", count, kArrayBuffer, out.views, out.accessors);
  out.tangent =
      out.binary.add(tangents, kFloat, "VEC4", count, kArrayBuffer, out.views, out.accessors);
  out.uv = out.binary.add(uvs, kFloat, "VEC2", count, kArrayBuffer, out.views, out.accessors);
  out.indices = out.binary.add(mesh.indices, kUnsignedInt, "SCALAR", int(mesh.indices.size()),
                               kElementArrayBuffer, out.views, out.accessors);
  return out;
}

// Textures written as PNGs beside the .gltf: one image, one texture each, sharing a repeating
// trilinear sampler.
struct GltfTextures {
  std::filesystem::path directory;
  std::string stem;
  QJsonArray images, textures;

  Result<int> add(const Image& image, const std::string& suffix, SampleFormat format) {
    const std::string name = stem + "_" + suffix + ".png";
    if (Status saved = saveImage(image, (directory / name).string(), format); !saved)
      return makeError(saved.error());
    images.append(QJsonObject{{"uri", QString::fromStdString(name)}, {"mimeType", "image/png"}});
    textures.append(QJsonObject{{"source", images.size() - 1}, {"sampler", 0}});
    return int(textures.size() - 1);
  }
};

// glTF reads roughness from green and metalness from blue, each times its factor, as the
// viewport does under pbr; a missing map is 1, which lets its factor through. One texture
// carries both, at the larger one's size.
Image packedMetallicRoughness(const Image* roughness, const Image* metallic) {
  const std::vector<std::optional<Image>> resized = resizedToLargest({roughness, metallic});
  if (resized[0])
    roughness = &*resized[0];
  if (resized[1])
    metallic = &*resized[1];
  const Image& size = roughness ? *roughness : *metallic;
  Image packed(size.width(), size.height(), 3);
  const auto texel = [](const Image* map, std::size_t p) {
    return map ? map->data()[p * std::size_t(map->channels())] : 1.0f;
  };
  for (std::size_t p = 0; p < packed.pixelCount(); ++p) {
    packed.data()[p * 3 + 1] = texel(roughness, p);
    packed.data()[p * 3 + 2] = texel(metallic, p);
  }
  return packed;
}

// The metallic-roughness material and its textures.
Result<QJsonObject> materialJson(const Material& material, GltfTextures& textures) {
  QJsonObject pbr{{"metallicFactor", exportedMetallic(material)},
                  {"roughnessFactor", exportedRoughness(material)}};
  QJsonObject gltfMaterial{{"name", QString::fromStdString(textures.stem)}};
  if (const Image* color = material.image(MapSlot::Color)) {
    auto index = textures.add(*color, "color", SampleFormat::UInt8);
    if (!index)
      return makeError(index.error());
    pbr.insert("baseColorTexture", QJsonObject{{"index", index.value()}});
  }
  const Image* roughness = material.image(MapSlot::Roughness);
  const Image* metallic = material.image(MapSlot::Metallic);
  if (roughness || metallic) {
    auto index = textures.add(packedMetallicRoughness(roughness, metallic), "metallic_roughness",
                              SampleFormat::UInt8);
    if (!index)
      return makeError(index.error());
    pbr.insert("metallicRoughnessTexture", QJsonObject{{"index", index.value()}});
    // Under classic shading a roughness map is the roughness itself (factor 1).
    if (roughness && !shadesPbr(material))
      pbr.insert("roughnessFactor", 1.0);
  }
  gltfMaterial.insert("pbrMetallicRoughness", pbr);
  if (const Image* normalMap = material.image(MapSlot::Normal)) {
    const Image converted =
        openGlNormalMap(*normalMap, material.parameterFlag(ParamId::NormalYDown));
    auto index = textures.add(converted, "normal", SampleFormat::UInt8);
    if (!index)
      return makeError(index.error());
    gltfMaterial.insert("normalTexture",
                        QJsonObject{{"index", index.value()},
                                    {"scale", material.parameter(ParamId::NormalStrength)}});
  }
  if (const Image* occlusion = material.image(MapSlot::AmbientOcclusion)) {
    auto index = textures.add(*occlusion, "occlusion", SampleFormat::UInt8);
    if (!index)
      return makeError(index.error());
    gltfMaterial.insert("occlusionTexture", QJsonObject{{"index", index.value()}});
  }
  return gltfMaterial;
}

// The material's extras.relief: technique, every parameter, and the height map (16-bit, as the
// parallax needs), referenced by its image, which no glTF texture samples.
Result<QJsonObject> reliefExtras(const Material& material, const GltfTextures& textures) {
  QJsonObject relief{{"technique", QString::fromUtf8(techniqueName(material.technique()).data())}};
  QJsonObject parameters;
  for (const ParameterSpec& spec : allParameters()) {
    parameters.insert(QString::fromUtf8(spec.name.data()),
                      parameterJson(spec, material.parameter(spec.id)));
  }
  relief.insert("parameters", parameters);
  if (const Image* height = material.image(MapSlot::Height)) {
    const std::string name = textures.stem + "_height.png";
    if (Status saved =
            saveImage(*height, (textures.directory / name).string(), SampleFormat::UInt16);
        !saved) {
      return makeError(saved.error());
    }
    relief.insert("heightImage", QString::fromStdString(name));
    relief.insert("note", "Texture coordinates are already multiplied by the tiling parameter.");
  }
  return relief;
}

}  // namespace

Result<std::string> exportGltf(const Preset& preset, const Mesh& mesh, const std::string& folder) {
  if (Status made = makeExportFolder(folder); !made)
    return makeError(made.error());
  if (mesh.vertices.empty() || mesh.indices.empty())
    return makeError("the mesh is empty");
  const Material& material = preset.material;
  const std::string stem = exportStem(material);
  const std::filesystem::path directory(folder);

  const GltfMeshBuffers buffers = meshBuffers(mesh, material.parameterf(ParamId::Tiling));
  const BinaryBuilder& binary = buffers.binary;
  GltfTextures textures{directory, stem, {}, {}};
  Result<QJsonObject> gltfMaterial = materialJson(material, textures);
  if (!gltfMaterial)
    return makeError(gltfMaterial.error());
  Result<QJsonObject> relief = reliefExtras(material, textures);
  if (!relief)
    return makeError(relief.error());
  gltfMaterial->insert("extras", QJsonObject{{"relief", relief.value()}});

  const std::string binName = stem + ".bin";
  const QJsonObject root{
      {"asset", QJsonObject{{"version", "2.0"}, {"generator", "Relief"}}},
      {"scene", 0},
      {"scenes", QJsonArray{QJsonObject{{"nodes", QJsonArray{0}}}}},
      {"nodes", QJsonArray{QJsonObject{{"mesh", 0}, {"name", QString::fromStdString(stem)}}}},
      {"meshes", QJsonArray{QJsonObject{
                     {"name", QString::fromStdString(mesh.name.empty() ? stem : mesh.name)},
                     {"primitives", QJsonArray{QJsonObject{
                                        {"attributes", QJsonObject{{"POSITION", buffers.position},
                                                                   {"NORMAL", buffers.normal},
                                                                   {"TANGENT", buffers.tangent},
                                                                   {"TEXCOORD_0", buffers.uv}}},
                                        {"indices", buffers.indices},
                                        {"material", 0},
                                        {"mode", 4}}}}}}},
      {"materials", QJsonArray{gltfMaterial.value()}},
      {"samplers",
       QJsonArray{QJsonObject{
           {"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 10497}}}},
      {"buffers", QJsonArray{QJsonObject{{"uri", QString::fromStdString(binName)},
                                         {"byteLength", qint64(binary.bytes().size())}}}},
      {"bufferViews", buffers.views},
      {"accessors", buffers.accessors},
  };
  QJsonObject document = root;
  if (!textures.images.isEmpty()) {
    document.insert("images", textures.images);
    document.insert("textures", textures.textures);
  }
  if (Status written = writeFileAtomically((directory / binName).string(), binary.bytes());
      !written) {
    return makeError(written.error());
  }
  const std::string gltfPath = (directory / (stem + ".gltf")).string();
  const QByteArray json = QJsonDocument(document).toJson(QJsonDocument::Indented);
  if (Status written = writeFileAtomically(
          gltfPath, std::string_view(json.constData(), std::size_t(json.size())));
      !written) {
    return makeError(written.error());
  }
  return gltfPath;
}

}  // namespace relief::core::inline exporters
