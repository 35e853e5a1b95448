#pragma once
// Colours of report figures: 8-bit RGB and the series palette.

#include <cstddef>
#include <cstdint>

namespace roomscout::plots {

struct Rgb {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

/// The k-th colour of the series palette (matplotlib's "tab10", repeating after 10), so the
/// same series index has the same colour in every figure.
Rgb paletteColor(std::size_t index);

namespace colors {
inline constexpr Rgb kBlack{0, 0, 0};
inline constexpr Rgb kWhite{255, 255, 255};
inline constexpr Rgb kText{34, 34, 34};
inline constexpr Rgb kAxis{80, 80, 80};
inline constexpr Rgb kGrid{225, 225, 225};
inline constexpr Rgb kReference{120, 120, 120};
inline constexpr Rgb kTrajectory{20, 90, 200};  ///< run.png's blue
inline constexpr Rgb kStart{40, 170, 40};       ///< run.png's green start marker
inline constexpr Rgb kEnd{220, 30, 30};         ///< run.png's red end marker
}  // namespace colors

}  // namespace roomscout::plots
