#include "views/common/page_tabs.h"

#include <QEvent>
#include <QIcon>
#include <QLayout>
#include <QScrollArea>
#include <QVariant>
#include <algorithm>

namespace mozzi {
namespace views {

namespace {
// Each page widget carries what it was opened as.
const char* const kPropPage = "mozziPageId";
const char* const kPropKind = "mozziItemKind";
const char* const kPropId = "mozziItemId";
const char* const kPropSpecimen = "mozziItemSpecimen";
const char* const kPropAnalysisKind = "mozziItemAnalysisKind";

void setItem(QWidget* page, const ProjectItem& item) {
  page->setProperty(kPropKind, static_cast<int>(item.kind));
  page->setProperty(kPropId, QVariant::fromValue<qlonglong>(item.id));
  page->setProperty(kPropSpecimen, QVariant::fromValue<qlonglong>(item.specimenId));
  page->setProperty(kPropAnalysisKind, item.analysisKind);
}

// What a page's scroll area holds: the page, as large as the viewport down to
// the least size its layout allows (plots at their minimum, wrapped labels at
// their height for the width). Put in the scroll area directly, a page with a
// wrapped label would be laid out at its preferred height for the width (Qt's
// height-for-width rule) and scroll at 1280x800 although its plots could shrink.
class PageHolder : public QWidget {
 public:
  explicit PageHolder(QWidget* page, QWidget* parent) : QWidget(parent), page_(page) {
    page_->setParent(this);
    page_->installEventFilter(this);
  }
  QWidget* page() const { return page_; }
  QSize minimumSizeHint() const override {
    QSize least = page_->minimumSizeHint().expandedTo(page_->minimumSize());
    if (QLayout* l = page_->layout(); l && l->hasHeightForWidth())
      least.setHeight(std::max(least.height(), l->minimumHeightForWidth(std::max(width(), least.width()))));
    return least;
  }
  QSize sizeHint() const override { return minimumSizeHint(); }

 protected:
  void resizeEvent(QResizeEvent*) override { page_->setGeometry(rect()); }
  bool event(QEvent* e) override {
    if (e->type() == QEvent::LayoutRequest) updateGeometry();  // the page's least size changed
    return QWidget::event(e);
  }
  bool eventFilter(QObject* watched, QEvent* e) override {
    if (watched == page_ && e->type() == QEvent::LayoutRequest) updateGeometry();
    return QWidget::eventFilter(watched, e);
  }

 private:
  QWidget* page_;
};

}  // namespace

PageTabs::PageTabs(const PageRegistry* registry, ProjectModel* model, JobRunner* jobs, QWidget* parent)
    : QTabWidget(parent), registry_(registry), model_(model), jobs_(jobs) {
  setObjectName(QStringLiteral("workArea"));
  setDocumentMode(true);
  setMovable(true);
  setTabsClosable(true);
  connect(this, &QTabWidget::tabCloseRequested, this, [this](int index) {
    QWidget* holder = widget(index);
    removeTab(index);
    holder->deleteLater();
  });
  // Item pages show records of the project they were opened in.
  connect(model_, &ProjectModel::projectChanged, this, &PageTabs::closeItemPages);
  // Record names in tab titles may change with the records.
  connect(model_, &ProjectModel::recordsChanged, this, &PageTabs::retitle);
}

QWidget* PageTabs::page(int index) const {
  auto* holder = qobject_cast<QScrollArea*>(widget(index));
  auto* inner = holder ? dynamic_cast<PageHolder*>(holder->widget()) : nullptr;
  return inner ? inner->page() : nullptr;
}

QWidget* PageTabs::currentPage() const {
  return page(currentIndex());
}

int PageTabs::indexOfPage(const QWidget* page) const {
  for (int i = 0; i < count(); ++i) {
    if (this->page(i) == page) return i;
  }
  return -1;
}

void PageTabs::setCurrentPage(QWidget* page) {
  if (const int index = indexOfPage(page); index >= 0) setCurrentIndex(index);
}

const PageSpec* PageTabs::specOf(const QWidget* page) const {
  return page ? registry_->find(page->property(kPropPage).toString()) : nullptr;
}

ProjectItem PageTabs::itemOf(const QWidget* page) const {
  if (!page) return {};
  return ProjectItem{static_cast<RecordKind>(page->property(kPropKind).toInt()), page->property(kPropId).toLongLong(),
                     page->property(kPropSpecimen).toLongLong(), page->property(kPropAnalysisKind).toString()};
}

QWidget* PageTabs::findPage(const QString& pageId, const ProjectItem& item) const {
  const PageSpec* spec = registry_->find(pageId);
  if (!spec) return nullptr;
  for (int i = 0; i < count(); ++i) {
    QWidget* page = this->page(i);
    if (page->property(kPropPage).toString() != pageId) continue;
    if (spec->singleton) return page;
    const ProjectItem shown = itemOf(page);
    if (shown.kind == item.kind && shown.id == item.id) return page;
  }
  return nullptr;
}

QWidget* PageTabs::openPage(const QString& pageId, const ProjectItem& item) {
  const PageSpec* spec = registry_->find(pageId);
  if (!spec) return nullptr;
  if (item.kind != RecordKind::None && !(spec->opensItem && spec->opensItem(item))) return nullptr;
  if (QWidget* page = findPage(pageId, item)) {
    if (spec->singleton && item.kind != RecordKind::None && spec->showItem) {
      spec->showItem(page, context(item));
      setItem(page, item);
    }
    setCurrentPage(page);
    return page;
  }
  QWidget* page = spec->create(context(item));
  if (!page) return nullptr;
  if (page->objectName().isEmpty()) page->setObjectName(spec->id + QStringLiteral("Page"));
  page->setProperty(kPropPage, spec->id);
  setItem(page, item);
  if (spec->singleton && item.kind != RecordKind::None && spec->showItem) spec->showItem(page, context(item));
  // Each page sits in a scroll area: a page taller or wider than the window
  // scrolls instead of growing the window past a 1280x800 screen.
  auto* holder = new QScrollArea(this);
  holder->setObjectName(spec->id + QStringLiteral("Holder"));
  holder->setFrameShape(QFrame::NoFrame);
  holder->setWidgetResizable(true);
  holder->setWidget(new PageHolder(page, holder));
  const int index = addTab(holder, spec->iconPath.isEmpty() ? QIcon() : QIcon(spec->iconPath), tabTitle(*spec, item));
  setTabToolTip(index, PageRegistry::summary(*spec));
  setCurrentIndex(index);
  return page;
}

QWidget* PageTabs::openItem(const ProjectItem& item) {
  const auto pages = registry_->pagesFor(item);
  return pages.empty() ? nullptr : openPage(pages.front()->id, item);
}

void PageTabs::openStartPages() {
  for (const PageSpec& spec : registry_->pages()) {
    if (spec.openAtStart) openPage(spec.id);
  }
  if (count() > 0) setCurrentIndex(0);
}

void PageTabs::followSelection(const ProjectItem& item) {
  if (item.kind == RecordKind::None) return;
  for (int i = 0; i < count(); ++i) {
    QWidget* page = this->page(i);
    const PageSpec* spec = specOf(page);
    if (!spec || !spec->singleton || !spec->showItem || !spec->opensItem || !spec->opensItem(item)) continue;
    spec->showItem(page, context(item));
    setItem(page, item);
  }
}

PageContext PageTabs::context(const ProjectItem& item) {
  return PageContext{
      model_, jobs_, item, this, log_, registry_, [this](const QString& pageId, const ProjectItem& target) {
        return openPage(pageId, target);
      }};
}

QString PageTabs::tabTitle(const PageSpec& spec, const ProjectItem& item) const {
  const QString title = PageRegistry::title(spec);
  if (spec.singleton || item.kind == RecordKind::None) return title;
  const QString name = model_->recordName(item.kind, item.id);
  return name.isEmpty() ? tr("%1 %2").arg(title).arg(item.id) : tr("%1: %2").arg(title, name);
}

void PageTabs::retitle() {
  for (int i = 0; i < count(); ++i) {
    if (const PageSpec* spec = specOf(page(i))) setTabText(i, tabTitle(*spec, itemOf(page(i))));
  }
}

void PageTabs::closeItemPages() {
  for (int i = count() - 1; i >= 0; --i) {
    QWidget* page = this->page(i);
    const PageSpec* spec = specOf(page);
    if (spec && !spec->singleton && itemOf(page).kind != RecordKind::None) {
      QWidget* holder = widget(i);
      removeTab(i);
      holder->deleteLater();
    }
  }
  retitle();
}

void PageTabs::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retitle();
  QTabWidget::changeEvent(event);
}

}  // namespace views
}  // namespace mozzi
