// The hostile corpus (HostileCorpus.h) through the relief-cli commands that read each kind of
// file, as a render farm would meet it. For every case and command: no signal and no sanitizer
// report, no hang (a time limit per run), a non-zero exit, the file's name in the message, and
// the output the command was given left byte-identical (a file already there stays as it was;
// an export folder gains nothing).
#include "HostileCorpus.h"
#include "support/TestPaths.h"

#include <QProcess>
#include <QProcessEnvironment>
#include <QStringList>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <mutex>
#include <thread>

namespace relief::test {
namespace {

namespace fs = std::filesystem;

// Sanitizer reports exit with these codes (set below), so a report is never mistaken for the
// command's own refusal; leak checks are left to the fuzz replays (tests/fuzz), which feed the
// same readers, because at ~0.4 s per process they would double this test's time.
constexpr int kAsanExit = 86;
constexpr int kUbsanExit = 87;
constexpr int kRunLimitMs = 60000;

QProcessEnvironment hostileEnvironment() {
  QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
  environment.insert(QStringLiteral("ASAN_OPTIONS"),
                     QStringLiteral("detect_leaks=0:abort_on_error=0:exitcode=%1").arg(kAsanExit));
  environment.insert(
      QStringLiteral("UBSAN_OPTIONS"),
      QStringLiteral("print_stacktrace=1:halt_on_error=1:exitcode=%1").arg(kUbsanExit));
  return environment;
}

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// What a command is given to write: a file that exists already, or a folder with one file.
struct Output {
  std::string path;
  bool folder = false;
  std::string sentinel;  // the bytes written before the run
};

struct PlannedRun {
  const HostileCase* hostile;
  QStringList arguments;
  Output output;
};

// The commands that read each kind, with `F` for the hostile file and `O` for the output.
std::vector<QStringList> commandsFor(HostileKind kind, const std::string& tinyPreset) {
  const auto list = [](std::initializer_list<const char*> words) {
    QStringList result;
    for (const char* word : words)
      result << QString::fromUtf8(word);
    return result;
  };
  switch (kind) {
    case HostileKind::Image:
      return {list({"info", "F"}), list({"generate", "normal", "--in", "F", "--out", "O.png"}),
              list({"compress", "--in", "F", "--format", "bc1", "--out", "O.dds"}),
              list({"render", "--height", "F", "--size", "32x32", "--out", "O.png"})};
    case HostileKind::Texture:
      return {list({"info", "F"}), list({"decode", "F", "--out", "O.png"}),
              list({"compress", "--in", "F", "--format", "bc1", "--out", "O.dds"}),
              list({"render", "--normal", "F", "--size", "32x32", "--out", "O.png"})};
    case HostileKind::Preset:
      return {list({"preset", "validate", "F"}), list({"preset", "info", "F"}),
              list({"render", "F", "--strict", "--size", "32x32", "--out", "O.png"}),
              list({"export", "--preset", "F", "--to", "package", "--strict", "--out", "O/"})};
    case HostileKind::Mesh:
      return {
          list({"render", tinyPreset.c_str(), "--mesh", "F", "--size", "32x32", "--out", "O.png"}),
          list({"export", "--preset", tinyPreset.c_str(), "--to", "gltf", "--mesh", "F", "--out",
                "O/"})};
  }
  return {};
}

// Every case runs the kind's first command (the one that only inspects the file) and one of the
// others in turn, so each command meets every third or so of the corpus and every file is read
// in full once. The commands past the first share their reader (loadImage, the texture and
// preset loaders), and running each file through all of them took a third of CI's time budget.
std::vector<QStringList> commandsForCase(std::size_t index, HostileKind kind,
                                         const std::string& tinyPreset) {
  const std::vector<QStringList> all = commandsFor(kind, tinyPreset);
  if (all.size() <= 2)
    return all;
  return {all.front(), all[1 + index % (all.size() - 1)]};
}

std::vector<PlannedRun> plan(const std::vector<HostileCase>& cases, const std::string& outputs,
                             const std::string& tinyPreset) {
  std::vector<PlannedRun> runs;
  for (std::size_t index = 0; index < cases.size(); ++index) {
    const HostileCase& hostile = cases[index];
    for (QStringList arguments : commandsForCase(index, hostile.kind, tinyPreset)) {
      if (hostile.problemsAreWarnings &&
          arguments.mid(0, 2).join(' ') == QStringLiteral("preset info"))
        continue;  // prints the problems as warnings by design
      PlannedRun run{&hostile, {}, {}};
      for (QString& argument : arguments) {
        if (argument == QStringLiteral("F")) {
          argument = QString::fromStdString(hostile.path);
        } else if (argument.startsWith(QStringLiteral("O"))) {
          const std::string id = std::to_string(runs.size());
          run.output.folder = argument.endsWith('/');
          run.output.path = outputs + "/out-" + id + argument.mid(1).toStdString();
          if (run.output.folder)
            run.output.path.pop_back();
          run.output.sentinel = "the output of an earlier run, " + id + "\n";
          argument = QString::fromStdString(run.output.path);
        }
      }
      run.arguments = arguments;
      runs.push_back(std::move(run));
    }
  }
  return runs;
}

void prepareOutput(const Output& output) {
  if (output.path.empty())
    return;
  const std::string file = output.folder ? output.path + "/earlier.txt" : output.path;
  if (output.folder)
    fs::create_directories(output.path);
  std::ofstream(file, std::ios::binary) << output.sentinel;
}

// Empty when the output is as it was, else what changed.
std::string outputChange(const Output& output) {
  if (output.path.empty())
    return {};
  const std::string file = output.folder ? output.path + "/earlier.txt" : output.path;
  if (readAll(file) != output.sentinel)
    return file + " was changed";
  if (output.folder) {
    const auto entries = std::distance(fs::directory_iterator(output.path), {});
    if (entries != 1)
      return output.path + " gained " + std::to_string(entries - 1) + " entries";
  }
  // A save that failed must not leave its temporary file next to the output.
  for (const fs::directory_entry& entry :
       fs::directory_iterator(fs::path(output.path).parent_path())) {
    const std::string name = entry.path().filename().string();
    if (name.find(".saving") != std::string::npos)
      return "a temporary file was left: " + name;
  }
  return {};
}

// Empty when the run met every expectation, else why not.
std::string judge(const PlannedRun& run, const QProcess& process, bool finished) {
  const std::string command = run.arguments.join(' ').left(160).toStdString();
  const std::string err =
      QString::fromUtf8(const_cast<QProcess&>(process).readAllStandardError()).toStdString();
  const std::string what = "[" + run.hostile->problem + "] relief-cli " + command + ": ";
  if (!finished)
    return what + "no answer within " + std::to_string(kRunLimitMs / 1000) + " s (a hang)";
  if (process.exitStatus() != QProcess::NormalExit)
    return what + "killed by a signal\n" + err;
  const int code = process.exitCode();
  if (code == kAsanExit || code == kUbsanExit || err.find("Sanitizer") != std::string::npos ||
      err.find("runtime error:") != std::string::npos)
    return what + "a sanitizer report\n" + err;
  if (code == 0)
    return what + "accepted (exit 0)\n" + err;
  if (err.find(run.hostile->named) == std::string::npos)
    return what + "the message does not name " + run.hostile->named + ": " + err.substr(0, 600);
  if (std::string change = outputChange(run.output); !change.empty())
    return what + change;
  return {};
}

// Runs every planned command, a few processes at a time, and returns the failures.
std::vector<std::string> runAll(const std::vector<PlannedRun>& runs) {
  const QProcessEnvironment environment = hostileEnvironment();
  std::atomic<std::size_t> next{0};
  std::mutex lock;
  std::vector<std::string> failures;
  const auto worker = [&] {
    for (std::size_t i = next++; i < runs.size(); i = next++) {
      const PlannedRun& run = runs[i];
      prepareOutput(run.output);
      QProcess process;
      process.setProcessEnvironment(environment);
      process.start(QStringLiteral(RELIEF_CLI_PATH), run.arguments);
      const bool finished = process.waitForFinished(kRunLimitMs);
      if (!finished) {
        process.kill();
        process.waitForFinished();
      }
      if (std::string failure = judge(run, process, finished); !failure.empty()) {
        const std::lock_guard<std::mutex> guard(lock);
        failures.push_back(failure);
      }
    }
  };
  // Processes wait on disk and the X server as much as on the CPU; three keep two cores busy.
  std::vector<std::thread> threads;
  for (int t = 0; t < 3; ++t)
    threads.emplace_back(worker);
  for (std::thread& thread : threads)
    thread.join();
  return failures;
}

class HostileCorpus : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const std::string root = scratchFolder() + "/hostile-corpus";
    fs::remove_all(root);
    fs::create_directories(root + "/files");
    fs::create_directories(root + "/outputs");
    s_cases = writeHostileCorpus(root + "/files");
    s_outputs = root + "/outputs";
    // A preset with no maps, for the export that reads a mesh: quick to load and to write.
    s_tinyPreset = root + "/tiny.relief";
    std::ofstream(s_tinyPreset) << R"({"format": "relief-material", "version": 2})";
  }

  void runKind(HostileKind kind, std::size_t atLeast) {
    std::vector<HostileCase> cases;
    std::copy_if(s_cases.begin(), s_cases.end(), std::back_inserter(cases),
                 [kind](const HostileCase& c) { return c.kind == kind; });
    EXPECT_GE(cases.size(), atLeast);
    const std::vector<PlannedRun> runs = plan(cases, s_outputs, s_tinyPreset);
    const std::vector<std::string> failures = runAll(runs);
    for (const std::string& failure : failures)
      ADD_FAILURE() << failure;
    std::printf("%zu cases, %zu runs, %zu failures\n", cases.size(), runs.size(), failures.size());
  }

  static inline std::vector<HostileCase> s_cases;
  static inline std::string s_outputs;
  static inline std::string s_tinyPreset;
};

TEST_F(HostileCorpus, HasAtLeast150Cases) {
  EXPECT_GE(s_cases.size(), 150u);
  std::map<HostileKind, int> perKind;
  for (const HostileCase& c : s_cases)
    ++perKind[c.kind];
  std::printf("hostile corpus: %zu cases (%d images, %d textures, %d presets, %d meshes)\n",
              s_cases.size(), perKind[HostileKind::Image], perKind[HostileKind::Texture],
              perKind[HostileKind::Preset], perKind[HostileKind::Mesh]);
}

TEST_F(HostileCorpus, ImagesAreRefusedByEveryCommand) {
  runKind(HostileKind::Image, 60);
}

TEST_F(HostileCorpus, TexturesAreRefusedByEveryCommand) {
  runKind(HostileKind::Texture, 50);
}

TEST_F(HostileCorpus, PresetsAreRefusedByEveryCommand) {
  runKind(HostileKind::Preset, 30);
}

TEST_F(HostileCorpus, MeshesAreRefusedByEveryCommand) {
  runKind(HostileKind::Mesh, 25);
}

}  // namespace
}  // namespace relief::test
