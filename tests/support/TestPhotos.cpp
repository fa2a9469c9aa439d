// TestPhotos; see TestPhotos.h.
#include "support/TestPhotos.h"

#include "core/image/ImageIO.h"

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

namespace relief::test {

namespace {

std::vector<core::Image> loadAll(const char* folder, std::initializer_list<const char*> names,
                                 const char* package) {
  std::vector<core::Image> photos;
  for (const char* name : names) {
    core::Result<core::Image> image = core::loadImage(std::string(folder) + name);
    if (!image) {
      ADD_FAILURE() << image.error() << " (install " << package << ": tools/install-deps.sh)";
      continue;
    }
    photos.push_back(std::move(image).value());
  }
  return photos;
}

std::vector<core::Image> scikitPhotographs(std::initializer_list<const char*> names) {
  return loadAll("/usr/lib/python3/dist-packages/skimage/data/", names, "python3-skimage");
}

}  // namespace

std::vector<core::Image> gameColourMaps() {
  return loadAll(
      "/usr/share/games/etr/terrains/",
      {"rock01.png", "grass01.png", "mud01.png", "pave01.png", "pebbles04.png", "snowy_rock02.png"},
      "extremetuxracer-data");
}

std::vector<core::Image> surfacePhotographs() {
  return scikitPhotographs({"brick.png", "grass.png", "gravel.png"});
}

std::vector<core::Image> photographCrops(int size) {
  std::vector<core::Image> photos;
  for (const core::Image& full : scikitPhotographs(
           {"astronaut.png", "coffee.png", "chelsea.png", "rocket.jpg", "motorcycle_left.png"})) {
    core::Image crop(size, size, full.channels(), full.colorSpace());
    const int x0 = (full.width() - size) / 2, y0 = (full.height() - size) / 2;
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        for (int c = 0; c < full.channels(); ++c)
          crop.at(x, y, c) = full.at(x0 + x, y0 + y, c);
      }
    }
    photos.push_back(std::move(crop));
  }
  return photos;
}

}  // namespace relief::test
