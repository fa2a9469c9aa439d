// Block codecs: one 4x4 block at a time for the BC and ETC/EAC families. Texels are RGBA
// floats in 0..1, row-major (index y * 4 + x); `validMask` bit (y * 4 + x) marks texels inside
// the image (edge blocks of sizes that are not multiples of 4 leave the rest out of the fit).
// Decoders write what a GPU samples from the block, in the same layout.
#pragma once

#include "core/compression/TextureFormat.h"

#include <cstdint>

namespace relief::core::inline compression {

using BlockTexels = float[16][4];

// Each family's codec is given only its own family's formats (Compressor.cpp dispatches on the
// table's family), so a codec tells its formats apart with ifs instead of a switch listing
// every other family's, and a format it does not know is a bug it reports with this: a new
// format of its family that it was not taught fails its first encode or decode (the tests
// round-trip every row of the table).
[[noreturn]] void throwNotOfFamily(const char* codec, TextureFormat format);

// BC1-BC5, DXT5nm and BC7: our own encoders and decoders. BC1's colour (also the colour half of
// BC2, BC3 and DXT5nm) is Bc1Encoder.cpp, in place of libsquish's cluster fit, which is ten
// times slower for the same quality (tools/bench-compress keeps libsquish as the reference
// row); BC3's alpha and BC4/BC5 channels are BcCodec.cpp's (libsquish's missed the 1 s target
// for 4096^2 BC5); BC7 is Bc7Encoder.cpp. libsquish decodes BC4/BC5 wrongly, so the decoders
// are ours too.
// `perceptual` weighs colour error by luminance; otherwise channels weigh alike (PSNR's measure).
void encodeBcBlock(TextureFormat format, CompressionQuality quality, bool perceptual,
                   const BlockTexels& texels, int validMask, std::uint8_t* out);
void decodeBcBlock(TextureFormat format, const std::uint8_t* in, BlockTexels& texels);

// BC7: our own encoder (Bc7Encoder.cpp; no Debian package has one) and decoder (Bc7Block.h).
// encodeBcBlock and decodeBcBlock dispatch BC7 here too.
void encodeBc7Block(CompressionQuality quality, const BlockTexels& texels, int validMask,
                    std::uint8_t* out);
// BC6H, unsigned or signed half floats: our own encoder (Bc6hEncoder.cpp) and decoder
// (Bc6hBlock.h); texels are linear values, RGB (alpha ignored). Not-a-number becomes 0,
// infinities the largest half, and negatives 0 in the unsigned format. encodeBcBlock and
// decodeBcBlock dispatch BC6H here too.
void encodeBc6hBlock(bool isSigned, CompressionQuality quality, const BlockTexels& texels,
                     int validMask, std::uint8_t* out);
// One BC1 colour block (8 bytes) from RGB in 0..255. `bc1`: a BC1 block, which may use the
// three-colour mode; otherwise the colour half of BC2/BC3, which always decodes four colours.
void encodeBc1Colour(const float rgb[16][3], int validMask, CompressionQuality quality,
                     bool perceptual, bool bc1, std::uint8_t* out);

// ETC1 (Etc1Encoder.cpp; also a valid ETC2 RGB block), ETC2 RGB (ETC1's modes, the planar mode
// and, at qualities normal and best, the T and H modes), ETC2 RGBA (that colour with our EAC
// alpha), EAC R11 and RG11: all our encoders. Decoding covers every ETC2 mode (individual,
// differential, T, H, planar), so files from other encoders decode too.
void encodeEtcBlock(TextureFormat format, CompressionQuality quality, const BlockTexels& texels,
                    int validMask, std::uint8_t* out);
void decodeEtcBlock(TextureFormat format, const std::uint8_t* in, BlockTexels& texels);

// EAC modifier tables (OpenGL ES 3.0, table C.9): a block's 4-bit table index picks a row, its
// 3-bit texel indices a column.
inline constexpr int kEacModifiers[16][8] = {
    {-3, -6, -9, -15, 2, 5, 8, 14}, {-3, -7, -10, -13, 2, 6, 9, 12}, {-2, -5, -8, -13, 1, 4, 7, 12},
    {-2, -4, -6, -13, 1, 3, 5, 12}, {-3, -6, -8, -12, 2, 5, 7, 11},  {-3, -7, -9, -11, 2, 6, 8, 10},
    {-4, -7, -8, -11, 3, 6, 7, 10}, {-3, -5, -8, -11, 2, 4, 7, 10},  {-2, -6, -8, -10, 1, 5, 7, 9},
    {-2, -5, -8, -10, 1, 4, 7, 9},  {-2, -4, -8, -10, 1, 3, 7, 9},   {-2, -5, -7, -10, 1, 4, 6, 9},
    {-3, -4, -7, -10, 2, 3, 6, 9},  {-1, -2, -3, -10, 0, 1, 2, 9},   {-4, -6, -8, -9, 3, 5, 7, 8},
    {-3, -5, -7, -9, 2, 4, 6, 8}};

// ETC1/ETC2 intensity modifier tables (OpenGL ES 3.0, table C.3; codeword 0..7); a texel's
// index (msb, lsb) picks 00 +a, 01 +b, 10 -a, 11 -b.
inline constexpr int kEtcModifiers[8][4] = {
    {2, 8, -2, -8},     {5, 17, -5, -17},   {9, 29, -9, -29},     {13, 42, -13, -42},
    {18, 60, -18, -60}, {24, 80, -24, -80}, {33, 106, -33, -106}, {47, 183, -47, -183}};

// ETC2's T and H mode distances (OpenGL ES 3.0, table C.8), picked by a 3-bit index.
inline constexpr int kEtc2Distances[8] = {3, 6, 11, 16, 23, 32, 41, 64};

// The pieces, for tests and benchmarks: one EAC block of one channel (11-bit R11 form or 8-bit
// alpha form).
void encodeEacChannel(const float values[16], int validMask, bool elevenBit,
                      CompressionQuality quality, std::uint8_t out[8]);
void decodeEacChannel(const std::uint8_t in[8], bool elevenBit, float values[16]);
void decodeEtc2Rgb(const std::uint8_t in[8], float rgb[16][3]);
// The mode an ETC2 RGB block is in (OpenGL ES 3.0 C.1.5: the differential bit, then the first
// channel whose differential sum leaves 0..31).
enum class Etc2Mode { Individual, Differential, T, H, Planar };
Etc2Mode etc2Mode(const std::uint8_t in[8]);
// ETC1's individual and differential modes (Etc1Encoder.cpp) for RGB in 0..255: a search of
// each half's base colour and table; returns the squared error over the valid texels. The
// block is valid ETC1 and ETC2 RGB.
float encodeEtc1(const float rgb[16][3], int validMask, CompressionQuality quality,
                 std::uint8_t out[8]);
// ETC2's planar mode (Etc2Planar.cpp) for RGB in 0..255; returns the squared error over the
// valid texels. ETC2 RGB and RGBA keep it where it beats the ETC1 block.
float encodeEtc2Planar(const float rgb[16][3], int validMask, std::uint8_t out[8]);
// ETC2's T and H modes (Etc2TAndH.cpp) for RGB in 0..255: the better of the two for the block;
// returns the squared error over the valid texels. Best searches more splits of the texels.
float encodeEtc2TOrH(const float rgb[16][3], int validMask, CompressionQuality quality,
                     std::uint8_t out[8]);

}  // namespace relief::core::inline compression
