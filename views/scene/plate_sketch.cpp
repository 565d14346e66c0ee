#include "views/scene/plate_sketch.h"

#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_marker.h>
#include <qwt_symbol.h>
#include <qwt_text.h>
#include <QCoreApplication>
#include <QFile>

// The silhouettes' resource lives in this static library (views/CMakeLists.txt);
// Q_INIT_RESOURCE must be called outside any namespace.
static void initSilhouetteResource() {
  Q_INIT_RESOURCE(silhouettes);
}

namespace mozzi {
namespace views {

namespace st = core::stiffness;

namespace {

const QColor kSilhouetteColour(120, 120, 120);
const QColor kLaserColour(220, 0, 0);
const QColor kPlateColour(90, 140, 200);

QString qs(const std::string& s) {
  return QString::fromStdString(s);
}

// The labels were first written for the Twist Axes page; they keep its
// translation context (QT_TRANSLATE_NOOP at each call, so lupdate finds them).
QString text(const char* source) {
  return QCoreApplication::translate("TwistAxesPage", source);
}

QVector<QPointF> points(const std::vector<core::Vector2>& v, bool closed) {
  QVector<QPointF> out;
  for (const auto& p : v) out.append(QPointF(p(0), p(1)));
  if (closed && !v.empty()) out.append(QPointF(v.front()(0), v.front()(1)));
  return out;
}

QwtPlotCurve* curve(QwtPlot* plot, const QColor& colour, double width, double z) {
  auto* c = new QwtPlotCurve;
  c->setPen(QPen(colour, width));
  c->setRenderHint(QwtPlotItem::RenderAntialiased, true);
  c->setItemAttribute(QwtPlotItem::Legend, false);
  c->setZ(z);
  c->attach(plot);
  return c;
}

}  // namespace

const core::Result<st::SilhouetteCatalogue>& silhouetteCatalogue() {
  static const core::Result<st::SilhouetteCatalogue> catalogue = [] {
    initSilhouetteResource();
    QFile file(QStringLiteral(":/silhouettes/silhouettes.json"));
    if (!file.open(QIODevice::ReadOnly))
      return core::Result<st::SilhouetteCatalogue>(
          core::makeError(core::ErrorCode::NotFound, "the silhouettes resource is missing", "silhouettes.json"));
    return st::parseSilhouettes(file.readAll().toStdString());
  }();
  return catalogue;
}

QString silhouettePointName(const std::string& name) {
  static const char* const kNames[] = {QT_TRANSLATE_NOOP("TwistAxesPoints", "steering head"),
                                       QT_TRANSLATE_NOOP("TwistAxesPoints", "swing-arm pivot"),
                                       QT_TRANSLATE_NOOP("TwistAxesPoints", "wheel hub"),
                                       QT_TRANSLATE_NOOP("TwistAxesPoints", "wheel contact point"),
                                       QT_TRANSLATE_NOOP("TwistAxesPoints", "wheel axle"),
                                       QT_TRANSLATE_NOOP("TwistAxesPoints", "dropouts"),
                                       QT_TRANSLATE_NOOP("TwistAxesPoints", "steerer tube")};
  for (const char* n : kNames)
    if (name == n) return QCoreApplication::translate("TwistAxesPoints", n);
  return qs(name);
}

PlateSketch::PlateSketch(QwtPlot* plot) : plot_(plot) {
  lasers_ = curve(plot_, kLaserColour, 1.0, 30);
  lasers_->setStyle(QwtPlotCurve::NoCurve);
  lasers_->setSymbol(new QwtSymbol(QwtSymbol::Ellipse, QBrush(kLaserColour), QPen(kLaserColour), QSize(7, 7)));
  plate_ = curve(plot_, kPlateColour, 1.5, 12);
}

PlateSketch::~PlateSketch() {
  clear();
  delete lasers_;
  delete plate_;
}

void PlateSketch::clear() {
  for (auto* c : silhouette_) delete c;
  silhouette_.clear();
  for (auto* m : markers_) delete m;
  markers_.clear();
  markerAlign_.clear();
  extent_.clear();
  lasers_->setSamples(QVector<QPointF>());
  plate_->setSamples(QVector<QPointF>());
}

void PlateSketch::draw(const PlateSketchInput& in) {
  clear();
  auto pointMarker = [&](const core::Vector2& at, QwtSymbol::Style style, const QColor& pen, const QBrush& brush,
                         int size, const QString& label, Qt::Alignment align) {
    auto* m = new QwtPlotMarker;
    m->setValue(at(0), at(1));
    m->setSymbol(new QwtSymbol(style, brush, QPen(pen, 1.5), QSize(size, size)));
    if (!label.isEmpty()) {
      QwtText t(label);
      t.setColor(pen);
      QColor back(Qt::white);
      back.setAlpha(200);
      t.setBackgroundBrush(back);
      m->setLabel(t);
      m->setLabelAlignment(align);
    }
    m->setZ(35);
    m->setItemAttribute(QwtPlotItem::AutoScale, false);
    m->attach(plot_);
    markers_.push_back(m);
    markerAlign_.push_back(align & Qt::AlignVertical_Mask);
  };
  if (in.silhouette) {
    for (const auto& poly : in.silhouette->polygons) {
      auto* c = curve(plot_, kSilhouetteColour, 1.5, 10);
      c->setSamples(points(poly, true));
      silhouette_.push_back(c);
    }
    if (in.silhouette->centreOfGravity) {
      extent_.push_back(*in.silhouette->centreOfGravity);
      pointMarker(*in.silhouette->centreOfGravity, QwtSymbol::Ellipse, QColor(0, 150, 0), QBrush(Qt::NoBrush), 13,
                  text(QT_TRANSLATE_NOOP("TwistAxesPage", "centre of gravity (estimated)")),
                  Qt::AlignRight | Qt::AlignBottom);
    }
  }
  const std::optional<core::Vector2> locked =
      in.constrainedEnd ? in.constrainedEnd
                        : (in.silhouette ? std::optional<core::Vector2>(in.silhouette->constrainedEnd) : std::nullopt);
  if (locked) {
    const QString name = in.silhouette ? silhouettePointName(in.silhouette->constrainedEndName)
                                       : QCoreApplication::translate("PlateSketch", "specimen's end");
    pointMarker(*locked, QwtSymbol::Rect, QColor(60, 60, 60), QBrush(QColor(60, 60, 60), Qt::BDiagPattern), 14,
                text(QT_TRANSLATE_NOOP("TwistAxesPage", "%1 (constrained)")).arg(name), Qt::AlignLeft | Qt::AlignTop);
    extent_.push_back(*locked);
  }
  if (!in.plateOutline.empty()) {
    plate_->setSamples(points(in.plateOutline, true));
    for (const auto& p : in.plateOutline) extent_.push_back(p);
  }
  lasers_->setSamples(points(in.laserPoints, false));
  for (std::size_t i = 0; i < in.laserPoints.size(); ++i) {
    auto* m = new QwtPlotMarker;
    m->setValue(in.laserPoints[i](0), in.laserPoints[i](1));
    QwtText t(text(QT_TRANSLATE_NOOP("TwistAxesPage", "L%1")).arg(i + 1));
    t.setColor(QColor(200, 0, 0));
    m->setLabel(t);
    m->setLabelAlignment(Qt::AlignRight | Qt::AlignBottom);
    m->setItemAttribute(QwtPlotItem::AutoScale, false);
    m->setZ(34);
    m->attach(plot_);
    markers_.push_back(m);
    markerAlign_.push_back(Qt::AlignBottom);
  }
  if (in.loadPoint) {
    const QString load = in.silhouette ? text(QT_TRANSLATE_NOOP("TwistAxesPage", "load point (%1)"))
                                             .arg(silhouettePointName(in.silhouette->loadPointName))
                                       : text(QT_TRANSLATE_NOOP("TwistAxesPage", "load point"));
    pointMarker(*in.loadPoint, QwtSymbol::Ellipse, Qt::black, QBrush(Qt::black), 12, load,
                Qt::AlignRight | Qt::AlignBottom);
    extent_.push_back(*in.loadPoint);
  }
}

}  // namespace views
}  // namespace mozzi
