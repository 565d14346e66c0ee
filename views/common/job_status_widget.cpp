#include "views/common/job_status_widget.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QToolButton>

#include "views/common/job_runner.h"

namespace mozzi {
namespace views {

JobStatusWidget::JobStatusWidget(JobRunner* jobs, QWidget* parent) : QWidget(parent), jobs_(jobs) {
  setObjectName(QStringLiteral("jobStatus"));
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  label_ = new QLabel(this);
  bar_ = new QProgressBar(this);
  bar_->setRange(0, 1000);
  bar_->setTextVisible(false);
  bar_->setMaximumWidth(fontMetrics().averageCharWidth() * 20);
  bar_->setMaximumHeight(fontMetrics().height());
  cancel_ = new QToolButton(this);
  cancel_->setObjectName(QStringLiteral("jobCancel"));
  cancel_->setAutoRaise(true);
  layout->addWidget(label_);
  layout->addWidget(bar_);
  layout->addWidget(cancel_);
  connect(cancel_, &QToolButton::clicked, this, [this] {
    if (shown_) jobs_->cancel(shown_);
  });
  connect(jobs_, &JobRunner::jobStarted, this, &JobStatusWidget::refresh);
  connect(jobs_, &JobRunner::jobFinished, this, &JobStatusWidget::refresh);
  connect(jobs_, &JobRunner::jobProgress, this, [this](int id, double fraction, const QString& step) {
    if (id != shown_) return;
    bar_->setValue(static_cast<int>(fraction * 1000.0));
    bar_->setToolTip(step);
  });
  retranslate();
  refresh();
}

QString JobStatusWidget::text() const {
  return label_->text();
}

void JobStatusWidget::refresh() {
  const QList<int> running = jobs_->runningJobs();
  shown_ = running.isEmpty() ? 0 : running.last();
  if (parentWidget()) setVisible(shown_ != 0);  // never pops up as a window of its own
  if (!shown_) return;
  QString text = jobs_->title(shown_);
  if (running.size() > 1) text += QLatin1Char(' ') + tr("(+%n more)", nullptr, running.size() - 1);
  label_->setText(text);
  bar_->setValue(static_cast<int>(jobs_->fraction(shown_) * 1000.0));
  bar_->setToolTip(jobs_->step(shown_));
}

void JobStatusWidget::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) {
    retranslate();
    refresh();
  }
  QWidget::changeEvent(event);
}

void JobStatusWidget::retranslate() {
  cancel_->setText(tr("Cancel"));
  cancel_->setToolTip(tr("Stop this job"));
}

}  // namespace views
}  // namespace mozzi
