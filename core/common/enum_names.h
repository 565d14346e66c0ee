#pragma once
// One table per enum <-> text (or code) mapping, read both ways: the name of a
// value, and the value of a name. Replaces a switch for each direction.
//
//   constexpr auto kNames = enumTable<FrfType>(
//       {{FrfType::Receptance, "receptance"}, {FrfType::Mobility, "mobility"}}, "?");
//   kNames.of(FrfType::Mobility)          // "mobility"
//   kNames.find("mobility")               // std::optional<FrfType>
//   parseEnum(kNames, text, "FRF type", where)  // Result, naming the accepted names
// A long table reads better as a named array of entries first:
//   constexpr EnumEntry<Verdict, const char*> kEntries[] = {{Verdict::Effect, "effect"}, ...};
//   constexpr auto kNames = enumTable(kEntries, "none");

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

#include "core/common/result.h"

namespace mozzi::core {

template <class E, class T>
struct EnumEntry {
  E value{};
  T text{};
};

enum class NameCase { Exact, Ignore };

template <class E, class T, std::size_t N>
class EnumTable {
 public:
  constexpr EnumTable(const EnumEntry<E, T> (&entries)[N], T fallback) : fallback_(fallback) {
    for (std::size_t k = 0; k < N; ++k) entries_[k] = entries[k];
  }

  // The text of `value`; the fallback for a value outside the table (a cast
  // integer that names no enumerator).
  constexpr T of(E value) const {
    for (const auto& e : entries_) {
      if (e.value == value) return e.text;
    }
    return fallback_;
  }

  // The value whose text is `text`, if any.
  constexpr std::optional<E> find(const T& text, NameCase nameCase = NameCase::Exact) const {
    for (const auto& e : entries_) {
      if (same(e.text, text, nameCase)) return e.value;
    }
    return std::nullopt;
  }

  constexpr const EnumEntry<E, T> (&entries() const)[N] { return entries_; }

 private:
  static constexpr bool same(const T& a, const T& b, NameCase nameCase) {
    if constexpr (std::is_convertible_v<T, std::string_view>) {
      const std::string_view x(a), y(b);
      if (nameCase == NameCase::Exact) return x == y;
      if (x.size() != y.size()) return false;
      for (std::size_t k = 0; k < x.size(); ++k) {
        if (asciiLower(x[k]) != asciiLower(y[k])) return false;
      }
      return true;
    } else {
      return a == b;
    }
  }

  static constexpr char asciiLower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

  EnumEntry<E, T> entries_[N]{};
  T fallback_{};
};

// enumTable<FrfType>({{FrfType::Receptance, "receptance"}, ...}, "?"): the
// entry count and the text type follow from the arguments.
template <class E, class T, std::size_t N>
constexpr EnumTable<E, T, N> enumTable(const EnumEntry<E, T> (&entries)[N], T fallback) {
  return EnumTable<E, T, N>(entries, fallback);
}

// "A, B or C": the texts of a name table, for an error that lists them.
template <class E, std::size_t N>
std::string acceptedNames(const EnumTable<E, const char*, N>& table) {
  std::string list;
  for (std::size_t k = 0; k < N; ++k) {
    if (k > 0) list += k + 1 == N ? " or " : ", ";
    list += table.entries()[k].text;
  }
  return list;
}

// The value named `text`, or a ParseError "unknown <what> '<text>' (expected
// A, B or C)" at `where`.
template <class E, std::size_t N>
Result<E> parseEnum(const EnumTable<E, const char*, N>& table, std::string_view text, const std::string& what,
                    const std::string& where, NameCase nameCase = NameCase::Exact) {
  const std::string copy(text);
  if (auto value = table.find(copy.c_str(), nameCase)) return *value;
  return makeError(ErrorCode::ParseError, "unknown " + what + " '" + copy + "' (expected " + acceptedNames(table) + ")",
                   where);
}

}  // namespace mozzi::core
