#include "views/scene/twist_csv_import.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>
#include <cmath>
#include <tuple>

#include "devices/rigtests/imported_twist.h"

namespace mozzi {
namespace views {

namespace st = core::stiffness;
namespace rt = devices::rigtests;

namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

QString qs(const std::string& s) {
  return QString::fromStdString(s);
}

}  // namespace

TwistCsvImport::TwistCsvImport(QWidget* parent) : QGroupBox(parent) {
  auto* layout = new QVBoxLayout(this);
  auto* row = new QHBoxLayout;
  open_ = new QPushButton;
  open_->setObjectName(QStringLiteral("openCsv"));
  kind_ = new QComboBox;
  kind_->setObjectName(QStringLiteral("csvKind"));
  kindLabel_ = new QLabel;
  row->addWidget(open_);
  row->addWidget(kindLabel_);
  row->addWidget(kind_, 1);
  layout->addLayout(row);
  keep_ = new QPushButton;
  keep_->setObjectName(QStringLiteral("keepImported"));
  keep_->setEnabled(false);
  layout->addWidget(keep_);
  connect(keep_, &QPushButton::clicked, this, &TwistCsvImport::keepRequested);

  // The modal file's controls, shown once a modal file is open.
  modalBox_ = new QWidget;
  auto* form = new QFormLayout(modalBox_);
  form->setContentsMargins(0, 0, 0, 0);
  type_ = new QComboBox;
  type_->setObjectName(QStringLiteral("frfType"));
  typeLabel_ = new QLabel;
  form->addRow(typeLabel_, type_);
  auto spin = [](const char* name) {
    auto* s = new QDoubleSpinBox;
    s->setObjectName(QLatin1String(name));
    s->setDecimals(2);
    s->setSuffix(QStringLiteral(" Hz"));
    s->setRange(0.0, 1e5);
    s->setEnabled(false);
    s->setKeyboardTracking(false);
    return s;
  };
  bendingHz_ = spin("bendingHz");
  torsionHz_ = spin("torsionHz");
  bendingLabel_ = new QLabel;
  torsionLabel_ = new QLabel;
  form->addRow(bendingLabel_, bendingHz_);
  form->addRow(torsionLabel_, torsionHz_);
  layout->addWidget(modalBox_);
  modalBox_->hide();
  modalInfo_ = new QLabel;
  modalInfo_->setObjectName(QStringLiteral("modalInfo"));
  modalInfo_->setWordWrap(true);
  modalInfo_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(modalInfo_);
  error_ = new QLabel;
  error_->setObjectName(QStringLiteral("importError"));
  error_->setWordWrap(true);
  error_->setStyleSheet(QStringLiteral("color: #b00000;"));
  error_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  error_->hide();
  layout->addWidget(error_);

  for (int i = 0; i < 4; ++i) kind_->addItem(QString());
  for (int i = 0; i < 3; ++i) type_->addItem(QString());
  type_->setCurrentIndex(static_cast<int>(core::FrfType::Accelerance));  // as `twist modal` without --type
  retranslate();

  connect(open_, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open a twist CSV"), QString(),
                                                      tr("CSV files (*.csv *.txt);;All files (*)"));
    if (path.isEmpty()) return;
    std::optional<st::PlateCsvKind> kind;
    if (kind_->currentIndex() > 0) kind = static_cast<st::PlateCsvKind>(kind_->currentIndex() - 1);
    openFile(path, kind);
  });
  for (QDoubleSpinBox* s : {bendingHz_, torsionHz_})
    connect(s, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this] {
      if (filling_) return;
      computeModal();
      emit modalChanged();
    });
  connect(type_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] {
    if (filling_ || modalIndex_ < 0) return;
    File& f = files_[static_cast<std::size_t>(modalIndex_)];
    auto frf = st::modalFrfFromCsv(f.csv, static_cast<core::FrfType>(type_->currentIndex()));
    if (frf) f.frf = std::move(frf).value();
    guessModes();  // the peaks of the summed FRFs move with the type
  });
}

void TwistCsvImport::retranslate() {
  filling_ = true;
  setTitle(tr("Plate CSV files"));
  open_->setText(tr("Open CSV…"));
  open_->setToolTip(tr("Read a plate CSV as mozzi-cli twist static, dynamic or modal reads it"));
  kindLabel_->setText(tr("as"));
  keep_->setText(tr("Keep imported tests in the project"));
  keep_->setToolTip(
      tr("Store the imported static and dynamic tests shown as rig tests of the specimen (a new "
         "specimen when none is chosen)"));
  const QString kinds[] = {tr("kind from the columns"), tr("static (force, displacements)"),
                           tr("dynamic (amplitude, phase)"), tr("modal (FRF Re, Im)")};
  for (int i = 0; i < 4; ++i) kind_->setItemText(i, kinds[i]);
  typeLabel_->setText(tr("Modal FRFs are"));
  // Index order of core::FrfType: receptance, mobility, accelerance.
  const QString types[] = {tr("receptance"), tr("mobility"), tr("accelerance")};
  for (int i = 0; i < 3; ++i) type_->setItemText(i, types[i]);
  bendingLabel_->setText(tr("Bending mode"));
  torsionLabel_->setText(tr("Torsion mode"));
  bendingHz_->setToolTip(tr("Frequency of the bending mode: the modal twist axis there is drawn (§1.4, §1.7)"));
  torsionHz_->setToolTip(tr("Frequency of the torsion mode: the modal twist axis there is drawn (§1.4, §1.7)"));
  filling_ = false;
  modalInfo_->setText(modalText());
  modalInfo_->setVisible(!modalInfo_->text().isEmpty());
}

void TwistCsvImport::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QGroupBox::changeEvent(event);
}

const TwistCsvImport::File* TwistCsvImport::file(int index) const {
  if (index < 0 || index >= static_cast<int>(files_.size())) return nullptr;
  return &files_[static_cast<std::size_t>(index)];
}

void TwistCsvImport::showError(const QString& text) {
  error_->setText(text);
  error_->setVisible(!text.isEmpty());
  if (!text.isEmpty()) emit message(text);
}

QString TwistCsvImport::errorText() const {
  return error_->text();
}

std::optional<QString> TwistCsvImport::openFile(const QString& path, std::optional<st::PlateCsvKind> kind) {
  auto fail = [&](const core::Error& e) -> std::optional<QString> {
    const QString text = tr("Cannot import %1: %2").arg(QFileInfo(path).fileName(), qs(e.describe()));
    showError(text);
    return text;
  };
  auto csv = st::readPlateCsv(path.toStdString(), true);
  if (!csv) return fail(csv.error());
  if (!kind) {
    auto guessed = st::guessPlateCsvKind(*csv);
    if (!guessed) return fail(guessed.error());
    kind = *guessed;
  }
  File f;
  f.path = path;
  f.name = QFileInfo(path).fileName();
  f.kind = *kind;
  std::string note;
  if (*kind == st::PlateCsvKind::Static) {
    auto v = rt::staticViewFromCsv(*csv, f.name.toStdString());
    if (!v) return fail(v.error());
    f.view = std::move(v).value();
  } else if (*kind == st::PlateCsvKind::Dynamic) {
    auto v = rt::dynamicViewFromCsv(*csv, f.name.toStdString(), &note);
    if (!v) return fail(v.error());
    f.view = std::move(v).value();
  } else {
    auto frf = st::modalFrfFromCsv(*csv, static_cast<core::FrfType>(type_->currentIndex()));
    if (!frf) return fail(frf.error());
    f.frf = std::move(frf).value();
  }
  f.csv = std::move(csv).value();
  int index = -1;
  for (std::size_t i = 0; i < files_.size(); ++i)
    if (files_[i].path == path && files_[i].kind == f.kind) index = static_cast<int>(i);
  if (index < 0) {
    files_.push_back(std::move(f));
    index = static_cast<int>(files_.size()) - 1;
  } else {
    files_[static_cast<std::size_t>(index)] = std::move(f);
  }
  for (const auto& file : files_) keep_->setEnabled(keep_->isEnabled() || file.view.has_value());
  showError(note.empty() ? QString() : tr("Some frequencies of %1 give no axis: %2").arg(path, qs(note)));
  if (*kind == st::PlateCsvKind::Modal) {
    modalIndex_ = index;
    modalBox_->show();
    guessModes();
  }
  emit imported(index);
  return std::nullopt;
}

// The bending and torsion frequencies at the two highest peaks of the modal
// file's summed FRFs (the band's ends when it has fewer).
void TwistCsvImport::guessModes() {
  const File* m = file(modalIndex_);
  if (!m || !m->frf) return;
  const double lo = m->frf->frequencyHz(0), hi = m->frf->frequencyHz(m->frf->lineCount() - 1);
  std::vector<double> peaks = st::frfPeakFrequencies(*m->frf, 2);
  while (peaks.size() < 2) peaks.push_back(peaks.empty() ? lo : hi);
  filling_ = true;
  for (QDoubleSpinBox* s : {bendingHz_, torsionHz_}) {
    s->setRange(lo, hi);
    s->setEnabled(true);
  }
  filling_ = false;
  setModeFrequencies(peaks[0], peaks[1]);
}

void TwistCsvImport::setModeFrequencies(double bendingHz, double torsionHz) {
  filling_ = true;
  bendingHz_->setValue(bendingHz);
  torsionHz_->setValue(torsionHz);
  filling_ = false;
  computeModal();
  emit modalChanged();
}

void TwistCsvImport::computeModal() {
  modal_ = ModalAxes{};
  const File* f = file(modalIndex_);
  if (f && f->frf) {
    modal_.file = f;
    std::vector<int> cols;
    for (std::size_t i = 0; i < f->csv.sensors.size(); ++i) cols.push_back(static_cast<int>(i));
    QStringList problems;
    const core::Vector2 load = f->csv.hasLoad ? f->csv.load : core::Vector2::Zero();
    for (auto [spin, into, what] : {std::tuple<QDoubleSpinBox*, std::optional<st::ModalAxis>*, QString>{
                                        bendingHz_, &modal_.bending, tr("bending")},
                                    {torsionHz_, &modal_.torsion, tr("torsion")}}) {
      auto r = st::modalTwistAxis(*f->frf, cols, 0, spin->value(), f->csv.sensors, load);
      if (r)
        *into = std::move(r).value();
      else
        problems << tr("no %1 axis at %2 Hz: %3").arg(what).arg(spin->value(), 0, 'f', 2).arg(qs(r.error().message));
    }
    modal_.problems = problems.join(QStringLiteral("; "));
  }
  modalInfo_->setText(modalText());
  modalInfo_->setVisible(!modalInfo_->text().isEmpty());
}

QString TwistCsvImport::modalText() const {
  if (!modal_.file) return QString();
  QStringList lines;
  lines << tr("Modal FRFs: %1").arg(modal_.file->name);
  for (auto [axis, what] : {std::pair<const std::optional<st::ModalAxis>*, QString>{&modal_.bending, tr("bending")},
                            {&modal_.torsion, tr("torsion")}}) {
    if (!*axis) continue;
    const auto& a = (*axis)->axis.axis.axis;
    lines << tr("%1 at %2 Hz (%3): β %4 ± %5°, foot (%6, %7) m")
                 .arg(what)
                 .arg((*axis)->frequencyHz, 0, 'f', 2)
                 .arg(qs(st::phasorAxisCaseName((*axis)->axis.method)))
                 .arg(a.beta * kDeg, 0, 'f', 2)
                 .arg(a.betaSigma * kDeg, 0, 'g', 2)
                 .arg(a.point(0), 0, 'f', 4)
                 .arg(a.point(1), 0, 'f', 4);
  }
  if (!modal_.problems.isEmpty()) lines << modal_.problems;
  return lines.join(QLatin1Char('\n'));
}

}  // namespace views
}  // namespace mozzi
