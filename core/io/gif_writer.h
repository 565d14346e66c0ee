#pragma once
// Animated GIF (GIF89a) writer for exported mode-shape animations: one global
// 256-colour palette (a 6 x 7 x 6 colour cube plus four greys), ordered 4 x 4
// Bayer dithering, LZW-compressed frames, a NETSCAPE2.0 block so viewers loop
// forever. Written from the GIF89a specification (CompuServe, 1990); no image
// library needed. Only writing: Mozzi never reads GIFs.

#include <cstdint>
#include <string>
#include <vector>

#include "core/common/result.h"

namespace mozzi::core::io {

// 8-bit RGB, rows top to bottom, 3 bytes per pixel, no padding.
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3
};

struct GifOptions {
  int delayCentiseconds = 4;  // per frame; 4 = 25 frames per second
  bool loop = true;
};

// Every frame must have the same size (1..65535 pixels a side).
Result<std::string> encodeAnimatedGif(const std::vector<RgbImage>& frames, const GifOptions& options = {});
Result<void> writeAnimatedGif(const std::string& path, const std::vector<RgbImage>& frames,
                              const GifOptions& options = {});

// The palette index of an RGB colour without dithering (exposed for tests).
int gifPaletteIndex(std::uint8_t r, std::uint8_t g, std::uint8_t b);
// The palette's colour at `index` (0..255), as 0xRRGGBB.
std::uint32_t gifPaletteColour(int index);

}  // namespace mozzi::core::io
