#pragma once
// The status-bar face of the JobRunner: the newest running job's title, its
// progress and a Cancel button, "+N more" when several run; hidden when idle.

#include <QWidget>

class QLabel;
class QProgressBar;
class QToolButton;

namespace mozzi {
namespace views {

class JobRunner;

class JobStatusWidget : public QWidget {
  Q_OBJECT
 public:
  explicit JobStatusWidget(JobRunner* jobs, QWidget* parent = nullptr);

  int shownJob() const { return shown_; }  // 0 when idle
  QString text() const;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void refresh();
  void retranslate();

  JobRunner* jobs_ = nullptr;
  QLabel* label_ = nullptr;
  QProgressBar* bar_ = nullptr;
  QToolButton* cancel_ = nullptr;
  int shown_ = 0;
};

}  // namespace views
}  // namespace mozzi
