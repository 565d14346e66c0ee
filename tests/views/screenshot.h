#pragma once
// The screenshot the page tests save for the user guide: into
// $MOZZI_SCREENSHOT_DIR (ctest sets build/screenshots), named `name`.png, or
// `name`@2x.png on a high-DPI screen (QT_SCALE_FACTOR=2), as every page test names them. Waits a moment first, so the
// layout has taken the sizes of texts set just before (`settleMs`: longer where a page lays out results posted just
// before).
#include <QDir>
#include <QString>
#include <QTest>
#include <QWidget>

namespace mozzi::views::test {

inline bool saveShot(QWidget& w, const QString& name, int settleMs = 50) {
  QTest::qWait(settleMs);
  const QDir dir(qEnvironmentVariable("MOZZI_SCREENSHOT_DIR", QDir::tempPath()));
  QDir().mkpath(dir.path());
  const bool hiDpi = w.devicePixelRatioF() > 1.0;
  return w.grab().save(dir.filePath(name + (hiDpi ? QStringLiteral("@2x.png") : QStringLiteral(".png"))));
}

}  // namespace mozzi::views::test
