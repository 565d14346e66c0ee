#include "core/report/report_html.h"

namespace mozzi::core::report {
namespace {

void writeTable(std::string& html, const Table& table) {
  html += "<table width=\"100%\" border=\"1\" cellspacing=\"0\" cellpadding=\"3\">";
  if (!table.caption.empty()) html += "<caption>" + escapeHtml(table.caption) + "</caption>";
  html += "<tr>";
  for (std::size_t c = 0; c < table.headers.size(); ++c) {
    std::string head = escapeHtml(table.headers[c]);
    if (c < table.units.size() && !table.units[c].empty()) head += " [" + escapeHtml(table.units[c]) + "]";
    html += "<th>" + head + "</th>";
  }
  html += "</tr>";
  for (const auto& row : table.rows) {
    html += "<tr>";
    for (const auto& cell : row) {
      html += cell.value ? "<td align=\"right\">" : "<td>";
      html += escapeHtml(cell.text) + "</td>";
    }
    html += "</tr>";
  }
  html += "</table>";
}

}  // namespace

std::string escapeHtml(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string toHtml(const Report& report, const std::function<std::string(const Figure&)>& figureSource,
                   int figureWidth) {
  std::string html = "<!DOCTYPE html><html lang=\"" + escapeHtml(report.language) +
                     "\"><head><meta charset=\"utf-8\"><title>" + escapeHtml(report.title) +
                     "</title><style>body{font-family:sans-serif} table{border-collapse:collapse;margin-bottom:1em} "
                     "caption{text-align:left;font-style:italic} th{background:#e8e8e8}</style></head><body>";
  html += "<h1>" + escapeHtml(report.title) + "</h1>";
  for (const auto& section : report.sections) {
    html += "<h2>" + escapeHtml(section.heading) + "</h2>";
    for (const auto& block : section.blocks) {
      if (const auto* p = std::get_if<Paragraph>(&block)) {
        html += "<p>" + escapeHtml(p->text) + "</p>";
      } else if (const auto* h = std::get_if<Heading>(&block)) {
        html += "<h3>" + escapeHtml(h->text) + "</h3>";
      } else if (const auto* t = std::get_if<Table>(&block)) {
        writeTable(html, *t);
      } else if (const auto* f = std::get_if<Figure>(&block)) {
        const std::string src = figureSource ? figureSource(*f) : std::string();
        if (src.empty()) {
          html += "<p><i>[" + escapeHtml(f->caption) + ": figure of the " + escapeHtml(f->view) +
                  " view, not rendered]</i></p>";
        } else {
          html += "<p><img src=\"" + escapeHtml(src) + "\" width=\"" + std::to_string(figureWidth) + "\" alt=\"" +
                  escapeHtml(f->caption) + "\"><br><i>" + escapeHtml(f->caption) + "</i></p>";
        }
      }
    }
  }
  html += "</body></html>\n";
  return html;
}

}  // namespace mozzi::core::report
