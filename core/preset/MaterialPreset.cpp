// Preset files; see MaterialPreset.h.
#include "core/preset/MaterialPreset.h"

#include "core/base/AtomicFile.h"
#include "core/base/InputFile.h"
#include "core/compression/BlockRdo.h"
#include "core/compression/MapFile.h"
#include "core/image/ImageIO.h"
#include "core/shading/Brdf.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace relief::core::inline preset {
namespace {

QString qstr(std::string_view text) {
  return QString::fromUtf8(text.data(), qsizetype(text.size()));
}

// Collects warnings that name the file.
class Problems {
 public:
  Problems(const std::string& path, std::vector<std::string>& warnings)
      : m_path(path), m_warnings(warnings) {}
  void add(const std::string& message) { m_warnings.push_back(m_path + ": " + message); }

 private:
  const std::string& m_path;
  std::vector<std::string>& m_warnings;
};

// A finite number from a JSON value within [low, high], or nullopt after a warning.
std::optional<double> readNumber(const QJsonValue& value, const std::string& what, double low,
                                 double high, Problems& problems) {
  if (!value.isDouble()) {
    problems.add(what + " should be a number; default kept");
    return std::nullopt;
  }
  const double number = value.toDouble();
  if (!std::isfinite(number)) {
    problems.add(what + " is not a finite number; default kept");
    return std::nullopt;
  }
  if (number < low || number > high) {
    const double clamped = std::clamp(number, low, high);
    problems.add(what + " = " + std::to_string(number) + " is outside " + std::to_string(low) +
                 ".." + std::to_string(high) + "; clamped to " + std::to_string(clamped));
    return clamped;
  }
  return number;
}

std::optional<glm::vec3> readVector(const QJsonValue& value, const std::string& what, double low,
                                    double high, Problems& problems) {
  const QJsonArray array = value.toArray();
  if (!value.isArray() || array.size() != 3) {
    problems.add(what + " should be an array of 3 numbers; default kept");
    return std::nullopt;
  }
  glm::vec3 result;
  for (int i = 0; i < 3; ++i) {
    const auto number =
        readNumber(array[i], what + "[" + std::to_string(i) + "]", low, high, problems);
    if (!number)
      return std::nullopt;
    result[i] = float(*number);
  }
  return result;
}

void readParameters(const QJsonObject& object, Material& material, Problems& problems) {
  for (auto it = object.begin(); it != object.end(); ++it) {
    const std::string key = it.key().toStdString();
    const std::optional<ParamId> id = findParameter(key);
    if (!id) {
      problems.add("unknown parameter '" + key + "' kept in the file but not used");
      continue;
    }
    const ParameterSpec& spec = parameterSpec(*id);
    if (it.value().isBool() && spec.kind == ParamKind::Bool) {
      material.setParameter(*id, it.value().toBool() ? 1.0 : 0.0);
    } else if (it.value().isString() && spec.kind == ParamKind::Choice) {
      Result<double> parsed = parseOptionValue(spec, it.value().toString().toStdString());
      if (!parsed) {
        problems.add(parsed.error() + "; default kept");
        continue;
      }
      material.setParameter(*id, parsed.value());
    } else if (it.value().isDouble() && spec.kind != ParamKind::Choice) {
      const auto value =
          readNumber(it.value(), "parameter '" + key + "'", spec.minimum, spec.maximum, problems);
      if (value)
        material.setParameter(*id, *value);
    } else {
      problems.add("parameter '" + key + "' has the wrong type (expected " +
                   (spec.kind == ParamKind::Bool     ? std::string("true or false")
                    : spec.kind == ParamKind::Choice ? std::string("a choice name")
                                                     : std::string("a number")) +
                   "); default kept");
    }
  }
}

MapCompression readCompression(const QJsonObject& object, const std::string& slot,
                               Problems& problems) {
  const std::string format = object.value(QStringLiteral("format")).toString().toStdString();
  const std::optional<TextureFormat> found = findTextureFormat(format);
  if (!found) {
    problems.add(slot + " map: unknown compression format '" + format + "' ignored");
    return std::nullopt;
  }
  CompressionSettings compression;
  compression.format = *found;
  const std::string quality =
      object.value(QStringLiteral("quality")).toString(QStringLiteral("normal")).toStdString();
  if (const std::optional<CompressionQuality> level = findCompressionQuality(quality)) {
    compression.quality = *level;
  } else {
    problems.add(slot + " map: compression quality '" + quality +
                 "' is not fast, normal or best; normal used");
  }
  compression.mipmaps = object.value(QStringLiteral("mipmaps")).toBool(true);
  // "zstd": the Zstandard level of the KTX2 file an export writes (absent: none).
  if (object.contains(QStringLiteral("zstd"))) {
    if (const std::optional<double> level =
            readNumber(object.value(QStringLiteral("zstd")), slot + " map: compression zstd", 0,
                       kMaxZstdLevel, problems)) {
      compression.zstdLevel = int(std::lround(*level));
    }
  }
  // "perceptual": BC1-BC3 colour error weighed by luminance (absent: uniform weights).
  compression.perceptual = object.value(QStringLiteral("perceptual")).toBool(false);
  // "mipFilter": the mip chain's filter, box or kaiser (absent: box).
  const std::string filter =
      object.value(QStringLiteral("mipFilter")).toString(QStringLiteral("box")).toStdString();
  if (const std::optional<MipFilter> mipFilter = findMipFilter(filter)) {
    compression.mipFilter = *mipFilter;
  } else {
    problems.add(slot + " map: mip filter '" + filter + "' is not box or kaiser; box used");
  }
  // "roughnessFromNormals": a roughness map's mips widened by the normal map's spread.
  compression.roughnessFromNormals =
      object.value(QStringLiteral("roughnessFromNormals")).toBool(false);
  // "alphaCoverage": the alpha cutoff whose coverage each mip level keeps (absent: off).
  if (object.contains(QStringLiteral("alphaCoverage"))) {
    if (const std::optional<double> cutoff =
            readNumber(object.value(QStringLiteral("alphaCoverage")),
                       slot + " map: compression alphaCoverage", 0.0, 1.0, problems)) {
      compression.alphaCoverage = float(*cutoff);
    }
  }
  // "rdo": the rate-distortion lambda for Zstandard (BlockRdo.h; absent: off).
  if (object.contains(QStringLiteral("rdo"))) {
    if (const std::optional<double> lambda =
            readNumber(object.value(QStringLiteral("rdo")), slot + " map: compression rdo", 0.0,
                       kMaxRdoLambda, problems)) {
      compression.rdoLambda = float(*lambda);
    }
  }
  return compression;
}

void readMaps(const QJsonObject& object, const std::string& path, Preset& preset,
              Problems& problems) {
  const QDir presetDir = QFileInfo(QString::fromStdString(path)).absoluteDir();
  std::map<std::string, std::shared_ptr<const Image>> packedFiles;  // by path
  for (auto it = object.begin(); it != object.end(); ++it) {
    const std::string name = it.key().toStdString();
    const std::optional<MapSlot> slot = findMapSlot(name);
    if (!slot) {
      problems.add("unknown map slot '" + name + "' kept in the file but not used");
      continue;
    }
    const QJsonObject entry = it.value().toObject();
    if (entry.contains(QStringLiteral("compression"))) {
      preset.compression[std::size_t(*slot)] =
          readCompression(entry.value(QStringLiteral("compression")).toObject(), name, problems);
    }
    const QString colorSpace = entry.value(QStringLiteral("colorSpace")).toString();
    if (!colorSpace.isEmpty() && colorSpace != qstr(colorSpaceName(mapSlotColorSpace(*slot)))) {
      problems.add(name + " map: colour space '" + colorSpace.toStdString() +
                   "' is not supported "
                   "for this slot; read as " +
                   std::string(colorSpaceName(mapSlotColorSpace(*slot))));
    }
    const QString relative = entry.value(QStringLiteral("path")).toString();
    if (relative.isEmpty()) {
      problems.add("map '" + name + "' has no path");
      continue;
    }
    // A NUL would cut the path short where the file system sees it: another file would load.
    if (relative.contains(QChar(0))) {
      problems.add(name + " map: the path contains a NUL character; not loaded");
      continue;
    }
    const std::string mapPath = QDir::cleanPath(presetDir.absoluteFilePath(relative)).toStdString();
    // The slots of one packed file (an ORM texture's three) decode it once.
    const bool packed = entry.contains(QStringLiteral("channel"));
    std::shared_ptr<const Image> image = packed ? packedFiles[mapPath] : nullptr;
    if (!image) {
      Result<Image> loaded = loadMapFile(mapPath);
      if (!loaded) {
        problems.add(name + " map not loaded: " + loaded.error());
        continue;
      }
      image = std::make_shared<const Image>(std::move(loaded).value());
      if (packed)
        packedFiles[mapPath] = image;
    }
    // "channel": the map is one channel of the file (an ORM texture's G is the roughness).
    int channel = -1;
    if (packed) {
      const std::string letter = entry.value(QStringLiteral("channel")).toString().toStdString();
      const std::optional<int> index = channelFromLetter(letter);
      if (!index) {
        problems.add(name + " map: channel '" + letter + "' is not r, g, b or a; not loaded");
        continue;
      }
      if (*index >= image->channels()) {
        problems.add(name + " map: " + relative.toStdString() + " has " +
                     std::to_string(image->channels()) + " channel(s), no '" + letter +
                     "'; not loaded");
        continue;
      }
      channel = *index;
    }
    auto map = channel >= 0 ? std::make_shared<const Image>(channelImage(*image, channel))
                            : std::move(image);
    preset.material.setMap(*slot, std::move(map), mapPath, channel);
  }
}

// Built-ins by name; anything with an extension is a file relative to the preset, as meshes.
// A file that is missing now is kept as given: the viewport says so and lights with the
// uniform white until it is back.
Environment readEnvironment(const QJsonObject& object, const QDir& presetDir, Problems& problems) {
  Environment result;
  const QString source = object.value(QStringLiteral("source")).toString();
  if (!source.isEmpty()) {
    result.source = QFileInfo(source).suffix().isEmpty()
                        ? source.toStdString()
                        : QDir::cleanPath(presetDir.absoluteFilePath(source)).toStdString();
  }
  if (auto v = readNumber(object.value(QStringLiteral("intensity")), "view.environment.intensity",
                          0, Environment::kMaxIntensity, problems))
    result.intensity = float(*v);
  if (auto v = readNumber(object.value(QStringLiteral("rotation")), "view.environment.rotation",
                          -360, 360, problems))
    result.rotationDeg = float(*v);
  if (object.contains(QStringLiteral("background"))) {
    const std::string name = object.value(QStringLiteral("background")).toString().toStdString();
    if (const std::optional<Background> background = findBackground(name))
      result.background = *background;
    else
      problems.add("view.environment.background '" + name + "' is not a background; color used");
  }
  return result;
}

void readView(const QJsonObject& object, const std::string& path, ViewState& view,
              Problems& problems) {
  const QDir presetDir = QFileInfo(QString::fromStdString(path)).absoluteDir();
  if (object.contains(QStringLiteral("mesh"))) {
    const QString mesh = object.value(QStringLiteral("mesh")).toString();
    // Primitives by name; anything with an extension is a file relative to the preset.
    view.mesh = QFileInfo(mesh).suffix().isEmpty()
                    ? mesh.toStdString()
                    : QDir::cleanPath(presetDir.absoluteFilePath(mesh)).toStdString();
  }
  if (object.contains(QStringLiteral("camera"))) {
    const QJsonObject camera = object.value(QStringLiteral("camera")).toObject();
    OrbitCamera result;
    if (auto v =
            readNumber(camera.value(QStringLiteral("yaw")), "view.camera.yaw", -360, 360, problems))
      result.yawDeg = float(*v);
    if (auto v = readNumber(camera.value(QStringLiteral("pitch")), "view.camera.pitch",
                            OrbitCamera::kMinPitchDeg, OrbitCamera::kMaxPitchDeg, problems))
      result.pitchDeg = float(*v);
    if (auto v = readNumber(camera.value(QStringLiteral("distance")), "view.camera.distance", 0.05,
                            500, problems))
      result.distance = float(*v);
    if (auto v =
            readNumber(camera.value(QStringLiteral("fov")), "view.camera.fov", 5, 120, problems))
      result.fovYDeg = float(*v);
    if (auto v = readVector(camera.value(QStringLiteral("target")), "view.camera.target", -1e4, 1e4,
                            problems))
      result.target = *v;
    view.camera = result;
  }
  if (object.contains(QStringLiteral("light"))) {
    const QJsonObject light = object.value(QStringLiteral("light")).toObject();
    DirectionalLight result;
    if (auto v = readNumber(light.value(QStringLiteral("azimuth")), "view.light.azimuth", -360, 360,
                            problems))
      result.azimuthDeg = float(*v);
    if (auto v = readNumber(light.value(QStringLiteral("elevation")), "view.light.elevation", -90,
                            90, problems))
      result.elevationDeg = float(*v);
    if (auto v =
            readVector(light.value(QStringLiteral("color")), "view.light.color", 0, 16, problems))
      result.color = *v;
    if (auto v = readNumber(light.value(QStringLiteral("intensity")), "view.light.intensity", 0,
                            100, problems))
      result.intensity = float(*v);
    if (auto v = readNumber(light.value(QStringLiteral("ambient")), "view.light.ambient", 0, 1,
                            problems))
      result.ambient = float(*v);
    view.light = result;
  }
  if (object.contains(QStringLiteral("display"))) {
    const QJsonObject display = object.value(QStringLiteral("display")).toObject();
    DisplayTransform result;
    if (auto v = readNumber(display.value(QStringLiteral("exposure")), "view.display.exposure",
                            DisplayTransform::kMinExposureEv, DisplayTransform::kMaxExposureEv,
                            problems))
      result.exposureEv = float(*v);
    if (display.contains(QStringLiteral("toneMapping"))) {
      const std::string name =
          display.value(QStringLiteral("toneMapping")).toString().toStdString();
      if (const std::optional<ToneMapper> mapper = findToneMapper(name))
        result.toneMapper = *mapper;
      else
        problems.add("view.display.toneMapping '" + name + "' is not a tone mapper; none used");
    }
    view.display = result;
  }
  if (object.contains(QStringLiteral("environment")))
    view.environment = readEnvironment(object.value(QStringLiteral("environment")).toObject(),
                                       presetDir, problems);
}

// Brings an older file's JSON to the current version.
// - Version 1 has no compression choices and no view; nothing in it changed meaning.
// - Version 2's default shading was classic, version 3's is pbr: a version 2 file without a
//   shading keeps classic, so it looks as it did. One without a roughness gets the one whose
//   GGX lobe matches its Blinn-Phong highlight: switching it to pbr keeps the highlight's width
//   (roughnessFromShininess). Specular (the highlight's strength) has no metallic-roughness
//   counterpart (a dielectric reflects 4% at normal incidence) and stays for classic shading.
QJsonObject migrate(QJsonObject root, int fromVersion) {
  if (fromVersion < 3) {
    QJsonObject parameters = root.value(QStringLiteral("parameters")).toObject();
    if (!parameters.contains(QStringLiteral("shading")))
      parameters.insert(QStringLiteral("shading"), QStringLiteral("classic"));
    if (!parameters.contains(QStringLiteral("roughness"))) {
      const double shininess = parameters.value(QStringLiteral("shininess"))
                                   .toDouble(parameterDefault(ParamId::Shininess));
      const double roughness = roughnessFromShininess(shininess);
      parameters.insert(QStringLiteral("roughness"), std::round(roughness * 1000.0) / 1000.0);
    }
    root.insert(QStringLiteral("parameters"), parameters);
  }
  root.insert(QStringLiteral("version"), kPresetVersion);
  return root;
}

// A float as the shortest decimal that reads back as the same float, so files say 0.12 and
// not 0.11999999731779099 (the float's exact double value).
double tidy(float value) {
  for (int digits = 6; digits <= 9; ++digits) {
    const double shorter = QString::number(double(value), 'g', digits).toDouble();
    if (float(shorter) == value)
      return shorter;
  }
  return double(value);
}

QJsonArray toJson(const glm::vec3& v) {
  return QJsonArray{tidy(v.x), tidy(v.y), tidy(v.z)};
}

// Values outside 0..1 (EXR heights, say) would be clipped by a PNG.
bool needsFloat(const Image& image) {
  const auto [low, high] = std::minmax_element(image.data(), image.data() + image.valueCount());
  return image.valueCount() > 0 && (*low < 0.0f || *high > 1.0f);
}

}  // namespace

QJsonValue parameterJson(const ParameterSpec& spec, double value) {
  switch (spec.kind) {
    case ParamKind::Bool:
      return value != 0.0;
    case ParamKind::Choice:
      return qstr(spec.choices[std::size_t(value)]);
    case ParamKind::Float:
    case ParamKind::Int:
      return value;
  }
  return value;  // not reached: every kind is handled above
}

Result<LoadedPreset> loadPreset(const std::string& path) {
  // A FIFO would block the read forever and /dev/zero would fill memory: only regular files of
  // a sane size are read (links are followed, so a link to either is refused too).
  if (auto checked = checkInputFile(path, std::uintmax_t(kMaxPresetBytes), "preset"); !checked)
    return makeError(checked.error());
  QFile file(QString::fromStdString(path));
  if (!file.open(QIODevice::ReadOnly)) {
    return makeError(path + ": cannot open (" + file.errorString().toStdString() + ")");
  }
  QJsonParseError parseError;
  const QJsonDocument document = QJsonDocument::fromJson(file.read(kMaxPresetBytes), &parseError);
  if (parseError.error != QJsonParseError::NoError) {
    return makeError(path + ": not a valid preset: " + parseError.errorString().toStdString() +
                     " at byte " + std::to_string(parseError.offset));
  }
  if (!document.isObject()) {
    return makeError(path + ": not a valid preset: the top level is not a JSON object");
  }
  QJsonObject root = document.object();
  if (root.value(QStringLiteral("format")).toString() != qstr(kPresetFormatName)) {
    return makeError(path + ": not a Relief preset (\"format\" is not \"" +
                     std::string(kPresetFormatName) + "\")");
  }
  const QJsonValue versionValue = root.value(QStringLiteral("version"));
  const double version = versionValue.toDouble(-1);
  if (!versionValue.isDouble() || version != std::floor(version) || version < 1) {
    return makeError(path + ": \"version\" must be a positive integer");
  }
  if (version > kPresetVersion) {
    // The number as written (2^63 too), not as an int would hold it.
    char written[32];
    std::snprintf(written, sizeof written, "%.0f", version);
    return makeError(path + ": written by a newer Relief (preset version " + written +
                     "; this program reads up to " + std::to_string(kPresetVersion) + ")");
  }

  LoadedPreset loaded;
  loaded.fileVersion = int(version);
  root = migrate(root, int(version));
  Problems problems(path, loaded.warnings);
  Preset& preset = loaded.preset;
  preset.preserved = root;
  Material& material = preset.material;
  material.setName(root.value(QStringLiteral("name"))
                       .toString(QFileInfo(QString::fromStdString(path)).completeBaseName())
                       .toStdString());
  if (root.contains(QStringLiteral("technique"))) {
    const std::string name = root.value(QStringLiteral("technique")).toString().toStdString();
    if (const std::optional<Technique> technique = findTechnique(name)) {
      material.setTechnique(*technique);
    } else {
      problems.add("unknown technique '" + name + "'; using " +
                   std::string(techniqueName(material.technique())));
    }
  }
  readParameters(root.value(QStringLiteral("parameters")).toObject(), material, problems);
  readMaps(root.value(QStringLiteral("maps")).toObject(), path, preset, problems);
  readView(root.value(QStringLiteral("view")).toObject(), path, preset.view, problems);
  return loaded;
}

namespace {

QJsonObject compressionJson(const CompressionSettings& compression) {
  QJsonObject choice{{QStringLiteral("format"), qstr(textureFormatInfo(compression.format).name)},
                     {QStringLiteral("quality"), qstr(compressionQualityName(compression.quality))},
                     {QStringLiteral("mipmaps"), compression.mipmaps}};
  if (compression.zstdLevel > 0)
    choice.insert(QStringLiteral("zstd"), compression.zstdLevel);
  if (compression.perceptual)
    choice.insert(QStringLiteral("perceptual"), true);
  if (compression.mipFilter != MipFilter::Box)
    choice.insert(QStringLiteral("mipFilter"), qstr(mipFilterName(compression.mipFilter)));
  if (compression.roughnessFromNormals)
    choice.insert(QStringLiteral("roughnessFromNormals"), true);
  if (compression.alphaCoverage > 0.0f)
    choice.insert(QStringLiteral("alphaCoverage"), double(compression.alphaCoverage));
  if (compression.rdoLambda > 0.0f)
    choice.insert(QStringLiteral("rdo"), double(compression.rdoLambda));
  return choice;
}

// The "maps" object: each map's path relative to the preset, colour space, channel and
// compression. A map generated in the editor (no file) is written beside the preset first, at
// full precision, and listed in `saved`.
Result<QJsonObject> mapsJson(const Preset& preset, const std::string& path, QJsonObject maps,
                             SavedPreset& saved) {
  const QFileInfo presetFile(QString::fromStdString(path));
  const QDir presetDir = presetFile.absoluteDir();
  const Material& material = preset.material;
  for (MapSlot slot : kAllMapSlots) {
    const QString key = qstr(mapSlotName(slot));
    const MaterialMap& map = material.map(slot);
    if (!map.image) {
      maps.remove(key);
      continue;
    }
    std::string mapPath = map.sourcePath;
    if (mapPath.empty()) {
      // Generated in the editor: write it beside the preset, at full precision.
      const bool floating = needsFloat(*map.image);
      const QString name = presetFile.completeBaseName() + QLatin1Char('_') + key +
                           (floating ? QStringLiteral(".exr") : QStringLiteral(".png"));
      mapPath = presetDir.absoluteFilePath(name).toStdString();
      const SampleFormat format = floating                 ? SampleFormat::Float
                                  : slot == MapSlot::Color ? SampleFormat::UInt8
                                                           : SampleFormat::UInt16;
      if (Status written = saveImage(*map.image, mapPath, format); !written) {
        return makeError(path + ": the generated " + key.toStdString() + " map could not be " +
                         "written, so the preset was not saved: " + written.error());
      }
      saved.writtenMaps.emplace_back(slot, mapPath);
    }
    QJsonObject entry = maps.value(key).toObject();
    entry.insert(QStringLiteral("path"),
                 presetDir.relativeFilePath(QString::fromStdString(mapPath)));
    entry.insert(QStringLiteral("colorSpace"), qstr(colorSpaceName(mapSlotColorSpace(slot))));
    if (map.sourceChannel >= 0 && !map.sourcePath.empty())
      entry.insert(QStringLiteral("channel"),
                   QString(QChar::fromLatin1(channelLetter(map.sourceChannel))));
    else
      entry.remove(QStringLiteral("channel"));
    const MapCompression& compression = preset.compression[std::size_t(slot)];
    if (!compression)
      entry.remove(QStringLiteral("compression"));
    else
      entry.insert(QStringLiteral("compression"), compressionJson(*compression));
    maps.insert(key, entry);
  }
  return maps;
}

// The "view" object: the mesh and environment files relative to the preset.
QJsonObject viewJson(const ViewState& state, const QDir& presetDir, QJsonObject view) {
  if (!state.mesh.empty()) {
    const QString mesh = QString::fromStdString(state.mesh);
    view.insert(QStringLiteral("mesh"),
                QFileInfo(mesh).isAbsolute() ? presetDir.relativeFilePath(mesh) : mesh);
  }
  if (state.camera) {
    const OrbitCamera& c = *state.camera;
    view.insert(QStringLiteral("camera"),
                QJsonObject{{QStringLiteral("yaw"), tidy(c.yawDeg)},
                            {QStringLiteral("pitch"), tidy(c.pitchDeg)},
                            {QStringLiteral("distance"), tidy(c.distance)},
                            {QStringLiteral("fov"), tidy(c.fovYDeg)},
                            {QStringLiteral("target"), toJson(c.target)}});
  }
  if (state.light) {
    const DirectionalLight& l = *state.light;
    view.insert(QStringLiteral("light"),
                QJsonObject{{QStringLiteral("azimuth"), tidy(l.azimuthDeg)},
                            {QStringLiteral("elevation"), tidy(l.elevationDeg)},
                            {QStringLiteral("color"), toJson(l.color)},
                            {QStringLiteral("intensity"), tidy(l.intensity)},
                            {QStringLiteral("ambient"), tidy(l.ambient)}});
  }
  if (state.display) {
    const DisplayTransform& d = *state.display;
    view.insert(QStringLiteral("display"),
                QJsonObject{{QStringLiteral("exposure"), tidy(d.exposureEv)},
                            {QStringLiteral("toneMapping"), qstr(toneMapperName(d.toneMapper))}});
  }
  if (state.environment) {
    const Environment& e = *state.environment;
    const QString source = QString::fromStdString(e.source);
    view.insert(
        QStringLiteral("environment"),
        QJsonObject{{QStringLiteral("source"),
                     QFileInfo(source).isAbsolute() ? presetDir.relativeFilePath(source) : source},
                    {QStringLiteral("intensity"), tidy(e.intensity)},
                    {QStringLiteral("rotation"), tidy(e.rotationDeg)},
                    {QStringLiteral("background"), qstr(backgroundName(e.background))}});
  }
  return view;
}

}  // namespace

Result<SavedPreset> savePreset(const Preset& preset, const std::string& path) {
  const Material& material = preset.material;
  SavedPreset saved;

  // Start from what was read, so unknown keys (top level, per map, per parameter) survive.
  QJsonObject root = preset.preserved;
  root.insert(QStringLiteral("format"), qstr(kPresetFormatName));
  root.insert(QStringLiteral("version"), kPresetVersion);
  if (!material.name().empty()) {
    root.insert(QStringLiteral("name"), QString::fromStdString(material.name()));
  }
  Result<QJsonObject> maps =
      mapsJson(preset, path, root.value(QStringLiteral("maps")).toObject(), saved);
  if (!maps)
    return makeError(maps.error());
  root.insert(QStringLiteral("maps"), maps.value());
  root.insert(QStringLiteral("technique"), qstr(techniqueName(material.technique())));
  QJsonObject parameters = root.value(QStringLiteral("parameters")).toObject();
  for (const ParameterSpec& spec : allParameters()) {
    parameters.insert(qstr(spec.name), parameterJson(spec, material.parameter(spec.id)));
  }
  root.insert(QStringLiteral("parameters"), parameters);

  const QJsonObject view =
      viewJson(preset.view, QFileInfo(QString::fromStdString(path)).absoluteDir(),
               root.value(QStringLiteral("view")).toObject());
  if (view.isEmpty()) {
    root.remove(QStringLiteral("view"));
  } else {
    root.insert(QStringLiteral("view"), view);
  }

  const QByteArray bytes = QJsonDocument(root).toJson(QJsonDocument::Indented);
  if (Status written =
          writeFileAtomically(path, std::string_view(bytes.constData(), std::size_t(bytes.size())));
      !written) {
    return makeError(written.error());
  }
  return saved;
}

}  // namespace relief::core::inline preset
