// GCC 12 reports std::variant members of a moved Result<Diagnosis> as "maybe
// uninitialized" where JobRunner hands the result over (a known false positive
// of its variant analysis at -O3); the other warnings stay errors.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "views/gap/model_test_view.h"

#include <qwt_legend.h>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_renderer.h>
#include <qwt_symbol.h>
#include <QBuffer>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPixmap>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

#include "core/common/text.h"
#include "core/gap/diagnosis_json.h"
#include "core/gap/problem_loader.h"
#include "core/report/gap_report.h"
#include "core/report/report_html.h"
#include "views/common/job_runner.h"
#include "views/gap/gap_terms.h"
#include "views/plots/interactive_plot.h"
#include "views/plots/plot_export.h"

namespace mozzi {
namespace views {
namespace {

constexpr int kBootstrapDefault = 200;

QString number(double value, int digits = 4) {
  return QString::fromStdString(core::formatNumber(value, digits));
}

QString joined(const std::vector<std::string>& items) {
  QStringList list;
  for (const auto& item : items) list << QString::fromStdString(item);
  return list.join(QStringLiteral(", "));
}

// The verdict names two effects fitted together (issue 16).
// Two effects at once: the verdict names both (core/report/gap_report.h).
bool twoEffects(const core::gap::Diagnosis& d) {
  return core::report::bestEffect(d).pair != nullptr;
}

QColor verdictColour(core::gap::Verdict verdict) {
  switch (verdict) {
    case core::gap::Verdict::Effect: return QColor(42, 157, 143);
    case core::gap::Verdict::None: return QColor(29, 53, 87);
    case core::gap::Verdict::Ambiguous:
    case core::gap::Verdict::Partial: return QColor(233, 150, 30);
    case core::gap::Verdict::Unexplained:
    case core::gap::Verdict::NotIdentifiable: return QColor(230, 57, 70);
  }
  return QColor(Qt::black);
}

QColor verdictColour(const std::string& name) {
  for (auto v : {core::gap::Verdict::Effect, core::gap::Verdict::None, core::gap::Verdict::Ambiguous,
                 core::gap::Verdict::Partial, core::gap::Verdict::Unexplained, core::gap::Verdict::NotIdentifiable})
    if (name == core::gap::verdictName(v)) return verdictColour(v);
  return QColor(Qt::black);
}

// A verdict's name (core's identifier, as the CLI's JSON writes it) in the
// page's language; an unknown name as it is.
QString verdictWord(const std::string& name) {
  if (name == "effect") return ModelTestView::tr("effect");
  if (name == "none") return ModelTestView::tr("none");
  if (name == "ambiguous") return ModelTestView::tr("ambiguous");
  if (name == "partial") return ModelTestView::tr("partial");
  if (name == "unexplained") return ModelTestView::tr("unexplained");
  if (name == "not_identifiable") return ModelTestView::tr("not identifiable");
  return QString::fromStdString(name);
}

// An overlay axis title core wrote in English, in the page's language; the
// FRF's "|H| [unit]" and unknown titles as they are.
QString axisTitle(const std::string& title) {
  if (title == "Frequency [Hz]") return ModelTestView::tr("Frequency [Hz]");
  if (title == "Pressure [bar]") return ModelTestView::tr("Pressure [bar]");
  return QString::fromStdString(title);
}

QwtPlotCurve* addCurve(QwtPlot* plot, const QColor& colour, Qt::PenStyle style) {
  auto* curve = new QwtPlotCurve;
  curve->setPen(colour, 1.5, style);
  curve->setRenderHint(QwtPlotItem::RenderAntialiased, true);
  curve->attach(plot);
  return curve;
}

QVector<QPointF> points(const std::vector<double>& x, const std::vector<double>& y, bool logY) {
  QVector<QPointF> out;
  const size_t n = std::min(x.size(), y.size());
  out.reserve(static_cast<int>(n));
  for (size_t i = 0; i < n; ++i) {
    // A log axis cannot show zero or negative values: leave those points out.
    if (!std::isfinite(y[i]) || (logY && y[i] <= 0.0)) continue;
    out.append(QPointF(x[i], y[i]));
  }
  return out;
}

}  // namespace

ModelTestView::ModelTestView(QWidget* parent, JobRunner* jobs)
    : QWidget(parent), jobs_(jobs ? jobs : new JobRunner(this)) {
  auto* layout = new QVBoxLayout(this);

  layout->addLayout(makeKeptRow());

  auto* inputs = new QGridLayout;
  modelLabel_ = new QLabel(this);
  modelPath_ = new QLineEdit(this);
  modelPath_->setObjectName(QStringLiteral("gapModelPath"));
  browseModel_ = new QPushButton(this);
  testLabel_ = new QLabel(this);
  testPath_ = new QLineEdit(this);
  testPath_->setObjectName(QStringLiteral("gapTestPath"));
  browseTest_ = new QPushButton(this);
  inputs->addWidget(modelLabel_, 0, 0);
  inputs->addWidget(modelPath_, 0, 1);
  inputs->addWidget(browseModel_, 0, 2);
  inputs->addWidget(testLabel_, 1, 0);
  inputs->addWidget(testPath_, 1, 1);
  inputs->addWidget(browseTest_, 1, 2);

  QHBoxLayout* options = makeOptionsRow();
  load_ = new QPushButton(this);
  run_ = new QPushButton(this);
  run_->setObjectName(QStringLiteral("gapRun"));
  cancel_ = new QPushButton(this);
  cancel_->setEnabled(false);
  export_ = new QPushButton(this);
  export_->setEnabled(false);

  auto* progressRow = new QHBoxLayout;
  progress_ = new QProgressBar(this);
  progress_->setRange(0, 1000);
  progress_->setValue(0);
  status_ = new QLabel(this);
  status_->setObjectName(QStringLiteral("gapStatus"));
  status_->setWordWrap(true);
  // The actions beside the progress they start: on the options row they made
  // the page wider than the tab area of a 1280-pixel window.
  for (QPushButton* action : {load_, run_, cancel_, export_}) progressRow->addWidget(action);
  progressRow->addWidget(progress_, 1);
  progressRow->addWidget(status_, 2);

  layout->addLayout(inputs);
  layout->addLayout(options);
  layout->addLayout(progressRow);

  auto* splitter = new QSplitter(Qt::Horizontal, this);
  auto* left = new QWidget(splitter);
  auto* leftLayout = new QVBoxLayout(left);
  leftLayout->setContentsMargins(0, 0, 0, 0);
  effectsLabel_ = new QLabel(left);
  effectsLabel_->setObjectName(QStringLiteral("gapEffectsLabel"));
  effects_ = new QListWidget(left);
  effects_->setObjectName(QStringLiteral("gapEffects"));
  verdict_ = new QLabel(left);
  verdict_->setObjectName(QStringLiteral("gapVerdict"));
  verdict_->setWordWrap(true);  // a verdict naming two effects with their locations is long
  QFont big = verdict_->font();
  big.setPointSizeF(big.pointSizeF() * 1.4);
  big.setBold(true);
  verdict_->setFont(big);
  explanation_ = new QTextBrowser(left);
  // Their height hints (192 px each) are ignored as the plot's below: they
  // share what the verdict leaves, at least a few lines each.
  effects_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Ignored);
  effects_->setMinimumHeight(fontMetrics().height() * 5);
  explanation_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Ignored);
  explanation_->setMinimumHeight(fontMetrics().height() * 6);
  leftLayout->addWidget(effectsLabel_);
  leftLayout->addWidget(effects_, 1);
  leftLayout->addWidget(verdict_);
  leftLayout->addWidget(explanation_, 2);

  results_ = new QTabWidget(splitter);
  results_->setObjectName(QStringLiteral("gapResults"));
  whereTabs_ = new QTabWidget(results_);
  whereTabs_->setObjectName(QStringLiteral("gapWhere"));
  ranking_ = new QTableWidget(results_);
  ranking_->setObjectName(QStringLiteral("gapRanking"));
  ranking_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  ranking_->setSelectionBehavior(QAbstractItemView::SelectRows);
  ranking_->horizontalHeader()->setStretchLastSection(true);
  auto* overlay = new QWidget(results_);
  auto* overlayLayout = new QVBoxLayout(overlay);
  overlayChoice_ = new QComboBox(overlay);
  overlayChoice_->setObjectName(QStringLiteral("gapOverlayChoice"));
  // The workbench's plot adapter: zoom, pan, Home and the export like every
  // other plot; autoscale on the curves' own range (not from 0 Hz).
  overlayPlot_ = new InteractivePlot(overlay);
  overlayPlot_->setObjectName(QStringLiteral("gapOverlayPlot"));
  // QwtPlot's own MinimumExpanding policy makes its size hint (40 px per
  // major tick of the left axis: a log axis over decades) the least height,
  // which pushed the page below the tab area. Its height hint is ignored
  // too: the page scroll area sizes a page with word-wrapped labels by its
  // preferred height for the width (QScrollArea with heightForWidth), and
  // the plot's hint made that 767 px on the demo's kept diagnosis at 1280 x
  // 800, a scroll for 606. It takes what the page leaves, at least 14 lines.
  overlayPlot_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Ignored);
  overlayPlot_->setMinimumHeight(fontMetrics().height() * 14);
  overlayPlot_->insertLegend(new QwtLegend, QwtPlot::BottomLegend);
  measuredCurve_ = addCurve(overlayPlot_, QColor(29, 53, 87), Qt::SolidLine);
  beforeCurve_ = addCurve(overlayPlot_, QColor(230, 57, 70), Qt::DashLine);
  afterCurve_ = addCurve(overlayPlot_, QColor(42, 157, 143), Qt::SolidLine);
  overlayLayout->addWidget(overlayChoice_);
  overlayLayout->addWidget(overlayPlot_, 1);
  results_->addTab(whereTabs_, QString());
  results_->addTab(ranking_, QString());
  results_->addTab(overlay, QString());
  splitter->addWidget(left);
  splitter->addWidget(results_);
  splitter->setStretchFactor(1, 3);
  layout->addWidget(splitter, 1);

  // Inputs changed: the loaded problem no longer matches them; run() reloads.
  const auto stale = [this] { problem_.reset(); };
  connect(modelPath_, &QLineEdit::textChanged, this, stale);
  connect(testPath_, &QLineEdit::textChanged, this, stale);
  // Files chosen: the band and the candidates are the next run's again.
  for (QLineEdit* path : {modelPath_, testPath_})
    connect(path, &QLineEdit::textEdited, this, [this] { setSetup(Setup::NextRun); });
  connect(bandLow_, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, stale);
  connect(bandHigh_, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, stale);
  connect(browseModel_, &QPushButton::clicked, this, &ModelTestView::browseModel);
  connect(browseTest_, &QPushButton::clicked, this, &ModelTestView::browseTest);
  connect(load_, &QPushButton::clicked, this, [this] { loadInputs(); });
  connect(run_, &QPushButton::clicked, this, [this] { run(); });
  connect(cancel_, &QPushButton::clicked, this, &ModelTestView::cancel);
  connect(export_, &QPushButton::clicked, this, [this] {
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Export Diagnosis Report"), QString(), tr("HTML report (*.html)"));
    if (path.isEmpty()) return;
    QString error;
    if (!exportReport(path, &error)) setStatus(error);
  });
  connect(overlayChoice_, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
          [this](int index) { showOverlay(index); });
  retranslate();
}

// Band, bootstrap samples and multistarts: the options of the next run.
QHBoxLayout* ModelTestView::makeOptionsRow() {
  auto* options = new QHBoxLayout;
  bandLabel_ = new QLabel(this);
  bandLow_ = new QDoubleSpinBox(this);
  bandHigh_ = new QDoubleSpinBox(this);
  bandLow_->setObjectName(QStringLiteral("gapBandLow"));
  bandHigh_->setObjectName(QStringLiteral("gapBandHigh"));
  for (QDoubleSpinBox* box : {bandLow_, bandHigh_}) {
    box->setRange(0.0, 1.0e6);
    box->setDecimals(1);
    box->setSuffix(QStringLiteral(" Hz"));
  }
  bootstrapLabel_ = new QLabel(this);
  bootstrap_ = new QSpinBox(this);
  bootstrap_->setRange(20, 5000);
  bootstrap_->setValue(kBootstrapDefault);
  multistartsLabel_ = new QLabel(this);
  multistarts_ = new QSpinBox(this);
  multistarts_->setRange(1, 100);
  multistarts_->setValue(core::gap::DiagnosisOptions{}.multistarts);
  options->addWidget(bandLabel_);
  options->addWidget(bandLow_);
  options->addWidget(bandHigh_);
  options->addSpacing(12);
  options->addWidget(bootstrapLabel_);
  options->addWidget(bootstrap_);
  options->addWidget(multistartsLabel_);
  options->addWidget(multistarts_);
  options->addStretch(1);
  return options;
}

ModelTestView::~ModelTestView() {
  // The job holds only shared state and delivers nothing once the view is
  // gone; ask it to stop so it does not run on for nobody.
  cancel();
}

void ModelTestView::setModelPath(const QString& path) {
  modelPath_->setText(path);
}
void ModelTestView::setTestPath(const QString& path) {
  testPath_->setText(path);
}
void ModelTestView::setBand(double lowHz, double highHz) {
  bandLow_->setValue(lowHz);
  bandHigh_->setValue(highHz);
}
void ModelTestView::setBootstrapSamples(int samples) {
  bootstrap_->setValue(samples);
}
void ModelTestView::setMultistarts(int starts) {
  multistarts_->setValue(starts);
}
void ModelTestView::setEffects(const QStringList& names) {
  for (int i = 0; i < effects_->count(); ++i) {
    QListWidgetItem* item = effects_->item(i);
    item->setCheckState(names.contains(item->data(Qt::UserRole).toString()) ? Qt::Checked : Qt::Unchecked);
  }
}
bool ModelTestView::isRunning() const {
  return jobId_ != 0 && jobs_->isRunning(jobId_);
}
QString ModelTestView::statusText() const {
  return status_->text();
}
QString ModelTestView::verdictText() const {
  return verdict_->text();
}
int ModelTestView::overlayCurveCount() const {
  return static_cast<int>(before_.size());
}

void ModelTestView::setStatus(const QString& text) {
  status_->setText(text);
}

void ModelTestView::browseModel() {
  const QString path = QFileDialog::getOpenFileName(this, tr("Choose Model"), modelPath_->text(),
                                                    tr("Models (*.json *.uff *.unv);;All files (*)"));
  if (!path.isEmpty()) setModelPath(path);
}

void ModelTestView::browseTest() {
  const QString path = QFileDialog::getOpenFileName(this, tr("Choose Test Data"), testPath_->text(),
                                                    tr("Test data (*.uff *.unv *.csv *.json);;All files (*)"));
  if (!path.isEmpty()) setTestPath(path);
}

bool ModelTestView::loadInputs() {
  if (isRunning()) return false;
  if (modelPath_->text().isEmpty() || testPath_->text().isEmpty()) {
    setStatus(tr("Choose a model file and a test file first."));
    return false;
  }
  core::gap::LoadOptions options;
  options.bandLowHz = bandLow_->value();
  if (bandHigh_->value() > 0.0) options.bandHighHz = bandHigh_->value();  // 0 = to the last line
  auto loaded = core::gap::loadGapProblem(modelPath_->text().toStdString(), testPath_->text().toStdString(), options);
  if (!loaded.ok()) {
    problem_.reset();
    effects_->clear();
    setStatus(tr("Cannot use these files: %1").arg(QString::fromStdString(loaded.error().describe())));
    return false;
  }
  problem_ = std::shared_ptr<const core::gap::GapProblem>(std::move(loaded.value()));
  std::map<std::string, std::vector<std::string>> locations;  // effect -> where it is tried
  for (const auto& candidate : problem_->candidates()) {
    auto& where = locations[candidate.effect];
    if (!candidate.location.empty()) where.push_back(joined(candidate.location).toStdString());
  }
  // A reload (new files or band) keeps the user's choices for effects still
  // offered. Each item shows the effect's words and keeps core's key (UserRole).
  QStringList unticked;
  for (int i = 0; i < effects_->count(); ++i) {
    if (effects_->item(i)->checkState() != Qt::Checked) unticked << effects_->item(i)->data(Qt::UserRole).toString();
  }
  fillEffects(locations, unticked);
  setSetup(Setup::NextRun);
  setStatus(tr("%1 data, %2 residuals, %3 candidate effects at their locations.")
                .arg(QString::fromStdString(problem_->dataKind()))
                .arg(problem_->residualCount())
                .arg(problem_->candidates().size()));
  return true;
}

bool ModelTestView::run() {
  if (isRunning()) return false;
  if (!problem_ && !loadInputs()) return false;
  core::gap::DiagnosisOptions options;
  options.bootstrapSamples = bootstrap_->value();
  options.multistarts = multistarts_->value();
  for (int i = 0; i < effects_->count(); ++i) {
    if (effects_->item(i)->checkState() == Qt::Checked)
      options.effects.push_back(effects_->item(i)->data(Qt::UserRole).toString().toStdString());
  }
  if (options.effects.empty()) {
    setStatus(tr("Tick at least one candidate effect."));
    return false;
  }
  auto problem = problem_;
  running_ = problem_;
  jobId_ = jobs_->run<core::gap::Diagnosis>(
      this, tr("Model vs test diagnosis"),
      [problem, options](JobProgress& progress) {
        core::gap::DiagnosisOptions withProgress = options;
        withProgress.progress = progress.callback();  // reports, and stops the fit when cancelled
        return core::gap::diagnose(*problem, withProgress);
      },
      [this](core::Result<core::gap::Diagnosis> result) { onFinished(std::move(result)); },
      [this](double fraction, const QString& step) { onProgress(fraction, step); });
  run_->setEnabled(false);
  load_->setEnabled(false);
  cancel_->setEnabled(true);
  progress_->setValue(0);
  setStatus(tr("Diagnosing..."));
  return true;
}

void ModelTestView::cancel() {
  if (isRunning()) jobs_->cancel(jobId_);
}

void ModelTestView::onProgress(double fraction, const QString& step) {
  progress_->setValue(static_cast<int>(std::clamp(fraction, 0.0, 1.0) * 1000.0));
  if (!step.isEmpty()) setStatus(step);
}

void ModelTestView::onFinished(core::Result<core::gap::Diagnosis> result) {
  jobId_ = 0;
  run_->setEnabled(true);
  load_->setEnabled(true);
  cancel_->setEnabled(false);
  const bool ok = result.ok();
  if (ok) {
    storedDiagnosis_.reset();
    storedId_ = 0;
    diagnosis_ = std::move(result).value();
    diagnosed_ = running_;
    progress_->setValue(1000);
    setStatus(tr("Diagnosis done."));
    showDiagnosis();
  } else {
    setStatus(tr("The diagnosis stopped: %1").arg(QString::fromStdString(result.error().describe())));
  }
  export_->setEnabled(diagnosis_.has_value());
  emit finished(ok);
}

void ModelTestView::showDiagnosis() {
  if (!diagnosis_) return;
  showDiagnosisText();
  fillWhere(&diagnosis_->gapBefore);
  fillRanking();
  computeOverlays();
}

void ModelTestView::showDiagnosisText() {
  const auto& d = *diagnosis_;
  // The effects of the verdict; two at once (issue 16): both.
  QStringList effects;
  if (twoEffects(d)) {
    for (const auto& e : d.pair.effects)
      effects << effectText(e.candidate.effect, e.candidate.location, e.candidate.equivalent);
  } else {
    for (int r : d.verdictSet)
      if (r >= 0 && r < static_cast<int>(d.ranking.size())) {
        const auto& c = d.ranking[static_cast<std::size_t>(r)].candidate;
        effects << effectText(c.effect, c.location, c.equivalent);
      }
  }
  showVerdict(QString::fromLatin1(core::gap::verdictName(d.verdict)), effects.size() == 2 && twoEffects(d)
                                                                          ? tr("%1 and %2").arg(effects[0], effects[1])
                                                                          : effects.join(QStringLiteral(", ")));
  explanation_->setPlainText(QString::fromStdString(d.explanation));
}

QString ModelTestView::effectText(const std::string& effect, const std::vector<std::string>& location,
                                  const std::vector<std::vector<std::string>>& equivalent) {
  const QString name = GapTerms::effectTitle(effect);  // "residual mode", not core's "residual_mode"
  if (location.empty()) return name;
  if (equivalent.size() == 1)
    return tr("%1 at %2 (equivalent at %3)").arg(name, joined(location), joined(equivalent[0]));
  if (equivalent.size() > 1) {
    // Two or more others (one reads "equivalent at"): a plain count.
    return tr("%1 at %2 (and %3 equivalent locations)")
        .arg(name, joined(location), QString::number(static_cast<qulonglong>(equivalent.size())));
  }
  return tr("%1 at %2").arg(name, joined(location));
}

// "Verdict: effect (residual mode)", coloured by the verdict.
void ModelTestView::showVerdict(const QString& verdict, const QString& effects) {
  const QString word = verdictWord(verdict.toStdString());
  verdict_->setText(effects.isEmpty() ? tr("Verdict: %1").arg(word) : tr("Verdict: %1 (%2)").arg(word, effects));
  QPalette palette = verdict_->palette();
  palette.setColor(QPalette::WindowText, verdictColour(verdict.toStdString()));
  verdict_->setPalette(palette);
}

void ModelTestView::fillWhere(const core::gap::GapMetrics* gap) {
  while (whereTabs_->count() > 0) {
    QWidget* page = whereTabs_->widget(0);
    whereTabs_->removeTab(0);
    delete page;
  }
  if (!gap) return;
  const auto& entries = gap->entries;
  std::vector<std::string> kinds;
  for (const auto& entry : entries) {
    if (std::find(kinds.begin(), kinds.end(), entry.kind) == kinds.end()) kinds.push_back(entry.kind);
  }
  for (const auto& kind : kinds) {
    std::vector<const core::gap::GapEntry*> rows;
    std::vector<std::string> detailNames;
    for (const auto& entry : entries) {
      if (entry.kind != kind) continue;
      rows.push_back(&entry);
      for (const auto& detail : entry.details) {
        if (std::find(detailNames.begin(), detailNames.end(), detail.first) == detailNames.end())
          detailNames.push_back(detail.first);
      }
    }
    auto* table = new QTableWidget(static_cast<int>(rows.size()), 4 + static_cast<int>(detailNames.size()), whereTabs_);
    table->setObjectName(QStringLiteral("gapWhere_%1").arg(QString::fromStdString(kind)));
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    QStringList headers{tr("Item"), GapTerms::columnTitle(gap->residualName), tr("z"), tr("Significant")};
    for (const auto& name : detailNames) headers << GapTerms::columnTitle(name);
    table->setHorizontalHeaderLabels(headers);
    for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
      const auto& entry = *rows[static_cast<size_t>(r)];
      table->setItem(r, 0, new QTableWidgetItem(GapTerms::itemLabel(entry.label)));
      table->setItem(r, 1, new QTableWidgetItem(number(entry.value)));
      table->setItem(r, 2, new QTableWidgetItem(number(entry.z, 3)));
      auto* flag = new QTableWidgetItem(entry.flagged ? tr("yes") : tr("no"));
      if (entry.flagged) flag->setForeground(QColor(230, 57, 70));
      table->setItem(r, 3, flag);
      for (const auto& detail : entry.details) {
        const auto at = std::find(detailNames.begin(), detailNames.end(), detail.first) - detailNames.begin();
        table->setItem(r, 4 + static_cast<int>(at), new QTableWidgetItem(number(detail.second)));
      }
    }
    table->resizeColumnsToContents();
    whereTabs_->addTab(table, GapTerms::kindTitle(kind));
  }
}

void ModelTestView::fillRanking() {
  std::vector<StoredDiagnosis::RankedEffect> rows;
  if (diagnosis_) {
    const auto& d = *diagnosis_;
    for (std::size_t r = 0; r < d.ranking.size(); ++r) {
      const auto& effect = d.ranking[r];
      StoredDiagnosis::RankedEffect row;
      row.effect = effect.candidate.effect;
      row.location = effect.candidate.location;
      row.equivalent = effect.candidate.equivalent;
      for (std::size_t p = 0; p < effect.parameters.size(); ++p) {
        StoredDiagnosis::Parameter parameter;
        if (p < effect.candidate.parameters.size()) {
          parameter.name = effect.candidate.parameters[p].name;
          parameter.unit = effect.candidate.parameters[p].unit;
        }
        parameter.value = effect.parameters[p];
        if (p < effect.stdErrors.size()) parameter.stdError = effect.stdErrors[p];
        row.parameters.push_back(parameter);
      }
      row.identifiable = effect.identifiable;
      row.inVerdict = std::find(d.verdictSet.begin(), d.verdictSet.end(), static_cast<int>(r)) != d.verdictSet.end();
      row.likelihoodRatio = effect.likelihoodRatio;
      row.heldOutImprovement = effect.heldOutImprovement;
      row.shrinkPct = effect.shrinkPct;
      rows.push_back(std::move(row));
    }
  }
  fillRankingRows(rows, diagnosis_ ? diagnosis_->threshold : 0.0);
}

// One row per ranked effect, those of the verdict in bold: the same table for
// a diagnosis just run and for one kept in the project.
void ModelTestView::fillRankingRows(const std::vector<StoredDiagnosis::RankedEffect>& rows, double threshold) {
  ranking_->clear();
  ranking_->setColumnCount(7);
  ranking_->setHorizontalHeaderLabels({tr("Effect"), tr("Location"), tr("Size ± standard error"),
                                       tr("Likelihood ratio"), tr("Threshold"), tr("Held-out gain"), tr("Shrink")});
  ranking_->setRowCount(static_cast<int>(rows.size()));
  for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
    const auto& effect = rows[static_cast<size_t>(r)];
    QStringList sizes;
    for (const auto& p : effect.parameters) {
      QString text = QStringLiteral("%1 = %2").arg(QString::fromStdString(p.name), number(p.value));
      if (p.stdError >= 0.0) text += QStringLiteral(" ± %1").arg(number(p.stdError, 2));
      if (!p.unit.empty()) text += QStringLiteral(" %1").arg(QString::fromStdString(p.unit));
      sizes << text;
    }
    if (!effect.identifiable) sizes << tr("(not identifiable)");
    ranking_->setItem(r, 0, new QTableWidgetItem(GapTerms::effectTitle(effect.effect)));
    // A family of locations that change the data alike (fitted once): the
    // first and the count here, every one in the tip.
    std::vector<std::string> all{joined(effect.location).toStdString()};
    for (const auto& other : effect.equivalent) all.push_back(joined(other).toStdString());
    auto* where = new QTableWidgetItem(
        effect.equivalent.empty()
            ? joined(effect.location)
            : tr("%1 (+%2 equivalent)")
                  .arg(joined(effect.location), QString::number(static_cast<qulonglong>(effect.equivalent.size()))));
    where->setToolTip(locationsTip(all));  // the cell is elided when the list is long
    ranking_->setItem(r, 1, where);
    ranking_->setItem(r, 2, new QTableWidgetItem(sizes.join(QStringLiteral("; "))));
    ranking_->setItem(r, 3, new QTableWidgetItem(number(effect.likelihoodRatio)));
    ranking_->setItem(r, 4, new QTableWidgetItem(number(threshold)));
    ranking_->setItem(r, 5,
                      new QTableWidgetItem(QStringLiteral("%1 %").arg(number(100.0 * effect.heldOutImprovement, 3))));
    ranking_->setItem(r, 6, new QTableWidgetItem(QStringLiteral("%1 %").arg(number(effect.shrinkPct, 3))));
    if (effect.inVerdict) {
      for (int c = 0; c < ranking_->columnCount(); ++c) {
        QFont font = ranking_->item(r, c)->font();
        font.setBold(true);
        ranking_->item(r, c)->setFont(font);
      }
    }
  }
  ranking_->resizeColumnsToContents();
  // A family of equivalent DOFs would make the location column as wide as the page.
  ranking_->setColumnWidth(1, std::min(ranking_->columnWidth(1), fontMetrics().averageCharWidth() * 28));
}

void ModelTestView::computeOverlays() {
  before_.clear();
  after_.clear();
  afterLabel_.clear();
  if (!diagnosis_ || !diagnosed_) return;
  const auto& d = *diagnosis_;
  before_ = diagnosed_->overlay({d.calibrated.data(), -1, nullptr});
  // "After": the verdict's pair, else its first effect, else the top-ranked one.
  const core::gap::RankedEffect* best = core::report::bestEffect(d).single;
  if (twoEffects(d) && d.pair.theta.size() == d.calibrated.size()) {
    std::vector<double> phi;
    for (const auto& e : d.pair.effects) phi.insert(phi.end(), e.parameters.begin(), e.parameters.end());
    after_ = diagnosed_->combinedOverlay(
        d.pair.theta.data(), {d.pair.effects[0].candidateIndex, d.pair.effects[1].candidateIndex}, phi.data());
  } else if (best && best->candidateIndex >= 0 && best->theta.size() == d.calibrated.size()) {
    after_ = diagnosed_->overlay({best->theta.data(), best->candidateIndex, best->parameters.data()});
  }
  afterLabel_ = liveAfterLabel();
  const QSignalBlocker block(overlayChoice_);
  overlayChoice_->clear();
  for (const auto& curve : before_) overlayChoice_->addItem(QString::fromStdString(curve.label));
  if (!before_.empty()) showOverlay(0);
}

bool ModelTestView::showOverlay(int index) {
  if (index < 0 || index >= static_cast<int>(before_.size())) return false;
  const auto& curve = before_[static_cast<size_t>(index)];
  if (overlayChoice_->currentIndex() != index) {
    const QSignalBlocker block(overlayChoice_);
    overlayChoice_->setCurrentIndex(index);
  }
  overlayPlot_->setLogY(curve.logY);
  overlayPlot_->setAxisTitle(QwtPlot::xBottom, axisTitle(curve.xLabel));
  overlayPlot_->setAxisTitle(QwtPlot::yLeft, axisTitle(curve.yLabel));
  measuredCurve_->setSamples(points(curve.x, curve.measured, curve.logY));
  beforeCurve_->setSamples(points(curve.x, curve.predicted, curve.logY));
  if (index < static_cast<int>(after_.size())) {
    const auto& after = after_[static_cast<size_t>(index)];
    afterCurve_->setSamples(points(after.x, after.predicted, after.logY));
  } else {
    afterCurve_->setSamples(QVector<QPointF>());
  }
  // Markers make sparse series (pressures, speeds) readable; FRFs are dense.
  const bool sparse = curve.x.size() < 40;
  measuredCurve_->setStyle(sparse ? QwtPlotCurve::NoCurve : QwtPlotCurve::Lines);
  measuredCurve_->setSymbol(
      sparse ? new QwtSymbol(QwtSymbol::Ellipse, QBrush(QColor(29, 53, 87)), QPen(QColor(29, 53, 87)), QSize(7, 7))
             : nullptr);
  afterCurve_->setTitle(afterLabel_.isEmpty() ? tr("model + best effect") : afterLabel_);
  overlayPlot_->autoscale();
  return true;
}

QString ModelTestView::htmlReport() const {
  if (!diagnosis_) return {};
  // The content comes from core (the same section as the project report); the
  // page only renders the figure: the overlay shown, as an inline PNG.
  core::report::Report report;
  report.title = tr("Model vs test").toStdString();
  report.sections.push_back(core::report::gapDiagnosisSection(*diagnosis_, modelPath_->text().toStdString(),
                                                              testPath_->text().toStdString()));
  const auto figure = [this](const core::report::Figure& f) -> std::string {
    if (f.view != "gap-overlay" || before_.empty()) return {};
    QPixmap pixmap(900, 450);
    pixmap.fill(Qt::white);
    QwtPlotRenderer renderer;
    renderer.renderTo(overlayPlot_, pixmap);
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    pixmap.save(&buffer, "PNG");
    return "data:image/png;base64," + png.toBase64().toStdString();
  };
  return QString::fromStdString(core::report::toHtml(report, figure, 900));
}

bool ModelTestView::exportReport(const QString& path, QString* error) const {
  if (!diagnosis_) {
    if (error) *error = tr("Nothing to export: run the diagnosis first.");
    return false;
  }
  QFile html(path);
  if (!html.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
    if (error) *error = tr("Cannot write %1: %2").arg(path, html.errorString());
    return false;
  }
  html.write(htmlReport().toUtf8());
  html.close();
  const QFileInfo info(path);
  QFile json(info.dir().filePath(info.completeBaseName() + QStringLiteral(".json")));
  if (!json.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
    if (error) *error = tr("Cannot write %1: %2").arg(json.fileName(), json.errorString());
    return false;
  }
  json.write(QByteArray::fromStdString(core::gap::diagnosisToJson(*diagnosis_).dump(2)));
  return true;
}

void ModelTestView::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

void ModelTestView::retranslate() {
  storedLabel_->setText(tr("Kept diagnoses"));
  stored_->setToolTip(tr("The gap diagnoses this project keeps"));
  showStored_->setText(tr("Show"));
  modelLabel_->setText(tr("Model"));
  modelPath_->setPlaceholderText(tr("mozzi-model/1 JSON, UFF 55 modes, tyre or stability gap file"));
  testLabel_->setText(tr("Test"));
  testPath_->setPlaceholderText(tr("UFF 58 FRFs, identified modes, relaxation lengths or stability frequencies"));
  browseModel_->setText(tr("Browse..."));
  browseTest_->setText(tr("Browse..."));
  bandLabel_->setText(tr("Band"));
  bootstrapLabel_->setText(tr("Bootstrap samples"));
  bootstrap_->setToolTip(tr("Simulated data sets that calibrate the false-attribution threshold"));
  multistartsLabel_->setText(tr("Multistarts"));
  multistarts_->setToolTip(tr("Starting points of every nonlinear fit (more are slower and safer)"));
  setSetup(setup_);  // the band's tips and the candidates' label
  // The candidates' words in this language, in their order; core's key stays (UserRole).
  for (int i = 0; i < effects_->count(); ++i)
    effects_->item(i)->setText(GapTerms::effectTitle(effects_->item(i)->data(Qt::UserRole).toString().toStdString()));
  effects_->sortItems();
  load_->setText(tr("Load"));
  run_->setText(tr("Run Diagnosis"));
  cancel_->setText(tr("Cancel"));
  export_->setText(tr("Export Report..."));
  results_->setTabText(0, tr("Where"));
  results_->setTabText(1, tr("Ranked effects"));
  results_->setTabText(2, tr("Overlay"));
  measuredCurve_->setTitle(tr("measured"));
  beforeCurve_->setTitle(tr("model"));
  if (diagnosis_ && diagnosed_) {
    afterLabel_ = liveAfterLabel();
  } else if (storedDiagnosis_) {
    afterLabel_ = storedAfterLabel(*storedDiagnosis_);
  }
  afterCurve_->setTitle(afterLabel_.isEmpty() ? tr("model + best effect") : afterLabel_);
  if (const int shown = overlayChoice_->currentIndex(); shown >= 0 && shown < static_cast<int>(before_.size())) {
    overlayPlot_->setAxisTitle(QwtPlot::xBottom, axisTitle(before_[static_cast<size_t>(shown)].xLabel));
    overlayPlot_->setAxisTitle(QwtPlot::yLeft, axisTitle(before_[static_cast<size_t>(shown)].yLabel));
  }
  if (diagnosis_) {
    showDiagnosisText();
    fillRanking();
  } else if (storedDiagnosis_) {
    showStoredText();
    fillRankingRows(storedDiagnosis_->ranking, storedDiagnosis_->threshold);
  } else {
    verdict_->setText(tr("No diagnosis yet"));
  }
}

}  // namespace views
}  // namespace mozzi
