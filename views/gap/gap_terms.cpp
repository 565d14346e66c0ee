#include "views/gap/gap_terms.h"

#include <QRegularExpression>

namespace mozzi {
namespace views {

QString GapTerms::kindTitle(const std::string& kind) {
  if (kind == "mode") return tr("Modes");
  if (kind == "band") return tr("Bands");
  if (kind == "dof") return tr("DOFs");
  if (kind == "condition") return tr("Conditions");
  if (kind == "prediction") return tr("Predictions");
  return QString::fromStdString(kind);
}

QString GapTerms::columnTitle(const std::string& key) {
  if (key == "frf_residual") return tr("FRF residual");
  if (key == "mode_residual") return tr("Mode residual");
  if (key == "predicted_hz") return tr("Predicted f [Hz]");
  if (key == "measured_hz") return tr("Measured f [Hz]");
  if (key == "predicted_zeta") return tr("Predicted zeta");
  if (key == "measured_zeta") return tr("Measured zeta");
  if (key == "frequency_error_pct") return tr("f error [%]");
  if (key == "zeta_error_pct") return tr("zeta error [%]");
  if (key == "frequency_z") return tr("f z");
  if (key == "zeta_z") return tr("zeta z");
  if (key == "mac") return tr("MAC");
  if (key == "raw_residual") return tr("RMS residual");
  if (key == "noise_floor") return tr("Noise floor");
  if (key == "chi2_per_residual") return tr("chi2 per residual");
  if (key == "lines") return tr("Lines");
  if (key == "measured") return tr("Measured");
  if (key == "predicted") return tr("Predicted");
  if (key == "uncertainty") return tr("Uncertainty");
  if (key == "found") return tr("Found");
  if (key == "from_m_s") return tr("From [m/s]");
  if (key == "to_m_s") return tr("To [m/s]");
  return QString::fromStdString(key);
}

QString GapTerms::itemLabel(const std::string& label) {
  if (label == "all") return tr("all");
  // core/gap/structural: "mode N (F Hz)", "mode N (F Hz) unpaired"
  static const QRegularExpression mode(QStringLiteral("^mode (\\d+) \\(([^ ]+) Hz\\)( unpaired)?$"));
  const QString text = QString::fromStdString(label);
  const auto m = mode.match(text);
  if (!m.hasMatch()) return text;
  return m.captured(3).isEmpty() ? tr("mode %1 (%2 Hz)").arg(m.captured(1), m.captured(2))
                                 : tr("mode %1 (%2 Hz), unpaired").arg(m.captured(1), m.captured(2));
}

}  // namespace views
}  // namespace mozzi
