// Bit packing shared by the ETC2 mode encoders (Etc2Planar.cpp, Etc2TAndH.cpp). ETC2 selects
// its T, H and planar modes through ETC1's differential reading of the first 63..32 bits: a
// channel's five bits plus its signed 3-bit delta leaving 0..31 selects T (red), H (green) or
// planar (blue) (OpenGL ES 3.0, C.1.5). The modes' own fields leave a few bits free to force
// that: these helpers set them.
#pragma once

#include <cstdint>

namespace relief::core::inline compression {

// Stores the low (high - low + 1) bits of `value` at bits high..low of the big-endian word.
inline void putBits(std::uint64_t& word, int value, int high, int low) {
  const int width = high - low + 1;
  word |= std::uint64_t(value & ((1 << width) - 1)) << low;
}

// Keeps a channel's differential sum in 0..31 whatever its delta, when the five bits' top bit
// (`topBit`: 63 red, 55 green) is free: set when the four bits below are under 8, the five
// bits are 16..23, else 8..15, and a delta of -4..3 stays in range.
inline void keepDifferentialInRange(std::uint64_t& word, int topBit) {
  if (((word >> (topBit - 4)) & 15) < 8)
    word |= std::uint64_t(1) << topBit;
}

// Makes a channel's differential sum leave 0..31 when the five bits' top three bits
// (fiveLow + 4 .. fiveLow + 2) and the delta's sign bit (deltaHigh) are free: with two known
// bits x at fiveLow + 1 .. fiveLow and two known bits y at deltaHigh - 1 .. deltaHigh - 2, the
// five bits 111xx plus the delta 0yy make 28 + x + y (over 31 when x + y >= 4), and 000xx plus
// 1yy make x + y - 4 (negative otherwise).
inline void forceDifferentialOverflow(std::uint64_t& word, int fiveLow, int deltaHigh) {
  const int x = int((word >> fiveLow) & 3), y = int((word >> (deltaHigh - 2)) & 3);
  if (x + y >= 4)
    word |= std::uint64_t(7) << (fiveLow + 2);
  else
    word |= std::uint64_t(1) << deltaHigh;
}

// The block's eight bytes, most significant first.
inline void storeBigEndian(std::uint64_t word, std::uint8_t out[8]) {
  for (int i = 0; i < 8; ++i)
    out[i] = std::uint8_t(word >> (56 - 8 * i));
}

}  // namespace relief::core::inline compression
