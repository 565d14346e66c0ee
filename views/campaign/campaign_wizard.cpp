#include "views/campaign/campaign_wizard.h"

#include <QComboBox>
#include <QEvent>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QScrollArea>
#include <QTabWidget>
#include <QVBoxLayout>
#include <QWizardPage>
#include <set>

#include "core/geometry/mesh_templates.h"
#include "devices/campaign/campaign_form.h"
#include "devices/campaign/campaign_store.h"
#include "devices/campaign/virtual_campaign.h"
#include "devices/common/driver.h"
#include "devices/sim/specimen_catalogue.h"
#include "devices/sim/specimen_models.h"
#include "views/common/project_model.h"
#include "views/panels/parameter_form.h"

namespace mozzi {
namespace views {

namespace cp = devices::campaign;

namespace {

QWizardPage* makePage(QWizard* wizard, int id, const QString& name, QLabel** intro, QWidget* body) {
  auto* page = new QWizardPage(wizard);
  page->setObjectName(name);
  auto* layout = new QVBoxLayout(page);
  *intro = new QLabel(page);
  (*intro)->setWordWrap(true);
  layout->addWidget(*intro);
  auto* scroll = new QScrollArea(page);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setWidget(body);
  layout->addWidget(scroll, 1);
  wizard->setPage(id, page);
  return page;
}

// The station driver's parameters (a simulated station is created to read
// them; a real one only when it is plugged in).
std::vector<devices::ParameterSpec> driverSpecs(const std::string& driverName) {
  devices::Driver* driver = devices::builtinDrivers().find(driverName);
  if (!driver) return {};
  auto found = driver->scan();
  if (!found || found->empty()) return {};
  auto device = driver->create(found->front());
  if (!device) return {};
  return (*device)->capabilities().parameters;
}

}  // namespace

CampaignWizard::CampaignWizard(ProjectModel* model, QWidget* parent) : QWizard(parent), model_(model) {
  setObjectName(QStringLiteral("campaignWizard"));
  setWizardStyle(QWizard::ClassicStyle);
  setOption(QWizard::NoBackButtonOnStartPage, true);
  resize(760, 560);
  intro_.resize(6, nullptr);

  // 1. Specimen and station
  auto* specimenBody = new QWidget;
  auto* specimenLayout = new QFormLayout(specimenBody);
  virtual_ = new QComboBox(specimenBody);
  virtual_->setObjectName(QStringLiteral("wizardVirtualSpecimen"));
  for (const auto& e : devices::sim::specimenCatalogue())
    virtual_->addItem(QString::fromStdString(e.name), QString::fromStdString(e.key));
  specimen_ = new QComboBox(specimenBody);
  specimen_->setObjectName(QStringLiteral("wizardSpecimen"));
  driver_ = new QComboBox(specimenBody);
  driver_->setObjectName(QStringLiteral("wizardStation"));
  driver_->addItem(QStringLiteral("-"), QStringLiteral("sim-hammer"));
  driver_->addItem(QStringLiteral("-"), QStringLiteral("mcc-usb1608fsplus"));
  name_ = new QLineEdit(specimenBody);
  name_->setObjectName(QStringLiteral("wizardName"));
  specimenLayout->addRow(QStringLiteral("-"), virtual_);
  specimenLayout->addRow(QStringLiteral("-"), specimen_);
  specimenLayout->addRow(QStringLiteral("-"), name_);
  specimenLayout->addRow(QStringLiteral("-"), driver_);
  makePage(this, SpecimenPage, QStringLiteral("wizardSpecimenPage"), &intro_[0], specimenBody);

  // 2. Template mesh and points
  auto* meshBody = new QWidget;
  auto* meshLayout = new QVBoxLayout(meshBody);
  template_ = new QComboBox(meshBody);
  template_->setObjectName(QStringLiteral("wizardTemplate"));
  for (const auto& t : core::geometry::meshTemplates())
    template_->addItem(QString::fromStdString(t.name), QString::fromStdString(t.key));
  templateNotes_ = new QLabel(meshBody);
  templateNotes_->setWordWrap(true);
  points_ = new QListWidget(meshBody);
  points_->setObjectName(QStringLiteral("wizardPoints"));
  meshLayout->addWidget(template_);
  meshLayout->addWidget(templateNotes_);
  meshLayout->addWidget(points_, 1);
  makePage(this, MeshPage, QStringLiteral("wizardMeshPage"), &intro_[1], meshBody);

  // 3.-6. Forms from ParameterSpec lists
  constraint_ = new ParameterForm(cp::formSpecs(cp::FormSection::Constraint));
  constraint_->setObjectName(QStringLiteral("wizardConstraintForm"));
  makePage(this, ConstraintPage, QStringLiteral("wizardConstraintPage"), &intro_[2], constraint_);
  excitation_ = new ParameterForm(cp::formSpecs(cp::FormSection::Excitation));
  excitation_->setObjectName(QStringLiteral("wizardExcitationForm"));
  makePage(this, ExcitationPage, QStringLiteral("wizardExcitationPage"), &intro_[3], excitation_);
  channelTabs_ = new QTabWidget;
  channelTabs_->setObjectName(QStringLiteral("wizardChannels"));
  makePage(this, TransducerPage, QStringLiteral("wizardTransducerPage"), &intro_[4], channelTabs_);
  auto* acquisitionBody = new QWidget;
  auto* acquisitionLayout = new QVBoxLayout(acquisitionBody);
  acquisition_ = new ParameterForm(cp::formSpecs(cp::FormSection::Acquisition), acquisitionBody);
  acquisition_->setObjectName(QStringLiteral("wizardAcquisitionForm"));
  stationBox_ = new QGroupBox(acquisitionBody);
  auto* stationLayout = new QVBoxLayout(stationBox_);
  station_ = new ParameterForm(stationBox_);
  stationLayout->addWidget(station_);
  station_->setObjectName(QStringLiteral("wizardStationForm"));
  problem_ = new QLabel(acquisitionBody);
  problem_->setObjectName(QStringLiteral("wizardProblem"));
  problem_->setWordWrap(true);
  problem_->setStyleSheet(QStringLiteral("QLabel { color: #b3261e; }"));
  acquisitionLayout->addWidget(acquisition_);
  acquisitionLayout->addWidget(stationBox_);
  acquisitionLayout->addWidget(problem_);
  acquisitionLayout->addStretch(1);
  makePage(this, AcquisitionPage, QStringLiteral("wizardAcquisitionPage"), &intro_[5], acquisitionBody);

  connect(virtual_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] {
    rebuildFromVirtualSpecimen();
    reloadSpecimens();
  });
  connect(template_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] { fillPoints(); });
  connect(driver_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] {
    rebuildFromVirtualSpecimen();
    retranslate();
  });

  rebuildFromVirtualSpecimen();
  reloadSpecimens();
  retranslate();
}

CampaignWizard::~CampaignWizard() = default;

ParameterForm* CampaignWizard::channelForm(int channel) const {
  return channel >= 0 && channel < channelCount() ? channels_[static_cast<std::size_t>(channel)] : nullptr;
}

QString CampaignWizard::problemText() const {
  return problem_->text();
}

void CampaignWizard::reloadSpecimens() {
  const QSignalBlocker block(specimen_);
  specimen_->clear();
  const std::string key = virtual_->currentData().toString().toStdString();
  const auto* entry = devices::sim::findSpecimen(key);
  const std::string catalogueName = entry ? entry->name : std::string();
  const std::string shortName = catalogueName.substr(0, catalogueName.find(", "));
  int match = -1;
  if (core::io::ProjectStore* store = model_->store()) {
    if (auto summary = store->summary()) {
      for (const auto& s : summary->specimens) {
        specimen_->addItem(QString::fromStdString(s.name), QVariant::fromValue<qlonglong>(s.id));
        if (s.name == catalogueName || s.name == shortName) match = specimen_->count() - 1;
      }
    }
  }
  if (match < 0) {  // the specimen is added to the project when the wizard finishes
    specimen_->addItem(tr("New specimen: %1").arg(QString::fromStdString(shortName)),
                       QVariant::fromValue<qlonglong>(0));
    match = specimen_->count() - 1;
  }
  specimen_->setCurrentIndex(match);
  if (name_->text().isEmpty() || name_->property("auto").toBool()) {
    name_->setText(tr("%1 hammer campaign").arg(QString::fromStdString(key)));
    name_->setProperty("auto", true);
  }
}

void CampaignWizard::rebuildFromVirtualSpecimen() {
  const std::string key = virtual_->currentData().toString().toStdString();
  auto def = cp::virtualSpecimenCampaign(key);
  if (!def) {
    base_.reset();
    showProblem(QString::fromStdString(def.error().describe()));
    return;
  }
  base_ = std::move(def).value();
  base_->meshTemplate = devices::sim::meshTemplateKey(key);
  // A real station: the same set-up, the DAQ's own parameters (read from
  // the device when it is plugged in, else its defaults).
  const std::string driver = driver_->currentData().toString().toStdString();
  if (!driver.empty() && driver != base_->driver) {
    base_->driver = driver;
    base_->deviceParameters.clear();
  }
  {
    const QSignalBlocker block(template_);
    const int index = template_->findData(QString::fromStdString(base_->meshTemplate));
    if (index >= 0) template_->setCurrentIndex(index);
  }
  fillPoints();
  // A value the forms refuse is shown by its field (ParameterForm); the
  // first one is also named under the acquisition page.
  QString problem;
  const auto note = [&problem](const core::Result<void>& r) {
    if (!r && problem.isEmpty()) problem = QString::fromStdString(r.error().describe());
  };
  note(constraint_->setValues(cp::formValues(*base_, cp::FormSection::Constraint)));
  note(excitation_->setValues(cp::formValues(*base_, cp::FormSection::Excitation)));
  note(acquisition_->setValues(cp::formValues(*base_, cp::FormSection::Acquisition)));
  for (ParameterForm* form : channels_) form->deleteLater();
  channels_.clear();
  channelTabs_->clear();
  for (std::size_t c = 0; c < base_->channels.size(); ++c) {
    auto* form = new ParameterForm(cp::formSpecs(cp::FormSection::Channel));
    form->setObjectName(QStringLiteral("wizardChannel%1").arg(c));
    note(form->setValues(cp::formValues(*base_, cp::FormSection::Channel, c)));
    if (base_->channels[c].roving) {
      if (auto* dof = qobject_cast<QLineEdit*>(form->editor("channel.dof"))) {
        dof->setEnabled(false);
        dof->setPlaceholderText(tr("roving: the point being measured"));
      }
    }
    channels_.push_back(form);
    const auto& ch = base_->channels[c];
    channelTabs_->addTab(form, tr("AI%1: %2").arg(ch.input).arg(QString::fromStdString(ch.name)));
  }
  station_->setSpecs(driverSpecs(base_->driver));
  note(station_->setValues(base_->deviceParameters));
  showProblem(problem);
}

void CampaignWizard::fillPoints() {
  points_->clear();
  const auto* t = core::geometry::findMeshTemplate(template_->currentData().toString().toStdString());
  if (!t) return;
  templateNotes_->setText(QString::fromStdString(t->source + (t->notes.empty() ? "" : ". " + t->notes)));
  // The points of the virtual specimen's own template are those it was
  // modelled on; another template lists its own measurement DOFs.
  const bool own = base_ && t->key == base_->meshTemplate;
  const std::vector<core::Dof>& dofs = own ? base_->points : t->measurementDofs;
  for (const auto& dof : dofs) {
    auto* item = new QListWidgetItem(QString::fromStdString(core::formatDof(dof)), points_);
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(Qt::Checked);
  }
}

core::Result<cp::CampaignDefinition> CampaignWizard::definition() const {
  if (!base_) return core::makeError(core::ErrorCode::InvalidArgument, "choose a virtual specimen", "specimen");
  cp::CampaignDefinition d = *base_;
  d.meshTemplate = template_->currentData().toString().toStdString();
  d.points.clear();
  for (int i = 0; i < points_->count(); ++i) {
    if (points_->item(i)->checkState() != Qt::Checked) continue;
    auto dof = core::parseDof(points_->item(i)->text().toStdString());
    if (!dof) return dof.error();
    d.points.push_back(*dof);
  }
  if (d.points.empty())
    return core::makeError(core::ErrorCode::InvalidArgument, "tick at least one point to measure", "points");
  if (d.driver == "sim-hammer") {  // the simulated specimen answers only at its own DOFs
    const std::set<core::Dof> known(base_->points.begin(), base_->points.end());
    for (const auto& p : d.points)
      if (!known.count(p))
        return core::makeError(core::ErrorCode::InvalidArgument,
                               "the simulated specimen has no DOF " + core::formatDof(p) + ": choose its own template",
                               "mesh template");
  }
  if (auto r = cp::applyForm(d, cp::FormSection::Constraint, constraint_->values()); !r) return r.error();
  if (auto r = cp::applyForm(d, cp::FormSection::Excitation, excitation_->values()); !r) return r.error();
  if (auto r = cp::applyForm(d, cp::FormSection::Acquisition, acquisition_->values()); !r) return r.error();
  for (std::size_t c = 0; c < channels_.size() && c < d.channels.size(); ++c)
    if (auto r = cp::applyForm(d, cp::FormSection::Channel, channels_[c]->values(), c); !r) return r.error();
  // Station parameters: those the campaign set, and those changed from the driver's defaults.
  for (const auto& spec : station_->specs()) {
    const auto value = station_->values().at(spec.key);
    if (d.deviceParameters.count(spec.key) || !(value == spec.defaultValue)) d.deviceParameters[spec.key] = value;
  }
  if (auto v = d.validate(); !v) return v.error();
  return d;
}

void CampaignWizard::showProblem(const QString& text) {
  problem_->setText(text);
  problem_->setVisible(!text.isEmpty());
}

void CampaignWizard::accept() {
  auto d = definition();
  if (!d) {
    showProblem(tr("The campaign cannot be made: %1").arg(QString::fromStdString(d.error().describe())));
    return;
  }
  core::io::ProjectStore* store = model_->store();
  if (!store) {
    showProblem(tr("No project is open."));
    return;
  }
  qint64 specimenId = specimen_->currentData().toLongLong();
  if (specimenId == 0) {
    const auto* entry = devices::sim::findSpecimen(d->specimenKey);
    const std::string name = entry ? entry->name.substr(0, entry->name.find(", ")) : d->specimenKey;
    auto added = model_->addSpecimen(QString::fromStdString(name), QString::fromStdString(entry ? entry->kind : ""),
                                     tr("virtual specimen %1").arg(QString::fromStdString(d->specimenKey)));
    if (!added) {
      showProblem(tr("Cannot add the specimen: %1").arg(QString::fromStdString(added.error().describe())));
      return;
    }
    specimenId = *added;
  }
  // A specimen without a mesh gets the campaign's template: the points are its
  // nodes, and the hammer station marks them on it. A mesh of its own is kept.
  if (const auto* t = core::geometry::findMeshTemplate(d->meshTemplate)) {
    auto existing = store->mesh(specimenId);
    if (!existing || existing->nodes.empty()) {
      if (auto set = model_->setMesh(specimenId, t->mesh); !set) {
        showProblem(tr("Cannot store the mesh: %1").arg(QString::fromStdString(set.error().describe())));
        return;
      }
    }
  }
  auto id = cp::createCampaign(*store, specimenId, name_->text().trimmed().toStdString(), *d,
                               tr("made with the new-campaign wizard").toStdString());
  if (!id) {
    showProblem(tr("Cannot store the campaign: %1").arg(QString::fromStdString(id.error().describe())));
    return;
  }
  created_ = *id;
  model_->notifyChanged(RecordKind::Campaign, specimenId);
  emit campaignCreated(created_);
  QWizard::accept();
}

void CampaignWizard::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWizard::changeEvent(event);
}

void CampaignWizard::retranslate() {
  setWindowTitle(tr("New Hammer Campaign"));
  page(SpecimenPage)->setTitle(tr("Specimen and station"));
  page(MeshPage)->setTitle(tr("Measurement mesh"));
  page(ConstraintPage)->setTitle(tr("Constraint"));
  page(ExcitationPage)->setTitle(tr("Excitation"));
  page(TransducerPage)->setTitle(tr("Transducers"));
  page(AcquisitionPage)->setTitle(tr("Acquisition and rejection rules"));
  intro_[0]->setText(
      tr("The specimen to test, its model in the simulated station, and the station. The campaign starts from "
         "the set-up of the thesis for that specimen; every later page can change it."));
  intro_[1]->setText(
      tr("The template mesh the points come from. Untick the points you will not measure; they are "
         "measured in the order shown."));
  intro_[2]->setText(tr("How the specimen is held during the test."));
  intro_[3]->setText(
      tr("Roving hammer or roving accelerometer, the fixed point, and how many accepted hits each "
         "point averages."));
  intro_[4]->setText(
      tr("The transducer on each input: model, serial, sensitivity from its calibration sheet, and "
         "where it measures."));
  intro_[5]->setText(
      tr("How each hit is recorded and which hits are rejected automatically; below, the station's "
         "own parameters."));
  driver_->setItemText(0, tr("Simulated hammer station (sim-hammer)"));
  driver_->setItemText(1, tr("MCC USB-1608FS-Plus (real DAQ)"));
  if (auto* form = qobject_cast<QFormLayout*>(specimen_->parentWidget()->layout())) {
    if (auto* l = qobject_cast<QLabel*>(form->labelForField(driver_))) l->setText(tr("Station:"));
    if (auto* l = qobject_cast<QLabel*>(form->labelForField(virtual_))) l->setText(tr("Virtual specimen:"));
    if (auto* l = qobject_cast<QLabel*>(form->labelForField(specimen_))) l->setText(tr("Project specimen:"));
    if (auto* l = qobject_cast<QLabel*>(form->labelForField(name_))) l->setText(tr("Campaign name:"));
  }
  station_->setToolTip(tr("The station driver's parameters"));
  stationBox_->setTitle(base_ ? tr("Station parameters (%1)").arg(QString::fromStdString(base_->driver))
                              : tr("Station parameters"));
  stationBox_->setToolTip(station_->specs().empty() ? tr("Plug the device in to see and set its parameters")
                                                    : QString());
}

}  // namespace views
}  // namespace mozzi
