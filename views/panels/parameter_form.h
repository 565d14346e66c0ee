#pragma once
// One form builder for every rig (STYLE 2, PulseView's pv/binding/device.cpp):
// widgets generated from a device's ParameterSpec list, so a new parameter in a
// driver appears in the GUI without GUI code. Bool -> check box; Integer ->
// spin box (a double spin box with no decimals when the range passes 32 bits);
// Real -> double spin box with the unit as suffix, the range, and decimals from
// the range and default; Choice -> combo box; Text -> line edit. Labels and
// help are translated in the context "Parameters" (parameter_texts.cpp lists
// them for lupdate); help is the tooltip. A value is checked with
// devices::validateParameter and a problem is shown under its field.

#include <QString>
#include <QWidget>
#include <map>
#include <string>
#include <vector>

#include "core/common/result.h"
#include "devices/common/parameters.h"

class QFormLayout;
class QLabel;

namespace mozzi {
namespace views {

class ParameterForm : public QWidget {
  Q_OBJECT
 public:
  explicit ParameterForm(QWidget* parent = nullptr);
  explicit ParameterForm(std::vector<devices::ParameterSpec> specs, QWidget* parent = nullptr);

  // Rebuilds the form; every field starts at its spec's default.
  void setSpecs(std::vector<devices::ParameterSpec> specs);
  const std::vector<devices::ParameterSpec>& specs() const { return specs_; }

  // Every parameter with the value shown (a complete map).
  devices::ParameterMap values() const;
  // Shows the given values (other fields keep theirs). A value the spec
  // refuses is brought to the nearest allowed one (a number clamped to the
  // range) and the reason shown by its field; unknown keys are ignored. The
  // first problem is returned, after every value was applied.
  core::Result<void> setValues(const devices::ParameterMap& values);
  void resetToDefaults();

  // The field editing `key` (QCheckBox, QSpinBox, QDoubleSpinBox, QComboBox or
  // QLineEdit), nullptr if none.
  QWidget* editor(const std::string& key) const;
  // The problem shown next to `key`'s field (empty when the value is fine).
  QString problem(const std::string& key) const;
  bool hasProblems() const;

 signals:
  // The user (or setValues/resetToDefaults, once) changed a value.
  void valuesChanged();

 protected:
  void changeEvent(QEvent* event) override;

 private:
  struct Field {
    QLabel* label = nullptr;
    QWidget* editor = nullptr;
    QLabel* problem = nullptr;
  };
  QWidget* makeEditor(const devices::ParameterSpec& spec);
  devices::ParameterValue read(size_t index) const;
  void write(size_t index, const devices::ParameterValue& value);
  void check(size_t index);
  void showProblem(size_t index, const QString& text);
  void retranslate();

  std::vector<devices::ParameterSpec> specs_;
  std::vector<Field> fields_;
  QFormLayout* layout_ = nullptr;
  bool applying_ = false;
};

// The number of decimals a Real field shows (2..9): two significant places
// past the smallest non-zero magnitude among its bounds and default, and at
// least a thousandth of a bounded range.
int parameterDecimals(const devices::ParameterSpec& spec);

}  // namespace views
}  // namespace mozzi
