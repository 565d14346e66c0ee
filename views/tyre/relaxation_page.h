#pragma once
// The Tyre Relaxation page (issue 22; thesis §5.4, Figures 36 and 43): for a
// tyre specimen of the project, the relaxation length its stored relaxation
// tests measured against the yaw frequency (one series per inflation
// pressure, with the eq. 48 prediction at that pressure as a dashed line) and
// against pressure (the eq. 48 prediction at the Table 17 pressures as stacked
// bars of its contributions, contact patch, camber, lateral, C- and S-shaped
// modes, as in Figure 43, with the measured band means over them), and the
// rigid-ring modes (Table 16, eq. 45 to 47) in a table.
//
// Everything shown comes from core::tire::relaxationOverview, computed on the
// job runner from the observed project; "Keep in project" stores it as an
// analysis record (kind "relaxation-prediction") for the report and the CLI.

#include <QWidget>
#include <optional>

#include "core/tire/relaxation_overview.h"
#include "views/common/page_registry.h"

class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;
class QwtPlot;

namespace mozzi {
namespace views {

class RelaxationPage : public QWidget {
  Q_OBJECT
 public:
  explicit RelaxationPage(const PageContext& ctx);

  // Shows a tyre specimen (or the specimen of a tyre test); recomputes.
  void showSpecimen(qint64 specimenId);
  void showTyreTest(qint64 tyreTestId);
  // Stores the shown overview as an analysis; its id, or 0 (the status says why).
  qint64 keepInProject();

  // For tests and the log.
  const std::optional<core::tire::RelaxationOverview>& overview() const { return overview_; }
  qint64 specimenId() const;
  QString statusText() const;
  QwtPlot* frequencyPlot() const { return frequency_; }
  QwtPlot* pressurePlot() const { return pressure_; }
  QTableWidget* ringTable() const { return ring_; }

 signals:
  void finished(bool ok);
  void message(const QString& text);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void fillSpecimens();
  void recompute();
  void present(core::Result<core::tire::RelaxationOverview> result);
  void showOverview();
  void showProblem(const QString& text);
  void clearPlots();
  void drawFrequency();
  void drawPressure();
  void fillRingTable();
  void retranslate();

  ProjectModel* model_ = nullptr;
  JobRunner* jobs_ = nullptr;
  std::optional<core::tire::RelaxationOverview> overview_;
  QLabel* tyreLabel_ = nullptr;
  QComboBox* tyre_ = nullptr;
  QPushButton* keep_ = nullptr;
  QLabel* status_ = nullptr;
  QLabel* inputs_ = nullptr;
  QwtPlot* frequency_ = nullptr;
  QwtPlot* pressure_ = nullptr;
  QLabel* ringTitle_ = nullptr;
  QTableWidget* ring_ = nullptr;
  qint64 wanted_ = 0;  // the specimen asked for before the list holds it
};

}  // namespace views
}  // namespace mozzi
