#pragma once
// The Twist Axes page's imported files: plate CSVs as `mozzi-cli twist
// static|dynamic|modal` reads them (core/stiffness/plate_csv.h, one parser for
// both; docs/cli/stiffness.md). "Open CSV…" reads a file of the chosen kind
// (or the kind its columns and header tell); a static or dynamic file becomes
// a test the page lists beside the project's rig tests (devices/rigtests/
// imported_twist.h); a modal file (hammer FRFs of the plate's accelerometers,
// thesis §1.4) gives the modal twist axes at the bending and torsion modes
// (§1.7), at frequencies the user sets, first guessed from the two highest
// peaks of the summed FRFs (again when the FRF type is changed). Imported files stay for the page's life; "Keep in
// project" asks the page to store the imported tests it shows as rig tests.

#include <QGroupBox>
#include <QString>
#include <optional>
#include <vector>

#include "core/common/frf_matrix.h"
#include "core/stiffness/dynamic_twist.h"
#include "core/stiffness/plate_csv.h"
#include "devices/rigtests/stiffness_results.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace mozzi {
namespace views {

class TwistCsvImport : public QGroupBox {
  Q_OBJECT
 public:
  struct File {
    QString path;
    QString name;  // the file name, as listed
    core::stiffness::PlateCsvKind kind = core::stiffness::PlateCsvKind::Static;
    std::optional<devices::rigtests::StiffnessTestView> view;  // static and dynamic files
    core::stiffness::PlateCsv csv;
    std::optional<core::FrfMatrix> frf;  // modal files
  };
  // The modal axes of the modal file shown, at the two mode frequencies.
  struct ModalAxes {
    const File* file = nullptr;
    std::optional<core::stiffness::ModalAxis> bending, torsion;
    QString problems;  // why an axis is missing (translated), empty when both are there
  };

  explicit TwistCsvImport(QWidget* parent = nullptr);

  // Reads `path` as `kind` (none: as its columns and header tell). On success
  // the file is added (a file already open is read again) and imported()
  // emitted with its index; on failure the error (naming file and line) is
  // shown, emitted by message() and returned.
  std::optional<QString> openFile(const QString& path,
                                  std::optional<core::stiffness::PlateCsvKind> kind = std::nullopt);
  const std::vector<File>& files() const { return files_; }
  const File* file(int index) const;

  // The modal file shown (the last opened) and its axes at the spin boxes' frequencies.
  const ModalAxes& modalAxes() const { return modal_; }
  // Sets the bending and torsion frequencies [Hz] of the modal axes.
  void setModeFrequencies(double bendingHz, double torsionHz);
  QDoubleSpinBox* bendingSpin() const { return bendingHz_; }
  QDoubleSpinBox* torsionSpin() const { return torsionHz_; }
  QComboBox* kindBox() const { return kind_; }
  QComboBox* typeBox() const { return type_; }
  QPushButton* keepButton() const { return keep_; }
  QString modalText() const;
  QString errorText() const;

 signals:
  void imported(int index);
  void modalChanged();
  // "Keep in project" was pressed (the page stores the imported tests it shows).
  void keepRequested();
  void message(const QString& text);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void computeModal();
  void guessModes();
  void showError(const QString& text);

  std::vector<File> files_;
  int modalIndex_ = -1;
  ModalAxes modal_;
  QPushButton* open_ = nullptr;
  QPushButton* keep_ = nullptr;
  QComboBox* kind_ = nullptr;
  QComboBox* type_ = nullptr;
  QLabel* kindLabel_ = nullptr;
  QLabel* typeLabel_ = nullptr;
  QLabel* bendingLabel_ = nullptr;
  QLabel* torsionLabel_ = nullptr;
  QDoubleSpinBox* bendingHz_ = nullptr;
  QDoubleSpinBox* torsionHz_ = nullptr;
  QWidget* modalBox_ = nullptr;
  QLabel* modalInfo_ = nullptr;
  QLabel* error_ = nullptr;
  bool filling_ = false;
};

}  // namespace views
}  // namespace mozzi
