// The Model vs Test page's kept diagnoses: the project's analyses of kind
// "gap-diagnosis" (core/report/gap_report.h analysisFromDiagnosis), listed and
// shown as they were stored, without the model and test files.
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTextBrowser>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/text.h"
#include "core/report/gap_report.h"
#include "views/common/kept_analyses.h"
#include "views/common/project_model.h"
#include "views/gap/gap_terms.h"
#include "views/gap/model_test_view.h"

namespace mozzi {
namespace views {
namespace {

// What analysisFromDiagnosis stores.
constexpr const char* kGapAnalysisKind = "gap-diagnosis";

QString number(double value) {
  return QString::fromStdString(core::formatNumber(value, 3));
}

}  // namespace

// The row above the inputs: the project's kept diagnoses, shown as stored
// (no run needed).
QHBoxLayout* ModelTestView::makeKeptRow() {
  auto* kept = new QHBoxLayout;
  storedLabel_ = new QLabel(this);
  stored_ = new QComboBox(this);
  stored_->setObjectName(QStringLiteral("gapStored"));
  stored_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  stored_->setEnabled(false);
  showStored_ = new QPushButton(this);
  showStored_->setObjectName(QStringLiteral("gapShowStored"));
  showStored_->setEnabled(false);
  kept->addWidget(storedLabel_);
  kept->addWidget(stored_, 1);
  kept->addWidget(showStored_);
  connect(showStored_, &QPushButton::clicked, this, [this] { showStored(stored_->currentData().toLongLong()); });
  connect(stored_, QOverload<int>::of(&QComboBox::activated), this,
          [this](int index) { showStored(stored_->itemData(index).toLongLong()); });
  return kept;
}

void ModelTestView::setProjectModel(ProjectModel* model) {
  if (project_) disconnect(project_, nullptr, this, nullptr);
  project_ = model;
  if (project_) {
    connect(project_, &ProjectModel::analysesChanged, this, &ModelTestView::refreshStored);
    // Another project: what it keeps, never a diagnosis of the one closed. A
    // diagnosis run on files is not the project's and stays.
    connect(project_, &ProjectModel::projectChanged, this, [this] {
      if (diagnosis_) {
        refreshStored();
        return;
      }
      if (storedDiagnosis_) {
        storedDiagnosis_.reset();
        storedId_ = 0;
        fillWhere(nullptr);
        fillRankingRows({}, 0.0);
        before_.clear();
        after_.clear();
        overlayChoice_->clear();
        effects_->clear();
        if (setup_ != Setup::NextRun) setBand(0.0, 0.0);
        setSetup(Setup::NextRun);
        for (QwtPlotCurve* curve : {measuredCurve_, beforeCurve_, afterCurve_}) curve->setSamples(QVector<QPointF>());
        overlayPlot_->replot();
        explanation_->clear();
        verdict_->setText(tr("No diagnosis yet"));
        setStatus(QString());
      }
      showNewestStored();
    });
  }
  refreshStored();
}

void ModelTestView::refreshStored() {
  showStored_->setEnabled(fillKeptAnalyses(stored_, project_, kGapAnalysisKind) > 0);
}

bool ModelTestView::showNewestStored() {
  refreshStored();
  const auto ids = keptAnalysisIds(stored_);
  return !ids.empty() && showStored(ids.back());
}

bool ModelTestView::showStored(qint64 analysisId) {
  if (!project_ || !project_->store()) {
    setStatus(tr("No project is open."));
    return false;
  }
  auto analysis = project_->store()->analysis(analysisId);
  if (!analysis) {
    setStatus(QString::fromStdString(analysis.error().describe()));
    return false;
  }
  auto parsed = parseStoredDiagnosis(analysis->resultJson);
  if (!parsed) {
    setStatus(tr("Analysis %1: %2").arg(analysisId).arg(QString::fromStdString(parsed.error().describe())));
    return false;
  }
  // The kept one replaces what was shown; a run on files stays possible.
  diagnosis_.reset();
  diagnosed_.reset();
  export_->setEnabled(false);
  storedDiagnosis_ = std::move(*parsed);
  storedId_ = analysisId;
  const int at = stored_->findData(QVariant::fromValue<qint64>(analysisId));
  if (at >= 0) {
    const QSignalBlocker block(stored_);
    stored_->setCurrentIndex(at);
  }
  storedDiagnosis_->name = analysis->name;
  const StoredDiagnosis& d = *storedDiagnosis_;
  showStoredText();
  fillWhere(&d.gapBefore);
  fillRankingRows(d.ranking, d.threshold);
  before_ = d.before;
  after_ = d.after;
  afterLabel_ = storedAfterLabel(d);
  {
    const QSignalBlocker block(overlayChoice_);
    overlayChoice_->clear();
    for (const auto& curve : before_) overlayChoice_->addItem(QString::fromStdString(curve.label));
  }
  if (!before_.empty()) showOverlay(0);
  showStoredSetup();
  progress_->setValue(0);
  return true;
}

// The inputs describe the diagnosis shown, not the defaults of a run nobody
// asked for. The stored result (analysisFromDiagnosis) keeps no band as such:
// its frequency overlay starts at the first line fitted and ends at the last
// (thinning keeps both), so that is the band; a diagnosis over another axis
// (tyre pressure) has none. Its candidates are the effects of its ranking,
// each at the locations it was fitted.
void ModelTestView::showStoredSetup() {
  const StoredDiagnosis& d = *storedDiagnosis_;
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const auto& curve : d.before) {
    if (curve.x.empty() || curve.xLabel.find("[Hz]") == std::string::npos) continue;
    const auto [lo, hi] = std::minmax_element(curve.x.begin(), curve.x.end());
    low = std::min(low, *lo);
    high = std::max(high, *hi);
  }
  const bool hasBand = std::isfinite(low) && std::isfinite(high) && high > low;
  if (hasBand) setBand(low, high);
  std::map<std::string, std::vector<std::string>> locations;
  for (const auto& row : d.ranking) {
    auto& where = locations[row.effect];
    std::string at;
    for (const auto& dof : row.location) at += (at.empty() ? "" : ", ") + dof;
    if (!at.empty()) where.push_back(at);
    for (const auto& other : row.equivalent) {
      std::string also;
      for (const auto& dof : other) also += (also.empty() ? "" : ", ") + dof;
      if (!also.empty()) where.push_back(also);
    }
  }
  fillEffects(locations, {});
  setSetup(hasBand ? Setup::KeptBand : Setup::KeptNoBand);
}

void ModelTestView::setSetup(Setup setup) {
  setup_ = setup;
  const bool kept = setup != Setup::NextRun;
  bandLow_->setEnabled(setup != Setup::KeptNoBand);
  bandHigh_->setEnabled(setup != Setup::KeptNoBand);
  switch (setup) {
    case Setup::NextRun:
      bandLow_->setToolTip(tr("Lowest frequency used (0 = from the first line)"));
      bandHigh_->setToolTip(tr("Highest frequency used (0 = to the last line)"));
      break;
    case Setup::KeptBand:
      bandLow_->setToolTip(tr("First line of the kept diagnosis shown; a new run on files uses the value here"));
      bandHigh_->setToolTip(tr("Last line of the kept diagnosis shown; a new run on files uses the value here"));
      break;
    case Setup::KeptNoBand:
      for (QDoubleSpinBox* box : {bandLow_, bandHigh_})
        box->setToolTip(tr("The kept diagnosis shown has no frequency band; the band sets up the next run on files"));
      break;
  }
  effectsLabel_->setText(kept ? tr("Candidate effects of the kept diagnosis") : tr("Candidate effects"));
  effects_->setToolTip(kept ? tr("The effects the kept diagnosis ranked; a run on files lists those its data offer")
                            : QString());
}

void ModelTestView::fillEffects(const std::map<std::string, std::vector<std::string>>& locations,
                                const QStringList& unticked) {
  effects_->clear();
  for (const auto& [effect, where] : locations) {
    // The effect's words shown, core's key kept for the run (ModelTestView::run).
    auto* item = new QListWidgetItem(GapTerms::effectTitle(effect), effects_);
    const QString key = QString::fromStdString(effect);
    item->setData(Qt::UserRole, key);
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(unticked.contains(key) ? Qt::Unchecked : Qt::Checked);
    if (!where.empty()) item->setToolTip(locationsTip(where));
  }
  effects_->sortItems();  // in the order of the words shown
}

// A residual mode may stand at a family of equivalent DOFs and be tried at
// many: the tip stays a screenful, however long the list.
QString ModelTestView::locationsTip(const std::vector<std::string>& locations) {
  constexpr std::size_t kShown = 12;
  constexpr int kEntryChars = 80;
  QStringList lines;
  for (std::size_t i = 0; i < locations.size() && i < kShown; ++i) {
    QString entry = QString::fromStdString(locations[i]);
    if (entry.size() > kEntryChars) entry = entry.left(kEntryChars - 1) + QChar(0x2026);
    lines << entry;
  }
  if (locations.size() > kShown) lines << tr("and %n more", nullptr, static_cast<int>(locations.size() - kShown));
  return tr("Locations:") + QLatin1Char('\n') + lines.join(QLatin1Char('\n'));
}

// Verdict (with the effects it names), explanation and the status line of
// the kept diagnosis shown.
// The legend of computeOverlays' "after" curve: it names each effect with
// its location (two residual modes read "model + residual mode +
// residual mode" without them).
QString ModelTestView::liveAfterLabel() const {
  if (!diagnosis_) return {};
  const auto& d = *diagnosis_;
  const core::report::BestEffect chosen = core::report::bestEffect(d);
  const core::gap::RankedEffect* best = chosen.single;
  if (chosen.pair && d.pair.theta.size() == d.calibrated.size()) {
    const auto& e = d.pair.effects;
    return tr("model + %1 + %2")
        .arg(effectText(e[0].candidate.effect, e[0].candidate.location, {}),
             effectText(e[1].candidate.effect, e[1].candidate.location, {}));
  }
  if (best && best->candidateIndex >= 0 && best->theta.size() == d.calibrated.size())
    return tr("model + %1").arg(effectText(best->candidate.effect, best->candidate.location, {}));
  return {};
}

// The stored overlay's legend in the page's language: the file keeps the
// English words and keys core wrote ("model + residual_mode at 12+Y"); the effect(s)
// it names are the verdict's (core::report::bestEffect), rebuilt here with
// tr() when they spell the same label, else the file's words as they are.
QString ModelTestView::storedAfterLabel(const StoredDiagnosis& d) {
  if (d.afterLabel.empty()) return {};
  // Core's own spelling of the stored label (core::report::effectAtLocation).
  auto english = [](const StoredDiagnosis::RankedEffect& r) {
    return core::report::effectAtLocation(core::gap::Candidate(r.effect, r.location, {}));
  };
  auto local = [](const StoredDiagnosis::RankedEffect& r) { return effectText(r.effect, r.location, {}); };
  std::vector<const StoredDiagnosis::RankedEffect*> verdict;
  for (const auto& r : d.ranking)
    if (r.inVerdict) verdict.push_back(&r);
  if (d.pair && verdict.size() == 2) {
    for (const auto& [a, b] : {std::pair(verdict[0], verdict[1]), std::pair(verdict[1], verdict[0])}) {
      if (d.afterLabel == "model + " + english(*a) + " + " + english(*b))
        return tr("model + %1 + %2").arg(local(*a), local(*b));
    }
  }
  const StoredDiagnosis::RankedEffect* single =
      d.best >= 0 ? &d.ranking[static_cast<std::size_t>(d.best)] : (d.ranking.empty() ? nullptr : &d.ranking.front());
  if (single && d.afterLabel == "model + " + english(*single)) return tr("model + %1").arg(local(*single));
  return QString::fromStdString(d.afterLabel);
}

void ModelTestView::showStoredText() {
  const StoredDiagnosis& d = *storedDiagnosis_;
  QStringList effects;
  for (const auto& row : d.ranking)
    if (row.inVerdict) effects << effectText(row.effect, row.location, row.equivalent);
  // Two effects fitted together (the verdict's pair) read as the page's run does.
  showVerdict(QString::fromStdString(d.verdict), d.pair && effects.size() == 2
                                                     ? tr("%1 and %2").arg(effects[0], effects[1])
                                                     : effects.join(QStringLiteral(", ")));
  explanation_->setPlainText(QString::fromStdString(d.explanation));
  QString status =
      tr("Kept diagnosis \"%1\" (analysis %2), as stored.").arg(QString::fromStdString(d.name)).arg(storedId_);
  // The held-out gain of what the verdict names: the pair fitted together, or its effect.
  const double heldOut = d.pair ? d.pairHeldOutImprovement
                                : (d.best >= 0 ? d.ranking[static_cast<std::size_t>(d.best)].heldOutImprovement
                                               : std::numeric_limits<double>::quiet_NaN());
  if (std::isfinite(heldOut))
    status += QLatin1Char(' ') +
              tr("With %1 the held-out residual is %2% lower.").arg(effects.join(tr(" and ")), number(100.0 * heldOut));
  setStatus(status);
}

}  // namespace views
}  // namespace mozzi
