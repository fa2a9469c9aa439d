// GltfPreflight; see GltfPreflight.h. The JSON is read with Qt (QJsonDocument), which is not
// recursive over arrays of indices, so a hostile hierarchy cannot overflow it either.
#include "core/mesh/GltfPreflight.h"

#include "core/base/Text.h"

#include <QByteArray>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace relief::core::inline mesh {
namespace {

// 0 past the end; glb is little-endian, as is every machine Relief runs on.
std::uint32_t readU32(const QByteArray& bytes, std::uint64_t offset) {
  std::uint32_t value = 0;
  if (offset + 4 <= std::uint64_t(bytes.size()))
    std::memcpy(&value, bytes.constData() + offset, 4);
  return value;
}

// The JSON chunk of a .glb whose 12-byte header was checked, after checking every chunk's
// length against the file.
Result<QByteArray> glbJson(const std::string& path, const QByteArray& file) {
  const auto fail = [&path](const std::string& problem) {
    return makeError(path + ": " + problem);
  };
  if (file.size() < 20)
    return fail("the file ends before its JSON chunk");
  const std::uint32_t jsonLength = readU32(file, 12);
  if (file.mid(16, 4) != "JSON")
    return fail("the first chunk is not the JSON chunk");
  if (std::uint64_t(jsonLength) + 20 > std::uint64_t(file.size())) {
    return fail("the JSON chunk claims " + std::to_string(jsonLength) +
                " bytes, more than the file holds");
  }
  std::uint64_t offset = 20 + std::uint64_t(jsonLength);
  while (offset + 8 <= std::uint64_t(file.size())) {
    const std::uint64_t length = readU32(file, offset);
    if (offset + 8 + length > std::uint64_t(file.size())) {
      return fail("a chunk at byte " + std::to_string(offset) + " claims " +
                  std::to_string(length) + " bytes, more than the file holds");
    }
    offset += 8 + length;
  }
  return file.mid(20, qsizetype(jsonLength));
}

// Deepest chain of children, walked with an explicit stack (no recursion to overflow). A node
// reached twice (a cycle or a shared child) is refused: glTF requires a strict tree.
Status checkNodes(const std::string& path, const QJsonArray& nodes) {
  if (nodes.size() > kMaxNodeCount) {
    return makeError(path + ": " + std::to_string(nodes.size()) + " nodes, more than the " +
                     std::to_string(kMaxNodeCount) + " Relief reads");
  }
  std::vector<int> parents(std::size_t(nodes.size()), 0);
  for (const QJsonValue& node : nodes) {
    for (const QJsonValue& child : node.toObject().value(QStringLiteral("children")).toArray()) {
      const int index = child.toInt(-1);
      if (index < 0 || index >= nodes.size())
        return makeError(path + ": a node names a child " + std::to_string(index) +
                         " that does not exist");
      if (++parents[std::size_t(index)] > 1)
        return makeError(path + ": node " + std::to_string(index) +
                         " has more than one parent (glTF nodes form a tree)");
    }
  }
  std::vector<std::pair<int, int>> stack;  // node, depth
  for (int root = 0; root < nodes.size(); ++root) {
    if (parents[std::size_t(root)] == 0)
      stack.emplace_back(root, 1);
  }
  std::size_t visited = 0;
  while (!stack.empty()) {
    const auto [node, depth] = stack.back();
    stack.pop_back();
    ++visited;
    if (depth > kMaxNodeDepth) {
      return makeError(path + ": nodes are nested more than " + std::to_string(kMaxNodeDepth) +
                       " deep; Relief reads flatter hierarchies");
    }
    for (const QJsonValue& child :
         nodes[node].toObject().value(QStringLiteral("children")).toArray())
      stack.emplace_back(child.toInt(), depth + 1);
  }
  if (visited != std::size_t(nodes.size()))
    return makeError(path + ": the node hierarchy has a cycle");
  return {};
}

// A scene lists root nodes: each must exist and have no parent (glTF 2.0, 3.5.2). Assimp 5.2
// builds a node listed as a root and as a child twice and loses memory (found by tests/fuzz).
Status checkSceneRoots(const std::string& path, const QJsonObject& root) {
  const QJsonArray nodes = root.value(QStringLiteral("nodes")).toArray();
  std::vector<bool> isChild(std::size_t(nodes.size()), false);
  for (const QJsonValue& node : nodes) {
    for (const QJsonValue& child : node.toObject().value(QStringLiteral("children")).toArray())
      isChild[std::size_t(child.toInt())] = true;  // checkNodes made sure the index exists
  }
  for (const QJsonValue& scene : root.value(QStringLiteral("scenes")).toArray()) {
    for (const QJsonValue& entry : scene.toObject().value(QStringLiteral("nodes")).toArray()) {
      const int index = entry.toInt(-1);
      if (index < 0 || index >= nodes.size())
        return makeError(path + ": a scene names a node " + std::to_string(index) +
                         " that does not exist");
      if (isChild[std::size_t(index)])
        return makeError(path + ": node " + std::to_string(index) +
                         " is a scene root and another node's child (glTF nodes form a tree)");
    }
  }
  return {};
}

// Buffers and images may name files beside the glTF (or data: URIs), never outside its folder.
Status checkUris(const std::string& path, const QJsonObject& root) {
  for (const QString& key : {QStringLiteral("buffers"), QStringLiteral("images")}) {
    for (const QJsonValue& entry : root.value(key).toArray()) {
      const QString uri = entry.toObject().value(QStringLiteral("uri")).toString();
      if (uri.isEmpty() || uri.startsWith(QStringLiteral("data:")))
        continue;
      const std::filesystem::path relative(uri.toStdString());
      bool escapes = relative.is_absolute() || uri.contains(QLatin1Char(':'));
      for (const std::filesystem::path& part : relative)
        escapes = escapes || part == "..";
      if (escapes) {
        return makeError(path + ": " + key.toStdString() + " URI \"" + uri.left(200).toStdString() +
                         "\" points outside the file's folder");
      }
    }
  }
  return {};
}

}  // namespace

Status preflightGltf(const std::string& path) {
  const std::string extension = lowerExtension(path);
  if (extension != "gltf" && extension != "glb")
    return {};
  QFile file(QString::fromStdString(path));
  if (!file.open(QIODevice::ReadOnly))
    return makeError(path + ": cannot open (" + file.errorString().toStdString() + ")");
  QByteArray json;
  if (extension == "glb") {
    // The header is checked before the whole file is read: a claimed length that the file does
    // not have is refused at once.
    const QByteArray header = file.peek(12);
    if (header.size() < 12 || !header.startsWith("glTF"))
      return makeError(path + ": not a binary glTF file (no \"glTF\" header)");
    if (const std::uint32_t declared = readU32(header, 8);
        std::uint64_t(declared) != std::uint64_t(file.size())) {
      return makeError(path + ": the header says " + std::to_string(declared) +
                       " bytes but the file has " + std::to_string(file.size()));
    }
    Result<QByteArray> chunk = glbJson(path, file.readAll());
    if (!chunk)
      return makeError(chunk.error());
    json = std::move(chunk).value();
  } else {
    json = file.readAll();
  }
  QJsonParseError error;
  const QJsonDocument document = QJsonDocument::fromJson(json, &error);
  if (error.error != QJsonParseError::NoError || !document.isObject()) {
    return makeError(path + ": not valid glTF JSON (" + error.errorString().toStdString() +
                     " at byte " + std::to_string(error.offset) + ")");
  }
  const QJsonObject root = document.object();
  if (Status nodes = checkNodes(path, root.value(QStringLiteral("nodes")).toArray()); !nodes)
    return nodes;
  if (Status roots = checkSceneRoots(path, root); !roots)
    return roots;
  return checkUris(path, root);
}

}  // namespace relief::core::mesh
