// A corpus of hostile and broken files, written when the test runs: every kind of file Relief
// reads (images, DDS and KTX2 textures, presets, meshes), each damaged in the ways real files
// and attackers damage them: cut short, header fields out of range or overflowing, wrong magic,
// loops, links to devices, FIFOs, folders. Most cases start from the fuzz targets' seeds
// (tests/fuzz/corpus/*/seed-*), so they are real files made by real writers, then damaged.
// Every case is invalid: a reader that accepts one is lying about the file.
#pragma once

#include <string>
#include <vector>

namespace relief::test {

enum class HostileKind { Image, Texture, Preset, Mesh };

struct HostileCase {
  HostileKind kind;
  std::string path;     // the file (or folder, FIFO, link) a command is given
  std::string problem;  // what is wrong with it, for failure messages
  // The name the error message must contain: the file's own name, or for a preset whose map
  // is the hostile part, the preset's name.
  std::string named;
  // The file itself reads and what it refers to does not (a preset's map): commands that
  // report such problems as warnings by design (`preset info`) may succeed on it.
  bool problemsAreWarnings = false;
};

// Writes the corpus into `folder` (which must exist and be empty) and returns its cases.
std::vector<HostileCase> writeHostileCorpus(const std::string& folder);

}  // namespace relief::test
