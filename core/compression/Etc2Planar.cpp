// ETC2's planar mode (OpenGL ES 3.0, section C.1.5 "Format RGB ETC2", planar mode): three
// colours, origin O, horizontal H and vertical V (R6 G7 B6 each), and every texel
// (x (H - O) + y (V - O) + 4 O + 2) >> 2: a smooth gradient, which ETC1's offsets from one or
// two base colours render as bands. Fitted by least squares (the plane through the texels,
// per channel), quantised, then each stored value nudged a step while the error falls, every
// candidate judged by decoding it with decodeEtc2Rgb, the decoder the GPU check tests.
#include "core/compression/BlockCodecs.h"
#include "core/compression/Etc2BlockBits.h"

#include <algorithm>
#include <cmath>

namespace relief::core::inline compression {
namespace {

// The nine stored values: O, H, V for R (6 bits), G (7), B (6).
struct Plane {
  int o[3], h[3], v[3];
};

constexpr int kBits[3] = {6, 7, 6};

// The block: the colours at the bit positions the decoder reads, bit 33 (differential) set,
// and the free bits chosen so that red and green stay in range and blue overflows, which is
// what selects planar mode.
void pack(const Plane& p, std::uint8_t out[8]) {
  std::uint64_t word = std::uint64_t(1) << 33;
  putBits(word, p.o[0], 62, 57);
  putBits(word, p.o[1] >> 6, 56, 56);
  putBits(word, p.o[1], 54, 49);
  putBits(word, p.o[2] >> 5, 48, 48);
  putBits(word, p.o[2] >> 3, 44, 43);
  putBits(word, p.o[2], 41, 39);
  putBits(word, p.h[0] >> 1, 38, 34);
  putBits(word, p.h[0], 32, 32);
  putBits(word, p.h[1], 31, 25);
  putBits(word, p.h[2], 24, 19);
  putBits(word, p.v[0], 18, 13);
  putBits(word, p.v[1], 12, 6);
  putBits(word, p.v[2], 5, 0);
  // Red and green stay in range (else T or H mode), blue leaves it: planar (Etc2BlockBits.h).
  keepDifferentialInRange(word, 63);
  keepDifferentialInRange(word, 55);
  forceDifferentialOverflow(word, 43, 42);
  storeBigEndian(word, out);
}

float errorOf(const Plane& p, const float rgb[16][3], int validMask, std::uint8_t out[8]) {
  pack(p, out);
  float decoded[16][3];
  decodeEtc2Rgb(out, decoded);
  float error = 0.0f;
  for (int t = 0; t < 16; ++t) {
    if (!((validMask >> t) & 1))
      continue;
    for (int c = 0; c < 3; ++c) {
      const float e = decoded[t][c] * 255.0f - rgb[t][c];
      error += e * e;
    }
  }
  return error;
}

// Nearest stored value of `bits` for an 8-bit value (bit replication, as the decoder extends).
int quantise(float value, int bits) {
  const int top = (1 << bits) - 1;
  const int guess = std::clamp(int(std::lround(value * float(top) / 255.0f)), 0, top);
  int best = guess;
  float bestError = 1e30f;
  for (int q = std::max(0, guess - 1); q <= std::min(top, guess + 1); ++q) {
    const int expanded = (q << (8 - bits)) | (q >> (2 * bits - 8));
    const float e = std::abs(float(expanded) - value);
    if (e < bestError) {
      bestError = e;
      best = q;
    }
  }
  return best;
}

}  // namespace

float encodeEtc2Planar(const float rgb[16][3], int validMask, std::uint8_t out[8]) {
  // Least squares for value = a + b x + c y over the valid texels (x, y in 0..3), per channel;
  // then O = a, H = a + 4 b, V = a + 4 c.
  double m[3][3] = {}, r[3][3] = {};
  for (int t = 0; t < 16; ++t) {
    if (!((validMask >> t) & 1))
      continue;
    const double basis[3] = {1.0, double(t % 4), double(t / 4)};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j)
        m[i][j] += basis[i] * basis[j];
      for (int c = 0; c < 3; ++c)
        r[c][i] += basis[i] * rgb[t][c];
    }
  }
  // Solve m k = r[c] by Cramer's rule (m is at most 3x3; singular when the valid texels lie on
  // one row or column, then the missing slope is 0).
  const auto determinant = [](const double a[3][3]) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  };
  const double det = determinant(m);
  Plane plane;
  for (int c = 0; c < 3; ++c) {
    double k[3] = {r[c][0] / std::max(m[0][0], 1.0), 0.0, 0.0};
    if (std::abs(det) > 1e-9) {
      for (int col = 0; col < 3; ++col) {
        double replaced[3][3];
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 3; ++j)
            replaced[i][j] = j == col ? r[c][i] : m[i][j];
        }
        k[col] = determinant(replaced) / det;
      }
    }
    plane.o[c] = quantise(float(k[0]), kBits[c]);
    plane.h[c] = quantise(float(k[0] + 4.0 * k[1]), kBits[c]);
    plane.v[c] = quantise(float(k[0] + 4.0 * k[2]), kBits[c]);
  }
  float best = errorOf(plane, rgb, validMask, out);
  for (int sweep = 0; sweep < 2 && best > 0.0f; ++sweep) {
    const float before = best;
    for (int c = 0; c < 3; ++c) {
      for (int* value : {&plane.o[c], &plane.h[c], &plane.v[c]}) {
        for (int step : {-1, 1}) {
          const int kept = *value;
          *value = std::clamp(kept + step, 0, (1 << kBits[c]) - 1);
          std::uint8_t trial[8];
          const float error = errorOf(plane, rgb, validMask, trial);
          if (error < best) {
            best = error;
          } else {
            *value = kept;
          }
        }
      }
    }
    if (best >= before)
      break;
  }
  errorOf(plane, rgb, validMask, out);
  return best;
}

}  // namespace relief::core::inline compression
