// Replays a fuzz target's corpus without libFuzzer, so the GCC build (AddressSanitizer and
// UBSan, what `make test` builds) runs every committed input: each file or folder named on the
// command line is fed to LLVMFuzzerTestOneInput once. A crash is the sanitizer's report and a
// non-zero exit; a clean run prints how many inputs it replayed.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace fs = std::filesystem;

namespace {

void replay(const fs::path& file, int& count) {
  std::ifstream stream(file, std::ios::binary);
  const std::vector<char> bytes{std::istreambuf_iterator<char>(stream), {}};
  std::fprintf(stderr, "replaying %s (%zu bytes)\n", file.c_str(), bytes.size());
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  ++count;
}

}  // namespace

int main(int argc, char** argv) {
  int count = 0;
  for (int i = 1; i < argc; ++i) {
    const fs::path argument(argv[i]);
    if (fs::is_directory(argument)) {
      std::vector<fs::path> files;
      for (const fs::directory_entry& entry : fs::directory_iterator(argument)) {
        if (entry.is_regular_file())
          files.push_back(entry.path());
      }
      std::sort(files.begin(), files.end());
      for (const fs::path& file : files)
        replay(file, count);
    } else {
      replay(argument, count);
    }
  }
  if (count == 0) {
    std::fprintf(stderr, "no inputs replayed: give corpus folders or files\n");
    return 2;
  }
  std::printf("replayed %d inputs, none crashed\n", count);
  return 0;
}
