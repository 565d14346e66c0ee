#pragma once
// Stiffness tables (issue 22; thesis Tables 3 to 5, 7, 9, 10, 13): every
// stored static stiffness-rig test of the project side by side, one column per
// specimen and constraint, the rows k_lat, a_tw, k_tw, the bending and
// torsion arms and stiffnesses and the twist axis inclination with their
// uncertainties; beside each measured column the thesis's values where the
// specimen is one of the thesis's (devices/sim/specimen_catalogue) and the
// difference in per cent. Copy or export as CSV.
//
// The page computes nothing: the columns come from
// devices/rigtests/stiffness_tables.h (the stored results, as the sequences
// wrote them). Reading them is a few small queries: no worker thread.

#include <QString>
#include <QWidget>
#include <vector>

#include "views/common/page_registry.h"

class QCheckBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace mozzi {
namespace devices::rigtests {
struct StiffnessColumn;
}
namespace views {

class StiffnessTablePage : public QWidget {
  Q_OBJECT
 public:
  explicit StiffnessTablePage(const PageContext& ctx);
  ~StiffnessTablePage() override;

  // Re-reads the project's static rig tests.
  void reload();
  // Selects rig test `testId`'s measured column (false when it is not shown:
  // a sine sweep, another project).
  bool showRigTest(qint64 testId);
  // Shows or hides the thesis's columns.
  void setThesisShown(bool shown);

  // The table as shown, as CSV (display units, full precision; one row per
  // quantity, per test the measured value, its uncertainty and the thesis's).
  QString csv() const;
  // Writes csv() to `path`; an empty string on success, else the reason.
  QString exportCsv(const QString& path) const;

  // For tests and the user guide. Each measured or thesis cell holds its SI
  // value in Qt::UserRole (and a measured cell its uncertainty in UserRole + 1).
  QTableWidget* table() const { return table_; }
  QCheckBox* thesisBox() const { return thesis_; }
  QString statusText() const;
  // The test shown in table column `column` (0 for a label or thesis column).
  qint64 testOfColumn(int column) const;

 signals:
  void message(const QString& text);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void buildUi();
  void retranslate();
  void fill();
  void copyCsv();
  void askExport();

  ProjectModel* model_ = nullptr;
  std::vector<devices::rigtests::StiffnessColumn> columns_;
  std::vector<std::string> skipped_;
  QString readError_;
  QTableWidget* table_ = nullptr;
  QCheckBox* thesis_ = nullptr;
  QPushButton* copy_ = nullptr;
  QPushButton* export_ = nullptr;
  QLabel* status_ = nullptr;
  QLabel* sources_ = nullptr;
};

}  // namespace views
}  // namespace mozzi
