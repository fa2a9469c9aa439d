// RenderHelper; see RenderHelper.h.
#include "RenderHelper.h"

#include "CliCommon.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <vector>

namespace relief::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kHelperName = "relief-cli-render";

// Beside this executable (a build tree), else in the installed libexec folder.
fs::path helperPath() {
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  const fs::path folder = error ? fs::path(".") : self.parent_path();
  const fs::path beside = folder / kHelperName;
  if (fs::exists(beside, error))
    return beside;
  return (folder / RELIEF_RENDER_HELPER_RELATIVE / kHelperName).lexically_normal();
}

}  // namespace

int runRenderHelper(int argc, char* argv[]) {
  const fs::path helper = helperPath();
  std::vector<char*> arguments(argv, argv + argc);
  static char quietFlag[] = "--quiet";
  if (quiet())
    arguments.push_back(quietFlag);
  arguments.push_back(nullptr);
  execv(helper.c_str(), arguments.data());
  printError(QStringLiteral("render: cannot start the renderer %1 (%2); the installation is "
                            "incomplete: reinstall Relief")
                 .arg(QString::fromStdString(helper.string()),
                      QString::fromLocal8Bit(std::strerror(errno))));
  return kExitFailure;
}

}  // namespace relief::cli
