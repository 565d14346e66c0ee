#pragma once
// Private to the rig test page (rig_test_page.cpp, rig_test_setup.cpp,
// rig_test_run.cpp, rig_test_plots.cpp): the hand-over buffer between the
// sequence's thread and the GUI thread, and the small helpers the four files
// share. Not included elsewhere.

#include <qwt_plot.h>
#include <QColor>
#include <QPointF>
#include <QString>
#include <QVector>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/common/result.h"
#include "devices/rigtests/rig_sequence.h"

class QwtPlotCurve;
class QWidget;

namespace mozzi {
namespace core::io {
class ProjectStore;
}  // namespace core::io
namespace devices {
class Device;
}  // namespace devices

namespace views {

class JobProgress;

namespace rt = devices::rigtests;

// What the sequence's thread hands to the GUI thread (rig_test_page.h).
struct RigHandOver {
  std::mutex mutex;
  std::vector<rt::LiveReadout> live;
  // Step reports and log lines in the order they came (the log view shows both).
  std::vector<std::variant<rt::StepReport, std::string>> events;
  std::optional<rt::Progress> progress;
  std::optional<rt::Outcome> outcome;  // kept even when the job ends cancelled
  bool specimenAdded = false;
  rt::CancelFlag cancel;
};

namespace rig_page {

constexpr double kPi = 3.14159265358979323846;
constexpr int kRedrawMs = 40;              // 25 Hz
constexpr double kPlotRateHz = 250.0;      // live curves keep at most this many points per second
constexpr double kTyreTimeWindowS = 10.0;  // seconds of the tyre tester's time traces shown
constexpr double kSineTimeWindowS = 2.0;   // seconds of the stiffness rig's sine traces shown
// Widths at 1280x800 with the project dock open (about 950 pixels for the
// page): the controls at least 34 characters wide, at first as wide as
// their form needs (at most 58); a
// plot at least 200 x 200 pixels (three side by side in a sine sweep).
constexpr int kControlsMinChars = 34;
constexpr int kControlsMaxChars = 58;
constexpr int kPlotMinWidth = 200;
constexpr int kPlotMinHeight = 200;

inline QString qs(const std::string& s) {
  return QString::fromStdString(s);
}

// Runs one sequence on a simulated rig: resolves the specimen (adds it to the
// project when it is not there), creates the device, follows the sequence
// with the hand-over buffer. Worker thread.
using SequenceRun = std::function<core::Result<rt::Outcome>(devices::Device&, const rt::StoreTarget&,
                                                            const rt::Callbacks&, const rt::CancelFlag*)>;

core::Result<rt::Outcome> runOnSimulatedRig(JobProgress& progress, RigHandOver& handOver,
                                            const std::shared_ptr<core::io::ProjectStore>& store,
                                            const std::string& specimenKey, bool tyre, const SequenceRun& run);

// Angles in degrees, everything else as stored (SI).
struct Shown {
  double value, uncertainty;
  QString unit;
};
inline Shown shown(double value, double uncertainty, const std::string& unit) {
  if (unit == "rad") return {value * 180.0 / kPi, uncertainty * 180.0 / kPi, QStringLiteral("deg")};
  if (unit == "rad/s") return {value * 180.0 / kPi, uncertainty * 180.0 / kPi, QStringLiteral("deg/s")};
  if (unit == "m") return {value * 1e3, uncertainty * 1e3, QStringLiteral("mm")};
  return {value, uncertainty, qs(unit)};
}

inline QString number(double v) {
  return QString::number(v, 'g', 5);
}

// A result key in words (the sequences' keys, devices/rigtests).
QString resultLabel(const std::string& key);

QwtPlotCurve* addCurve(QwtPlot* plot, const QColor& colour, int yAxis = QwtPlot::yLeft);
// An axis title in the page's font, on one line for a vertical axis: Qwt's
// default (larger, bold, wrapped at word breaks) split a unit over lines and,
// at scale 2, laid the wrapped title over the tick labels.
void setAxisText(QwtPlot* plot, int axis, const QString& text);
QwtPlot* makePlot(QWidget* parent);

inline void trimFront(QVector<QPointF>& v, double fromX) {
  int n = 0;
  while (n < v.size() && v[n].x() < fromX) ++n;
  if (n > 0) v.remove(0, n);
}

}  // namespace rig_page
}  // namespace views
}  // namespace mozzi
