#pragma once
// What the Stiffness and Lumped Fork page tests share: the demo project they
// open (the rig tests and identified modes `mozzi-cli project demo` writes)
// and the screenshot they save into MOZZI_SCREENSHOT_DIR (name@2x.png under
// QT_SCALE_FACTOR=2), as the user guide's figures.
#include <QApplication>
#include <QDir>
#include <QTemporaryDir>
#include <QtTest>

#include "views/common/project_model.h"
#include "views/screenshot.h"

namespace stiffness_pages {

inline void saveShot(QWidget& page, const QString& name) {
  // Results posted just before are laid out first.
  mozzi::views::test::saveShot(page, name, 200);
}

// Creates the demo project in `dir` and opens it in `model`; the error text, empty when it worked.
inline QString openDemo(mozzi::views::ProjectModel& model, const QTemporaryDir& dir) {
  if (!dir.isValid()) return QStringLiteral("no temporary folder");
  auto created = model.createDemo(dir.filePath(QStringLiteral("demo.mozzi")));
  return created.ok() ? QString() : QString::fromStdString(created.error().describe());
}

// Shows `page` at 1280 x 800 (logical pixels) and waits until it is on screen.
inline bool showAt1280x800(QWidget& page) {
  page.resize(1280, 800);
  page.show();
  return QTest::qWaitForWindowExposed(&page);
}

}  // namespace stiffness_pages
