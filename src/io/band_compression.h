#pragma once
// Lossless compression of half-float pixels for the network (load-balanced bands, io/half_pixels.h).
// Rendered sky is smooth and mostly dark: neighbouring halves of one colour channel share their
// high byte and differ by a little in the low one. So the halves are split into channel planes,
// each half replaced by its difference (mod 2^16) from the previous one of its plane, the
// differences split into a high-byte and a low-byte plane, and the planes compressed with
// Zstandard (RFC 8878) at its fastest standard level. Decompression inverts every step exactly.
#include <cstdint>
#include <vector>

namespace aurorawall::io {

// `halves` (interleaved R, G, B when `channels` is 3) compressed; any length, any bits.
std::vector<std::uint8_t> compressHalves(const std::vector<std::uint16_t>& halves, int channels);

// The `count` halves that `compressed` holds. Throws std::runtime_error, with the reason, when the
// bytes are not a compressed block of exactly `count` halves (corrupt, truncated or another size).
std::vector<std::uint16_t> decompressHalves(const std::vector<std::uint8_t>& compressed, std::size_t count,
                                            int channels);

} // namespace aurorawall::io
