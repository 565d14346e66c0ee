#pragma once
// The screenshot the page tests save for the user guide: into
// $MOZZI_SCREENSHOT_DIR (ctest sets build/screenshots), named `name`.png, or
// `name`_x2.png under QT_SCALE_FACTOR=2. Waits a moment first, so the layout
// has taken the sizes of texts set just before.
#include <QDir>
#include <QString>
#include <QTest>
#include <QWidget>

namespace mozzi::views::test {

inline bool saveShot(QWidget& w, const QString& name) {
  QTest::qWait(50);
  const QDir dir(qEnvironmentVariable("MOZZI_SCREENSHOT_DIR", QDir::tempPath()));
  QDir().mkpath(dir.path());
  const QString scale = qEnvironmentVariable("QT_SCALE_FACTOR");
  const QString file = scale.isEmpty() || scale == QLatin1String("1") ? name : name + QStringLiteral("_x") + scale;
  return w.grab().save(dir.filePath(file + QStringLiteral(".png")));
}

}  // namespace mozzi::views::test
