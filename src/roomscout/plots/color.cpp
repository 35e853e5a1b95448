#include "roomscout/plots/color.hpp"

#include <array>

namespace roomscout::plots {

Rgb paletteColor(std::size_t index) {
  static constexpr std::array<Rgb, 10> kTab10 = {{{31, 119, 180},
                                                  {255, 127, 14},
                                                  {44, 160, 44},
                                                  {214, 39, 40},
                                                  {148, 103, 189},
                                                  {140, 86, 75},
                                                  {227, 119, 194},
                                                  {127, 127, 127},
                                                  {188, 189, 34},
                                                  {23, 190, 207}}};
  return kTab10[index % kTab10.size()];
}

}  // namespace roomscout::plots
