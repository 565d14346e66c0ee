#include "core/io/gif_writer.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <unordered_map>

namespace mozzi::core::io {
namespace {

// Palette: indices 0..251 the cube r in 0..5, g in 0..6, b in 0..5
// (index = (r * 7 + g) * 6 + b), 252..255 greys between the cube's greys.
constexpr int kR = 6, kG = 7, kB = 6;

int level(int value, int levels) {
  return (value * (levels - 1) + 127) / 255;
}
int levelValue(int l, int levels) {
  return l * 255 / (levels - 1);
}

// 4 x 4 Bayer matrix, thresholds in (-0.5, 0.5) of one palette step.
constexpr std::array<int, 16> kBayer = {0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5};

int ditheredIndex(int r, int g, int b, int x, int y) {
  const double t = (kBayer[static_cast<std::size_t>((y & 3) * 4 + (x & 3))] + 0.5) / 16.0 - 0.5;
  auto q = [t](int v, int levels) {
    const double scaled = v * (levels - 1) / 255.0 + t;
    return std::clamp(static_cast<int>(scaled + 0.5), 0, levels - 1);
  };
  return (q(r, kR) * kG + q(g, kG)) * kB + q(b, kB);
}

void put16(std::string& s, int v) {
  s += static_cast<char>(v & 0xFF);
  s += static_cast<char>((v >> 8) & 0xFF);
}

// Variable-length-code LZW as GIF uses it (LSB-first bit packing, clear code
// 2^minCodeSize, end code + 1, codes up to 12 bits), in 255-byte sub-blocks.
class LzwEncoder {
 public:
  explicit LzwEncoder(std::string& out) : out_(out) {}

  void encode(const std::vector<std::uint8_t>& indices) {
    constexpr int kMinCodeSize = 8;
    const int clear = 1 << kMinCodeSize;
    const int end = clear + 1;
    out_ += static_cast<char>(kMinCodeSize);
    auto reset = [&]() {
      table_.clear();
      next_ = end + 1;
      width_ = kMinCodeSize + 1;
    };
    reset();
    emit(clear);
    int prefix = -1;
    for (std::uint8_t c : indices) {
      if (prefix < 0) {
        prefix = c;
        continue;
      }
      const std::uint32_t key = (static_cast<std::uint32_t>(prefix) << 8) | c;
      const auto it = table_.find(key);
      if (it != table_.end()) {
        prefix = it->second;
        continue;
      }
      emit(prefix);
      if (next_ < 4096) {
        table_.emplace(key, next_);
        // The decoder widens one code later than the encoder adds it.
        if (next_ == (1 << width_) && width_ < 12) ++width_;
        ++next_;
      } else {
        emit(clear);
        reset();
      }
      prefix = c;
    }
    if (prefix >= 0) emit(prefix);
    emit(end);
    if (bits_ > 0) pushByte(static_cast<std::uint8_t>(buffer_ & 0xFF));
    flushBlock();
    out_ += '\0';  // block terminator
  }

 private:
  void emit(int code) {
    buffer_ |= static_cast<std::uint32_t>(code) << bits_;
    bits_ += width_;
    while (bits_ >= 8) {
      pushByte(static_cast<std::uint8_t>(buffer_ & 0xFF));
      buffer_ >>= 8;
      bits_ -= 8;
    }
  }
  void pushByte(std::uint8_t b) {
    block_.push_back(b);
    if (block_.size() == 255) flushBlock();
  }
  void flushBlock() {
    if (block_.empty()) return;
    out_ += static_cast<char>(block_.size());
    out_.append(reinterpret_cast<const char*>(block_.data()), block_.size());
    block_.clear();
  }

  std::string& out_;
  std::unordered_map<std::uint32_t, int> table_;
  int next_ = 0;
  int width_ = 9;
  std::uint32_t buffer_ = 0;
  int bits_ = 0;
  std::vector<std::uint8_t> block_;
};

}  // namespace

std::uint32_t gifPaletteColour(int index) {
  if (index < 0 || index > 255) return 0;
  if (index < kR * kG * kB) {
    const int b = index % kB, g = (index / kB) % kG, r = index / (kB * kG);
    return (static_cast<std::uint32_t>(levelValue(r, kR)) << 16) |
           (static_cast<std::uint32_t>(levelValue(g, kG)) << 8) | static_cast<std::uint32_t>(levelValue(b, kB));
  }
  const std::uint32_t grey = static_cast<std::uint32_t>(25 + 51 * (index - kR * kG * kB));  // 25, 76, 127, 178
  return (grey << 16) | (grey << 8) | grey;
}

int gifPaletteIndex(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  return (level(r, kR) * kG + level(g, kG)) * kB + level(b, kB);
}

Result<std::string> encodeAnimatedGif(const std::vector<RgbImage>& frames, const GifOptions& options) {
  if (frames.empty()) return makeError(ErrorCode::InvalidArgument, "no frames to write", "GIF export");
  const int w = frames.front().width, h = frames.front().height;
  if (w <= 0 || h <= 0 || w > 65535 || h > 65535) {
    return makeError(ErrorCode::InvalidArgument, "frame size must be 1..65535 pixels a side", "GIF export");
  }
  for (std::size_t f = 0; f < frames.size(); ++f) {
    if (frames[f].width != w || frames[f].height != h ||
        frames[f].rgb.size() != static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3) {
      return makeError(ErrorCode::InvalidArgument, "frame " + std::to_string(f + 1) + " differs in size from frame 1",
                       "GIF export");
    }
  }
  if (options.delayCentiseconds < 0 || options.delayCentiseconds > 65535) {
    return makeError(ErrorCode::InvalidArgument, "frame delay must be 0..65535 centiseconds", "GIF export");
  }
  std::string s = "GIF89a";
  put16(s, w);
  put16(s, h);
  s += static_cast<char>(0xF7);  // global colour table, 8 bits colour resolution, 256 entries
  s += '\0';                     // background colour index
  s += '\0';                     // pixel aspect ratio: not given
  for (int i = 0; i < 256; ++i) {
    const std::uint32_t c = gifPaletteColour(i);
    s += static_cast<char>((c >> 16) & 0xFF);
    s += static_cast<char>((c >> 8) & 0xFF);
    s += static_cast<char>(c & 0xFF);
  }
  if (options.loop) {
    s += "\x21\xFF\x0BNETSCAPE2.0";
    s += "\x03\x01";
    put16(s, 0);  // loop forever
    s += '\0';
  }
  std::vector<std::uint8_t> indices(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  for (const auto& frame : frames) {
    s += "\x21\xF9\x04";
    s += static_cast<char>(0x04);  // disposal: leave in place (each frame is full size)
    put16(s, options.delayCentiseconds);
    s += '\0';  // transparent index (unused)
    s += '\0';
    s += ',';  // image descriptor
    put16(s, 0);
    put16(s, 0);
    put16(s, w);
    put16(s, h);
    s += '\0';  // no local table, not interlaced
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const std::size_t p = static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
        indices[p] = static_cast<std::uint8_t>(
            ditheredIndex(frame.rgb[3 * p], frame.rgb[3 * p + 1], frame.rgb[3 * p + 2], x, y));
      }
    }
    LzwEncoder(s).encode(indices);
  }
  s += ';';  // trailer
  return s;
}

Result<void> writeAnimatedGif(const std::string& path, const std::vector<RgbImage>& frames, const GifOptions& options) {
  auto bytes = encodeAnimatedGif(frames, options);
  if (!bytes) return makeError(bytes.error().code, bytes.error().message, path);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) return makeError(ErrorCode::IoError, "cannot create the file", path);
  out << *bytes;
  out.close();
  if (!out) return makeError(ErrorCode::IoError, "cannot write the file", path);
  return {};
}

}  // namespace mozzi::core::io
