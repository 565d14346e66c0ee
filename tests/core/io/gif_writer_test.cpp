// The animated GIF writer against the GIF89a specification: the header and
// blocks are where the specification puts them, and an LZW decoder written
// here from the specification (independent of the encoder) gives back, for
// every pixel, the palette index of its colour (flat colours that sit on the
// palette are not dithered). The Qt GIF reader decodes the same files in
// tests/views/scene/mode_animation_view_test.cpp.
#include "core/io/gif_writer.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace mozzi::core::io {
namespace {

int u16(const std::string& s, std::size_t at) {
  return static_cast<unsigned char>(s[at]) | (static_cast<unsigned char>(s[at + 1]) << 8);
}

// Decodes the LZW data starting at `pos` (minimum code size byte), advancing
// `pos` past the block terminator.
std::vector<int> decodeLzw(const std::string& s, std::size_t& pos) {
  const int minCodeSize = static_cast<unsigned char>(s[pos++]);
  std::string data;
  for (;;) {
    const int n = static_cast<unsigned char>(s[pos++]);
    if (n == 0) break;
    data.append(s, pos, static_cast<std::size_t>(n));
    pos += static_cast<std::size_t>(n);
  }
  const int clear = 1 << minCodeSize, end = clear + 1;
  std::vector<std::vector<int>> table;
  auto reset = [&]() {
    table.assign(static_cast<std::size_t>(end + 1), {});
    for (int i = 0; i < clear; ++i) table[static_cast<std::size_t>(i)] = {i};
  };
  reset();
  int width = minCodeSize + 1;
  std::size_t bit = 0;
  std::vector<int> out;
  int previous = -1;
  for (;;) {
    int code = 0;
    for (int b = 0; b < width; ++b, ++bit) {
      if (bit / 8 >= data.size()) return out;
      code |= ((static_cast<unsigned char>(data[bit / 8]) >> (bit % 8)) & 1) << b;
    }
    if (code == clear) {
      reset();
      width = minCodeSize + 1;
      previous = -1;
      continue;
    }
    if (code == end) break;
    std::vector<int> entry;
    if (code < static_cast<int>(table.size())) {
      entry = table[static_cast<std::size_t>(code)];
    } else {  // the KwKwK case
      entry = table[static_cast<std::size_t>(previous)];
      entry.push_back(entry.front());
    }
    out.insert(out.end(), entry.begin(), entry.end());
    if (previous >= 0 && table.size() < 4096) {
      auto added = table[static_cast<std::size_t>(previous)];
      added.push_back(entry.front());
      table.push_back(added);
      if (static_cast<int>(table.size()) == (1 << width) && width < 12) ++width;
    }
    previous = code;
  }
  return out;
}

TEST(GifWriter, FramesDecodeToThePaletteIndicesOfTheirColours) {
  // Two 300 x 40 frames of flat palette colours in vertical bands (long runs
  // fill the 4096-code table, so the clear-and-restart path is exercised).
  const int w = 300, h = 40;
  std::vector<RgbImage> frames(2);
  for (int f = 0; f < 2; ++f) {
    frames[f].width = w;
    frames[f].height = h;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const int index = (x / 7 + y * 3 + f * 11) % 252;  // cube colours only
        const std::uint32_t c = gifPaletteColour(index);
        frames[f].rgb.push_back(static_cast<std::uint8_t>(c >> 16));
        frames[f].rgb.push_back(static_cast<std::uint8_t>(c >> 8));
        frames[f].rgb.push_back(static_cast<std::uint8_t>(c));
      }
  }
  GifOptions options;
  options.delayCentiseconds = 4;
  auto bytes = encodeAnimatedGif(frames, options);
  ASSERT_TRUE(bytes.ok()) << bytes.error().describe();
  const std::string& s = *bytes;
  ASSERT_EQ(s.substr(0, 6), "GIF89a");
  EXPECT_EQ(u16(s, 6), w);
  EXPECT_EQ(u16(s, 8), h);
  EXPECT_EQ(static_cast<unsigned char>(s[10]), 0xF7);  // global table of 256 colours
  std::size_t pos = 13 + 3 * 256;
  ASSERT_EQ(s.substr(pos, 14), std::string("\x21\xFF\x0BNETSCAPE2.0", 14));
  pos += 14 + 5;  // sub-block 3 1 loop-count(2) terminator
  for (int f = 0; f < 2; ++f) {
    ASSERT_EQ(static_cast<unsigned char>(s[pos]), 0x21);
    ASSERT_EQ(static_cast<unsigned char>(s[pos + 1]), 0xF9);
    EXPECT_EQ(u16(s, pos + 4), 4);  // delay [1/100 s]
    pos += 8;
    ASSERT_EQ(s[pos], ',');
    EXPECT_EQ(u16(s, pos + 5), w);
    EXPECT_EQ(u16(s, pos + 7), h);
    pos += 10;
    const std::vector<int> pixels = decodeLzw(s, pos);
    ASSERT_EQ(pixels.size(), static_cast<std::size_t>(w * h)) << "frame " << f;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        ASSERT_EQ(pixels[static_cast<std::size_t>(y * w + x)], (x / 7 + y * 3 + f * 11) % 252)
            << "frame " << f << " pixel " << x << "," << y;
  }
  EXPECT_EQ(s[pos], ';');
  EXPECT_EQ(pos + 1, s.size());
}

TEST(GifWriter, PaletteIndexRoundTripsTheCubeAndRefusesBadFrames) {
  for (int i = 0; i < 252; ++i) {
    const std::uint32_t c = gifPaletteColour(i);
    EXPECT_EQ(gifPaletteIndex(static_cast<std::uint8_t>(c >> 16), static_cast<std::uint8_t>(c >> 8),
                              static_cast<std::uint8_t>(c)),
              i);
  }
  EXPECT_FALSE(encodeAnimatedGif({}).ok());
  RgbImage a{2, 2, std::vector<std::uint8_t>(12, 0)};
  RgbImage b{3, 2, std::vector<std::uint8_t>(18, 0)};
  auto r = encodeAnimatedGif({a, b});
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("frame 2"), std::string::npos);
}

}  // namespace
}  // namespace mozzi::core::io
