#pragma once
// Private helpers of the UFF reader and writer: Fortran-style number scanning
// and fixed-column fields. Not part of the public face (core/io/uff/uff.h).

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>

namespace mozzi::core::io::uff::detail {

inline bool isBlankChar(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

inline std::string_view trimRight(std::string_view s) {
  while (!s.empty() && (isBlankChar(s.back()) || s.back() == '\0')) s.remove_suffix(1);
  return s;
}
inline std::string_view trim(std::string_view s) {
  s = trimRight(s);
  while (!s.empty() && isBlankChar(s.front())) s.remove_prefix(1);
  return s;
}
inline bool isBlank(std::string_view s) {
  return trim(s).empty();
}

// The blank-separated words of a line, one at a time:
//   Words words(line); std::string_view w; while (words.next(w)) ...
// (views into the line).
class Words {
 public:
  explicit Words(std::string_view line) : rest_(trim(line)) {}
  bool next(std::string_view& word) {
    if (rest_.empty()) return false;
    std::size_t k = 0;
    while (k < rest_.size() && !isBlankChar(rest_[k])) ++k;
    word = rest_.substr(0, k);
    rest_ = trim(rest_.substr(k));
    return true;
  }

 private:
  std::string_view rest_;
};

// The dataset delimiter: "    -1" in columns 1-6 (any blanks around -1 accepted).
inline bool isDelimiter(std::string_view s) {
  return trim(s) == "-1";
}

// Columns [start, start + width) of a fixed-format record, clamped to the line.
inline std::string_view field(std::string_view line, std::size_t start, std::size_t width) {
  if (start >= line.size()) return {};
  return line.substr(start, width);
}

// An integer field: blanks around it allowed; false when empty or not an integer.
inline bool parseInt(std::string_view text, long long& out) {
  text = trim(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return false;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && end == text.data() + text.size();
}

enum class NumberStatus { Ok, Malformed, NonFinite };

// One Fortran-style real at p (no leading blanks): optional sign, E/e/D/d
// exponent. On success sets `value` and returns the end of the number.
inline const char* parseNumber(const char* p, const char* end, double& value, NumberStatus& status) {
  status = NumberStatus::Ok;
  const char* start = p;
  if (p < end && *p == '+') ++p;  // from_chars does not take a leading '+'
  auto [q, ec] = std::from_chars(p, end, value, std::chars_format::general);
  if (ec == std::errc::invalid_argument) {
    status = NumberStatus::Malformed;
    return nullptr;
  }
  const bool fortranD = q < end && (*q == 'D' || *q == 'd');
  if (fortranD || ec == std::errc::result_out_of_range) {
    // Slow path: copy the token, D -> E, and let strtod decide (it also
    // resolves underflow to 0 / subnormal and overflow to HUGE_VAL).
    const char* t = q;
    if (fortranD) {
      ++t;
      if (t < end && (*t == '+' || *t == '-')) ++t;
      const char* digits = t;
      while (t < end && *t >= '0' && *t <= '9') ++t;
      if (t == digits) {
        status = NumberStatus::Malformed;
        return nullptr;
      }
    }
    char buffer[128];
    const std::size_t n = static_cast<std::size_t>(t - start);
    if (n >= sizeof(buffer)) {
      status = NumberStatus::Malformed;
      return nullptr;
    }
    std::memcpy(buffer, start, n);
    buffer[n] = '\0';
    for (std::size_t i = 0; i < n; ++i)
      if (buffer[i] == 'D' || buffer[i] == 'd') buffer[i] = 'E';
    char* stop = nullptr;
    value = std::strtod(buffer, &stop);
    if (stop != buffer + n) {
      status = NumberStatus::Malformed;
      return nullptr;
    }
    q = t;
  }
  if (!std::isfinite(value)) status = NumberStatus::NonFinite;
  return q;
}

struct ScanResult {
  NumberStatus status = NumberStatus::Ok;
  std::size_t column = 0;  // 0-based column of the offending text
  bool stopped = false;    // the sink refused a value (too many)
};

// Every number on a line, in order, to sink(double) -> bool (false: stop).
// Numbers are separated by blanks; a field that runs into the next one is
// accepted only when the next starts with a sign ("4.1E+03-3.1E+03", which
// fixed-width Fortran output produces), so "1.0E+001.0E+00" is malformed.
template <class Sink>
inline ScanResult scanNumbers(std::string_view line, Sink&& sink) {
  const char* begin = line.data();
  const char* p = begin;
  const char* end = begin + line.size();
  bool afterNumber = false;
  while (p < end) {
    const char c = *p;
    if (isBlankChar(c)) {
      ++p;
      afterNumber = false;
      continue;
    }
    if (afterNumber && c != '-' && c != '+')
      return {NumberStatus::Malformed, static_cast<std::size_t>(p - begin), false};
    double v = 0.0;
    NumberStatus st;
    const char* q = parseNumber(p, end, v, st);
    if (st != NumberStatus::Ok) return {st, static_cast<std::size_t>(p - begin), false};
    if (!sink(v)) return {NumberStatus::Ok, static_cast<std::size_t>(p - begin), true};
    p = q;
    afterNumber = true;
  }
  return {};
}

// Printable excerpt of a line for error messages (at most 40 bytes).
inline std::string excerpt(std::string_view line, std::size_t column = 0) {
  if (column > line.size()) column = line.size();
  std::string_view s = line.substr(column, 40);
  std::string out;
  for (char c : s) out += (static_cast<unsigned char>(c) < 32 || c == 127) ? '?' : c;
  return out;
}

}  // namespace mozzi::core::io::uff::detail
