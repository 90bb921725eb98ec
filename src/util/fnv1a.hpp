#pragma once
// 64-bit FNV-1a (Fowler–Noll–Vo) digests of numbers and text, fed one 64-bit word at a
// time, least significant byte first, so the digest does not depend on the machine's byte
// order: mesh hashes (io/provenance.hpp) and checkpoint checksums (io/checkpoint_file.hpp).
// Host-only.
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

namespace rouleau {

class Fnv1a64 {
 public:
  void add_word(std::uint64_t word) {
    for (int byte = 0; byte < 8; ++byte) {
      state_ ^= (word >> (8 * byte)) & 0xffu;
      state_ *= 0x100000001b3ull;  // FNV 64-bit prime
    }
  }
  // The IEEE-754 bits of `value`.
  void add_double(double value) {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    add_word(bits);
  }
  // The length, then each byte as a word.
  void add_text(const std::string& text) {
    add_word(text.size());
    for (unsigned char c : text) add_word(c);
  }
  std::uint64_t digest() const { return state_; }
  // The digest as 16 lowercase hex digits.
  std::string hex_digest() const {
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(state_));
    return hex;
  }

 private:
  std::uint64_t state_ = 0xcbf29ce484222325ull;  // FNV 64-bit offset basis
};

}  // namespace rouleau
