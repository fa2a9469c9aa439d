// The names of relief-cli's options, declared once per meaning and shared by the commands that
// take them: each command's option table (CliOptions) and its parsing read the same constant,
// so --out means one thing everywhere and a misspelt name does not compile. Names that come
// from core's tables (map slots, generator inputs and options) are spelt there.
#pragma once

#include <QString>

namespace relief::cli::option {

inline const QString kAlso = QStringLiteral("also");
inline const QString kBackground = QStringLiteral("background");
inline const QString kCheck = QStringLiteral("check");
inline const QString kCostTable = QStringLiteral("cost-table");
inline const QString kDistance = QStringLiteral("distance");
inline const QString kFarther = QStringLiteral("farther");
inline const QString kEngine = QStringLiteral("engine");
inline const QString kEnvironment = QStringLiteral("environment");
inline const QString kEnvironmentIntensity = QStringLiteral("environment-intensity");
inline const QString kEnvironmentRotation = QStringLiteral("environment-rotation");
inline const QString kExposure = QStringLiteral("exposure");
inline const QString kFeather = QStringLiteral("feather");
inline const QString kFlipMap = QStringLiteral("flip-map");
inline const QString kFormat = QStringLiteral("format");
inline const QString kHeight = QStringLiteral("height");
inline const QString kHeightScale = QStringLiteral("height-scale");
inline const QString kHex = QStringLiteral("hex");
inline const QString kIn = QStringLiteral("in");
inline const QString kJson = QStringLiteral("json");
inline const QString kLayout = QStringLiteral("layout");
inline const QString kLevel = QStringLiteral("level");
inline const QString kLightIntensity = QStringLiteral("light-intensity");
inline const QString kLightPitch = QStringLiteral("light-pitch");
inline const QString kLightYaw = QStringLiteral("light-yaw");
inline const QString kMaps = QStringLiteral("maps");
inline const QString kMaxError = QStringLiteral("max-error");
inline const QString kMesh = QStringLiteral("mesh");
inline const QString kMethod = QStringLiteral("method");
inline const QString kMetrics = QStringLiteral("metrics");
inline const QString kMipFilter = QStringLiteral("mip-filter");
inline const QString kRoughnessFromNormals = QStringLiteral("roughness-from-normals");
inline const QString kAlphaCoverage = QStringLiteral("alpha-coverage");
inline const QString kCompressionError = QStringLiteral("compression-error");
inline const QString kRendered = QStringLiteral("rendered");
inline const QString kMips = QStringLiteral("mips");
inline const QString kNormal = QStringLiteral("normal");
inline const QString kOrm = QStringLiteral("orm");
inline const QString kOut = QStringLiteral("out");
inline const QString kOutDir = QStringLiteral("out-dir");
inline const QString kPatch = QStringLiteral("patch");
inline const QString kPerceptual = QStringLiteral("perceptual");
inline const QString kPitch = QStringLiteral("pitch");
inline const QString kPreset = QStringLiteral("preset");
inline const QString kQuality = QStringLiteral("quality");
inline const QString kRaw = QStringLiteral("raw");
inline const QString kRdo = QStringLiteral("rdo");
inline const QString kAllow8Bit = QStringLiteral("allow-8bit");
inline const QString kRecut = QStringLiteral("recut");
inline const QString kRepeats = QStringLiteral("repeats");
inline const QString kSeams = QStringLiteral("seams");
inline const QString kSet = QStringLiteral("set");
inline const QString kShading = QStringLiteral("shading");
inline const QString kSize = QStringLiteral("size");
inline const QString kSlot = QStringLiteral("slot");
inline const QString kStats = QStringLiteral("stats");
inline const QString kStrict = QStringLiteral("strict");
inline const QString kSwizzle = QStringLiteral("swizzle");
inline const QString kTechnique = QStringLiteral("technique");
inline const QString kTextures = QStringLiteral("textures");
inline const QString kTo = QStringLiteral("to");
inline const QString kTonemap = QStringLiteral("tonemap");
inline const QString kView = QStringLiteral("view");
inline const QString kYaw = QStringLiteral("yaw");
inline const QString kBudget = QStringLiteral("budget");
inline const QString kTargetFlip = QStringLiteral("target-flip");
inline const QString kTargetPsnr = QStringLiteral("target-psnr");
inline const QString kDevice = QStringLiteral("device");
inline const QString kChooseCompression = QStringLiteral("choose-compression");
inline const QString kProgressLines = QStringLiteral("progress-lines");
inline const QString kZstd = QStringLiteral("zstd");

}  // namespace relief::cli::option
