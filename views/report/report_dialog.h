#pragma once
// The workbench's Report dialog (issue 23): which sections (check boxes, in
// report order), which specimen (or all), the language, and the outputs (PDF
// file and/or HTML folder). It opens on the project's report template
// (core/report/report_template.h) and saves the choice back into the project
// when accepted, so `mozzi-cli report` without --sections writes the same
// report.

#include <QDialog>
#include <QString>
#include <vector>

#include "core/report/report_template.h"

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace mozzi {
namespace views {

class ProjectModel;

class ReportDialog : public QDialog {
  Q_OBJECT
 public:
  // Reads the template of `model`'s project (the defaults when it has none or
  // cannot be read: every section, every specimen, English, PDF).
  explicit ReportDialog(ProjectModel* model, QWidget* parent = nullptr);

  core::report::ReportTemplate reportTemplate() const;
  void setReportTemplate(const core::report::ReportTemplate& t);
  QString pdfPath() const;
  QString htmlDir() const;
  void setPdfPath(const QString& path);
  void setHtmlDir(const QString& dir);
  // Saves the template into the project; false with *error when it cannot
  // (a read-only project). accept() calls it.
  bool saveTemplate(QString* error = nullptr);
  QCheckBox* sectionBox(const std::string& key) const;
  QComboBox* specimenBox() const { return specimen_; }
  QComboBox* languageBox() const { return language_; }

  void accept() override;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void updateOk();

  ProjectModel* model_;
  std::vector<std::pair<std::string, QCheckBox*>> sections_;
  QLabel* sectionsLabel_ = nullptr;
  QLabel* specimenLabel_ = nullptr;
  QComboBox* specimen_ = nullptr;
  QLabel* languageLabel_ = nullptr;
  QComboBox* language_ = nullptr;
  QCheckBox* pdf_ = nullptr;
  QLineEdit* pdfPath_ = nullptr;
  QPushButton* pdfBrowse_ = nullptr;
  QCheckBox* html_ = nullptr;
  QLineEdit* htmlDir_ = nullptr;
  QPushButton* htmlBrowse_ = nullptr;
  QLabel* status_ = nullptr;
  QDialogButtonBox* buttons_ = nullptr;
};

// The translated name of a report section key ("Modal parameters").
QString reportSectionTitle(const std::string& key);

}  // namespace views
}  // namespace mozzi
