#pragma once
// The new-campaign wizard (issue 15): specimen and station, template mesh and
// the points to measure, constraint, excitation, transducers, acquisition.
// Every form is built by the one form builder (ParameterForm) from
// ParameterSpec lists: the campaign's own (devices/campaign/campaign_form.h)
// and the station driver's. It starts from the campaign a technician would
// set up on the chosen virtual specimen (virtualSpecimenCampaign) and ends
// with a definition the engine accepts, stored in the project with
// devices::campaign::createCampaign.

#include <QWizard>
#include <optional>
#include <vector>

#include "devices/campaign/campaign_definition.h"

class QComboBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QTabWidget;

namespace mozzi {
namespace views {

class ParameterForm;
class ProjectModel;

class CampaignWizard : public QWizard {
  Q_OBJECT
 public:
  enum PageId { SpecimenPage, MeshPage, ConstraintPage, ExcitationPage, TransducerPage, AcquisitionPage };

  explicit CampaignWizard(ProjectModel* model, QWidget* parent = nullptr);
  ~CampaignWizard() override;

  // The definition as the forms now describe it (validated), or the error
  // naming the field.
  core::Result<devices::campaign::CampaignDefinition> definition() const;
  // The campaign made when the wizard finished (0 before).
  qint64 createdCampaign() const { return created_; }

  // For tests: the widgets a user fills in.
  QComboBox* specimenBox() const { return specimen_; }
  QComboBox* virtualSpecimenBox() const { return virtual_; }
  QComboBox* stationBox() const { return driver_; }
  QComboBox* templateBox() const { return template_; }
  QListWidget* pointList() const { return points_; }
  QLineEdit* nameEdit() const { return name_; }
  ParameterForm* constraintForm() const { return constraint_; }
  ParameterForm* excitationForm() const { return excitation_; }
  ParameterForm* acquisitionForm() const { return acquisition_; }
  ParameterForm* stationForm() const { return station_; }
  ParameterForm* channelForm(int channel) const;
  int channelCount() const { return static_cast<int>(channels_.size()); }
  QString problemText() const;

  void accept() override;

 signals:
  void campaignCreated(qint64 campaignId);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void reloadSpecimens();
  void rebuildFromVirtualSpecimen();  // the base definition and every form
  void fillPoints();
  void showProblem(const QString& text);

  ProjectModel* model_;
  std::optional<devices::campaign::CampaignDefinition> base_;
  qint64 created_ = 0;

  QComboBox* specimen_ = nullptr;
  QComboBox* virtual_ = nullptr;
  QComboBox* driver_ = nullptr;
  QLineEdit* name_ = nullptr;
  QComboBox* template_ = nullptr;
  QLabel* templateNotes_ = nullptr;
  QListWidget* points_ = nullptr;
  ParameterForm* constraint_ = nullptr;
  ParameterForm* excitation_ = nullptr;
  QTabWidget* channelTabs_ = nullptr;
  std::vector<ParameterForm*> channels_;
  ParameterForm* acquisition_ = nullptr;
  ParameterForm* station_ = nullptr;
  QGroupBox* stationBox_ = nullptr;
  QLabel* problem_ = nullptr;
  std::vector<QLabel*> intro_;
};

}  // namespace views
}  // namespace mozzi
