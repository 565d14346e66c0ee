#pragma once
// Core's gap diagnosis names its results with keys ("frf_residual",
// "predicted_hz", entry kinds "mode", "band", items "mode 2 (56.8 Hz)",
// effects "residual_mode"):
// the words the Model vs Test page shows for them, through tr(). A key the
// page does not know is shown as core wrote it.

#include <QCoreApplication>
#include <QString>
#include <string>

namespace mozzi {
namespace views {

class GapTerms {
  Q_DECLARE_TR_FUNCTIONS(GapTerms)

 public:
  // Title of the Where tab of one kind of entry: "Modes", "Bands", "DOFs", ...
  static QString kindTitle(const std::string& kind);
  // Column title of a residual or a detail: "FRF residual", "Predicted f [Hz]", ...
  static QString columnTitle(const std::string& key);
  // An entry's label: "mode 2 (56.8 Hz)" and "all" in the page's language.
  static QString itemLabel(const std::string& label);
  // An effect's name, the thing a candidate is called: "residual mode" for
  // "residual_mode" (core/gap/structural, fork, tire, stability).
  static QString effectTitle(const std::string& key);
};

}  // namespace views
}  // namespace mozzi
