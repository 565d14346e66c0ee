#include "views/gap/gap_terms.h"

#include <QRegularExpression>
#include <iterator>

namespace mozzi {
namespace views {

namespace {
// Core's key and the page's title for it (QT_TRANSLATE_NOOP: lupdate reads
// the titles, GapTerms::tr translates them when shown).
struct Term {
  const char* key;
  const char* title;
};

const Term kKinds[] = {
    {"mode", QT_TRANSLATE_NOOP("GapTerms", "Modes")},
    {"band", QT_TRANSLATE_NOOP("GapTerms", "Bands")},
    {"dof", QT_TRANSLATE_NOOP("GapTerms", "DOFs")},
    {"condition", QT_TRANSLATE_NOOP("GapTerms", "Conditions")},
    {"prediction", QT_TRANSLATE_NOOP("GapTerms", "Predictions")},
};

const Term kColumns[] = {
    {"frf_residual", QT_TRANSLATE_NOOP("GapTerms", "FRF residual")},
    {"mode_residual", QT_TRANSLATE_NOOP("GapTerms", "Mode residual")},
    {"predicted_hz", QT_TRANSLATE_NOOP("GapTerms", "Predicted f [Hz]")},
    {"measured_hz", QT_TRANSLATE_NOOP("GapTerms", "Measured f [Hz]")},
    {"predicted_zeta", QT_TRANSLATE_NOOP("GapTerms", "Predicted zeta")},
    {"measured_zeta", QT_TRANSLATE_NOOP("GapTerms", "Measured zeta")},
    {"frequency_error_pct", QT_TRANSLATE_NOOP("GapTerms", "f error [%]")},
    {"zeta_error_pct", QT_TRANSLATE_NOOP("GapTerms", "zeta error [%]")},
    {"frequency_z", QT_TRANSLATE_NOOP("GapTerms", "f z")},
    {"zeta_z", QT_TRANSLATE_NOOP("GapTerms", "zeta z")},
    {"mac", QT_TRANSLATE_NOOP("GapTerms", "MAC")},
    {"raw_residual", QT_TRANSLATE_NOOP("GapTerms", "RMS residual")},
    {"noise_floor", QT_TRANSLATE_NOOP("GapTerms", "Noise floor")},
    {"chi2_per_residual", QT_TRANSLATE_NOOP("GapTerms", "chi2 per residual")},
    {"lines", QT_TRANSLATE_NOOP("GapTerms", "Lines")},
    {"measured", QT_TRANSLATE_NOOP("GapTerms", "Measured")},
    {"predicted", QT_TRANSLATE_NOOP("GapTerms", "Predicted")},
    {"uncertainty", QT_TRANSLATE_NOOP("GapTerms", "Uncertainty")},
    {"found", QT_TRANSLATE_NOOP("GapTerms", "Found")},
    {"from_m_s", QT_TRANSLATE_NOOP("GapTerms", "From [m/s]")},
    {"to_m_s", QT_TRANSLATE_NOOP("GapTerms", "To [m/s]")},
};

// The effects of core's catalogues (docs/gap.md).
const Term kEffects[] = {
    // core/gap/structural (effectName)
    {"mass_loading", QT_TRANSLATE_NOOP("GapTerms", "mass loading")},
    {"boundary_stiffness", QT_TRANSLATE_NOOP("GapTerms", "boundary stiffness")},
    {"element_stiffness", QT_TRANSLATE_NOOP("GapTerms", "element stiffness")},
    {"residual_mode", QT_TRANSLATE_NOOP("GapTerms", "residual mode")},
    {"hysteretic_damping", QT_TRANSLATE_NOOP("GapTerms", "hysteretic damping")},
    {"exponential_window", QT_TRANSLATE_NOOP("GapTerms", "exponential window")},
    {"sensor_misalignment", QT_TRANSLATE_NOOP("GapTerms", "sensor misalignment")},
    // core/gap/fork (also boundary_stiffness above)
    {"stiffness_location", QT_TRANSLATE_NOOP("GapTerms", "stiffness location")},
    {"bending_stiffness", QT_TRANSLATE_NOOP("GapTerms", "bending stiffness")},
    {"inertia", QT_TRANSLATE_NOOP("GapTerms", "inertia")},
    {"residual_compliance", QT_TRANSLATE_NOOP("GapTerms", "residual compliance")},
    {"inertia_error", QT_TRANSLATE_NOOP("GapTerms", "inertia error")},
    // core/gap/tire
    {"belt_modes", QT_TRANSLATE_NOOP("GapTerms", "belt modes")},
    {"carcass_damping", QT_TRANSLATE_NOOP("GapTerms", "carcass damping")},
    {"trail_feedback", QT_TRANSLATE_NOOP("GapTerms", "trail feedback")},
    {"contact_patch_fraction", QT_TRANSLATE_NOOP("GapTerms", "contact patch fraction")},
    {"ring_pressure_stiffening", QT_TRANSLATE_NOOP("GapTerms", "ring pressure stiffening")},
    // core/gap/stability
    {"fork_bending", QT_TRANSLATE_NOOP("GapTerms", "fork bending")},
    {"fork_torsion", QT_TRANSLATE_NOOP("GapTerms", "fork torsion")},
    {"tyre_relaxation", QT_TRANSLATE_NOOP("GapTerms", "tyre relaxation")},
};

template <std::size_t N>
QString titleOf(const Term (&terms)[N], const std::string& key) {
  for (const Term& t : terms) {
    if (key == t.key) return GapTerms::tr(t.title);
  }
  return QString::fromStdString(key);
}
}  // namespace

QString GapTerms::kindTitle(const std::string& kind) {
  return titleOf(kKinds, kind);
}

QString GapTerms::columnTitle(const std::string& key) {
  return titleOf(kColumns, key);
}

QString GapTerms::effectTitle(const std::string& key) {
  return titleOf(kEffects, key);
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
