#pragma once
// Mode animation on the open project: the modes of every modal result (each on
// its specimen's mesh), the chosen result's first mode shown, its FRF set (when
// the result names one) for operating deflection shapes. Re-reads when modal
// results or meshes change.

#include <QWidget>

namespace mozzi {
namespace views {

class ModeAnimationView;
class ProjectModel;

class ModeAnimationPage : public QWidget {
  Q_OBJECT
 public:
  // `modalResultId` 0: the first result of the project.
  ModeAnimationPage(ProjectModel* model, qint64 modalResultId, QWidget* parent = nullptr);
  ModeAnimationView* view() const { return view_; }
  void reload();

 signals:
  void message(const QString& text);

 private:
  ProjectModel* model_;
  qint64 resultId_;
  ModeAnimationView* view_ = nullptr;
};

}  // namespace views
}  // namespace mozzi
