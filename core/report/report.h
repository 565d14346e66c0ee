#pragma once
// A report's content, without widgets (issue 23): sections of paragraphs,
// sub-headings, tables (caption, column units, numbers kept beside their
// text) and figure placeholders that name the view which renders them. Built
// from what the project stores (project_report.h) or from a gap diagnosis
// (gap_report.h); rendered to HTML here (report_html.h) and to PDF by
// views/report, so the CLI and the workbench write the same report.

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace mozzi::core::report {

// One table cell: the text shown and, for a number, the value it shows (in the
// column's unit) and its standard uncertainty when stored.
struct Cell {
  std::string text;
  std::optional<double> value;
  std::optional<double> uncertainty;
};

struct Table {
  std::string caption;
  std::vector<std::string> headers;
  std::vector<std::string> units;  // one per header; empty for a column without unit
  std::vector<std::vector<Cell>> rows;
};

struct Paragraph {
  std::string text;
};

struct Heading {  // a sub-heading inside a section
  std::string text;
};

// What a renderer draws. `view` names the view that renders it (the table of
// renderers is views/report/report_figures.cpp): "frf-overlay" and
// "frf-coherence" (FRF set `recordId`), "mesh" (specimen), "stabilization" and
// "mode-shape" (modal result; `index` the mode, from 0), "twist-axes" (rig
// test), "tyre-steady-state" (tyre test), "tyre-relaxation" (specimen),
// "gap-overlay" (stored analysis, or 0: the Model vs Test page's diagnosis).
// `id` is a file-name stem.
struct Figure {
  std::string id;
  std::string view;
  std::int64_t recordId = 0;
  std::string caption;
  int index = 0;
};

using Block = std::variant<Paragraph, Heading, Table, Figure>;

struct Section {
  std::string key;  // "title", "frf", "modal", "stiffness", "tyre", "gap"
  std::string heading;
  std::vector<Block> blocks;
};

struct Report {
  std::string title;
  std::string language = "en";  // ISO 639-1 code of the text (report_text.h)
  std::vector<Section> sections;

  const Section* section(const std::string& key) const {
    for (const auto& s : sections)
      if (s.key == key) return &s;
    return nullptr;
  }
};

// A number cell: `digits` significant digits, "value ± uncertainty" when the
// uncertainty is positive.
Cell numberCell(double value, int digits = 6, double uncertainty = 0.0, int uncertaintyDigits = 2);
Cell textCell(std::string text);

}  // namespace mozzi::core::report
