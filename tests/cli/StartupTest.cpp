// What relief-cli maps into memory, checked without timing anything (a shared machine's timings
// are noise): the commands that read and write PNG, DDS and KTX2 load only Qt Core, the codec
// libraries and the C++ runtime, never OpenImageIO, Assimp, Qt GUI, OpenGL or X, whose hundreds
// of libraries made every process take half a second to start (docs/architecture.md,
// "Start-up"). The list comes from the dynamic loader itself (LD_DEBUG=files names every object
// it maps, at start and on dlopen). A TGA, which only OpenImageIO reads, shows the check sees a
// module when one is loaded.
#include "cli/CliRunner.h"
#include "support/TestPaths.h"

#include <QProcess>
#include <QRegularExpression>
#include <QStringList>

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace relief::test {
namespace {

struct Loaded {
  int exitCode = -1;
  std::set<std::string> libraries;  // file names of every shared object mapped
  std::string errors;               // standard error without the loader's lines
};

Loaded runAndListLibraries(const QStringList& arguments) {
  QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
  environment.insert(QStringLiteral("LD_DEBUG"), QStringLiteral("files"));
  const CliRun run = runCli(arguments, environment);
  Loaded loaded;
  loaded.exitCode = run.crashed ? -1 : run.exitCode;
  // "  1234:\tfile=libQt6Core.so.6 [0];  needed by /path/relief-cli [0]" and
  // "  1234:\tfile=/path/librelief_oiio.so [0];  dynamically loaded by ... [0]".
  static const QRegularExpression kMapped(QStringLiteral(R"(^\s*\d+:\s+file=(\S+) \[)"));
  static const QRegularExpression kLoaderLine(QStringLiteral(R"(^\s*\d+:)"));
  for (const QString& line : QString::fromStdString(run.err).split('\n')) {
    const QRegularExpressionMatch match = kMapped.match(line);
    if (match.hasMatch()) {
      const QString file = match.captured(1);
      loaded.libraries.insert(file.mid(file.lastIndexOf('/') + 1).toStdString());
    } else if (!kLoaderLine.match(line).hasMatch()) {
      loaded.errors += line.toStdString() + "\n";
    }
  }
  return loaded;
}

// What the PNG, DDS and KTX2 commands may map: the C/C++ runtime, Qt Core and what it links on
// Debian 12 (ICU, GLib, PCRE2, double-conversion, BLAKE2, zstd), the codecs Relief links (zlib,
// libdeflate, Zstandard, FFTW, astcenc, libsquish, Android's ETC1) and the sanitizer runtimes of
// the test build.
bool allowed(const std::string& library) {
  static const QRegularExpression kAllowed(QStringLiteral(
      R"(^(libc|libm|libdl|librt|libpthread|libgcc_s|libstdc\+\+|libgomp|libasan|libubsan|)"
      R"(libQt6Core|libQt6Concurrent|libicu(uc|i18n|data)|libglib-2\.0|libpcre2-(8|16)|)"
      R"(libdouble-conversion|libb2|libzstd|libz|libdeflate|libfftw3f(_threads)?|libastcenc|libsquish|)"
      R"(libETC1)\.so)"));
  return kAllowed.match(QString::fromStdString(library)).hasMatch();
}

std::string notAllowed(const Loaded& loaded) {
  std::string list;
  for (const std::string& library : loaded.libraries) {
    if (!allowed(library))
      list += " " + library;
  }
  return list;
}

class Startup : public ::testing::Test {
 protected:
  static QString sample(const char* name) {
    return QString::fromStdString(sourcePath(std::string("samples/bricks/") + name));
  }
  static QString scratch(const char* name) {
    return QString::fromStdString(scratchFolder() + "/" + name);
  }
};

TEST_F(Startup, VersionAndInfoMapOnlyCoreLibraries) {
  for (const QStringList& arguments :
       {QStringList{"--version"}, QStringList{"info", sample("bricks_height.png")}}) {
    const Loaded loaded = runAndListLibraries(arguments);
    ASSERT_EQ(loaded.exitCode, 0) << arguments.join(' ').toStdString() << "\n" << loaded.errors;
    EXPECT_GE(loaded.libraries.count("libQt6Core.so.6"), 1u) << "the loader's list was not read";
    EXPECT_EQ(notAllowed(loaded), "") << arguments.join(' ').toStdString();
  }
}

TEST_F(Startup, PngCommandsMapOnlyCoreLibraries) {
  const QString texture = scratch("startup-bc5.ktx2");
  const QStringList commands[] = {
      {"compress", "--in", sample("bricks_normal.png"), "--normal", "--format", "bc5", "--out",
       texture},
      {"decode", texture, "--out", scratch("startup-decoded.png")},
      {"compare", sample("bricks_normal.png"), texture},
      {"generate", "normal", "--in", sample("bricks_height.png"), "--out",
       scratch("startup-normal.png")},
      {"preset", "info", sample("bricks.relief")},
  };
  for (const QStringList& arguments : commands) {
    const Loaded loaded = runAndListLibraries(arguments);
    ASSERT_EQ(loaded.exitCode, 0) << arguments.join(' ').toStdString() << "\n" << loaded.errors;
    EXPECT_EQ(notAllowed(loaded), "") << arguments.join(' ').toStdString();
  }
}

// The check can fail: a TGA needs OpenImageIO, and its module and libraries show in the list.
TEST_F(Startup, AFileOnlyOpenImageIOReadsLoadsItsModule) {
  const QString tga = scratch("startup.tga");
  QProcess convert;
  convert.start(QStringLiteral("convert"), {sample("bricks_color.png"), tga});
  ASSERT_TRUE(convert.waitForFinished(60000) && convert.exitCode() == 0)
      << "ImageMagick's convert is needed (tools/install-deps.sh)";
  const Loaded loaded = runAndListLibraries({"info", tga});
  ASSERT_EQ(loaded.exitCode, 0) << loaded.errors;
  EXPECT_EQ(loaded.libraries.count("librelief_oiio.so"), 1u);
  const std::string extra = notAllowed(loaded);
  EXPECT_NE(extra.find("libOpenImageIO.so"), std::string::npos) << extra;
  EXPECT_GT(loaded.libraries.size(), 100u) << "OpenImageIO's dependencies on Debian 12";
}

}  // namespace
}  // namespace relief::test
