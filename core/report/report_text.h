#pragma once
// The report's words in the reader's language (issue 23): core builds the
// report without Qt, so its headings, captions, table headers and sentences
// pass through this small message catalogue (English sources, Italian in
// report_text_it.cpp). Numbers and dates follow the language too: a decimal
// comma and day/month/year in Italian. Symbols (k_lat, mass_loading, verdict
// names, units) are the same in every language.

#include <initializer_list>
#include <string>

#include "core/common/result.h"
#include "core/report/report.h"

namespace mozzi::core::report {

enum class Language { English, Italian };

// "en" or "it" (also "english", "italiano"); InvalidArgument naming the code otherwise.
Result<Language> parseLanguage(const std::string& code);
const char* languageCode(Language language);  // "en", "it"

class Texts {
 public:
  explicit Texts(Language language = Language::English) : language_(language) {}
  Language language() const { return language_; }

  // The message `english` in the language, with %1..%9 replaced by `args`
  // (an English source missing from the catalogue stays English).
  std::string operator()(const char* english, std::initializer_list<std::string> args = {}) const;

  // formatNumber with the language's decimal separator.
  std::string number(double value, int significantDigits = 4) const;
  // numberCell (report.h) with the language's decimal separator.
  Cell numberCell(double value, int digits = 6, double uncertainty = 0.0, int uncertaintyDigits = 2) const;
  // An ISO 8601 UTC time stamp ("2026-11-28T03:28:10Z" or "2026-11-28 03:28 UTC")
  // as "2026-11-28 03:28 UTC" (English) or "28/11/2026 03:28 UTC" (Italian);
  // anything else is returned as it is.
  std::string date(const std::string& isoUtc) const;

 private:
  Language language_;
};

// The Italian of an English source string; nullptr when the catalogue lacks it.
const char* italianText(const std::string& english);

}  // namespace mozzi::core::report
