#include "views/report/report_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFileDialog>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>
#include <algorithm>

#include "core/report/project_report.h"
#include "views/common/project_model.h"

namespace mozzi {
namespace views {

QString reportSectionTitle(const std::string& key) {
  // The headings of core's catalogue (report_text_it.cpp) as the dialog shows them.
  static const std::pair<const char*, const char*> titles[] = {
      {"title", QT_TRANSLATE_NOOP("ReportDialog", "Project and specimens")},
      {"frf", QT_TRANSLATE_NOOP("ReportDialog", "Frequency response functions")},
      {"modal", QT_TRANSLATE_NOOP("ReportDialog", "Modal parameters")},
      {"stiffness", QT_TRANSLATE_NOOP("ReportDialog", "Stiffness tests")},
      {"tyre", QT_TRANSLATE_NOOP("ReportDialog", "Tyre tests")},
      {"gap", QT_TRANSLATE_NOOP("ReportDialog", "Gap diagnoses")},
      {"stability", QT_TRANSLATE_NOOP("ReportDialog", "Stability against speed")},
      {"wheelchair", QT_TRANSLATE_NOOP("ReportDialog", "Wheelchair manoeuvres")},
  };
  for (const auto& [k, title] : titles)
    if (key == k) return QCoreApplication::translate("ReportDialog", title);
  // A section added later: its heading from core's catalogue.
  return QString::fromStdString(core::report::sectionHeading(key));
}

ReportDialog::ReportDialog(ProjectModel* model, QWidget* parent) : QDialog(parent), model_(model) {
  auto* layout = new QVBoxLayout(this);
  sectionsLabel_ = new QLabel(this);
  layout->addWidget(sectionsLabel_);
  auto* grid = new QGridLayout;
  const auto& keys = core::report::reportSectionKeys();
  for (std::size_t i = 0; i < keys.size(); ++i) {
    auto* box = new QCheckBox(this);
    box->setObjectName(QString::fromStdString("section-" + keys[i]));
    grid->addWidget(box, static_cast<int>(i / 2), static_cast<int>(i % 2));
    sections_.emplace_back(keys[i], box);
    connect(box, &QCheckBox::toggled, this, &ReportDialog::updateOk);
  }
  layout->addLayout(grid);

  auto* form = new QFormLayout;
  specimenLabel_ = new QLabel(this);
  specimen_ = new QComboBox(this);
  specimen_->addItem(QString(), QString());  // every specimen
  if (auto summary = model_->summary())
    for (const auto& s : summary->specimens)
      specimen_->addItem(QString::fromStdString(s.name), QString::fromStdString(s.name));
  form->addRow(specimenLabel_, specimen_);
  languageLabel_ = new QLabel(this);
  language_ = new QComboBox(this);
  language_->addItem(QStringLiteral("English"), QStringLiteral("en"));  // each in its own language
  language_->addItem(QStringLiteral("Italiano"), QStringLiteral("it"));
  form->addRow(languageLabel_, language_);
  layout->addLayout(form);

  auto output = [this, layout](QCheckBox*& check, QLineEdit*& edit, QPushButton*& browse) {
    auto* row = new QHBoxLayout;
    check = new QCheckBox(this);
    edit = new QLineEdit(this);
    browse = new QPushButton(this);
    row->addWidget(check);
    row->addWidget(edit, 1);
    row->addWidget(browse);
    layout->addLayout(row);
    connect(check, &QCheckBox::toggled, edit, &QWidget::setEnabled);
    connect(check, &QCheckBox::toggled, this, &ReportDialog::updateOk);
    connect(edit, &QLineEdit::textChanged, this, &ReportDialog::updateOk);
  };
  output(pdf_, pdfPath_, pdfBrowse_);
  output(html_, htmlDir_, htmlBrowse_);
  connect(pdfBrowse_, &QPushButton::clicked, this, [this] {
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Report PDF"), pdfPath_->text(), tr("PDF documents (*.pdf)"));
    if (!path.isEmpty()) pdfPath_->setText(path);
  });
  connect(htmlBrowse_, &QPushButton::clicked, this, [this] {
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Report HTML folder"), htmlDir_->text());
    if (!dir.isEmpty()) htmlDir_->setText(dir);
  });
  status_ = new QLabel(this);
  status_->setWordWrap(true);
  layout->addWidget(status_);
  buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  connect(buttons_, &QDialogButtonBox::accepted, this, &ReportDialog::accept);
  connect(buttons_, &QDialogButtonBox::rejected, this, &ReportDialog::reject);
  layout->addWidget(buttons_);

  core::report::ReportTemplate t;
  if (model_->store()) {
    auto saved = core::report::loadReportTemplate(*model_->store());
    if (saved && *saved) t = **saved;
    if (!saved)
      status_->setText(
          tr("The project's report template cannot be read: %1").arg(QString::fromStdString(saved.error().describe())));
  }
  setReportTemplate(t);
  retranslate();
}

core::report::ReportTemplate ReportDialog::reportTemplate() const {
  core::report::ReportTemplate t;
  bool all = true;
  for (const auto& [key, box] : sections_) {
    if (box->isChecked())
      t.sections.push_back(key);
    else
      all = false;
  }
  if (all) t.sections.clear();  // every section, including those added later
  t.specimen = specimen_->currentData().toString().toStdString();
  t.language = language_->currentData().toString() == QLatin1String("it") ? core::report::Language::Italian
                                                                          : core::report::Language::English;
  t.pdf = pdf_->isChecked();
  t.html = html_->isChecked();
  return t;
}

void ReportDialog::setReportTemplate(const core::report::ReportTemplate& t) {
  for (const auto& [key, box] : sections_)
    box->setChecked(t.sections.empty() || std::find(t.sections.begin(), t.sections.end(), key) != t.sections.end());
  const int specimen = specimen_->findData(QString::fromStdString(t.specimen));
  specimen_->setCurrentIndex(specimen < 0 ? 0 : specimen);
  language_->setCurrentIndex(t.language == core::report::Language::Italian ? 1 : 0);
  pdf_->setChecked(t.pdf);
  html_->setChecked(t.html);
  pdfPath_->setEnabled(t.pdf);
  htmlDir_->setEnabled(t.html);
  updateOk();
}

QString ReportDialog::pdfPath() const {
  return pdf_->isChecked() ? pdfPath_->text() : QString();
}
QString ReportDialog::htmlDir() const {
  return html_->isChecked() ? htmlDir_->text() : QString();
}
void ReportDialog::setPdfPath(const QString& path) {
  pdfPath_->setText(path);
}
void ReportDialog::setHtmlDir(const QString& dir) {
  htmlDir_->setText(dir);
}

QCheckBox* ReportDialog::sectionBox(const std::string& key) const {
  for (const auto& [k, box] : sections_)
    if (k == key) return box;
  return nullptr;
}

bool ReportDialog::saveTemplate(QString* error) {
  if (!model_->store()) return false;
  auto saved = core::report::saveReportTemplate(*model_->store(), reportTemplate());
  if (!saved && error) *error = QString::fromStdString(saved.error().describe());
  return saved.ok();
}

void ReportDialog::accept() {
  QString error;
  if (!saveTemplate(&error)) {
    // The report is still written; the template is not kept.
    status_->setText(tr("The report template was not saved: %1").arg(error));
  }
  QDialog::accept();
}

void ReportDialog::updateOk() {
  bool anySection = false;
  for (const auto& entry : sections_) anySection = anySection || entry.second->isChecked();
  const bool pdfOk = !pdf_->isChecked() || !pdfPath_->text().trimmed().isEmpty();
  const bool htmlOk = !html_->isChecked() || !htmlDir_->text().trimmed().isEmpty();
  const bool output = pdf_->isChecked() || html_->isChecked();
  if (auto* ok = buttons_ ? buttons_->button(QDialogButtonBox::Ok) : nullptr)
    ok->setEnabled(anySection && pdfOk && htmlOk && output);
}

void ReportDialog::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QDialog::changeEvent(event);
}

void ReportDialog::retranslate() {
  setWindowTitle(tr("Report"));
  sectionsLabel_->setText(tr("Sections (each is left out when the project has no data for it):"));
  for (const auto& [key, box] : sections_) box->setText(reportSectionTitle(key));
  specimenLabel_->setText(tr("Specimen:"));
  specimen_->setItemText(0, tr("Every specimen"));
  languageLabel_->setText(tr("Report language:"));
  pdf_->setText(tr("PDF"));
  html_->setText(tr("HTML folder"));
  pdfBrowse_->setText(tr("Browse..."));
  htmlBrowse_->setText(tr("Browse..."));
}

}  // namespace views
}  // namespace mozzi
