#include "HostileCorpus.h"

#include "core/preset/MaterialPreset.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <stdexcept>

#include <sys/stat.h>

namespace relief::test {
namespace {

namespace fs = std::filesystem;
using Bytes = std::string;

Bytes readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error("hostile corpus: cannot read the seed " + path);
  return Bytes(std::istreambuf_iterator<char>(in), {});
}

Bytes seed(const std::string& target, const std::string& name) {
  return readFile(sourcePath("tests/fuzz/corpus/" + target + "/seed-" + name));
}

// Little- and big-endian field access at byte offsets; writes past the end grow the buffer.
std::uint32_t get32(const Bytes& b, std::size_t at) {
  std::uint32_t v = 0;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}
std::uint16_t get16(const Bytes& b, std::size_t at) {
  std::uint16_t v = 0;
  std::memcpy(&v, b.data() + at, 2);
  return v;
}
void put(Bytes& b, std::size_t at, const void* value, std::size_t size) {
  if (b.size() < at + size)
    b.resize(at + size, '\0');
  std::memcpy(b.data() + at, value, size);
}
void put32(Bytes& b, std::size_t at, std::uint32_t v) {
  put(b, at, &v, 4);
}
void put64(Bytes& b, std::size_t at, std::uint64_t v) {
  put(b, at, &v, 8);
}
void put16(Bytes& b, std::size_t at, std::uint16_t v) {
  put(b, at, &v, 2);
}
void put32be(Bytes& b, std::size_t at, std::uint32_t v) {
  const unsigned char bytes[4] = {
      static_cast<unsigned char>(v >> 24), static_cast<unsigned char>(v >> 16),
      static_cast<unsigned char>(v >> 8), static_cast<unsigned char>(v)};
  put(b, at, bytes, 4);
}

Bytes half(const Bytes& b) {
  return b.substr(0, b.size() / 2);
}

// Deterministic noise (a 32-bit LCG), so the corpus is the same on every run.
Bytes noise(std::size_t size, std::uint32_t state) {
  Bytes b(size, '\0');
  for (char& c : b) {
    state = state * 1664525u + 1013904223u;
    c = char(state >> 24);
  }
  return b;
}

// ---- PNG: chunks are length (BE), type, data, CRC over type and data.
std::uint32_t crc32(const char* data, std::size_t size) {
  std::uint32_t crc = 0xffffffffu;
  for (std::size_t i = 0; i < size; ++i) {
    crc ^= static_cast<unsigned char>(data[i]);
    for (int bit = 0; bit < 8; ++bit)
      crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}
constexpr std::size_t kIhdrData = 16;  // after the signature (8), length (4) and "IHDR" (4)
void fixPngCrc(Bytes& b, std::size_t typeAt, std::size_t dataLength) {
  put32be(b, typeAt + 4 + dataLength, crc32(b.data() + typeAt, 4 + dataLength));
}
Bytes pngWithIhdr(Bytes b, std::size_t field, const Bytes& value) {
  b.replace(kIhdrData + field, value.size(), value);
  fixPngCrc(b, 12, 13);
  return b;
}
Bytes be32(std::uint32_t v) {
  Bytes b;
  put32be(b, 0, v);
  return b;
}

// ---- TIFF (little-endian, as libtiff writes on x86): entries of the first IFD.
std::size_t tiffEntry(const Bytes& b, std::uint16_t tag) {
  const std::uint32_t ifd = get32(b, 4);
  const std::uint16_t count = get16(b, ifd);
  for (std::uint16_t i = 0; i < count; ++i) {
    const std::size_t entry = ifd + 2 + 12 * std::size_t(i);
    if (get16(b, entry) == tag)
      return entry;
  }
  throw std::runtime_error("hostile corpus: the TIFF seed has no tag " + std::to_string(tag));
}
// Makes `tag` a single LONG holding `value`.
Bytes tiffWithTag(Bytes b, std::uint16_t tag, std::uint32_t value) {
  const std::size_t entry = tiffEntry(b, tag);
  put16(b, entry + 2, 4);
  put32(b, entry + 4, 1);
  put32(b, entry + 8, value);
  return b;
}
enum TiffTag : std::uint16_t {
  kWidth = 256,
  kLength = 257,
  kBitsPerSample = 258,
  kCompression = 259,
  kStripOffsets = 273,
  kSamplesPerPixel = 277,
  kStripByteCounts = 279,
  kTileWidth = 322,
  kTileOffsets = 324,
};

// ---- OpenEXR: after the magic and version, attributes "name\0type\0" size (int32) value.
std::size_t exrAttributeValue(const Bytes& b, const std::string& wanted) {
  std::size_t at = 8;
  while (at < b.size() && b[at] != '\0') {
    const std::string name(b.data() + at);
    at += name.size() + 1;
    const std::string type(b.data() + at);
    at += type.size() + 1;
    const std::uint32_t size = get32(b, at);
    at += 4;
    if (name == wanted)
      return at;
    at += size;
  }
  throw std::runtime_error("hostile corpus: the EXR seed has no attribute " + wanted);
}
Bytes exrWith(Bytes b, const std::string& attribute, std::size_t offset, const Bytes& value) {
  b.replace(exrAttributeValue(b, attribute) + offset, value.size(), value);
  return b;
}
Bytes le32(std::uint32_t v) {
  Bytes b;
  put32(b, 0, v);
  return b;
}

// A copy with one little-endian field changed (DDS and KTX2 headers).
Bytes with32(Bytes b, std::size_t at, std::uint32_t value) {
  put32(b, at, value);
  return b;
}
Bytes with64(Bytes b, std::size_t at, std::uint64_t value) {
  put64(b, at, value);
  return b;
}

// ---- DDS: "DDS ", the 124-byte header, then (FourCC "DX10") a 20-byte DX10 header.
enum DdsField : std::size_t {
  kDdsSize = 4,
  kDdsHeight = 12,
  kDdsWidth = 16,
  kDdsDepth = 24,
  kDdsMips = 28,
  kDdsPixelFormatSize = 76,
  kDdsPixelFlags = 80,
  kDdsFourCC = 84,
  kDdsBitCount = 88,
  kDdsCaps2 = 112,
};
// The BC1 seed as a DX10 file (DXGI_FORMAT_BC1_UNORM, 2D, one layer), then one field changed.
Bytes ddsDx10(const Bytes& bc1, std::size_t field, std::uint32_t value) {
  Bytes b = bc1;
  std::memcpy(b.data() + kDdsFourCC, "DX10", 4);
  Bytes dx10;
  put32(dx10, 0, 71);  // dxgiFormat
  put32(dx10, 4, 3);   // resourceDimension: TEXTURE2D
  put32(dx10, 8, 0);   // miscFlag
  put32(dx10, 12, 1);  // arraySize
  put32(dx10, 16, 0);  // miscFlags2
  put32(dx10, field, value);
  b.insert(128, dx10);
  return b;
}

// ---- KTX2: the fixed header (80 bytes), then the level index (three u64 per level).
enum Ktx2Field : std::size_t {
  kVkFormat = 12,
  kPixelWidth = 20,
  kPixelHeight = 24,
  kPixelDepth = 28,
  kLayerCount = 32,
  kFaceCount = 36,
  kLevelCount = 40,
  kSupercompression = 44,
  kDfdOffset = 48,
  kKvdOffset = 56,
  kKvdLength = 60,
  kSgdLength = 72,
  kLevel0Offset = 80,
  kLevel0Length = 88,
};

Bytes presetJson(const std::string& body) {
  return R"({"format": "relief-material", )" + body + "}";
}
Bytes presetWithMap(const std::string& mapPath) {
  return presetJson(R"("version": 2, "maps": {"height": {"path": ")" + mapPath + R"("}})");
}

Bytes gltfDocument(const std::string& nodes, const std::string& buffers) {
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":)" + nodes +
         R"(,"meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"indices":2}]}],)"
         R"("buffers":)" +
         buffers +
         R"(,"bufferViews":[{"buffer":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":32},)"
         R"({"buffer":0,"byteOffset":80,"byteLength":12}],"accessors":[)"
         R"({"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},)"
         R"({"bufferView":1,"componentType":5126,"count":4,"type":"VEC2"},)"
         R"({"bufferView":2,"componentType":5123,"count":6,"type":"SCALAR"}]})";
}

Bytes glbHeader(std::uint32_t version, std::uint32_t length) {
  Bytes b = "glTF";
  put32(b, 4, version);
  put32(b, 8, length);
  return b;
}

class CorpusWriter {
 public:
  explicit CorpusWriter(std::string folder) : m_folder(std::move(folder)) {}

  // A file with these bytes; `named` defaults to the file's own name.
  void file(HostileKind kind, const std::string& name, const Bytes& bytes,
            const std::string& problem, const std::string& named = {}) {
    const std::string path = m_folder + "/" + name;
    std::ofstream(path, std::ios::binary) << bytes;
    add(kind, path, problem, named.empty() ? name : named);
  }

  // A file whose hostile part is what it refers to (see HostileCase::problemsAreWarnings).
  void referring(HostileKind kind, const std::string& name, const Bytes& bytes,
                 const std::string& problem) {
    file(kind, name, bytes, problem);
    m_cases.back().problemsAreWarnings = true;
  }

  // What is not a regular file: a folder, a FIFO, links to a device and to nothing, a name
  // with no file, and a file larger than any of its kind (sparse, so it uses no disk).
  void nonFiles(HostileKind kind, const std::string& extension) {
    const std::string stem = m_folder + "/" + kindName(kind) + "-";
    fs::create_directory(stem + "folder." + extension);
    add(kind, stem + "folder." + extension, "a folder", kindName(kind) + "-folder." + extension);
    const std::string fifo = stem + "fifo." + extension;
    if (::mkfifo(fifo.c_str(), 0600) != 0)
      throw std::runtime_error("hostile corpus: mkfifo failed for " + fifo);
    add(kind, fifo, "a FIFO (reading it would block forever)",
        kindName(kind) + "-fifo." + extension);
    fs::create_symlink("/dev/zero", stem + "zero." + extension);
    add(kind, stem + "zero." + extension, "a link to /dev/zero (endless)",
        kindName(kind) + "-zero." + extension);
    fs::create_symlink(m_folder + "/nothing-here", stem + "dangling." + extension);
    add(kind, stem + "dangling." + extension, "a link to nothing",
        kindName(kind) + "-dangling." + extension);
    add(kind, stem + "missing." + extension, "no such file",
        kindName(kind) + "-missing." + extension);
  }

  void sparse(HostileKind kind, const std::string& name, const Bytes& start, std::uintmax_t size,
              const std::string& problem) {
    file(kind, name, start, problem);
    fs::resize_file(m_folder + "/" + name, size);
  }

  const std::string& folder() const { return m_folder; }
  std::vector<HostileCase> take() { return std::move(m_cases); }

 private:
  static std::string kindName(HostileKind kind) {
    switch (kind) {
      case HostileKind::Image:
        return "image";
      case HostileKind::Texture:
        return "texture";
      case HostileKind::Preset:
        return "preset";
      case HostileKind::Mesh:
        return "mesh";
    }
    return "file";
  }
  void add(HostileKind kind, const std::string& path, const std::string& problem,
           const std::string& named) {
    m_cases.push_back(HostileCase{kind, path, problem, named});
  }

  std::string m_folder;
  std::vector<HostileCase> m_cases;
};

void writeImages(CorpusWriter& w) {
  const HostileKind k = HostileKind::Image;
  const std::vector<std::pair<std::string, std::string>> seeds = {
      {"png", "rgb8.png"},        {"png", "grey16.png"},   {"png", "rgba8.png"},
      {"png", "greyalpha.png"},   {"tiff", "strips8.tif"}, {"tiff", "lzw16.tif"},
      {"tiff", "tiledfloat.tif"}, {"tiff", "rgbazip.tif"}, {"exr", "half.exr"},
      {"exr", "float.exr"},       {"exr", "tiledmip.exr"}, {"exr", "piz.exr"}};
  for (const auto& [target, name] : seeds) {
    w.file(k, "half-" + name, half(seed(target, name)), "cut at half its length");
  }
  for (const std::string name : {"rgb8.png", "strips8.tif", "tiledfloat.tif", "half.exr"}) {
    const std::string target = name.substr(name.size() - 3) == "png"   ? "png"
                               : name.substr(name.size() - 3) == "exr" ? "exr"
                                                                       : "tiff";
    w.file(k, "header-" + name, seed(target, name).substr(0, 20), "cut inside the header");
  }

  const Bytes png = seed("png", "rgb8.png");
  Bytes badSignature = png;
  badSignature[1] = 'Q';
  w.file(k, "signature.png", badSignature, "a damaged PNG signature");
  w.file(k, "width0.png", pngWithIhdr(png, 0, be32(0)), "IHDR width 0");
  w.file(k, "huge.png", pngWithIhdr(pngWithIhdr(png, 0, be32(100000)), 4, be32(100000)),
         "IHDR 100000x100000");
  // Within the size limit, but a few hundred bytes cannot hold 16384x16384 texels even at
  // deflate's best ratio; reading it would allocate 4 GiB first.
  w.file(k, "claims16k.png",
         pngWithIhdr(pngWithIhdr(pngWithIhdr(png, 0, be32(16384)), 4, be32(16384)), 9, "\x06"),
         "IHDR 16384x16384 RGBA in a few hundred bytes");
  w.file(k, "depth3.png", pngWithIhdr(png, 8, "\x03"), "bit depth 3 (not a PNG depth)");
  w.file(k, "colortype5.png", pngWithIhdr(png, 9, "\x05"), "colour type 5 (undefined)");
  w.file(k, "compression1.png", pngWithIhdr(png, 10, "\x01"), "compression method 1");
  w.file(k, "interlace7.png", pngWithIhdr(png, 12, "\x07"), "interlace method 7");
  Bytes ihdrCrc = png;
  ihdrCrc[29] = char(ihdrCrc[29] ^ 0x40);
  w.file(k, "ihdrcrc.png", ihdrCrc, "a wrong IHDR CRC");
  const std::size_t idat = png.find("IDAT");
  const std::uint32_t idatLength = get32(png, idat - 4);
  Bytes garbageIdat = png;
  garbageIdat.replace(idat + 4, 8, noise(8, 7));
  fixPngCrc(garbageIdat, idat, __builtin_bswap32(idatLength));
  w.file(k, "zlib.png", garbageIdat, "IDAT that is not zlib data (CRC correct)");
  // Found by the fuzzer: libpng allocated a text chunk's claimed length (1.7 GB) first.
  Bytes bigText = png.substr(0, 33);
  put32be(bigText, 33, 0x696c6573u);
  bigText += "tEXtSoftware" + Bytes(200, 'x') + png.substr(33);
  w.file(k, "textlength.png", bigText, "a tEXt chunk that claims 1.7 GB");
  Bytes longIdat = png;
  put32be(longIdat, idat - 4, 0x7fffffffu);
  w.file(k, "idatlength.png", longIdat, "an IDAT length of 2^31-1");

  const Bytes tiff = seed("tiff", "strips8.tif");
  const Bytes tiled = seed("tiff", "tiledfloat.tif");
  Bytes ifdPast = tiff;
  put32(ifdPast, 4, 0x7ffffff0u);
  w.file(k, "ifdoffset.tif", ifdPast, "first IFD past the end of the file");
  Bytes ifdZero = tiff;
  put32(ifdZero, 4, 0);
  w.file(k, "ifdzero.tif", ifdZero, "first IFD at offset 0");
  Bytes ifdCount = tiff;
  put16(ifdCount, get32(tiff, 4), 0xffff);
  w.file(k, "ifdcount.tif", ifdCount, "65535 IFD entries");
  w.file(k, "width0.tif", tiffWithTag(tiff, kWidth, 0), "ImageWidth 0");
  w.file(k, "width100k.tif", tiffWithTag(tiff, kWidth, 100000), "ImageWidth 100000");
  w.file(k, "length1g.tif", tiffWithTag(tiff, kLength, 1000000000), "ImageLength 10^9");
  w.file(k, "samples0.tif", tiffWithTag(tiff, kSamplesPerPixel, 0), "SamplesPerPixel 0");
  w.file(k, "samples1000.tif", tiffWithTag(tiff, kSamplesPerPixel, 1000), "SamplesPerPixel 1000");
  w.file(k, "bits0.tif", tiffWithTag(tiff, kBitsPerSample, 0), "BitsPerSample 0");
  w.file(k, "bits128.tif", tiffWithTag(tiff, kBitsPerSample, 128), "BitsPerSample 128");
  w.file(k, "compression.tif", tiffWithTag(tiff, kCompression, 12345), "Compression 12345");
  w.file(k, "stripoffset.tif", tiffWithTag(tiff, kStripOffsets, 0x7ffffff0u),
         "StripOffsets past the end");
  w.file(k, "stripcount.tif", tiffWithTag(tiff, kStripByteCounts, 0xfffffff0u),
         "StripByteCounts of 4 GiB");
  w.file(k, "tilewidth0.tif", tiffWithTag(tiled, kTileWidth, 0), "TileWidth 0");
  w.file(k, "tileoffset.tif", tiffWithTag(tiled, kTileOffsets, 0x7ffffff0u),
         "TileOffsets past the end");

  const Bytes exr = seed("exr", "half.exr");
  Bytes exrMagic = exr;
  exrMagic[0] = 'x';
  w.file(k, "magic.exr", exrMagic, "a damaged EXR magic number");
  Bytes exrVersion = exr;
  exrVersion[4] = 99;
  w.file(k, "version.exr", exrVersion, "EXR version 99");
  w.file(k, "inverted.exr", exrWith(exr, "dataWindow", 8, le32(0xfffffff0u)),
         "a data window with xMax < xMin");
  w.file(k, "window100k.exr", exrWith(exr, "dataWindow", 8, le32(99999)),
         "a data window 100000 wide");
  w.file(k, "windowwrap.exr", exrWith(exr, "dataWindow", 0, le32(0x80000000u)),
         "a data window from -2^31 (its width overflows)");
  w.file(k, "compression.exr", exrWith(exr, "compression", 0, "\x63"), "compression 99");
  w.file(k, "nochannels.exr", exrWith(exr, "channels", 0, Bytes(1, '\0')), "no channels");
  w.file(k, "pixeltype.exr", exrWith(exr, "channels", 2, le32(7)), "channel pixel type 7");
  const Bytes mip = seed("exr", "tiledmip.exr");
  w.file(k, "tilesize0.exr", exrWith(mip, "tiles", 0, le32(0)), "tile width 0");
  w.file(k, "tilemode.exr", exrWith(mip, "tiles", 8, "\x77"), "tile level mode 0x77");
  // Found by the fuzzer: OpenEXR allocated what these headers claim (2 GB) before reading.
  Bytes claimsAttribute = exr;
  put32(claimsAttribute, exrAttributeValue(exr, "channels") - 4, 0x7ff00000u);
  w.file(k, "attributesize.exr", claimsAttribute, "an attribute that claims 2 GB");
  Bytes tinyTiles =
      exrWith(exrWith(mip, "dataWindow", 8, le32(16383)), "dataWindow", 12, le32(16383));
  tinyTiles = exrWith(exrWith(tinyTiles, "tiles", 0, le32(1)), "tiles", 4, le32(1));
  w.file(k, "tiles1x1.exr", tinyTiles, "16384x16384 mip-mapped in 1x1 tiles, from 1 KiB");

  for (const std::string extension : {"png", "tif", "exr", "jpg", "tga", "hdr"})
    w.file(k, "empty." + extension, "", "an empty file");
  w.file(k, "noise.png", noise(4096, 1), "4 KiB of noise named .png");
  w.file(k, "noise.tif", "II*\0" + noise(4096, 2), "a TIFF signature and then noise");
  w.file(k, "noise.exr", "\x76\x2f\x31\x01" + noise(4096, 3), "an EXR magic and then noise");
  w.file(k, "text.exr", "this is text, not an image\n", "text named .exr");
  Bytes uncompressedDds = seed("dds", "bc1.dds");
  put32(uncompressedDds, kDdsPixelFlags, 0x40);
  put32(uncompressedDds, kDdsFourCC, 0);
  put32(uncompressedDds, kDdsBitCount, 0);
  w.file(k, "disguised.png", uncompressedDds, "an uncompressed DDS (bit count 0) named .png");
  w.nonFiles(k, "png");
}

void writeTextures(CorpusWriter& w) {
  const HostileKind k = HostileKind::Texture;
  for (const std::string name : {"bc1.dds", "bc3.dds", "bc5.dds", "dxt5nm.dds", "bc7.dds"}) {
    const Bytes bytes = seed("dds", name);
    w.file(k, "half-" + name, half(bytes), "cut at half its length");
    w.file(k, "header-" + name, bytes.substr(0, 100), "cut inside the header");
  }
  const Bytes dds = seed("dds", "bc1.dds");
  Bytes magic = dds;
  magic[0] = 'X';
  w.file(k, "magic.dds", magic, "no DDS magic");
  w.file(k, "headersize.dds", with32(dds, kDdsSize, 0), "header size 0");
  w.file(k, "pfsize.dds", with32(dds, kDdsPixelFormatSize, 0), "pixel format size 0");
  w.file(k, "width0.dds", with32(dds, kDdsWidth, 0), "width 0");
  w.file(k, "height0.dds", with32(dds, kDdsHeight, 0), "height 0");
  w.file(k, "width16385.dds", with32(dds, kDdsWidth, 16385), "width 16385 (over the limit)");
  w.file(k, "widthmax.dds", with32(dds, kDdsWidth, 0xffffffffu), "width 2^32-1");
  w.file(k, "height2g.dds", with32(dds, kDdsHeight, 0x80000000u), "height 2^31");
  w.file(k, "mips40.dds", with32(dds, kDdsMips, 40), "40 mip levels for 8x8");
  w.file(k, "mipsmax.dds", with32(dds, kDdsMips, 0xffffffffu), "2^32-1 mip levels");
  Bytes fourcc = dds;
  std::memcpy(fourcc.data() + kDdsFourCC, "ABCD", 4);
  w.file(k, "fourcc.dds", fourcc, "FourCC ABCD");
  Bytes uncompressed = with32(with32(dds, kDdsPixelFlags, 0x40), kDdsBitCount, 0);
  put32(uncompressed, kDdsFourCC, 0);
  w.file(k, "uncompressed.dds", uncompressed, "uncompressed, bit count 0");
  Bytes rgba = with32(with32(dds, kDdsPixelFlags, 0x41), kDdsBitCount, 32);
  put32(rgba, kDdsFourCC, 0);
  w.file(k, "rgba32.dds", rgba, "uncompressed 32-bit RGBA (not a block format)");
  w.file(k, "cube.dds", with32(dds, kDdsCaps2, 0xfe00) + Bytes(5 * 32, 'x'), "a cube map");
  w.file(k, "volume.dds", with32(with32(dds, kDdsCaps2, 0x200000), kDdsDepth, 4) + Bytes(96, 'x'),
         "a volume of depth 4");
  w.file(k, "dx10format0.dds", ddsDx10(dds, 0, 0), "DX10 header with DXGI format 0");
  w.file(k, "dx10format.dds", ddsDx10(dds, 0, 9999), "DX10 header with DXGI format 9999");
  w.file(k, "dx10array0.dds", ddsDx10(dds, 12, 0), "DX10 array size 0");
  w.file(k, "dx10array2.dds", ddsDx10(dds, 12, 2), "DX10 array of 2 layers");
  w.file(k, "dx10volume.dds", ddsDx10(dds, 4, 4), "DX10 resource dimension 3D");
  w.file(k, "dx10cube.dds", ddsDx10(dds, 8, 4), "DX10 cube flag");
  w.file(k, "dx10cut.dds", ddsDx10(dds, 0, 71).substr(0, 136), "DX10 header cut short");
  Bytes huge = with32(with32(dds, kDdsWidth, 32768), kDdsHeight, 32768);
  w.sparse(k, "huge32k.dds", huge, 128 + std::uintmax_t(32768) * 32768 / 2,
           "32768x32768 BC1 (legal DDS, over Relief's limit)");

  for (const std::string name :
       {"bc1.ktx2", "etc2.ktx2", "astc4x4.ktx2", "eac-rg11.ktx2", "bc7.ktx2"}) {
    const Bytes bytes = seed("ktx2", name);
    w.file(k, "half-" + name, half(bytes), "cut at half its length");
    w.file(k, "header-" + name, bytes.substr(0, 60), "cut inside the header");
  }
  const Bytes ktx = seed("ktx2", "bc1.ktx2");
  Bytes identifier = ktx;
  identifier[1] = 'Q';
  w.file(k, "identifier.ktx2", identifier, "a damaged KTX2 identifier");
  w.file(k, "vkformat0.ktx2", with32(ktx, kVkFormat, 0), "vkFormat 0 (undefined)");
  w.file(k, "vkformat.ktx2", with32(ktx, kVkFormat, 9999), "vkFormat 9999");
  w.file(k, "width0.ktx2", with32(ktx, kPixelWidth, 0), "pixelWidth 0");
  w.file(k, "width16385.ktx2", with32(ktx, kPixelWidth, 16385), "pixelWidth 16385");
  w.file(k, "widthmax.ktx2", with32(ktx, kPixelWidth, 0xffffffffu), "pixelWidth 2^32-1");
  w.file(k, "height0.ktx2", with32(ktx, kPixelHeight, 0), "pixelHeight 0 (a 1D texture)");
  w.file(k, "depth4.ktx2", with32(ktx, kPixelDepth, 4), "pixelDepth 4 (a volume)");
  w.file(k, "layers3.ktx2", with32(ktx, kLayerCount, 3), "an array of 3 layers");
  w.file(k, "faces6.ktx2", with32(ktx, kFaceCount, 6), "6 faces (a cube map)");
  w.file(k, "levels100.ktx2", with32(ktx, kLevelCount, 100), "100 levels");
  w.file(k, "zstd.ktx2", with32(ktx, kSupercompression, 2),
         "Zstandard supercompression flag on uncompressed levels");
  w.file(k, "scheme99.ktx2", with32(ktx, kSupercompression, 99), "supercompression scheme 99");
  w.file(k, "leveloffset.ktx2", with64(ktx, kLevel0Offset, 0x7ffffffff0ull),
         "level 0 past the end of the file");
  w.file(k, "levellength.ktx2", with64(ktx, kLevel0Length, 0x8000000000000000ull),
         "level 0 of 2^63 bytes");
  w.file(k, "leveloverflow.ktx2", with64(ktx, kLevel0Offset, 0xfffffffffffffff8ull),
         "level 0 offset + length overflows 64 bits");
  w.file(k, "dfdoffset.ktx2", with32(ktx, kDfdOffset, 0x7ffffff0u), "DFD past the end");
  w.file(k, "kvdlength.ktx2", with32(with32(ktx, kKvdOffset, 100), kKvdLength, 0xfffffff0u),
         "4 GiB of key/value data");
  w.file(k, "sgdlength.ktx2", with64(ktx, kSgdLength, 0xfffffffffffffff0ull),
         "2^64 bytes of supercompression data");

  // Zstandard-supercompressed levels: a damaged frame, and an inflated size that is a lie.
  const Bytes zstd = seed("ktx2", "bc1-zstd.ktx2");
  Bytes damagedFrame = zstd;
  damagedFrame[std::size_t(get32(zstd, kLevel0Offset)) + 5] ^= 0x5a;
  w.file(k, "zstdframe.ktx2", damagedFrame, "a damaged Zstandard frame in level 0");
  w.file(k, "zstdsize.ktx2", with64(zstd, kLevel0Length + 8, 0x10000000000ull),
         "level 0 claims to inflate to 1 TiB");
  w.file(k, "empty.dds", "", "an empty file");
  w.file(k, "empty.ktx2", "", "an empty file");
  w.file(k, "magiconly.dds", "DDS ", "the DDS magic alone");
  w.file(k, "identifieronly.ktx2", ktx.substr(0, 12), "the KTX2 identifier alone");
  w.file(k, "noise.dds", "DDS " + noise(2048, 4), "the DDS magic and then noise");
  w.file(k, "noise.ktx2", ktx.substr(0, 12) + noise(2048, 5), "the KTX2 identifier and noise");
  w.nonFiles(k, "dds");
}

void writePresets(CorpusWriter& w) {
  const HostileKind k = HostileKind::Preset;
  const std::string folder = w.folder();
  w.file(k, "empty.relief", "", "an empty file");
  w.file(k, "brace.relief", "{", "an unterminated object");
  w.file(k, "array.relief", "[]", "a JSON array");
  w.file(k, "null.relief", "null", "JSON null");
  w.file(k, "string.relief", "\"relief-material\"", "a JSON string");
  w.file(k, "noise.relief", noise(1024, 6), "1 KiB of noise");
  w.file(k, "nested.relief", Bytes(100000, '['), "100000 nested arrays");
  w.file(k, "utf8.relief", presetJson("\"version\": 2, \"name\": \"\xff\xfe\xc0\""),
         "invalid UTF-8");
  const Bytes sample = readFile(samplePreset("bricks"));
  w.file(k, "half.relief", half(sample), "a sample cut at half its length");
  w.file(k, "format-missing.relief", R"({"version": 2})", "no format name");
  w.file(k, "format-wrong.relief", R"({"format": "relief-materia", "version": 2})",
         "a wrong format name");
  w.file(k, "version-missing.relief", presetJson(R"("name": "x")"), "no version");
  for (const auto& [name, version] : std::vector<std::pair<std::string, std::string>>{
           {"string", "\"2\""},
           {"zero", "0"},
           {"negative", "-1"},
           {"fraction", "1.5"},
           {"next", std::to_string(relief::core::kPresetVersion + 1)},
           {"1e308", "1e308"},
           {"2pow63", "9223372036854775808"},
           {"bool", "true"}}) {
    w.file(k, "version-" + name + ".relief", presetJson("\"version\": " + version),
           "version " + version);
  }
  w.sparse(k, "big.relief", "{", std::uintmax_t(20) << 20, "20 MiB (sparse)");
  w.nonFiles(k, "relief");

  // Presets whose maps are the hostile part: the preset reads, the map does not. `preset
  // validate` and --strict renders and exports must refuse them, naming the preset.
  const auto mapCase = [&](const std::string& name, const std::string& mapPath,
                           const std::string& problem) {
    w.referring(k, name, presetWithMap(mapPath), problem);
  };
  fs::create_directory(folder + "/map-folder.png");
  mapCase("map-folder.relief", "map-folder.png", "a map that is a folder");
  ::mkfifo((folder + "/map-fifo.png").c_str(), 0600);
  mapCase("map-fifo.relief", "map-fifo.png", "a map that is a FIFO");
  fs::create_symlink("/dev/zero", folder + "/map-zero.png");
  mapCase("map-zero.relief", "map-zero.png", "a map linked to /dev/zero");
  mapCase("map-truncated.relief", "half-rgb8.png", "a map cut at half its length");
  mapCase("map-dds.relief", "uncompressed.dds", "a map that is an uncompressed DDS");
  mapCase("map-nul.relief", "height\\u0000.png", "a NUL in the map path");
  mapCase("map-long.relief", Bytes(100000, 'a') + ".png", "a map path of 100000 characters");
  mapCase("map-escape.relief", "../../../../../../etc/shadow", "a map outside every folder");
  mapCase("map-missing.relief", "no-such-map.png", "a map that does not exist");
  w.referring(k, "map-number.relief", presetJson(R"("version": 2, "maps": {"height": 42})"),
              "a map entry that is a number");
  w.referring(k, "map-compression.relief",
              presetJson(R"("version": 2, "maps": {"height": {"path": "half-rgb8.png",)"
                         R"( "compression": {"format": "bc9"}}})"),
              "an unknown compression format");
  w.referring(k, "parameter-type.relief",
              presetJson(R"("version": 2, "parameters": {"heightScale": "deep"})"),
              "a parameter that is a string");
  w.referring(k, "parameter-range.relief",
              presetJson(R"("version": 2, "parameters": {"maxSamples": -1e308})"),
              "a parameter of -1e308");
  w.referring(k, "technique.relief", presetJson(R"("version": 2, "technique": "raytrace")"),
              "an unknown technique");
  w.referring(k, "view.relief",
              presetJson(R"("version": 2, "view": {"camera": {"distance": -1e308}, "mesh": 7})"),
              "a view with a negative distance and a numeric mesh");
}

void writeMeshes(CorpusWriter& w) {
  const HostileKind k = HostileKind::Mesh;
  const std::string quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n";
  w.file(k, "empty.obj", "", "an empty file");
  w.file(k, "noise.obj", noise(2048, 8), "2 KiB of noise named .obj");
  w.file(k, "nofaces.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\n", "vertices and no faces");
  w.file(k, "nouv.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n", "no texture coordinates");
  w.file(k, "index0.obj", quad + "f 0/1 2/2 3/3\n", "face index 0");
  w.file(k, "index1g.obj", quad + "f 1/1 2/2 1000000000/3\n", "face index 10^9");
  w.file(k, "negative.obj", quad + "f -1/1 -2/2 -9/3\n", "a relative index before the first");
  w.file(k, "nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nf 1/1 2/2 3/3\n",
         "a NaN position");
  w.file(k, "inf.obj", "v 0 0 0\nv inf 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nf 1/1 2/2 3/3\n",
         "an infinite position");
  w.file(k, "overflow.obj", "v 0 0 0\nv 1e39 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nf 1/1 2/2 3/3\n",
         "a position beyond float range");

  const std::string embedded =
      R"([{"byteLength":92,"uri":"data:application/octet-stream;base64,)"
      R"(AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAACAPwAAgD8AAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/AAAAAAAAgD8AAIA/AAAAAAAAgD8AAAEAAgAAAAIAAwA="}])";
  const std::string oneNode = R"([{"mesh":0}])";
  w.file(k, "empty.gltf", "", "an empty file");
  w.file(k, "text.gltf", "not json at all", "not JSON");
  w.file(k, "array.gltf", "[1, 2, 3]", "a JSON array");
  std::string deep;
  for (int i = 0; i < 20000; ++i)
    deep += (i ? "," : "") +
            (i + 1 < 20000 ? "{\"children\":[" + std::to_string(i + 1) + "]}" : std::string("{}"));
  w.file(k, "deep.gltf", gltfDocument("[" + deep + "]", embedded), "20000 nested nodes");
  w.file(k, "cycle.gltf", gltfDocument(R"([{"mesh":0,"children":[1]},{"children":[0]}])", embedded),
         "a node cycle");
  w.file(k, "shared.gltf",
         gltfDocument(R"([{"children":[1,2]},{"children":[2]},{"mesh":0}])", embedded),
         "a node with two parents");
  w.file(k, "childrange.gltf", gltfDocument(R"([{"mesh":0,"children":[99]}])", embedded),
         "a child index past the nodes");
  w.file(k, "escape.gltf", gltfDocument(oneNode, R"([{"byteLength":92,"uri":"../../etc/passwd"}])"),
         "a buffer URI outside the folder");
  w.file(k, "absolute.gltf", gltfDocument(oneNode, R"([{"byteLength":92,"uri":"/etc/passwd"}])"),
         "an absolute buffer URI");
  w.file(k, "nobuffer.gltf", gltfDocument(oneNode, R"([{"byteLength":92,"uri":"gone.bin"}])"),
         "a buffer file that does not exist");
  w.file(k, "base64.gltf",
         gltfDocument(oneNode,
                      R"([{"byteLength":92,"uri":"data:application/octet-stream;base64,@@@@"}])"),
         "a data URI that is not base64");
  w.file(k, "bytelength.gltf",
         gltfDocument(oneNode, R"([{"byteLength":9007199254740992,"uri":"data:,"}])"),
         "a buffer of 2^53 bytes");
  Bytes countHuge = gltfDocument(oneNode, embedded);
  countHuge.replace(countHuge.find("\"count\":4"), 9, "\"count\":1000000000");
  w.file(k, "count.gltf", countHuge, "an accessor of 10^9 vertices in a 92-byte buffer");
  Bytes viewPast = gltfDocument(oneNode, embedded);
  viewPast.replace(viewPast.find("\"byteOffset\":80"), 15, "\"byteOffset\":8000");
  w.file(k, "viewpast.gltf", viewPast, "a buffer view past its buffer");
  w.file(k, "nomesh.gltf", R"({"asset":{"version":"2.0"},"nodes":[{}],"scenes":[{"nodes":[0]}]})",
         "no meshes");

  const Bytes glb = seed("glb", "quad.glb");
  w.file(k, "claims4g.glb", glbHeader(2, 0xfffffff0u) + Bytes(64, '\0'), "a length of 4 GiB");
  w.file(k, "half.glb", half(glb), "cut at half its length");
  Bytes glbMagic = glb;
  glbMagic[0] = 'x';
  w.file(k, "magic.glb", glbMagic, "no glTF magic");
  Bytes glbVersion = glb;
  put32(glbVersion, 4, 1);
  w.file(k, "version1.glb", glbVersion, "glb version 1");
  Bytes chunkPast = glb;
  put32(chunkPast, 12, 0x7ffffff0u);
  w.file(k, "chunklength.glb", chunkPast, "a JSON chunk longer than the file");
  Bytes chunkJson = glb;
  chunkJson.replace(20, 8, "garbage!");
  w.file(k, "chunkjson.glb", chunkJson, "a JSON chunk that is not JSON");
  w.nonFiles(k, "obj");
}

}  // namespace

std::vector<HostileCase> writeHostileCorpus(const std::string& folder) {
  CorpusWriter writer(folder);
  writeImages(writer);
  writeTextures(writer);
  writePresets(writer);
  writeMeshes(writer);
  return writer.take();
}

}  // namespace relief::test
