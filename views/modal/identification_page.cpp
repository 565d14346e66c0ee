#include "views/modal/identification_page.h"

#include <qwt_plot_curve.h>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollBar>
#include <QSpinBox>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <ctime>

#include "core/io/project_store.h"
#include "core/modal/mode_merging.h"
#include "core/modal/shape_tools.h"
#include "devices/campaign/frf_set_window.h"
#include "views/common/dof_text.h"
#include "views/common/job_runner.h"
#include "views/common/project_model.h"
#include "views/plots/decimating_curve.h"
#include "views/plots/interactive_plot.h"
#include "views/plots/mac_plot.h"
#include "views/plots/stabilization_plot.h"

namespace mozzi {
namespace views {

namespace md = core::modal;
using identification::Method;

namespace {

// Tabs of the right-hand side.
constexpr int kSynthesisTab = 0;
constexpr int kMacTab = 1;

// CPU time of the calling thread [ms].
double threadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

}  // namespace

QTableWidgetItem* IdentificationPage::cell(const QString& text) {
  auto* item = new QTableWidgetItem(text);
  item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
  item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
  return item;
}

IdentificationPage::IdentificationPage(const PageContext& ctx) : QWidget(ctx.parent) {
  model_ = ctx.model;
  jobs_ = ctx.jobs;
  log_ = ctx.log;
  auto* layout = new QVBoxLayout(this);
  auto* bar = new QHBoxLayout;
  setLabel_ = new QLabel(this);
  setBox_ = new QComboBox(this);
  setBox_->setObjectName(QStringLiteral("identificationFrfSet"));
  setBox_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  setBox_->setMinimumContentsLength(14);
  bandLabel_ = new QLabel(this);
  lowBox_ = new QDoubleSpinBox(this);
  lowBox_->setObjectName(QStringLiteral("identificationBandLow"));
  highBox_ = new QDoubleSpinBox(this);
  highBox_->setObjectName(QStringLiteral("identificationBandHigh"));
  for (QDoubleSpinBox* b : {lowBox_, highBox_}) {
    b->setRange(0.0, 1e6);
    b->setDecimals(2);
    b->setSuffix(QStringLiteral(" Hz"));
  }
  methodLabel_ = new QLabel(this);
  methodBox_ = new QComboBox(this);
  methodBox_->setObjectName(QStringLiteral("identificationMethod"));
  for (int i = 0; i < 4; ++i) methodBox_->addItem(QString());
  orderLabel_ = new QLabel(this);
  orderBox_ = new QSpinBox(this);
  orderBox_->setObjectName(QStringLiteral("identificationMaxOrder"));
  orderBox_->setRange(8, 400);  // the CLI's --max-order range
  orderBox_->setValue(60);
  backdropLabel_ = new QLabel(this);
  backdropBox_ = new QComboBox(this);
  backdropBox_->setObjectName(QStringLiteral("identificationBackdrop"));
  backdropBox_->addItem(QString());
  backdropBox_->addItem(QString());
  refineBox_ = new QCheckBox(this);
  refineBox_->setObjectName(QStringLiteral("identificationRefine"));
  refineBox_->setChecked(true);
  runButton_ = new QPushButton(this);
  runButton_->setObjectName(QStringLiteral("identificationRun"));
  cancelButton_ = new QPushButton(this);
  cancelButton_->setObjectName(QStringLiteral("identificationCancel"));
  cancelButton_->setEnabled(false);
  progress_ = new QProgressBar(this);
  progress_->setRange(0, 1000);
  progress_->setMaximumWidth(200);
  // Two rows, so that the page fits 1280 pixels at any scale: what is
  // identified (set, band), then how (method, order, backdrop) and the run.
  for (QWidget* w : std::initializer_list<QWidget*>{setLabel_, setBox_, bandLabel_, lowBox_, highBox_})
    bar->addWidget(w);
  bar->setStretchFactor(setBox_, 1);
  auto* bar2 = new QHBoxLayout;
  for (QWidget* w : std::initializer_list<QWidget*>{methodLabel_, methodBox_, orderLabel_, orderBox_, backdropLabel_,
                                                    backdropBox_, refineBox_, runButton_, cancelButton_, progress_})
    bar2->addWidget(w);
  bar2->addStretch(1);
  layout->addLayout(bar);
  layout->addLayout(bar2);
  status_ = new QLabel(this);
  status_->setObjectName(QStringLiteral("identificationStatus"));
  status_->setWordWrap(true);
  warning_ = new QLabel(this);
  warning_->setObjectName(QStringLiteral("identificationWarning"));
  warning_->setWordWrap(true);
  warning_->setStyleSheet(QStringLiteral("QLabel { color: #9a3c00; font-weight: bold; }"));
  warning_->hide();
  layout->addWidget(status_);
  layout->addWidget(warning_);

  auto* split = new QSplitter(Qt::Horizontal, this);
  auto* left = new QSplitter(Qt::Vertical, split);
  diagram_ = new StabilizationPlot(left);
  diagram_->setObjectName(QStringLiteral("identificationDiagram"));
  auto* tablePane = new QWidget(left);
  auto* tableLayout = new QVBoxLayout(tablePane);
  tableLayout->setContentsMargins(0, 0, 0, 0);
  table_ = new QTableWidget(0, 9, tablePane);
  table_->setObjectName(QStringLiteral("identificationModalTable"));
  table_->verticalHeader()->setVisible(false);
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  tableLayout->addWidget(table_);
  auto* buttons = new QHBoxLayout;
  autoButton_ = new QPushButton(tablePane);
  autoButton_->setObjectName(QStringLiteral("identificationAutomatic"));
  nameEdit_ = new QLineEdit(tablePane);
  nameEdit_->setObjectName(QStringLiteral("identificationName"));
  saveButton_ = new QPushButton(tablePane);
  saveButton_->setObjectName(QStringLiteral("identificationSave"));
  buttons->addWidget(autoButton_);
  buttons->addStretch(1);
  buttons->addWidget(nameEdit_, 2);
  buttons->addWidget(saveButton_);
  tableLayout->addLayout(buttons);
  // Small minimum sizes: the splitters share what the window has (1280x800 at
  // scale 1 and 2), the user drags them.
  diagram_->setMinimumSize(200, 160);
  // The table shows three modes at least (header, rows, the scroll bar under them).
  table_->setMinimumHeight(table_->horizontalHeader()->sizeHint().height() +
                           3 * table_->verticalHeader()->defaultSectionSize() +
                           table_->horizontalScrollBar()->sizeHint().height() + 2 * table_->frameWidth());
  left->addWidget(diagram_);
  left->addWidget(tablePane);
  left->setStretchFactor(0, 3);
  left->setStretchFactor(1, 2);

  tabs_ = new QTabWidget(split);
  auto* synthPane = new QWidget(tabs_);
  auto* synthLayout = new QVBoxLayout(synthPane);
  synthesisFrfBox_ = new QComboBox(synthPane);
  synthesisFrfBox_->setObjectName(QStringLiteral("identificationSynthesisFrf"));
  synthesis_ = new InteractivePlot(synthPane);
  synthesis_->setObjectName(QStringLiteral("identificationSynthesis"));
  residuals_ = new QTableWidget(0, 4, synthPane);
  residuals_->setObjectName(QStringLiteral("identificationResiduals"));
  residuals_->verticalHeader()->setVisible(false);
  residuals_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
  residuals_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
  residuals_->horizontalHeader()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
  residuals_->horizontalHeader()->setStretchLastSection(true);
  residuals_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  synthesis_->setMinimumSize(160, 120);
  residuals_->setMinimumHeight(60);
  synthLayout->addWidget(synthesisFrfBox_);
  synthLayout->addWidget(synthesis_, 3);
  synthLayout->addWidget(residuals_, 1);
  auto* macPane = new QWidget(tabs_);
  auto* macLayout = new QVBoxLayout(macPane);
  autoMacLabel_ = new QLabel(macPane);
  autoMac_ = new MacPlot(macPane);
  autoMac_->setObjectName(QStringLiteral("identificationAutoMac"));
  macLabel_ = new QLabel(macPane);
  mac_ = new MacPlot(macPane);
  mac_->setObjectName(QStringLiteral("identificationMac"));
  autoMac_->setMinimumSize(120, 100);
  mac_->setMinimumSize(120, 100);
  macLayout->addWidget(autoMacLabel_);
  macLayout->addWidget(autoMac_, 1);
  macLayout->addWidget(macLabel_);
  macLayout->addWidget(mac_, 1);
  tabs_->insertTab(kSynthesisTab, synthPane, QString());
  tabs_->insertTab(kMacTab, macPane, QString());
  split->addWidget(left);
  split->addWidget(tabs_);
  split->setStretchFactor(0, 3);
  split->setStretchFactor(1, 2);
  layout->addWidget(split, 1);

  connect(runButton_, &QPushButton::clicked, this, &IdentificationPage::run);
  connect(cancelButton_, &QPushButton::clicked, this, &IdentificationPage::cancel);
  connect(autoButton_, &QPushButton::clicked, this, &IdentificationPage::resetSelection);
  connect(saveButton_, &QPushButton::clicked, this, [this] { save(nameEdit_->text()); });
  connect(diagram_, &StabilizationPlot::poleClicked, this, &IdentificationPage::togglePole);
  connect(setBox_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int i) {
    if (i >= 0) setFrfSet(setBox_->itemData(i).toLongLong());
  });
  connect(synthesisFrfBox_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] { showSynthesis(); });
  // Before a run the backdrop follows the choice at once.
  connect(backdropBox_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] { changeBackdrop(); });
  connect(tabs_, &QTabWidget::currentChanged, this, [this] { showTabs(); });
  connect(model_, &ProjectModel::frfSetsChanged, this, &IdentificationPage::reloadSets);
  connect(model_, &ProjectModel::projectChanged, this, &IdentificationPage::reloadSets);
  retranslate();
  reloadSets();
  if (ctx.item.kind == RecordKind::FrfSet) setFrfSet(ctx.item.id);
}

IdentificationPage::~IdentificationPage() = default;

void IdentificationPage::reloadSets() {
  const QSignalBlocker block(setBox_);
  setBox_->clear();
  core::io::ProjectStore* store = model_->store();
  if (!store) return;
  auto sets = store->frfSets();
  if (!sets) {
    setStatus(tr("Cannot list the FRF sets: %1").arg(QString::fromStdString(sets.error().describe())), true);
    return;
  }
  for (const auto& s : *sets) {
    setBox_->addItem(tr("%1 (id %2, %3 x %4 FRFs)")
                         .arg(QString::fromStdString(s.name))
                         .arg(s.id)
                         .arg(s.responseCount)
                         .arg(s.referenceCount),
                     QVariant::fromValue<qlonglong>(s.id));
  }
  const int i = setBox_->findData(QVariant::fromValue<qlonglong>(frfSetId_));
  if (i >= 0) setBox_->setCurrentIndex(i);
}

bool IdentificationPage::setFrfSet(qint64 id) {
  core::io::ProjectStore* store = model_->store();
  if (!store) return false;
  auto frf = model_->frfSet(id);
  if (!frf) {
    setStatus(tr("Cannot read FRF set %1: %2").arg(id).arg(QString::fromStdString(frf.error().describe())), true);
    return false;
  }
  if ((*frf)->lineCount() < 2 || (*frf)->referenceCount() < 1) {
    setStatus(tr("FRF set %1 holds no FRF to identify").arg(id), true);
    return false;
  }
  auto tau = devices::campaign::frfSetExponentialTauS(*store, id);
  if (!tau) {
    setStatus(
        tr("Cannot read the windows of FRF set %1: %2").arg(id).arg(QString::fromStdString(tau.error().describe())),
        true);
    return false;
  }
  windowTauS_ = *tau;
  specimenId_ = 0;
  if (auto sets = store->frfSets()) {
    for (const auto& s : *sets) {
      if (s.id == id) specimenId_ = s.specimenId;
    }
  }
  const bool same = id == frfSetId_;
  frfSetId_ = id;
  frf_ = std::move(frf).value();
  fitter_.reset();  // over the set it replaces
  {
    const QSignalBlocker block(setBox_);
    const int i = setBox_->findData(QVariant::fromValue<qlonglong>(id));
    if (i >= 0) setBox_->setCurrentIndex(i);
  }
  if (!same) {
    cancelKeptDiagram();
    // The whole set as the band until the user narrows it (0 Hz excluded: no
    // mode there), or the kept identification's band.
    const double f0 = frf_->frequencyHz[0] > 0.0 ? frf_->frequencyHz[0] : frf_->frequencyHz[1];
    setBand(f0, frf_->frequencyHz[frf_->lineCount() - 1]);
    outcome_.reset();
    chosen_.clear();
    automatic_.clear();
    fit_.reset();
    kept_.reset();
    selectionIsKept_ = false;
    showBackdrop();
    loadKept();
    updateSaveButton();
    if (kept_) {
      setBand(kept_->info.bandLowHz, kept_->info.bandHighHz);
      diagram_->setAxisScale(QwtPlot::xBottom, kept_->info.bandLowHz, kept_->info.bandHighHz);
      diagram_->replot();
      // Once the page is drawn: on two cores the job slowed the opening by
      // 10-15 ms (57-66 ms against 36-51 without it on the demo).
      QTimer::singleShot(150, this, [this] { drawDiagramBehindKept(); });
    }
  }
  const QSignalBlocker block(synthesisFrfBox_);
  synthesisFrfBox_->clear();
  for (const auto& ref : frf_->references) {
    for (const auto& rsp : frf_->responses) synthesisFrfBox_->addItem(tr("H %1 / %2").arg(dofText(rsp), dofText(ref)));
  }
  // The synthesis starts on the strongest FRF (a DOF no mode moves gives a
  // zero FRF, nothing to compare).
  int strongest = 0;
  double best = -1.0;
  for (std::size_t i = 0; i < frf_->h.size(); ++i) {
    for (Eigen::Index o = 0; o < frf_->responseCount(); ++o) {
      const double n = frf_->h[i].col(o).squaredNorm();
      if (n > best) {
        best = n;
        strongest = static_cast<int>(static_cast<Eigen::Index>(i) * frf_->responseCount() + o);
      }
    }
  }
  synthesisFrfBox_->setCurrentIndex(strongest);
  QString text = tr("FRF set %1: %2 responses x %3 references, %4 lines, %5 to %6 Hz. Choose a band and run.")
                     .arg(id)
                     .arg(frf_->responseCount())
                     .arg(frf_->referenceCount())
                     .arg(frf_->lineCount())
                     .arg(frf_->frequencyHz[0])
                     .arg(frf_->frequencyHz[frf_->lineCount() - 1]);
  if (windowTauS_ > 0.0)
    text += QLatin1Char(' ') + tr("Measured with an exponential window (tau = %1 s): its damping is removed from the "
                                  "modes.")
                                   .arg(windowTauS_);
  if (kept_) {
    text += QLatin1Char(' ') +
            tr("Shown: the kept identification '%1' (%2, %3 .. %4 Hz), %n mode(s) and their "
               "synthesis; Run identifies again.",
               nullptr, static_cast<int>(kept_->table.modes.size()))
                .arg(QString::fromStdString(kept_->info.name), QString::fromStdString(kept_->info.method))
                .arg(kept_->info.bandLowHz, 0, 'f', 1)
                .arg(kept_->info.bandHighHz, 0, 'f', 1);
  }
  setStatus(text, false);
  updateSelection();
  return true;
}

void IdentificationPage::setBand(double lo, double hi) {
  lowBox_->setValue(lo);
  highBox_->setValue(hi);
}

void IdentificationPage::setMethod(Method m) {
  methodBox_->setCurrentIndex(static_cast<int>(m));
}

void IdentificationPage::setMaxOrder(int order) {
  orderBox_->setValue(order);
}

void IdentificationPage::setBackdrop(identification::Backdrop b) {
  backdropBox_->setCurrentIndex(static_cast<int>(b));
}

void IdentificationPage::setRefine(bool on) {
  refineBox_->setChecked(on);
}

bool IdentificationPage::isRunning() const {
  return jobId_ != 0 && jobs_->isRunning(jobId_);
}

void IdentificationPage::run() {
  if (!frf_ || isRunning()) return;
  cancelKeptDiagram();  // the run replaces what it would draw
  identification::Options opt;
  opt.method = static_cast<Method>(methodBox_->currentIndex());
  opt.bandLowHz = lowBox_->value();
  opt.bandHighHz = highBox_->value();
  opt.maxOrder = orderBox_->value();
  opt.backdrop = static_cast<identification::Backdrop>(backdropBox_->currentIndex());
  opt.refine = refineBox_->isChecked();
  auto frf = frf_;
  runButton_->setEnabled(false);
  cancelButton_->setEnabled(true);
  progress_->setValue(0);
  setStatus(tr("Identifying %1 .. %2 Hz ...").arg(opt.bandLowHz).arg(opt.bandHighHz), false);
  jobId_ = jobs_->run<identification::Outcome>(
      this, tr("Identification"), [frf, opt](JobProgress& p) { return identification::identify(*frf, opt, p); },
      [this](core::Result<identification::Outcome> r) { onFinished(std::move(r)); },
      [this](double f, const QString& step) {
        progress_->setValue(static_cast<int>(f * 1000));
        if (!step.isEmpty()) setStatus(tr("Identifying: %1").arg(step), false);
      });
}

void IdentificationPage::cancel() {
  if (jobId_) jobs_->cancel(jobId_);
  cancelKeptDiagram();
}

void IdentificationPage::onFinished(core::Result<identification::Outcome> result) {
  QElapsedTimer timer;
  timer.start();
  const double cpu0 = threadCpuMs();
  jobId_ = 0;
  runButton_->setEnabled(true);
  cancelButton_->setEnabled(false);
  if (!result) {
    progress_->setValue(0);
    const bool cancelled = result.error().code == core::ErrorCode::Cancelled;
    setStatus(cancelled ? tr("Identification cancelled.")
                        : tr("Identification failed: %1").arg(QString::fromStdString(result.error().describe())),
              !cancelled);
    emit finished(false);
    return;
  }
  progress_->setValue(1000);
  outcome_ = std::move(result).value();
  kept_.reset();    // the run replaces the kept identification
  fitter_.reset();  // the band may have changed
  showOutcomeDiagram();
  takeAutomaticSelection();
  chosen_ = automatic_;
  selectionIsAutomatic_ = true;
  selectionIsKept_ = false;
  updateSelection();
  diagram_->repaint();  // drawn now, not at the next event loop turn
  diagramMs_ = static_cast<double>(timer.nsecsElapsed()) * 1e-6;
  diagramCpuMs_ = threadCpuMs() - cpu0;
  QString status = tr("%n mode(s) selected automatically in %1 .. %2 Hz; click a pole to add or remove it.", nullptr,
                      static_cast<int>(automatic_.size()))
                       .arg(outcome_->options.bandLowHz)
                       .arg(outcome_->options.bandHighHz);
  if (outcome_->refined && outcome_->refinedLines < outcome_->bandLines) {  // as the CLI says it
    status += QLatin1Char(' ') + tr("Refined on %L1 of %L2 band lines: those carrying the modes.")
                                     .arg(static_cast<qlonglong>(outcome_->refinedLines))
                                     .arg(static_cast<qlonglong>(outcome_->bandLines));
  }
  setStatus(status, false);
  if (log_)
    log_(tr("Identification of FRF set %1: %n mode(s)", nullptr, static_cast<int>(automatic_.size())).arg(frfSetId_));
  emit finished(true);
}

std::vector<core::Complex> IdentificationPage::chosenPoles() const {
  std::vector<core::Complex> out;
  for (const auto& c : chosen_) out.push_back(c.pole);
  return out;
}

void IdentificationPage::togglePole(int index) {
  if (!outcome_ || !outcome_->diagram || index < 0 || index >= static_cast<int>(outcome_->diagram->poles.size()))
    return;
  QElapsedTimer timer;
  timer.start();
  const double cpu0 = threadCpuMs();
  bool removed = false;
  for (std::size_t i = 0; i < chosen_.size(); ++i) {
    if (chosen_[i].diagramIndex == index) {
      chosen_.erase(chosen_.begin() + static_cast<std::ptrdiff_t>(i));
      removed = true;
      break;
    }
  }
  if (!removed) {
    const auto& p = outcome_->diagram->poles[static_cast<std::size_t>(index)];
    chosen_.push_back(Chosen{p.pole, p.shape, index});
  }
  selectionIsAutomatic_ = false;
  selectionIsKept_ = false;
  updateSelection();
  table_->repaint();
  synthesis_->repaint();
  diagram_->repaint();
  selectionMs_ = static_cast<double>(timer.nsecsElapsed()) * 1e-6;
  selectionCpuMs_ = threadCpuMs() - cpu0;
}

void IdentificationPage::resetSelection() {
  if (!outcome_) return;
  chosen_ = automatic_;
  selectionIsAutomatic_ = true;
  selectionIsKept_ = false;
  updateSelection();
}

void IdentificationPage::updateSelection() {
  // Modes in frequency order.
  std::sort(chosen_.begin(), chosen_.end(),
            [](const Chosen& a, const Chosen& b) { return std::abs(a.pole) < std::abs(b.pole); });
  std::vector<int> indices;
  std::vector<double> freqs;
  std::vector<md::ModeCandidate> cand;
  for (const auto& c : chosen_) {
    indices.push_back(c.diagramIndex);
    freqs.push_back(md::poleFrequencyHz(c.pole));
    cand.push_back({md::poleFrequencyHz(c.pole), c.shape});
  }
  diagram_->setSelection(indices, freqs);
  warnings_.clear();
  if (outcome_ && outcome_->diagram) {
    warnings_ = md::selectionWarnings(cand, md::sameModeCriteria(identification::estimatorOptions(outcome_->options),
                                                                 outcome_->diagram->resolutionHz));
  }
  fit_.reset();
  const auto band = selectionBand();
  if (frf_ && band && !chosen_.empty()) {
    if (outcome_ && selectionIsAutomatic_ && !outcome_->diagram) {
      // Single-mode methods: the model is the estimate (no LSFD).
      identification::Fit fit;
      fit.model = outcome_->model;
      fit_ = fit;
    } else {
      if (!fitter_) {
        auto fitter = identification::SelectionFitter::create(frf_, band->first, band->second);
        if (fitter) {
          fitter_ = std::move(fitter).value();
        } else {
          setStatus(tr("The chosen poles cannot be fitted: %1").arg(QString::fromStdString(fitter.error().describe())),
                    true);
        }
      }
      if (fitter_) {
        auto fit = fitter_->fit(chosenPoles());
        if (fit) {
          fit_ = std::move(fit).value();
        } else {
          setStatus(tr("The chosen poles cannot be fitted: %1").arg(QString::fromStdString(fit.error().describe())),
                    true);
        }
      }
    }
  }
  QStringList lines;
  for (const auto& w : warnings_)
    lines << tr("Warning: %1. Remove one of the two.").arg(QString::fromStdString(w.text));
  warning_->setText(lines.join(QLatin1Char('\n')));
  warning_->setVisible(!lines.isEmpty());
  showTable();
  synthesisStale_ = macStale_ = true;
  showTabs();
  emit selectionChanged();
  updateSaveButton();
}

void IdentificationPage::showTable() {
  rows_.clear();
  if (fit_) {
    // The automatic selection shows the refined model with its standard
    // errors (the CLI's numbers); a hand-made or kept one its LSFD fit, the
    // kept one with the standard errors it was kept with.
    const bool automatic = outcome_ && selectionIsAutomatic_ && (outcome_->refined || !outcome_->diagram);
    const md::ModalModel& m = automatic ? outcome_->model : fit_->model;
    auto rows = automatic ? md::modalTableRows(m, outcome_->frequencyStdHz, outcome_->zetaStd) : md::modalTableRows(m);
    if (rows) rows_ = std::move(rows).value();
    if (auto c = md::removeExponentialWindow(rows_, windowTauS_); !c) {
      setStatus(
          tr("Cannot remove the exponential window's damping: %1").arg(QString::fromStdString(c.error().describe())),
          true);
    }
    if (!automatic && kept_ && selectionIsKept_ && kept_->table.modes.size() == rows_.size()) {
      for (std::size_t r = 0; r < rows_.size(); ++r) {
        const core::io::StoredMode& kept = kept_->table.modes[r];
        // The fit keeps the kept poles: the same f, but to rounding (the window's decay put back and removed).
        if (std::abs(kept.frequencyHz - rows_[r].frequencyHz) > 1e-9 * kept.frequencyHz) continue;
        rows_[r].frequencyStdHz = kept.frequencyStdHz;
        rows_[r].zetaStd = kept.dampingRatioStd;
        if (kept.dampingRatioStd) rows_[r].etaStd = 2.0 * *kept.dampingRatioStd;
      }
    }
  }
  table_->setRowCount(static_cast<int>(rows_.size()));
  auto opt = [](const std::optional<double>& v, int digits) {
    return v ? QString::number(*v, 'g', digits) : QStringLiteral("-");
  };
  for (int r = 0; r < static_cast<int>(rows_.size()); ++r) {
    const auto& row = rows_[static_cast<std::size_t>(r)];
    table_->setItem(r, 0, cell(QString::number(r + 1)));
    table_->setItem(r, 1, cell(QString::number(row.frequencyHz, 'f', 4)));
    table_->setItem(r, 2, cell(opt(row.frequencyStdHz, 3)));
    table_->setItem(r, 3, cell(QString::number(row.zeta, 'g', 4)));
    table_->setItem(r, 4, cell(opt(row.zetaStd, 3)));
    table_->setItem(r, 5, cell(QString::number(row.eta, 'g', 4)));
    table_->setItem(r, 6, cell(QString::number(row.mpc, 'f', 4)));
    table_->setItem(r, 7, cell(QString::number(row.mpdDegrees, 'f', 2)));
    table_->setItem(r, 8, cell(QString::number(row.complexity, 'f', 4)));
  }
}

void IdentificationPage::showTabs() {
  if (tabs_->currentIndex() == kSynthesisTab && synthesisStale_) showSynthesis();
  if (tabs_->currentIndex() == kMacTab && macStale_) showMac();
}

void IdentificationPage::showMac() {
  macStale_ = false;
  const md::ModalModel* m =
      fit_ ? (selectionIsAutomatic_ && outcome_ && outcome_->refined ? &outcome_->model : &fit_->model) : nullptr;
  if (!m || m->modes.empty()) {
    autoMac_->setMatrix(core::Matrix(), {}, {});
    mac_->setMatrix(core::Matrix(), {}, {});
    return;
  }
  auto measured = md::measuredShapes(*m);
  if (!measured) return;
  const md::ShapeSet* shapes = &measured->set;
  QStringList labels;
  for (const auto& md : m->modes) labels << tr("%1 Hz").arg(md.frequencyHz(), 0, 'f', 1);
  autoMac_->setMatrix(md::macMatrix(shapes->shapes, shapes->shapes), labels, labels);
  // Against the automatic selection's refined shapes.
  if (outcome_ && !outcome_->model.modes.empty()) {
    auto ref = md::measuredShapes(outcome_->model);
    if (ref) {
      QStringList refLabels;
      for (const auto& md : outcome_->model.modes) refLabels << tr("%1 Hz").arg(md.frequencyHz(), 0, 'f', 1);
      mac_->setMatrix(md::macMatrix(shapes->shapes, ref->set.shapes), labels, refLabels);
    }
  }
}

void IdentificationPage::save(const QString& name) {
  if (!outcome_ || !fit_ || chosen_.empty() || !model_->store()) {
    emit saveFailed(tr("Nothing to save: run the identification and choose at least one pole."));
    return;
  }
  // The CLI's name unless the user gave one (made unique as the CLI makes it).
  QString title = name;
  if (title.isEmpty()) {
    std::string base = md::defaultModalResultName(identification::methodKey(outcome_->options.method),
                                                  outcome_->options.bandLowHz, outcome_->options.bandHighHz);
    if (auto existing = model_->store()->modalResults()) base = md::uniqueModalResultName(*existing, specimenId_, base);
    title = QString::fromStdString(base);
  }
  if ((selectionIsAutomatic_ && outcome_->refined) || !outcome_->diagram) {
    storeModel(outcome_->model, title, outcome_->frequencyStdHz, outcome_->zetaStd);  // refined: the CLI's numbers
    return;
  }
  // A hand-made selection is refined as the CLI refines the automatic one.
  auto frf = frf_;
  const md::ModalModel start = fit_->model;
  const double lo = outcome_->options.bandLowHz, hi = outcome_->options.bandHighHz;
  setStatus(tr("Refining the selection before saving ..."), false);
  saveButton_->setEnabled(false);  // one save at a time
  jobId_ = jobs_->run<md::RefineResult>(
      this, tr("Refine and save"),
      [frf, start, lo, hi](JobProgress& p) { return identification::refine(*frf, start, lo, hi, p); },
      [this, title](core::Result<md::RefineResult> r) {
        jobId_ = 0;
        if (!r) {
          const QString why =
              tr("Refinement failed, nothing saved: %1").arg(QString::fromStdString(r.error().describe()));
          setStatus(why, true);
          updateSaveButton();
          emit saveFailed(why);
          return;
        }
        storeModel(r->model, title, r->frequencyStdHz, r->zetaStd);
      });
}

void IdentificationPage::storeModel(const md::ModalModel& model, const QString& name,
                                    const std::vector<double>& frequencyStdHz, const std::vector<double>& zetaStd) {
  auto table = md::modalTableOf(model, frequencyStdHz, zetaStd);
  if (table) {  // the table's numbers: the window's decay removed, as the CLI stores them
    if (auto c = md::removeExponentialWindow(*table, windowTauS_); !c) table = c.error();
  }
  if (!table) {
    const QString why = tr("Cannot store the modes: %1").arg(QString::fromStdString(table.error().describe()));
    setStatus(why, true);
    updateSaveButton();
    emit saveFailed(why);
    return;
  }
  core::io::ModalResultInfo info;
  info.specimenId = specimenId_;
  info.frfSetId = frfSetId_;
  info.name = name.toStdString();
  info.method = identification::storedMethodName(outcome_->options.method);
  info.bandLowHz = outcome_->options.bandLowHz;
  info.bandHighHz = outcome_->options.bandHighHz;
  auto id = model_->addModalResult(info, *table);
  if (!id) {
    const QString why = tr("Cannot store the modes: %1").arg(QString::fromStdString(id.error().describe()));
    setStatus(why, true);
    updateSaveButton();
    emit saveFailed(why);
    return;
  }
  setStatus(tr("Saved %n mode(s) as modal result %1.", nullptr, static_cast<int>(table->modes.size())).arg(*id), false);
  if (log_) log_(tr("Modal result %1 saved from FRF set %2").arg(*id).arg(frfSetId_));
  selectionIsKept_ = true;  // saved: a second click would store a copy
  updateSaveButton();
  emit saved(*id);
}

void IdentificationPage::setStatus(const QString& text, bool error) {
  status_->setText(text);
  status_->setStyleSheet(error ? QStringLiteral("QLabel { color: #b00020; }") : QString());
}

QString IdentificationPage::statusText() const {
  return status_->text();
}

QString IdentificationPage::warningText() const {
  return warning_->isHidden() ? QString() : warning_->text();
}

void IdentificationPage::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

void IdentificationPage::retranslate() {
  setLabel_->setText(tr("FRF set"));
  bandLabel_->setText(tr("Band"));
  lowBox_->setToolTip(tr("Lowest frequency of the band"));
  highBox_->setToolTip(tr("Highest frequency of the band"));
  methodLabel_->setText(tr("Method"));
  methodBox_->setItemText(0, tr("pLSCF (PolyMAX)"));
  methodBox_->setItemText(1, tr("LSCE"));
  methodBox_->setItemText(2, tr("Peak picking"));
  methodBox_->setItemText(3, tr("Circle fit"));
  orderLabel_->setText(tr("Max order"));
  backdropLabel_->setText(tr("Over"));
  backdropBox_->setItemText(0, tr("Sum"));
  backdropBox_->setItemText(1, tr("CMIF"));
  backdropBox_->setToolTip(tr("What the stabilization diagram is drawn over"));
  refineBox_->setText(tr("Refine"));
  refineBox_->setToolTip(
      tr("Refine frequencies, damping and residues together after the automatic selection "
         "(standard errors; as mozzi-cli identify)"));
  runButton_->setText(tr("Run"));
  cancelButton_->setText(tr("Cancel"));
  autoButton_->setText(tr("Automatic selection"));
  autoButton_->setToolTip(tr("Back to the poles the automatic selection chose"));
  nameEdit_->setPlaceholderText(tr("Name of the modal result"));
  saveButton_->setText(tr("Save modes"));
  updateSaveButton();
  table_->setHorizontalHeaderLabels({tr("Mode"), tr("f [Hz]"), tr("std f [Hz]"), tr("zeta"), tr("std zeta"), tr("eta"),
                                     tr("MPC"), tr("MPD [deg]"), tr("Complexity")});
  residuals_->setHorizontalHeaderLabels({tr("FRF"), tr("Residual [%]"), tr("Level [dB]"), tr("Misfit [dB]")});
  residuals_->horizontalHeaderItem(1)->setToolTip(tr("RMS of H - synthesis over the band against the FRF's own RMS"));
  residuals_->horizontalHeaderItem(2)->setToolTip(
      tr("RMS of the FRF over the band against the strongest FRF's (0 dB): a high residual far down is noise"));
  residuals_->horizontalHeaderItem(3)->setToolTip(
      tr("RMS of H - synthesis against the strongest FRF's RMS (level + 20 log10 residual); the list is sorted by "
         "it, worst first"));
  tabs_->setTabText(0, tr("Synthesis"));
  tabs_->setTabText(1, tr("MAC"));
  autoMacLabel_->setText(tr("AutoMAC of the chosen modes"));
  macLabel_->setText(tr("MAC: chosen modes (rows) against the automatic selection (columns)"));
  synthesis_->setAxisTitle(QwtPlot::xBottom, tr("Frequency [Hz]"));
  synthesis_->setAxisTitle(QwtPlot::yLeft, tr("|H| [dB]"));
}

}  // namespace views
}  // namespace mozzi
