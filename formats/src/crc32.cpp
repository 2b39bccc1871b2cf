#include "hullcook/format/crc32.h"

#include <array>
#include <cstring>

#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define HULLCOOK_CRC32_FOLDING 1
#endif

namespace hullcook::format {
namespace {

// Slicing-by-16 (Intel's slicing method, 16 tables): table k advances the CRC over a byte
// followed by k zero bytes, so that sixteen bytes are folded per step. Validating a bundle is
// dominated by this loop.
using Tables = std::array<std::array<std::uint32_t, 256>, 16>;

constexpr std::uint32_t kPolynomial = 0xEDB88320u;  // reflected

constexpr Tables make_tables() {
  Tables tables{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t c = i;
    for (int bit = 0; bit < 8; ++bit) c = (c & 1u) ? kPolynomial ^ (c >> 1) : c >> 1;
    tables[0][i] = c;
  }
  for (std::uint32_t i = 0; i < 256; ++i)
    for (std::size_t k = 1; k < tables.size(); ++k)
      tables[k][i] = (tables[k - 1][i] >> 8) ^ tables[0][tables[k - 1][i] & 0xFFu];
  return tables;
}

constexpr Tables kTables = make_tables();
constexpr std::size_t kBlock = 16;

// Advances the (non-inverted) CRC state over 16 bytes. Little-endian hosts only (the bundle
// layout header refuses others).
inline std::uint32_t fold_block(std::uint32_t state, const unsigned char* bytes) noexcept {
  std::uint32_t w[4];
  std::memcpy(w, bytes, sizeof w);
  w[0] ^= state;
  std::uint32_t result = 0;
  for (std::size_t word = 0; word < 4; ++word)
    for (std::size_t byte = 0; byte < 4; ++byte)
      result ^= kTables[15 - 4 * word - byte][(w[word] >> (8 * byte)) & 0xFFu];
  return result;
}

inline std::uint32_t fold_bytes(std::uint32_t state, const unsigned char* bytes,
                                std::size_t size) noexcept {
  for (; size >= kBlock; size -= kBlock, bytes += kBlock) state = fold_block(state, bytes);
  for (; size > 0; --size) state = kTables[0][(state ^ *bytes++) & 0xFFu] ^ (state >> 8);
  return state;
}

// a * b mod the CRC polynomial, in the reflected bit order (bit 31 is x^0).
std::uint32_t multiply_mod(std::uint32_t a, std::uint32_t b) noexcept {
  std::uint32_t product = 0;
  for (int bit = 0; bit < 32; ++bit, a <<= 1) {
    if (a & 0x80000000u) product ^= b;
    b = (b & 1u) ? (b >> 1) ^ kPolynomial : b >> 1;
  }
  return product;
}

// x^(8 n) mod the polynomial: multiplying a CRC state by it appends n zero bytes.
std::uint32_t zero_bytes_operator(std::size_t n) noexcept {
  std::uint32_t result = 0x80000000u;  // 1
  std::uint32_t power = 0x00800000u;   // x^8
  for (; n > 0; n >>= 1, power = multiply_mod(power, power))
    if (n & 1u) result = multiply_mod(result, power);
  return result;
}

// One slicing chain is bound by its own latency (each block waits for the last), not by the
// loads, so large inputs run as kStreams independent chains over consecutive stripes, which
// the CPU overlaps. Because a CRC is linear, crc(A || B) = crc(A) * x^(8 |B|) + crc(B): the
// stripes' states are then combined with one multiplication each.
constexpr std::size_t kStreams = 3;
constexpr std::size_t kMinStripe = 4096;  // below it the combination would not pay

#ifdef HULLCOOK_CRC32_FOLDING
// Folding with carry-less multiplication (Intel, "Fast CRC Computation for Generic Polynomials
// Using PCLMULQDQ", 2009), used when the CPU has PCLMULQDQ (checked at each call: no global
// state): four 128-bit lanes are folded 64 bytes ahead, then into one, then reduced to 32 bits
// with Barrett's method. The constants are x^k mod P for the distances folded, bit-reflected.
// lane * x^distance + next, for the distance whose constants are in k.
__attribute__((target("pclmul,sse4.1"))) inline __m128i fold(__m128i lane, __m128i k,
                                                             __m128i next) noexcept {
  return _mm_xor_si128(_mm_xor_si128(_mm_clmulepi64_si128(lane, k, 0x11), next),
                       _mm_clmulepi64_si128(lane, k, 0x00));
}

// Advances the non-inverted state over size bytes, size >= 64 and a multiple of 16.
__attribute__((target("pclmul,sse4.1"))) std::uint32_t fold_clmul(std::uint32_t state,
                                                                  const unsigned char* bytes,
                                                                  std::size_t size) noexcept {
  alignas(16) static constexpr std::uint64_t k1k2[] = {0x0154442bd4, 0x01c6e41596};
  alignas(16) static constexpr std::uint64_t k3k4[] = {0x01751997d0, 0x00ccaa009e};
  alignas(16) static constexpr std::uint64_t k5k0[] = {0x0163cd6124, 0x0000000000};
  alignas(16) static constexpr std::uint64_t poly[] = {0x01db710641, 0x01f7011641};
  auto load = [](const unsigned char* p) {
    return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
  };

  __m128i lanes[4] = {load(bytes), load(bytes + 16), load(bytes + 32), load(bytes + 48)};
  lanes[0] = _mm_xor_si128(lanes[0], _mm_cvtsi32_si128(static_cast<int>(state)));
  bytes += 64;
  size -= 64;
  __m128i k = _mm_load_si128(reinterpret_cast<const __m128i*>(k1k2));
  for (; size >= 64; size -= 64, bytes += 64)
    for (int lane = 0; lane < 4; ++lane)
      lanes[lane] = fold(lanes[lane], k, load(bytes + 16 * lane));
  k = _mm_load_si128(reinterpret_cast<const __m128i*>(k3k4));
  __m128i x = fold(lanes[0], k, lanes[1]);
  x = fold(x, k, lanes[2]);
  x = fold(x, k, lanes[3]);
  for (; size >= 16; size -= 16, bytes += 16) x = fold(x, k, load(bytes));
  // 128 bits to 64, then to 32 (Barrett).
  const __m128i low32 = _mm_setr_epi32(~0, 0, ~0, 0);
  x = _mm_xor_si128(_mm_srli_si128(x, 8), _mm_clmulepi64_si128(x, k, 0x10));
  k = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(k5k0));
  x = _mm_xor_si128(_mm_srli_si128(x, 4), _mm_clmulepi64_si128(_mm_and_si128(x, low32), k, 0x00));
  k = _mm_load_si128(reinterpret_cast<const __m128i*>(poly));
  __m128i t = _mm_and_si128(_mm_clmulepi64_si128(_mm_and_si128(x, low32), k, 0x10), low32);
  x = _mm_xor_si128(x, _mm_clmulepi64_si128(t, k, 0x00));
  return static_cast<std::uint32_t>(_mm_extract_epi32(x, 1));
}
#endif

}  // namespace

std::uint32_t crc32_portable(std::uint32_t crc, const void* data, std::size_t size) noexcept {
  const auto* bytes = static_cast<const unsigned char*>(data);
  std::uint32_t state = ~crc;
  const std::size_t stripe = size / (kStreams * kBlock) * kBlock;
  if (stripe >= kMinStripe) {
    std::uint32_t states[kStreams] = {state};  // the later stripes start from zero
    for (std::size_t offset = 0; offset < stripe; offset += kBlock)
      for (std::size_t s = 0; s < kStreams; ++s)
        states[s] = fold_block(states[s], bytes + s * stripe + offset);
    const std::uint32_t shift = zero_bytes_operator(stripe);
    state = states[0];
    for (std::size_t s = 1; s < kStreams; ++s) state = multiply_mod(state, shift) ^ states[s];
    bytes += kStreams * stripe;
    size -= kStreams * stripe;
  }
  return ~fold_bytes(state, bytes, size);
}

std::uint32_t crc32(std::uint32_t crc, const void* data, std::size_t size) noexcept {
#ifdef HULLCOOK_CRC32_FOLDING
  if (size >= 64 && __builtin_cpu_supports("pclmul") && __builtin_cpu_supports("sse4.1")) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    const std::size_t folded = size / 16 * 16;
    return ~fold_bytes(fold_clmul(~crc, bytes, folded), bytes + folded, size - folded);
  }
#endif
  return crc32_portable(crc, data, size);
}

}  // namespace hullcook::format
