#include "views/panels/parameter_form.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>
#include <QVBoxLayout>
#include <algorithm>
#include <climits>
#include <cmath>

namespace mozzi {
namespace views {

namespace {

// Bounds of a field without declared bounds.
constexpr double kUnboundedReal = 1.0e12;

const char* const kContext = "Parameters";

QString translated(const std::string& text) {
  return text.empty() ? QString() : QCoreApplication::translate(kContext, text.c_str());
}

double asReal(const devices::ParameterValue& v, double fallback) {
  if (std::holds_alternative<double>(v)) return std::get<double>(v);
  if (std::holds_alternative<std::int64_t>(v)) return static_cast<double>(std::get<std::int64_t>(v));
  return fallback;
}

QString number(double v) {
  return QString::number(v, 'g', 8);
}

}  // namespace

int parameterDecimals(const devices::ParameterSpec& spec) {
  // Significant places after the leading digit of a magnitude: 0.05 -> 2 + 2 = 4.
  const auto decimalsFor = [](double magnitude, int extra) {
    return static_cast<int>(std::ceil(-std::log10(magnitude))) + extra;
  };
  int decimals = 2;
  double smallest = 0.0;
  for (double v : {spec.min.value_or(0.0), spec.max.value_or(0.0), asReal(spec.defaultValue, 0.0)}) {
    v = std::abs(v);
    if (v > 0.0 && (smallest == 0.0 || v < smallest)) smallest = v;
  }
  if (smallest > 0.0) decimals = std::max(decimals, decimalsFor(smallest, 2));
  // A bounded range is resolved to a thousandth (a probability in [0, 1]: 3 decimals).
  if (spec.min && spec.max && *spec.max > *spec.min) {
    decimals = std::max(decimals, decimalsFor((*spec.max - *spec.min) / 100.0, 1));
  }
  return std::clamp(decimals, 2, 9);
}

ParameterForm::ParameterForm(QWidget* parent) : QWidget(parent) {
  layout_ = new QFormLayout(this);
  layout_->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
}

ParameterForm::ParameterForm(std::vector<devices::ParameterSpec> specs, QWidget* parent) : ParameterForm(parent) {
  setSpecs(std::move(specs));
}

void ParameterForm::setSpecs(std::vector<devices::ParameterSpec> specs) {
  while (layout_->rowCount() > 0) layout_->removeRow(0);
  fields_.clear();
  specs_ = std::move(specs);
  for (size_t i = 0; i < specs_.size(); ++i) {
    const auto& spec = specs_[i];
    Field field;
    auto* cell = new QWidget(this);
    auto* cellLayout = new QVBoxLayout(cell);
    cellLayout->setContentsMargins(0, 0, 0, 0);
    cellLayout->setSpacing(2);
    field.editor = makeEditor(spec);
    field.editor->setParent(cell);
    // One width for every field, so the column reads as one.
    if (spec.type != devices::ParameterType::Bool) field.editor->setMinimumWidth(fontMetrics().averageCharWidth() * 24);
    field.editor->setObjectName(QString::fromStdString(spec.key));
    field.problem = new QLabel(cell);
    field.problem->setObjectName(QString::fromStdString(spec.key) + QStringLiteral(".problem"));
    field.problem->setWordWrap(false);  // a wrapped label gets clipped in a form row
    QPalette palette = field.problem->palette();
    palette.setColor(QPalette::WindowText, QColor(200, 30, 45));
    field.problem->setPalette(palette);
    field.problem->hide();
    // Text grows with the form (names, serials, DOF lists read whole); numbers
    // and choices keep the one width.
    if (spec.type == devices::ParameterType::Text) {
      cellLayout->addWidget(field.editor);
    } else {
      cellLayout->addWidget(field.editor, 0, Qt::AlignLeft);
    }
    cellLayout->addWidget(field.problem);
    field.label = new QLabel(this);
    field.label->setBuddy(field.editor);
    layout_->addRow(field.label, cell);
    fields_.push_back(field);
  }
  retranslate();
  resetToDefaults();
}

QWidget* ParameterForm::makeEditor(const devices::ParameterSpec& spec) {
  const size_t index = fields_.size();
  auto edited = [this, index] {
    if (applying_) return;
    showProblem(index, QString());
    check(index);
    emit valuesChanged();
  };
  switch (spec.type) {
    case devices::ParameterType::Bool: {
      auto* box = new QCheckBox;
      connect(box, &QCheckBox::toggled, this, edited);
      return box;
    }
    case devices::ParameterType::Integer: {
      const double lo = spec.min.value_or(double(INT_MIN));
      const double hi = spec.max.value_or(double(INT_MAX));
      if (lo < double(INT_MIN) || hi > double(INT_MAX)) {
        // Wider than a QSpinBox (a 32-bit seed): whole numbers in a double box, exact below 2^53.
        auto* box = new QDoubleSpinBox;
        box->setDecimals(0);
        box->setRange(std::ceil(lo), std::floor(hi));
        if (!spec.unit.empty()) box->setSuffix(QLatin1Char(' ') + QString::fromStdString(spec.unit));
        connect(box, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, edited);
        return box;
      }
      auto* box = new QSpinBox;
      box->setRange(static_cast<int>(std::ceil(lo)), static_cast<int>(std::floor(hi)));
      if (!spec.unit.empty()) box->setSuffix(QLatin1Char(' ') + QString::fromStdString(spec.unit));
      connect(box, QOverload<int>::of(&QSpinBox::valueChanged), this, edited);
      return box;
    }
    case devices::ParameterType::Real: {
      auto* box = new QDoubleSpinBox;
      const int decimals = parameterDecimals(spec);
      box->setDecimals(decimals);  // before the range, which it rounds
      const double lo = spec.min.value_or(-kUnboundedReal);
      const double hi = spec.max.value_or(kUnboundedReal);
      box->setRange(lo, hi);
      // A step of about a hundredth of a bounded range, never below the last decimal shown.
      double step = std::pow(10.0, -decimals + 1);
      if (spec.min && spec.max && hi > lo)
        step = std::max(step, std::pow(10.0, std::floor(std::log10((hi - lo) / 100.0))));
      box->setSingleStep(step);
      if (!spec.unit.empty()) box->setSuffix(QLatin1Char(' ') + QString::fromStdString(spec.unit));
      connect(box, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, edited);
      return box;
    }
    case devices::ParameterType::Choice: {
      auto* box = new QComboBox;
      for (const auto& choice : spec.choices)
        box->addItem(QString::fromStdString(choice), QString::fromStdString(choice));
      connect(box, QOverload<int>::of(&QComboBox::currentIndexChanged), this, edited);
      return box;
    }
    case devices::ParameterType::Text: {
      auto* edit = new QLineEdit;
      connect(edit, &QLineEdit::textChanged, this, edited);
      return edit;
    }
  }
  return new QWidget;
}

devices::ParameterValue ParameterForm::read(size_t index) const {
  const auto& spec = specs_[index];
  QWidget* w = fields_[index].editor;
  switch (spec.type) {
    case devices::ParameterType::Bool: return static_cast<QCheckBox*>(w)->isChecked();
    case devices::ParameterType::Integer:
      if (auto* wide = qobject_cast<QDoubleSpinBox*>(w)) return static_cast<std::int64_t>(std::llround(wide->value()));
      return static_cast<std::int64_t>(static_cast<QSpinBox*>(w)->value());
    case devices::ParameterType::Real: return static_cast<QDoubleSpinBox*>(w)->value();
    case devices::ParameterType::Choice: return static_cast<QComboBox*>(w)->currentData().toString().toStdString();
    case devices::ParameterType::Text: return static_cast<QLineEdit*>(w)->text().toStdString();
  }
  return std::string();
}

void ParameterForm::write(size_t index, const devices::ParameterValue& value) {
  const auto& spec = specs_[index];
  QWidget* w = fields_[index].editor;
  switch (spec.type) {
    case devices::ParameterType::Bool:
      if (std::holds_alternative<bool>(value)) static_cast<QCheckBox*>(w)->setChecked(std::get<bool>(value));
      break;
    case devices::ParameterType::Integer: {
      if (auto* wide = qobject_cast<QDoubleSpinBox*>(w)) {
        const double v = asReal(value, wide->value());
        if (std::isfinite(v)) wide->setValue(std::round(v));
        break;
      }
      auto* box = static_cast<QSpinBox*>(w);
      const double v = std::clamp(asReal(value, box->value()), double(box->minimum()), double(box->maximum()));
      box->setValue(static_cast<int>(std::llround(v)));
      break;
    }
    case devices::ParameterType::Real: {
      auto* box = static_cast<QDoubleSpinBox*>(w);
      const double v = asReal(value, box->value());
      if (std::isfinite(v)) box->setValue(v);  // QDoubleSpinBox clamps to its range
      break;
    }
    case devices::ParameterType::Choice: {
      auto* box = static_cast<QComboBox*>(w);
      if (std::holds_alternative<std::string>(value)) {
        const int at = box->findData(QString::fromStdString(std::get<std::string>(value)));
        if (at >= 0) box->setCurrentIndex(at);
      }
      break;
    }
    case devices::ParameterType::Text:
      if (std::holds_alternative<std::string>(value))
        static_cast<QLineEdit*>(w)->setText(QString::fromStdString(std::get<std::string>(value)));
      break;
  }
}

devices::ParameterMap ParameterForm::values() const {
  devices::ParameterMap map;
  for (size_t i = 0; i < specs_.size(); ++i) map[specs_[i].key] = read(i);
  return map;
}

core::Result<void> ParameterForm::setValues(const devices::ParameterMap& values) {
  std::optional<core::Error> first;
  applying_ = true;
  for (size_t i = 0; i < specs_.size(); ++i) {
    const auto it = values.find(specs_[i].key);
    if (it == values.end()) continue;
    showProblem(i, QString());
    auto valid = devices::validateParameter(specs_[i], it->second);
    write(i, it->second);
    if (!valid) {
      const auto& spec = specs_[i];
      const double given = asReal(it->second, std::nan(""));
      const bool numeric = spec.type == devices::ParameterType::Real || spec.type == devices::ParameterType::Integer;
      const bool outOfRange =
          numeric && std::isfinite(given) && ((spec.min && given < *spec.min) || (spec.max && given > *spec.max));
      if (outOfRange) {
        const QString unit = QString::fromStdString(spec.unit);
        showProblem(i, tr("%1 %2 is outside %3 to %4 %2; %5 is used")
                           .arg(number(given), unit, number(spec.min.value_or(-kUnboundedReal)),
                                number(spec.max.value_or(kUnboundedReal)), number(asReal(read(i), 0.0))));
      } else {
        showProblem(i, tr("Not accepted: %1").arg(QString::fromStdString(valid.error().message)));
      }
      if (!first) first = valid.error();
    }
  }
  applying_ = false;
  emit valuesChanged();
  if (first) return *first;
  return {};
}

void ParameterForm::resetToDefaults() {
  applying_ = true;
  for (size_t i = 0; i < specs_.size(); ++i) {
    write(i, specs_[i].defaultValue);
    showProblem(i, QString());
  }
  applying_ = false;
  emit valuesChanged();
}

QWidget* ParameterForm::editor(const std::string& key) const {
  for (size_t i = 0; i < specs_.size(); ++i) {
    if (specs_[i].key == key) return fields_[i].editor;
  }
  return nullptr;
}

QString ParameterForm::problem(const std::string& key) const {
  for (size_t i = 0; i < specs_.size(); ++i) {
    if (specs_[i].key == key) return fields_[i].problem->text();
  }
  return {};
}

bool ParameterForm::hasProblems() const {
  return std::any_of(fields_.begin(), fields_.end(), [](const Field& f) { return !f.problem->text().isEmpty(); });
}

void ParameterForm::check(size_t index) {
  auto valid = devices::validateParameter(specs_[index], read(index));
  if (!valid) showProblem(index, tr("Not accepted: %1").arg(QString::fromStdString(valid.error().message)));
}

void ParameterForm::showProblem(size_t index, const QString& text) {
  QLabel* label = fields_[index].problem;
  label->setText(text);
  label->setVisible(!text.isEmpty());
}

void ParameterForm::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

void ParameterForm::retranslate() {
  for (size_t i = 0; i < specs_.size(); ++i) {
    const auto& spec = specs_[i];
    fields_[i].label->setText(translated(spec.label.empty() ? spec.key : spec.label));
    const QString help = translated(spec.help);
    fields_[i].editor->setToolTip(help);
    fields_[i].label->setToolTip(help);
  }
}

}  // namespace views
}  // namespace mozzi
