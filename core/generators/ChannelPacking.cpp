// ChannelPacking; see ChannelPacking.h.
#include "core/generators/ChannelPacking.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
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

namespace {

struct Term {
  int input = -1;  // -1: constant
  int channel = 0;
  bool invert = false;
  float constant = 0.0f;
};

Result<Term> parseTerm(const std::vector<NamedMap>& inputs, std::string_view text) {
  // Messages are built by appending: GCC 12 warns falsely (-Wrestrict, its bug 105329) about
  // "'" + std::string(...) once inlined at -O3.
  const auto problem = [text](std::string_view what) {
    std::string message = "'";
    message.append(text).append("': ").append(what);
    return makeError(message);
  };
  Term term;
  double number = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (error == std::errc() && end == text.data() + text.size()) {
    if (!(number >= 0.0 && number <= 1.0))
      return problem("a constant must lie in 0..1");
    term.constant = float(number);
    return term;
  }
  std::string_view rest = text;
  if (rest.substr(0, 2) == "1-") {
    term.invert = true;
    rest.remove_prefix(2);
  }
  const std::size_t dot = rest.rfind('.');
  const std::size_t channel = dot == std::string_view::npos || dot + 2 != rest.size()
                                  ? std::string_view::npos
                                  : std::string_view("rgba").find(rest[dot + 1]);
  if (channel == std::string_view::npos) {
    return problem(
        "expected a map and a channel (e.g. ao.r or 1-roughness.g) or a constant in 0..1");
  }
  const std::string_view name = rest.substr(0, dot);
  std::string names;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (inputs[i].name == name) {
      term.input = int(i);
      term.channel = int(channel);
      return term;
    }
    names.append(names.empty() ? "" : ", ").append(inputs[i].name);
  }
  std::string what = "no map called '";
  what.append(name).append("' (given: ").append(names.empty() ? "none" : names).append(")");
  return problem(what);
}

}  // namespace

Result<Image> packChannels(const std::vector<NamedMap>& inputs,
                           const std::vector<std::string>& terms) {
  if (terms.empty() || terms.size() > 4)
    return makeError("give 1 to 4 output channels (" + std::to_string(terms.size()) + " given)");
  std::vector<Term> parsed;
  const Image* first = nullptr;
  for (const std::string& text : terms) {
    Result<Term> term = parseTerm(inputs, text);
    if (!term)
      return makeError(term.error());
    if (term->input >= 0) {
      const Image* image = inputs[std::size_t(term->input)].image;
      if (!first)
        first = image;
      if (image->width() != first->width() || image->height() != first->height()) {
        return makeError("the maps differ in size (" + std::to_string(first->width()) + "x" +
                         std::to_string(first->height()) + " and " +
                         std::to_string(image->width()) + "x" + std::to_string(image->height()) +
                         ")");
      }
    }
    parsed.push_back(term.value());
  }
  // Constants alone take the size of the first input given, or one texel.
  if (!first) {
    for (const NamedMap& input : inputs)
      first = first ? first : input.image;
  }
  const int width = first ? first->width() : 1, height = first ? first->height() : 1;
  Image result(width, height, int(parsed.size()), ColorSpace::Linear);
  result.setSourceBitsPerChannel(16);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      for (std::size_t c = 0; c < parsed.size(); ++c) {
        const Term& term = parsed[c];
        float value = term.constant;
        if (term.input >= 0) {
          const Image& source = *inputs[std::size_t(term.input)].image;
          value = term.channel < source.channels() ? source.at(x, y, term.channel)
                  : term.channel == 3              ? 1.0f
                                                   : source.at(x, y, 0);
          if (term.invert)
            value = 1.0f - value;
        }
        result.at(x, y, int(c)) = value;
      }
    }
  }
  return result;
}

Result<Image> swizzleChannels(const std::vector<const Image*>& inputs, const std::string& names,
                              const std::string& swizzle) {
  std::vector<NamedMap> named;
  for (std::size_t i = 0; i < inputs.size() && i < names.size(); ++i)
    named.push_back({std::string(1, names[i]), inputs[i]});
  std::vector<std::string> terms;
  std::istringstream words(swizzle);
  for (std::string word; words >> word;)
    terms.push_back(word);
  Result<Image> packed = packChannels(named, terms);
  if (!packed)
    return makeError("swizzle '" + swizzle + "': " + packed.error());
  return packed;
}

const std::vector<PackLayout>& packLayouts() {
  static const std::vector<PackLayout> layouts = {
      {"orm",
       "ORM (glTF, Unreal)",
       "R ambient occlusion, G roughness, B metallic: glTF 2.0's occlusion and "
       "metallicRoughness textures in one, and Unreal's ORM convention.",
       {"ao.r", "roughness.r", "metallic.r"}},
      {"unity-mask",
       "Unity HDRP mask map",
       "R metallic, G ambient occlusion, B detail mask (1: detail everywhere), A smoothness "
       "(1 - roughness).",
       {"metallic.r", "ao.r", "1", "1-roughness.r"}},
      {"unity-metallic",
       "Unity URP/Built-in metallic map",
       "R metallic, A smoothness (1 - roughness); G and B unused (0).",
       {"metallic.r", "0", "0", "1-roughness.r"}},
      {"normal-height",
       "Normal + height in alpha",
       "The normal map's RGB with the height in A (references 001 and 003: one fetch for both).",
       {"normal.r", "normal.g", "normal.b", "height.r"}},
  };
  return layouts;
}

const PackLayout* findPackLayout(std::string_view name) {
  for (const PackLayout& layout : packLayouts()) {
    if (layout.name == name)
      return &layout;
  }
  return nullptr;
}

Result<std::vector<UnpackedMap>> unpackLayout(const Image& packed, const PackLayout& layout) {
  std::vector<UnpackedMap> maps;
  for (std::size_t c = 0; c < layout.terms.size(); ++c) {
    std::string_view term = layout.terms[c];
    const bool invert = term.starts_with("1-");
    if (invert)
      term.remove_prefix(2);
    const std::size_t dot = term.find('.');
    if (dot == std::string_view::npos)
      continue;  // a constant
    if (int(c) >= packed.channels()) {
      return makeError("it has " + std::to_string(packed.channels()) + " channel(s); the " +
                       std::string(layout.label) + " layout keeps " + std::string(term, 0, dot) +
                       " in channel " + "RGBA"[c]);
    }
    Image map = channelImage(packed, int(c));
    if (invert) {
      for (std::size_t p = 0; p < map.pixelCount(); ++p)
        map.data()[p] = 1.0f - map.data()[p];
    }
    maps.push_back({std::string(term.substr(0, dot)), std::move(map), int(c)});
  }
  return maps;
}

std::optional<float> neutralMapValue(std::string_view name) {
  if (name == "ao" || name == "roughness")
    return 1.0f;
  if (name == "metallic" || name == "height")
    return 0.0f;
  if (name == "normal")
    return 0.5f;  // the flat normal's X and Y; its Z (b) is 1, handled by the caller's map
  return std::nullopt;
}

std::string neutralValueNote(std::string_view name) {
  char value[16];
  std::snprintf(value, sizeof value, "%g", double(neutralMapValue(name).value_or(0.0f)));
  std::string note = "no ";
  note.append(name).append(" map: its neutral value ").append(value).append(" was used");
  return note;
}

std::vector<std::string> resolveLayoutTerms(const PackLayout& layout,
                                            const std::vector<NamedMap>& available,
                                            std::vector<std::string>* substituted) {
  std::vector<std::string> terms;
  for (std::string_view term : layout.terms) {
    std::string_view name = term;
    const bool inverted = name.substr(0, 2) == "1-";
    if (inverted)
      name.remove_prefix(2);
    const std::size_t dot = name.rfind('.');
    if (dot == std::string_view::npos) {  // a constant
      terms.emplace_back(term);
      continue;
    }
    name = name.substr(0, dot);
    const bool present = std::any_of(available.begin(), available.end(),
                                     [&](const NamedMap& map) { return map.name == name; });
    const std::optional<float> neutral = neutralMapValue(name);
    if (present || !neutral) {
      terms.emplace_back(term);
      continue;
    }
    float value = *neutral;
    if (name == "normal" && term.substr(term.size() - 2) == ".b")
      value = 1.0f;
    if (inverted)
      value = 1.0f - value;
    char text[16];
    std::snprintf(text, sizeof text, "%g", double(value));
    terms.emplace_back(text);
    if (substituted &&
        std::find(substituted->begin(), substituted->end(), name) == substituted->end())
      substituted->emplace_back(name);
  }
  return terms;
}

}  // namespace relief::core::inline generators
