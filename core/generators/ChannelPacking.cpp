// ChannelPacking; see ChannelPacking.h.
#include "core/generators/ChannelPacking.h"

#include <algorithm>
#include <sstream>

namespace relief::core::inline generators {

LevelsRange autoLevels(Image& height) {
  LevelsRange range{1e300, -1e300};
  const int channels = height.channels();
  for (std::size_t i = 0; i < height.pixelCount(); ++i) {
    const double v = height.data()[i * std::size_t(channels)];
    range.low = std::min(range.low, v);
    range.high = std::max(range.high, v);
  }
  if (!(range.high > range.low))
    return range;
  const double span = range.high - range.low;
  for (std::size_t i = 0; i < height.pixelCount(); ++i) {
    float& v = height.data()[i * std::size_t(channels)];
    v = float((v - range.low) / span);
  }
  return range;
}

HeightCompensation compensateLevels(const LevelsRange& range, double heightScale,
                                    double heightBias) {
  // h = low + h' span  =>  s = h' (span scale) + (low scale + bias).
  const double span = range.high - range.low;
  return {heightScale * span, heightBias + heightScale * range.low};
}

Image packHeightIntoNormalAlpha(const Image& normals, const Image& height) {
  Image packed(normals.width(), normals.height(), 4, ColorSpace::Linear);
  packed.setSourceBitsPerChannel(16);
  for (int y = 0; y < normals.height(); ++y) {
    for (int x = 0; x < normals.width(); ++x) {
      const float* n = normals.pixel(x, y);
      float* out = packed.pixel(x, y);
      for (int c = 0; c < 3; ++c)
        out[c] = n[std::min(c, normals.channels() - 1)];
      out[3] = height.at(x, y, 0);
    }
  }
  return packed;
}

Result<Image> swizzleChannels(const std::vector<const Image*>& inputs, const std::string& names,
                              const std::string& swizzle) {
  struct Term {
    int input = -1;  // -1: constant
    int channel = 0;
    float constant = 0.0f;
  };
  std::vector<Term> terms;
  std::istringstream words(swizzle);
  std::string word;
  while (words >> word) {
    Term term;
    if (word == "0" || word == "1") {
      term.constant = word == "1" ? 1.0f : 0.0f;
    } else if (word.size() == 3 && word[1] == '.') {
      const std::size_t input = names.find(word[0]);
      const std::size_t channel = std::string("rgba").find(word[2]);
      if (input == std::string::npos || input >= inputs.size() || channel == std::string::npos) {
        return makeError("swizzle '" + swizzle + "': '" + word + "' is not one of the inputs (" +
                         names + ") followed by .r, .g, .b or .a");
      }
      term.input = int(input);
      term.channel = int(channel);
    } else {
      return makeError("swizzle '" + swizzle + "': cannot read '" + word +
                       "' (expected e.g. n.r, h.r, 0 or 1)");
    }
    terms.push_back(term);
  }
  if (terms.empty() || terms.size() > 4) {
    return makeError("swizzle '" + swizzle + "': give 1 to 4 output channels");
  }
  const Image& first = *inputs.front();
  for (const Image* input : inputs) {
    if (input->width() != first.width() || input->height() != first.height()) {
      return makeError("swizzle: the inputs differ in size (" + std::to_string(first.width()) +
                       "x" + std::to_string(first.height()) + " and " +
                       std::to_string(input->width()) + "x" + std::to_string(input->height()) +
                       ")");
    }
  }
  Image result(first.width(), first.height(), int(terms.size()), ColorSpace::Linear);
  result.setSourceBitsPerChannel(16);
  for (int y = 0; y < result.height(); ++y) {
    for (int x = 0; x < result.width(); ++x) {
      for (std::size_t c = 0; c < terms.size(); ++c) {
        const Term& term = terms[c];
        float value = term.constant;
        if (term.input >= 0) {
          const Image& source = *inputs[std::size_t(term.input)];
          // A missing channel reads as grey's only channel, or 1 for alpha.
          value = term.channel < source.channels() ? source.at(x, y, term.channel)
                  : term.channel == 3              ? 1.0f
                                                   : source.at(x, y, 0);
        }
        result.at(x, y, int(c)) = value;
      }
    }
  }
  return result;
}

}  // namespace relief::core::inline generators
