#pragma once
// A Report as one HTML page (UTF-8, no scripts, no external style sheet). The
// same page is the HTML report's index.html and, read by QTextDocument, the
// PDF's content (views/report), so both carry the same headings and numbers.

#include <functional>
#include <string>

#include "core/report/report.h"

namespace mozzi::core::report {

// `figureSource` gives the <img> src of a figure (a file name, a data: URI, a
// resource name); an empty string leaves a placeholder saying which view
// renders it. Figures are `figureWidth` CSS pixels wide.
std::string toHtml(const Report& report, const std::function<std::string(const Figure&)>& figureSource,
                   int figureWidth = 640);

// &, <, >, " escaped.
std::string escapeHtml(const std::string& text);

}  // namespace mozzi::core::report
