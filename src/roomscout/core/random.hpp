#pragma once
// The one mapping from a generator's bits to a uniform double that every random choice uses:
// the standard distributions differ between standard libraries, and runs must not.

#include <random>

namespace roomscout {

/// A uniform double in [0, 1) from the top 53 bits of one draw.
inline double unitDouble(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

}  // namespace roomscout
