#include "core/report/report_text.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <vector>

#include "core/common/text.h"

namespace mozzi::core::report {

Result<Language> parseLanguage(const std::string& code) {
  std::string lower = code;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  if (lower == "en" || lower == "english") return Language::English;
  if (lower == "it" || lower == "italian" || lower == "italiano") return Language::Italian;
  return makeError(ErrorCode::InvalidArgument, "unknown report language '" + code + "' (known: en, it)",
                   "report language");
}

const char* languageCode(Language language) {
  return language == Language::Italian ? "it" : "en";
}

std::string Texts::operator()(const char* english, std::initializer_list<std::string> args) const {
  std::string text = english;
  if (language_ == Language::Italian)
    if (const char* it = italianText(text)) text = it;
  if (args.size() == 0) return text;
  // %1..%9, each replaced once in a single pass (an argument holding "%2" stays as it is).
  const std::vector<std::string> values(args);
  std::string out;
  out.reserve(text.size() + 32);
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 1 < text.size() && text[i + 1] >= '1' && text[i + 1] <= '9') {
      const auto n = static_cast<std::size_t>(text[i + 1] - '1');
      if (n < values.size()) {
        out += values[n];
        ++i;
        continue;
      }
    }
    out += text[i];
  }
  return out;
}

std::string Texts::number(double value, int significantDigits) const {
  std::string s = formatNumber(value, significantDigits);
  if (language_ == Language::Italian) std::replace(s.begin(), s.end(), '.', ',');
  return s;
}

Cell Texts::numberCell(double value, int digits, double uncertainty, int uncertaintyDigits) const {
  Cell cell = report::numberCell(value, digits, uncertainty, uncertaintyDigits);
  if (language_ == Language::Italian) std::replace(cell.text.begin(), cell.text.end(), '.', ',');
  return cell;
}

std::string Texts::date(const std::string& iso) const {
  int y = 0, mo = 0, d = 0, h = 0, mi = 0;
  char sep = 0;
  // "YYYY-MM-DDTHH:MM..." or "YYYY-MM-DD HH:MM..."
  if (std::sscanf(iso.c_str(), "%4d-%2d-%2d%c%2d:%2d", &y, &mo, &d, &sep, &h, &mi) != 6 || (sep != 'T' && sep != ' '))
    return iso;
  char buf[48];
  if (language_ == Language::Italian)
    std::snprintf(buf, sizeof buf, "%02d/%02d/%04d %02d:%02d UTC", d, mo, y, h, mi);
  else
    std::snprintf(buf, sizeof buf, "%04d-%02d-%02d %02d:%02d UTC", y, mo, d, h, mi);
  return buf;
}

}  // namespace mozzi::core::report
