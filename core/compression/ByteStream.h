// Little-endian byte writing and bounds-checked reading for the container files (DDS, KTX2 are
// little-endian). The reader never reads past its end: a short read sets a flag and returns
// zero, so a parser checks `ok()` once after reading a header.
#pragma once

#include "core/base/Result.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace relief::core::inline compression {

// A reader's failure, naming the file first.
inline Error fileError(const std::string& name, const std::string& problem) {
  return makeError(name + ": " + problem);
}

class ByteWriter {
 public:
  void u8(std::uint8_t value) { m_bytes.push_back(value); }
  void u32(std::uint32_t value) {
    for (int i = 0; i < 4; ++i)
      m_bytes.push_back(std::uint8_t(value >> (8 * i)));
  }
  void u64(std::uint64_t value) {
    for (int i = 0; i < 8; ++i)
      m_bytes.push_back(std::uint8_t(value >> (8 * i)));
  }
  void bytes(const std::uint8_t* data, std::size_t size) {
    m_bytes.insert(m_bytes.end(), data, data + size);
  }
  void text(std::string_view value) { m_bytes.insert(m_bytes.end(), value.begin(), value.end()); }
  void zeros(std::size_t count) { m_bytes.resize(m_bytes.size() + count, 0); }
  void padTo(std::size_t alignment) {
    while (m_bytes.size() % alignment != 0)
      m_bytes.push_back(0);
  }
  // Overwrites a u32 or u64 written earlier (offsets known only later).
  void patchU32(std::size_t at, std::uint32_t value) {
    for (int i = 0; i < 4; ++i)
      m_bytes[at + std::size_t(i)] = std::uint8_t(value >> (8 * i));
  }
  void patchU64(std::size_t at, std::uint64_t value) {
    for (int i = 0; i < 8; ++i)
      m_bytes[at + std::size_t(i)] = std::uint8_t(value >> (8 * i));
  }
  std::size_t size() const { return m_bytes.size(); }
  std::vector<std::uint8_t>& data() { return m_bytes; }

 private:
  std::vector<std::uint8_t> m_bytes;
};

class ByteReader {
 public:
  ByteReader(const std::vector<std::uint8_t>& bytes, std::size_t offset = 0)
      : m_bytes(bytes),
        m_position(offset <= bytes.size() ? offset : bytes.size()),
        m_ok(offset <= bytes.size()) {}

  std::uint32_t u32() {
    std::uint32_t value = 0;
    if (take(4)) {
      for (int i = 0; i < 4; ++i)
        value |= std::uint32_t(m_bytes[m_position - 4 + std::size_t(i)]) << (8 * i);
    }
    return value;
  }
  std::uint64_t u64() {
    const std::uint64_t low = u32();
    return low | std::uint64_t(u32()) << 32;
  }
  void skip(std::size_t count) { take(count); }
  bool ok() const { return m_ok; }
  std::size_t position() const { return m_position; }

 private:
  bool take(std::size_t count) {
    if (!m_ok || count > m_bytes.size() - m_position) {
      m_ok = false;
      return false;
    }
    m_position += count;
    return true;
  }

  const std::vector<std::uint8_t>& m_bytes;
  std::size_t m_position;
  bool m_ok;
};

}  // namespace relief::core::inline compression
