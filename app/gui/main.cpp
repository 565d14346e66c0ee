// mozzi: the GUI workbench. Usage: mozzi [PROJECT.mozzi]
#include <QApplication>
#include <QCommandLineParser>
#include <QFileInfo>

#include "app/build_info.h"
#include "app/gui/main_window.h"
#include "views/scene/scene_view.h"

int main(int argc, char** argv) {
  mozzi::views::SceneView::prepareSurfaceFormat();  // before QApplication (VTK)
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("Mozzi"));
  QApplication::setApplicationName(QStringLiteral("Mozzi"));
  QApplication::setApplicationVersion(QString::fromLatin1(mozzi::buildinfo::kMozziVersion));

  QCommandLineParser parser;
  parser.setApplicationDescription(QApplication::translate("main", "Structural dynamics workbench"));
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument(QStringLiteral("project"), QApplication::translate("main", "Project file to open"));
  QCommandLineOption screenshot(QStringLiteral("screenshot"),
                                QApplication::translate("main", "Save a screenshot of the window to FILE and quit."),
                                QStringLiteral("FILE"));
  parser.addOption(screenshot);
  parser.process(app);

  mozzi::app::MainWindow window;
  window.show();
  if (!parser.positionalArguments().isEmpty()) window.openProject(parser.positionalArguments().constFirst());

  if (parser.isSet(screenshot)) {
    // For documentation and for checking a build by eye: render, grab, quit.
    const QString file = parser.value(screenshot);
    QMetaObject::invokeMethod(
        &window,
        [&window, file] {
          const bool ok = window.grab().save(file);
          QApplication::exit(ok ? 0 : 1);
        },
        Qt::QueuedConnection);
  }
  return app.exec();
}
