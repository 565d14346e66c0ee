#include "views/scene/twist_axes_page.h"

#include <qwt_plot_curve.h>
#include <qwt_plot_marker.h>
#include <qwt_scale_widget.h>
#include <qwt_symbol.h>
#include <qwt_text.h>
#include <QComboBox>
#include <QCoreApplication>
#include <QEvent>
#include <QFile>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSlider>
#include <QSplitter>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <tuple>

#include "core/io/project_store.h"
#include "core/stiffness/silhouettes.h"
#include "core/stiffness/twist_geometry.h"
#include "devices/rigtests/imported_twist.h"
#include "devices/rigtests/stiffness_results.h"
#include "views/plots/interactive_plot.h"
#include "views/plots/marker_labels.h"
#include "views/scene/plate_sketch.h"
#include "views/scene/twist_csv_import.h"

namespace mozzi {
namespace views {

namespace st = core::stiffness;
namespace rt = devices::rigtests;

// What the selection shows (read once per selection).
struct TwistAxesData {
  std::optional<rt::StiffnessTestView> statics, dynamics;
  std::optional<st::PlacedSilhouette> silhouette;
  QString silhouetteError;
  std::optional<st::AxisPath> path;
  // The plate of an imported modal file, when no test gives one.
  std::optional<rt::StiffnessTestView> modalPlate;
  // Geometry of the set-up (of the static test, else of the dynamic one, else of the modal file).
  const rt::StiffnessTestView* geometry() const {
    return statics ? &*statics : (dynamics ? &*dynamics : (modalPlate ? &*modalPlate : nullptr));
  }
};

namespace {

constexpr double kPi = 3.14159265358979323846;
const QColor kStaticColour(20, 20, 20);
const QColor kDynamicColour(200, 30, 30);
const QColor kPathColour(230, 120, 0);
const QColor kModalColour(40, 90, 170);

QString qs(const std::string& s) {
  return QString::fromStdString(s);
}

QwtPlotCurve* addCurve(QwtPlot* plot, const QColor& colour, double width, Qt::PenStyle style, bool autoscaled,
                       double z) {
  auto* c = new QwtPlotCurve;
  c->setPen(QPen(colour, width, style));
  c->setRenderHint(QwtPlotItem::RenderAntialiased, true);
  c->setItemAttribute(QwtPlotItem::AutoScale, autoscaled);
  c->setZ(z);
  c->attach(plot);
  return c;
}

QVector<QPointF> points(const std::vector<core::Vector2>& v, bool closed = false) {
  QVector<QPointF> out;
  for (const auto& p : v) out.append(QPointF(p(0), p(1)));
  if (closed && !v.empty()) out.append(QPointF(v.front()(0), v.front()(1)));
  return out;
}

// "value ± sigma unit" in display units (kN/m, kN m/rad, mm, deg).
QString withSigma(const rt::StoredQuantity* q) {
  if (!q) return QStringLiteral("-");
  double scale = 1.0;
  QString unit = qs(q->unit);
  if (q->unit == "N/m") {
    scale = 1e-3;
    unit = QStringLiteral("kN/m");
  } else if (q->unit == "N m/rad") {
    scale = 1e-3;
    unit = QStringLiteral("kN m/rad");
  } else if (q->unit == "m") {
    scale = 1e3;
    unit = QStringLiteral("mm");
  } else if (q->unit == "rad") {
    scale = 180.0 / kPi;
    unit = QStringLiteral("°");
  }
  const QString value = QString::number(q->value * scale, 'f', q->unit == "rad" ? 2 : 1);
  if (q->uncertainty > 0)
    return QStringLiteral("%1 ± %2 %3").arg(value, QString::number(q->uncertainty * scale, 'g', 2), unit);
  return QStringLiteral("%1 %2").arg(value, unit);
}

}  // namespace

TwistAxesPage::TwistAxesPage(const PageContext& ctx)
    : QWidget(ctx.parent), model_(ctx.model), data_(std::make_unique<TwistAxesData>()) {
  buildUi();
  retranslate();
  reload();
  connect(model_, &ProjectModel::rigTestsChanged, this, &TwistAxesPage::reload);
  connect(model_, &ProjectModel::projectChanged, this, &TwistAxesPage::reload);
  if (ctx.item.kind == RecordKind::RigTest) showRigTest(ctx.item.id);
}

TwistAxesPage::~TwistAxesPage() = default;

void TwistAxesPage::buildUi() {
  auto* left = new QWidget;
  auto* leftLayout = new QVBoxLayout(left);
  auto* form = new QFormLayout;
  specimen_ = new QComboBox;
  specimen_->setObjectName(QStringLiteral("specimen"));
  static_ = new QComboBox;
  static_->setObjectName(QStringLiteral("staticTest"));
  dynamic_ = new QComboBox;
  dynamic_->setObjectName(QStringLiteral("dynamicTest"));
  for (QComboBox* box : {specimen_, static_, dynamic_}) {
    box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    box->setMinimumContentsLength(18);
  }
  specimenLabel_ = new QLabel;
  staticLabel_ = new QLabel;
  dynamicLabel_ = new QLabel;
  form->addRow(specimenLabel_, specimen_);
  form->addRow(staticLabel_, static_);
  form->addRow(dynamicLabel_, dynamic_);
  leftLayout->addLayout(form);
  import_ = new TwistCsvImport;
  import_->setObjectName(QStringLiteral("csvImport"));
  leftLayout->addWidget(import_);

  auto* freq = new QHBoxLayout;
  frequencyLabel_ = new QLabel;
  slider_ = new QSlider(Qt::Horizontal);
  slider_->setObjectName(QStringLiteral("frequency"));
  slider_->setTickPosition(QSlider::TicksBelow);
  slider_->setPageStep(1);
  slider_->setEnabled(false);
  frequencyValue_ = new QLabel;
  frequencyValue_->setObjectName(QStringLiteral("frequencyValue"));
  frequencyValue_->setMinimumWidth(frequencyValue_->fontMetrics().horizontalAdvance(QStringLiteral("000.0 Hz")));
  freq->addWidget(frequencyLabel_);
  freq->addWidget(slider_, 1);
  freq->addWidget(frequencyValue_);
  leftLayout->addLayout(freq);

  table_ = new QTableWidget(0, 3);
  table_->setObjectName(QStringLiteral("results"));
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionMode(QAbstractItemView::NoSelection);
  table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  table_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
  leftLayout->addWidget(table_);

  silhouetteNote_ = new QLabel;
  silhouetteNote_->setObjectName(QStringLiteral("silhouetteNote"));
  silhouetteNote_->setWordWrap(true);
  QFont small = silhouetteNote_->font();
  small.setPointSizeF(small.pointSizeF() * 0.9);
  silhouetteNote_->setFont(small);
  leftLayout->addWidget(silhouetteNote_);
  status_ = new QLabel;
  status_->setObjectName(QStringLiteral("status"));
  status_->setWordWrap(true);
  status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  leftLayout->addWidget(status_);
  leftLayout->addStretch(1);

  plot_ = new InteractivePlot;
  plot_->setObjectName(QStringLiteral("twistPlot"));
  plot_->setCursorOnClick(false);
  plot_->setMinimumSize(320, 280);

  // Items that persist over selections.
  sketch_ = std::make_unique<PlateSketch>(plot_);
  extent_ = addCurve(plot_, Qt::transparent, 0.0, Qt::NoPen, true, 0);
  extent_->setStyle(QwtPlotCurve::NoCurve);
  staticAxis_ = addCurve(plot_, kStaticColour, 2.5, Qt::SolidLine, false, 20);
  staticArm_ = addCurve(plot_, kStaticColour, 1.0, Qt::DotLine, true, 19);
  bendAxis_ = addCurve(plot_, kModalColour, 1.5, Qt::DashLine, false, 15);
  torsAxis_ = addCurve(plot_, kModalColour, 1.5, Qt::DotLine, false, 15);
  path_ = addCurve(plot_, kPathColour, 1.5, Qt::SolidLine, true, 25);
  path_->setSymbol(new QwtSymbol(QwtSymbol::Ellipse, QBrush(Qt::white), QPen(kPathColour, 1.5), QSize(7, 7)));
  dynamicAxis_ = addCurve(plot_, kDynamicColour, 2.0, Qt::SolidLine, false, 22);
  dynamicFoot_ = new QwtPlotMarker;
  dynamicFoot_->setSymbol(new QwtSymbol(QwtSymbol::Ellipse, QBrush(kDynamicColour), QPen(kDynamicColour), QSize(9, 9)));
  dynamicFoot_->setItemAttribute(QwtPlotItem::AutoScale, false);
  dynamicFoot_->setZ(26);
  dynamicFoot_->attach(plot_);
  dynamicFoot_->hide();
  staticAxisLabel_ = label(QString(), kStaticColour);
  dynamicAxisLabel_ = label(QString(), kDynamicColour);
  bendLabel_ = label(QString(), kModalColour);
  torsLabel_ = label(QString(), kModalColour);
  plot_->setEqualAspect(true);

  auto* split = new QSplitter(Qt::Horizontal);
  split->addWidget(left);
  split->addWidget(plot_);
  split->setStretchFactor(0, 0);
  split->setStretchFactor(1, 1);
  split->setSizes({400, 880});
  auto* layout = new QHBoxLayout(this);
  layout->addWidget(split);

  connect(specimen_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] {
    if (filling_) return;
    fillTests();
    loadTests();
  });
  for (QComboBox* box : {static_, dynamic_})
    connect(box, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] {
      if (!filling_) loadTests();
    });
  connect(slider_, &QSlider::valueChanged, this, &TwistAxesPage::drawFrequency);
  connect(import_, &TwistCsvImport::imported, this, &TwistAxesPage::showImported);
  connect(import_, &TwistCsvImport::modalChanged, this, [this] {
    if (!filling_) loadTests();
  });
  connect(import_, &TwistCsvImport::message, this, &TwistAxesPage::message);
  connect(import_, &TwistCsvImport::keepRequested, this, &TwistAxesPage::keepImported);
  // The axes are lines across the view: re-clipped whenever the view moves.
  auto queueClip = [this] {
    if (clipQueued_) return;
    clipQueued_ = true;
    QTimer::singleShot(0, this, [this] {
      clipQueued_ = false;
      clipAxes();
    });
  };
  connect(plot_->axisWidget(QwtPlot::xBottom), &QwtScaleWidget::scaleDivChanged, this, queueClip);
  connect(plot_->axisWidget(QwtPlot::yLeft), &QwtScaleWidget::scaleDivChanged, this, queueClip);
}

QwtPlotMarker* TwistAxesPage::label(const QString& text, const QColor& colour) {
  auto* m = new QwtPlotMarker;
  QwtText t(text);
  t.setColor(colour);
  QColor back(Qt::white);
  back.setAlpha(200);
  t.setBackgroundBrush(back);
  m->setLabel(t);
  m->setLabelAlignment(Qt::AlignRight | Qt::AlignTop);
  m->setItemAttribute(QwtPlotItem::AutoScale, false);
  m->setZ(40);
  m->attach(plot_);
  return m;
}

void TwistAxesPage::retranslate() {
  specimenLabel_->setText(tr("Specimen"));
  staticLabel_->setText(tr("Static test"));
  dynamicLabel_->setText(tr("Dynamic test"));
  frequencyLabel_->setText(tr("Frequency"));
  table_->setHorizontalHeaderLabels({tr("Quantity"), tr("Static"), tr("Dynamic")});
  plot_->setAxisTitle(QwtPlot::xBottom, tr("u [m] (plate plane)"));
  plot_->setAxisTitle(QwtPlot::yLeft, tr("v [m]"));
  static_->setToolTip(tr("The static ramp test whose twist axis is drawn (black)"));
  dynamic_->setToolTip(tr("The sine sweep whose dynamic twist axis is drawn (red) at the slider's frequency"));
  slider_->setToolTip(tr("Excitation frequency of the sine sweep: moves the dynamic twist axis"));
  if (data_ && (data_->statics || data_->dynamics)) {
    const int keep = slider_->value();
    drawStatic();
    slider_->setValue(keep);
    drawFrequency();
  }
}

void TwistAxesPage::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) {
    retranslate();
    reload();
  }
  QWidget::changeEvent(event);
}

void TwistAxesPage::reload() {
  fillSpecimens();
  fillTests();
  loadTests();
}

void TwistAxesPage::fillSpecimens() {
  const qint64 keep = specimen_->currentData().toLongLong();
  filling_ = true;
  specimen_->clear();
  core::io::ProjectStore* store = model_->store();
  if (store) {
    auto tests = store->rigTests();
    if (tests) {
      QList<qint64> seen;
      for (const auto& t : *tests) {
        if (seen.contains(t.specimenId)) continue;
        seen.append(t.specimenId);
        specimen_->addItem(qs(t.specimenName), QVariant::fromValue<qlonglong>(t.specimenId));
      }
    }
  }
  const int at = specimen_->findData(QVariant::fromValue<qlonglong>(keep));
  if (at >= 0) specimen_->setCurrentIndex(at);
  filling_ = false;
}

void TwistAxesPage::fillTests() {
  const qint64 keepStatic = static_->currentData().toLongLong(), keepDynamic = dynamic_->currentData().toLongLong();
  const qint64 specimen = specimen_->currentData().toLongLong();
  filling_ = true;
  static_->clear();
  dynamic_->clear();
  static_->addItem(tr("(none)"), QVariant::fromValue<qlonglong>(0));
  dynamic_->addItem(tr("(none)"), QVariant::fromValue<qlonglong>(0));
  addImportedTests();
  core::io::ProjectStore* store = model_->store();
  if (store && specimen != 0) {
    auto tests = store->rigTests();
    if (tests) {
      for (const auto& t : *tests) {
        if (t.specimenId != specimen) continue;
        QComboBox* box = t.kind == "dynamic" ? dynamic_ : static_;
        box->addItem(qs(t.name), QVariant::fromValue<qlonglong>(t.id));
      }
    }
  }
  // The kept test, else the latest of each kind.
  for (auto [box, keep] : {std::pair<QComboBox*, qint64>{static_, keepStatic}, {dynamic_, keepDynamic}}) {
    const int at = box->findData(QVariant::fromValue<qlonglong>(keep));
    box->setCurrentIndex(keep != 0 && at >= 0 ? at : box->count() - 1);
  }
  filling_ = false;
}

// Imported static and dynamic files, listed after "(none)" with negative ids
// -(index + 1) into the import's files, whatever the specimen.
void TwistAxesPage::addImportedTests() {
  const auto& files = import_->files();
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (!files[i].view) continue;
    QComboBox* box = files[i].view->dynamic ? dynamic_ : static_;
    box->addItem(tr("%1 (imported)").arg(files[i].name),
                 QVariant::fromValue<qlonglong>(-static_cast<qlonglong>(i) - 1));
  }
}

void TwistAxesPage::showImported(int index) {
  const TwistCsvImport::File* f = import_->file(index);
  if (!f) return;
  fillTests();
  if (f->view) {
    QComboBox* box = f->view->dynamic ? dynamic_ : static_;
    filling_ = true;
    box->setCurrentIndex(box->findData(QVariant::fromValue<qlonglong>(-static_cast<qlonglong>(index) - 1)));
    filling_ = false;
  }
  loadTests();
}

bool TwistAxesPage::keepImported() {
  core::io::ProjectStore* store = model_->store();
  if (!store) {
    setStatus(tr("Open a project to keep the imported tests in."), true);
    return false;
  }
  qint64 specimen = specimen_->currentData().toLongLong();
  std::optional<qint64> kept[2];
  QStringList names;
  QComboBox* boxes[2] = {static_, dynamic_};
  for (int k = 0; k < 2; ++k) {
    const qint64 id = boxes[k]->currentData().toLongLong();
    if (id > 0) kept[k] = id;
    const TwistCsvImport::File* f = id < 0 ? import_->file(static_cast<int>(-id - 1)) : nullptr;
    if (!f || !f->view) continue;
    if (specimen == 0) {
      auto made =
          store->addSpecimen("imported twist tests", "imported", "plate CSV files imported on the Twist Axes page");
      if (!made) {
        setStatus(tr("Cannot add a specimen: %1").arg(qs(made.error().describe())), true);
        return false;
      }
      specimen = *made;
      model_->notifyChanged(RecordKind::Specimen, specimen);
    }
    auto r = rt::storeImportedTest(*store, specimen, *f->view, f->path.toStdString());
    if (!r) {
      setStatus(tr("Cannot keep %1: %2").arg(f->name, qs(r.error().describe())), true);
      return false;
    }
    kept[k] = *r;
    names << f->name;
  }
  if (names.isEmpty()) {
    setStatus(tr("Choose an imported static or dynamic test to keep."), true);
    return false;
  }
  model_->notifyChanged(RecordKind::RigTest);
  selectTests(kept[0], kept[1]);
  setStatus(tr("Kept in the project: %1").arg(names.join(QStringLiteral(", "))));
  return true;
}

bool TwistAxesPage::selectTests(std::optional<qint64> staticTest, std::optional<qint64> dynamicTest) {
  core::io::ProjectStore* store = model_->store();
  if (!store) return false;
  const qint64 any = staticTest ? *staticTest : (dynamicTest ? *dynamicTest : 0);
  auto test = store->rigTest(any);
  if (!test) return false;
  filling_ = true;
  const int s = specimen_->findData(QVariant::fromValue<qlonglong>(test->specimenId));
  if (s < 0) {
    filling_ = false;
    return false;
  }
  specimen_->setCurrentIndex(s);
  filling_ = false;
  fillTests();
  filling_ = true;
  const int a = static_->findData(QVariant::fromValue<qlonglong>(staticTest.value_or(0)));
  const int b = dynamic_->findData(QVariant::fromValue<qlonglong>(dynamicTest.value_or(0)));
  if (a >= 0) static_->setCurrentIndex(a);
  if (b >= 0) dynamic_->setCurrentIndex(b);
  filling_ = false;
  loadTests();
  return a >= 0 && b >= 0;
}

void TwistAxesPage::showRigTest(qint64 testId) {
  core::io::ProjectStore* store = model_->store();
  if (!store) return;
  auto test = store->rigTest(testId);
  if (!test) {
    setStatus(tr("Cannot read the rig test: %1").arg(qs(test.error().describe())), true);
    return;
  }
  fillSpecimens();
  const int s = specimen_->findData(QVariant::fromValue<qlonglong>(test->specimenId));
  if (s < 0) return;
  filling_ = true;
  specimen_->setCurrentIndex(s);
  filling_ = false;
  fillTests();  // the latest of each kind
  QComboBox* box = test->kind == core::io::StoredRigTest::Kind::Dynamic ? dynamic_ : static_;
  filling_ = true;
  box->setCurrentIndex(box->findData(QVariant::fromValue<qlonglong>(testId)));
  filling_ = false;
  loadTests();
}

void TwistAxesPage::loadTests() {
  *data_ = TwistAxesData{};
  core::io::ProjectStore* store = model_->store();
  QStringList problems;
  auto read = [&](QComboBox* box, std::optional<rt::StiffnessTestView>& into) {
    const qint64 id = box->currentData().toLongLong();
    if (id < 0) {
      if (const auto* f = import_->file(static_cast<int>(-id - 1)); f && f->view) into = f->view;
      return;
    }
    if (!store || id == 0) return;
    auto view = rt::readStiffnessTest(*store, id);
    if (view)
      into = std::move(view).value();
    else
      problems << tr("Cannot read '%1': %2").arg(box->currentText(), qs(view.error().describe()));
  };
  read(static_, data_->statics);
  read(dynamic_, data_->dynamics);
  if (const auto& modal = import_->modalAxes(); modal.file) {
    rt::StiffnessTestView plate;
    plate.name = modal.file->name.toStdString();
    plate.loadPoint = modal.file->csv.hasLoad ? modal.file->csv.load : core::Vector2::Zero();
    plate.laserPoints = modal.file->csv.sensors;
    data_->modalPlate = std::move(plate);
    if (!modal.problems.isEmpty()) problems << modal.problems;
  }
  if (data_->dynamics) {
    auto path = st::dynamicAxisPath(data_->dynamics->dynamicAxes(), data_->dynamics->loadPoint);
    if (path)
      data_->path = std::move(path).value();
    else
      problems << tr("No dynamic axis to trace: %1").arg(qs(path.error().describe()));
  }
  if (const auto* g = data_->geometry()) {
    const auto& catalogue = silhouetteCatalogue();
    std::string key = g->specimenKey;
    if (key.empty() && data_->dynamics) key = data_->dynamics->specimenKey;
    if (!catalogue) {
      data_->silhouetteError = qs(catalogue.error().describe());
    } else if (key.empty()) {
      data_->silhouetteError = tr("the test does not name a virtual specimen, so no outline is known");
    } else {
      auto placed = st::placeSilhouette(*catalogue, key, g->loadPoint);
      if (placed)
        data_->silhouette = std::move(placed).value();
      else
        data_->silhouetteError = qs(placed.error().describe());
    }
  }
  slider_->blockSignals(true);
  const int n = data_->path ? static_cast<int>(data_->path->points.size()) : 0;
  slider_->setRange(0, std::max(0, n - 1));
  slider_->setValue(0);
  slider_->setEnabled(n > 1);
  slider_->blockSignals(false);
  drawStatic();
  drawFrequency();
  if (!problems.isEmpty()) {
    setStatus(problems.join(QStringLiteral("\n")), true);
  } else if (!data_->statics && !data_->dynamics && !data_->modalPlate) {
    setStatus(store ? tr("No stiffness-rig test to show: run one on the Stiffness Rig page.")
                    : tr("No project is open."));
  } else {
    QStringList notes;
    for (const auto* v : {data_->statics ? &*data_->statics : nullptr, data_->dynamics ? &*data_->dynamics : nullptr})
      if (v && v->status != core::io::TestStatus::Complete)
        notes << tr("'%1' is %2: %3").arg(qs(v->name), qs(core::io::testStatusName(v->status)), qs(v->statusNote));
    setStatus(notes.join(QStringLiteral("\n")), !notes.isEmpty());
  }
}

void TwistAxesPage::drawStatic() {
  for (auto* m : markers_) delete m;
  markers_.clear();
  markerAlign_.clear();
  staticArm_->setSamples(QVector<QPointF>());
  extent_->setSamples(QVector<QPointF>());
  const TwistAxesData& d = *data_;
  const rt::StiffnessTestView* g = d.geometry();
  // The specimen and the plate set-up: the drawing the Stiffness Rig page's set-up view shares.
  PlateSketchInput sketch;
  sketch.silhouette = d.silhouette ? &*d.silhouette : nullptr;
  if (g) {
    sketch.laserPoints = g->laserPoints;
    sketch.loadPoint = g->loadPoint;
    sketch.plateOutline = g->plateOutline;
    if (!d.silhouette) sketch.constrainedEnd = g->constrainedEnd;
  }
  sketch_->draw(sketch);
  std::vector<core::Vector2> extent = sketch_->extent();
  if (d.silhouette) {
    silhouetteNote_->setText(tr("Outline: %1, approximate (not to scale of a drawing): %2")
                                 .arg(qs(d.silhouette->name), qs(d.silhouette->source)));
  } else {
    silhouetteNote_->setText(d.silhouetteError.isEmpty() ? QString()
                                                         : tr("No outline drawn: %1").arg(d.silhouetteError));
  }
  extent_->setSamples(points(extent));
  if (d.statics && d.statics->axis) {
    const core::Vector2 foot = st::footOf(*d.statics->axis, d.statics->loadPoint);
    staticArm_->setSamples(points({d.statics->loadPoint, foot}));
    auto* m = new QwtPlotMarker;
    const core::Vector2 mid = d.statics->loadPoint + 0.3 * (foot - d.statics->loadPoint);
    m->setValue(mid(0), mid(1));
    QwtText t(tr("a_tw"));
    t.setColor(kStaticColour);
    m->setLabel(t);
    m->setItemAttribute(QwtPlotItem::AutoScale, false);
    m->setZ(34);
    m->attach(plot_);
    markers_.push_back(m);
    markerAlign_.push_back(Qt::AlignTop);
  }
  staticAxisLabel_->setLabel(QwtText());
  // Every item is in: fit the view (equal aspect), then the axes across it.
  plot_->autoscale();
  fillTable();
  clipAxes();
}

void TwistAxesPage::drawFrequency() {
  const TwistAxesData& d = *data_;
  if (d.path && !d.path->points.empty()) {
    QVector<QPointF> feet;
    for (const auto& p : d.path->points) feet.append(QPointF(p.foot(0), p.foot(1)));
    path_->setSamples(feet);
    const auto& at = d.path->points[static_cast<std::size_t>(std::clamp(slider_->value(), 0, slider_->maximum()))];
    frequencyValue_->setText(tr("%1 Hz").arg(at.frequencyHz, 0, 'g', 4));
    dynamicFoot_->setValue(at.foot(0), at.foot(1));
    dynamicFoot_->show();
  } else {
    path_->setSamples(QVector<QPointF>());
    frequencyValue_->setText(QStringLiteral("-"));
    dynamicFoot_->hide();
  }
  fillTable();
  clipAxes();
}

std::optional<double> TwistAxesPage::shownFrequencyHz() const {
  if (!data_->path || data_->path->points.empty()) return std::nullopt;
  return data_->path->points[static_cast<std::size_t>(std::clamp(slider_->value(), 0, slider_->maximum()))].frequencyHz;
}

void TwistAxesPage::clipAxes() {
  const TwistAxesData& d = *data_;
  const QwtInterval x = plot_->axisInterval(QwtPlot::xBottom), y = plot_->axisInterval(QwtPlot::yLeft);
  st::PlaneBox view;
  view.include(core::Vector2(x.minValue(), y.minValue()));
  view.include(core::Vector2(x.maxValue(), y.maxValue()));
  // A line across the view, labelled near its upper end.
  const double centreU = 0.5 * (x.minValue() + x.maxValue());
  // Point labels on the side towards the view's centre, so none leaves it.
  auto place = [&](const std::vector<QwtPlotMarker*>& markers, const std::vector<Qt::Alignment>& align) {
    for (std::size_t i = 0; i < markers.size(); ++i)
      markers[i]->setLabelAlignment((markers[i]->xValue() < centreU ? Qt::AlignRight : Qt::AlignLeft) | align[i]);
  };
  place(sketch_->markers(), sketch_->markerAlignments());
  place(markers_, markerAlign_);
  // `along`: where the label sits, as a fraction of the segment from its upper
  // end (the four lines' labels apart from each other); other places along
  // the line are the label's fallbacks when another label is there.
  std::vector<LabelChoice> axisLabels;
  auto draw = [&](QwtPlotCurve* curve, QwtPlotMarker* tag, const std::optional<st::PlateAxis>& axis,
                  const QString& text, double along) {
    curve->setSamples(QVector<QPointF>());
    tag->setLabel(QwtText());
    if (!axis) return;
    auto seg = st::clipAxis(*axis, view);
    if (!seg) return;
    curve->setSamples(points({seg->from, seg->to}));
    const core::Vector2 top = seg->to(1) >= seg->from(1) ? seg->to : seg->from;
    const core::Vector2 other = seg->to(1) >= seg->from(1) ? seg->from : seg->to;
    const core::Vector2 at = top + along * (other - top);
    tag->setValue(at(0), at(1));
    LabelChoice choice{tag, {}};
    for (double step : {0.0, 0.08, -0.08, 0.16, -0.16, 0.24, -0.24, 0.32, -0.32, 0.4, -0.4, 0.5, -0.5, 0.6, -0.6}) {
      const double f = along + step;
      if (f < 0.03 || f > 0.97) continue;
      const core::Vector2 p = top + f * (other - top);
      const Qt::Alignment away = p(0) > centreU ? Qt::AlignLeft : Qt::AlignRight;
      const Qt::Alignment towards = away == Qt::AlignLeft ? Qt::AlignRight : Qt::AlignLeft;
      choice.spots.push_back({QPointF(p(0), p(1)), away | Qt::AlignVCenter});
      choice.spots.push_back({QPointF(p(0), p(1)), towards | Qt::AlignVCenter});
    }
    axisLabels.push_back(std::move(choice));
    QwtText t(text);
    t.setColor(curve->pen().color());
    QColor back(Qt::white);
    back.setAlpha(200);
    t.setBackgroundBrush(back);
    t.setFont(plot_->font());
    tag->setLabel(t);
    // The label on the side of the line away from the view's centre.
    tag->setLabelAlignment(at(0) > centreU ? Qt::AlignLeft | Qt::AlignVCenter : Qt::AlignRight | Qt::AlignVCenter);
  };
  const rt::StiffnessTestView* g = d.geometry();
  draw(staticAxis_, staticAxisLabel_, d.statics ? d.statics->axis : std::nullopt, tr("static twist axis"), 0.90);
  // The modal axes of an imported hammer test (§1.4, §1.7), else the set-up's.
  const auto& modal = import_->modalAxes();
  if (modal.file) {
    for (auto [curve, tag, axis, text, along] :
         {std::tuple<QwtPlotCurve*, QwtPlotMarker*, const std::optional<st::ModalAxis>*, QString, double>{
              bendAxis_, bendLabel_, &modal.bending, tr("bending axis (modal, %1 Hz)"), 0.08},
          {torsAxis_, torsLabel_, &modal.torsion, tr("torsion axis (modal, %1 Hz)"), 0.75}}) {
      draw(curve, tag, *axis ? std::optional<st::PlateAxis>((*axis)->axis.axis.axis) : std::nullopt,
           *axis ? text.arg((*axis)->frequencyHz, 0, 'g', 4) : QString(), along);
    }
  } else {
    draw(bendAxis_, bendLabel_, g ? g->bendAxis : std::nullopt, tr("bending axis (set-up)"), 0.08);
    draw(torsAxis_, torsLabel_, g ? g->torsAxis : std::nullopt, tr("torsion axis (set-up)"), 0.75);
  }
  std::optional<st::PlateAxis> dyn;
  QString dynText;
  if (d.path && !d.path->points.empty()) {
    const auto& at = d.path->points[static_cast<std::size_t>(std::clamp(slider_->value(), 0, slider_->maximum()))];
    dyn = at.axis;
    dynText = tr("dynamic twist axis, %1 Hz").arg(at.frequencyHz, 0, 'g', 4);
  }
  draw(dynamicAxis_, dynamicAxisLabel_, dyn, dynText, 0.22);
  separateLabels(axisLabels);
  plot_->replot();
}

// The labels apart (thesis figures are crowded near the load point): the
// points' labels first, each at the first clear spot around its point, then
// the axes' along their lines; none covers another or a marked point.
void TwistAxesPage::separateLabels(const std::vector<LabelChoice>& axisLabels) {
  std::vector<LabelChoice> labels;
  std::vector<QRectF> obstacles;
  auto around = [this](QPointF value, QSizeF size) {
    const QPointF at(plot_->transform(QwtPlot::xBottom, value.x()), plot_->transform(QwtPlot::yLeft, value.y()));
    return QRectF(at.x() - size.width() / 2.0, at.y() - size.height() / 2.0, size.width(), size.height());
  };
  std::vector<QwtPlotMarker*> points = sketch_->markers();
  points.insert(points.end(), markers_.begin(), markers_.end());
  for (QwtPlotMarker* m : points) {
    if (m->symbol()) obstacles.push_back(around(m->value(), m->symbol()->size()));
    if (m->label().isEmpty()) continue;
    const Qt::Alignment preferred = m->labelAlignment();
    const Qt::Alignment h = preferred & Qt::AlignHorizontal_Mask, v = preferred & Qt::AlignVertical_Mask;
    const Qt::Alignment otherH = h == Qt::AlignLeft ? Qt::AlignRight : Qt::AlignLeft;
    LabelChoice choice{m, {}};
    for (Qt::Alignment hh : {h, otherH, Qt::Alignment(Qt::AlignHCenter)})
      for (Qt::Alignment vv :
           {v, Qt::Alignment(Qt::AlignBottom), Qt::Alignment(Qt::AlignTop), Qt::Alignment(Qt::AlignVCenter)}) {
        if (hh == Qt::AlignHCenter && vv == Qt::AlignVCenter) continue;  // over its own point
        choice.spots.push_back({m->value(), hh | vv});
      }
    labels.push_back(std::move(choice));
  }
  const QwtSeriesData<QPointF>* lasers = sketch_->laserCurve()->data();
  for (std::size_t i = 0; i < lasers->size(); ++i)
    obstacles.push_back(around(lasers->sample(i), QSizeF(4, 4)));  // its label sits 2.5 px off
  if (dynamicFoot_->isVisible()) obstacles.push_back(around(dynamicFoot_->value(), QSizeF(10, 10)));
  labels.insert(labels.end(), axisLabels.begin(), axisLabels.end());
  placeMarkerLabels(plot_, labels, obstacles);
}

void TwistAxesPage::fillTable() {
  const TwistAxesData& d = *data_;
  struct Row {
    const char* key;
    QString label, tip;
  };
  const Row rows[] = {{"k_lat", tr("k_lat"), tr("lateral stiffness at the load point, F / x_lat (eq. 29)")},
                      {"k_tw", tr("k_tw"), tr("twist stiffness about the axis, k_lat a_tw² (eq. 30)")},
                      {"a_tw", tr("a_tw"), tr("twist arm: distance of the load point from the axis")},
                      {"axis_inclination", tr("β"), tr("inclination of the axis from the plate's v axis towards u")},
                      {"axis_point_u", tr("foot u"), tr("u of the axis's point nearest the load point")},
                      {"axis_point_v", tr("foot v"), tr("v of the axis's point nearest the load point")}};
  const rt::StiffnessTestView::Step* step = nullptr;
  if (d.dynamics && d.path && !d.path->points.empty()) {
    const double f = *shownFrequencyHz();
    for (const auto& s : d.dynamics->steps)
      if (s.frequencyHz == f) step = &s;
  }
  table_->setRowCount(static_cast<int>(std::size(rows)));
  for (int r = 0; r < static_cast<int>(std::size(rows)); ++r) {
    const auto& row = rows[r];
    const rt::StoredQuantity* s = d.statics ? d.statics->result(row.key) : nullptr;
    const rt::StoredQuantity* dy = nullptr;
    if (step) {
      const auto it = step->results.find(row.key);
      if (it != step->results.end()) dy = &it->second;
    }
    const QString items[] = {row.label, withSigma(s), withSigma(dy)};
    for (int c = 0; c < 3; ++c) {
      auto* item = new QTableWidgetItem(items[c]);
      if (c > 0) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      item->setData(Qt::UserRole, QString::fromLatin1(row.key));
      item->setToolTip(c == 0 ? row.tip : items[c]);
      table_->setItem(r, c, item);
    }
  }
  table_->setHorizontalHeaderItem(
      2, new QTableWidgetItem(shownFrequencyHz() ? tr("Dynamic, %1 Hz").arg(*shownFrequencyHz(), 0, 'g', 4)
                                                 : tr("Dynamic")));
  table_->resizeColumnsToContents();
  table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  // As tall as its rows: the page's free height goes to the plot's side panel stretch.
  int h = table_->horizontalHeader()->height() + 2 * table_->frameWidth();
  for (int r = 0; r < table_->rowCount(); ++r) h += table_->rowHeight(r);
  table_->setFixedHeight(h);
}

QString TwistAxesPage::silhouetteText() const {
  return data_->silhouette ? qs(data_->silhouette->name + ": " + data_->silhouette->source) : QString();
}

QString TwistAxesPage::statusText() const {
  return status_->text();
}

QStringList TwistAxesPage::plotLabels() const {
  QStringList out;
  for (const QwtPlotItem* item : plot_->itemList(QwtPlotItem::Rtti_PlotMarker)) {
    const auto* m = static_cast<const QwtPlotMarker*>(item);
    if (m->isVisible() && !m->label().isEmpty()) out << m->label().text();
  }
  return out;
}

void TwistAxesPage::setStatus(const QString& text, bool error) {
  status_->setText(text);
  status_->setStyleSheet(error ? QStringLiteral("color: #b00000;") : QString());
  if (error && !text.isEmpty()) emit message(text);
}

}  // namespace views
}  // namespace mozzi
