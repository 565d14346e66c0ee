#pragma once
// Twist axes over the component (issue 22; thesis §1.2, §1.3, Figures 15 to
// 18, 20, 21 and 29): in the plane of the component, its approximate
// silhouette (resources/silhouettes), the constrained end, the load point, the
// laser points, the centre of gravity where the silhouette has one, the static
// twist axis of a stored static stiffness test and, for a stored sine sweep,
// the dynamic twist axis at the frequency the slider picks with the trace of
// its foot over all frequencies; the bending and torsion axes of the rig
// set-up where it names them. Each is labelled. A small table gives k_lat,
// k_tw, a_tw and the axis inclination with their uncertainties, static and at
// the chosen frequency.
//
// Besides the project's tests, plate CSVs as `mozzi-cli twist` reads them
// (TwistCsvImport, "Open CSV…"): static and dynamic files are listed with the
// tests; a modal file (hammer FRFs, §1.4) gives the bending and torsion modal
// twist axes (§1.7) drawn in place of the set-up's.
//
// The page computes nothing: it reads the tests through
// devices/rigtests/stiffness_results.h, places the silhouette, traces the
// path and clips the axes to the view with core/stiffness (silhouettes.h,
// twist_geometry.h) and draws on the project's plot adapter (InteractivePlot,
// equal aspect). Reading two tests is a few small queries: no worker thread.

#include <QString>
#include <QWidget>
#include <memory>
#include <optional>
#include <vector>

#include "views/common/page_registry.h"
#include "views/plots/marker_labels.h"

class QComboBox;
class QLabel;
class QSlider;
class QTableWidget;
class QwtPlotCurve;
class QwtPlotMarker;

namespace mozzi {
namespace views {

class InteractivePlot;
class PlateSketch;
class TwistCsvImport;
struct TwistAxesData;

class TwistAxesPage : public QWidget {
  Q_OBJECT
 public:
  explicit TwistAxesPage(const PageContext& ctx);
  ~TwistAxesPage() override;

  // Shows rig test `testId` (static or dynamic), its specimen, and the latest
  // test of the other kind on the same specimen.
  void showRigTest(qint64 testId);
  // Shows these tests (either may be absent; both of one specimen); false if
  // a test is not in the lists.
  bool selectTests(std::optional<qint64> staticTest, std::optional<qint64> dynamicTest);
  // Re-reads the project's rig tests (the lists), keeping the selection.
  void reload();

  // The controls and drawn items, for tests and the user guide's figures.
  QComboBox* specimenBox() const { return specimen_; }
  QComboBox* staticBox() const { return static_; }
  QComboBox* dynamicBox() const { return dynamic_; }
  QSlider* frequencySlider() const { return slider_; }
  InteractivePlot* plot() const { return plot_; }
  QTableWidget* resultsTable() const { return table_; }
  QwtPlotCurve* staticAxisCurve() const { return staticAxis_; }
  QwtPlotCurve* dynamicAxisCurve() const { return dynamicAxis_; }
  QwtPlotCurve* pathCurve() const { return path_; }
  QwtPlotCurve* bendingAxisCurve() const { return bendAxis_; }
  QwtPlotCurve* torsionAxisCurve() const { return torsAxis_; }
  // The imported CSV files ("Open CSV…").
  TwistCsvImport* csvImport() const { return import_; }
  // The frequency whose dynamic axis is drawn (none without a sweep).
  std::optional<double> shownFrequencyHz() const;
  // The silhouette's name and source ("" when none is drawn), the status line.
  QString silhouetteText() const;
  QString statusText() const;
  // Text of every label drawn on the plot (load point, axes, ...).
  QStringList plotLabels() const;

 signals:
  void message(const QString& text);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void buildUi();
  void retranslate();
  void fillSpecimens();
  void fillTests();
  void loadTests();
  void drawStatic();
  void drawFrequency();
  void clipAxes();
  void separateLabels(const std::vector<LabelChoice>& axisLabels);
  void fillTable();
  void setStatus(const QString& text, bool error = false);
  void addImportedTests();
  void showImported(int index);

 public:
  // Stores the imported static and dynamic tests shown as rig tests of the
  // chosen specimen (a new one when none is chosen) and shows them; false
  // with the reason in the status line when nothing could be stored.
  bool keepImported();

 private:
  QwtPlotMarker* label(const QString& text, const QColor& colour);

  ProjectModel* model_;
  std::unique_ptr<TwistAxesData> data_;

  QLabel* specimenLabel_ = nullptr;
  QLabel* staticLabel_ = nullptr;
  QLabel* dynamicLabel_ = nullptr;
  QLabel* frequencyLabel_ = nullptr;
  QLabel* frequencyValue_ = nullptr;
  QLabel* silhouetteNote_ = nullptr;
  QLabel* status_ = nullptr;
  QComboBox* specimen_ = nullptr;
  QComboBox* static_ = nullptr;
  QComboBox* dynamic_ = nullptr;
  QSlider* slider_ = nullptr;
  QTableWidget* table_ = nullptr;
  InteractivePlot* plot_ = nullptr;
  TwistCsvImport* import_ = nullptr;

  // Items rebuilt per selection; the axis lines are clipped to the view.
  std::unique_ptr<PlateSketch> sketch_;     // silhouette, plate, lasers, load point, constrained end
  std::vector<QwtPlotMarker*> markers_;     // the page's own labels (a_tw)
  std::vector<Qt::Alignment> markerAlign_;  // their labels' vertical alignment
  QwtPlotCurve* extent_ = nullptr;          // draws nothing: the points the view must hold
  QwtPlotCurve* staticAxis_ = nullptr;
  QwtPlotCurve* staticArm_ = nullptr;
  QwtPlotCurve* bendAxis_ = nullptr;
  QwtPlotCurve* torsAxis_ = nullptr;
  QwtPlotCurve* path_ = nullptr;
  QwtPlotCurve* dynamicAxis_ = nullptr;
  QwtPlotMarker* dynamicFoot_ = nullptr;
  QwtPlotMarker* staticAxisLabel_ = nullptr;
  QwtPlotMarker* dynamicAxisLabel_ = nullptr;
  QwtPlotMarker* bendLabel_ = nullptr;
  QwtPlotMarker* torsLabel_ = nullptr;
  bool filling_ = false;
  bool clipQueued_ = false;
};

}  // namespace views
}  // namespace mozzi
