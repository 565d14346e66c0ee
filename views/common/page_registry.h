#pragma once
// Pages registered once, in one table (WORKBENCH.md "Pages, registered once";
// the shape of app/cli/command.h's CommandRegistrar). The main window builds
// its Pages/Tools menu entries and the project tree's "Open in ..." actions in
// one loop over this table and opens pages as tabs. The table itself is one
// function, app/gui/builtin_pages.cpp: registerBuiltinPages(), one entry per
// page (static registrars in a static library would be dropped by the linker).
// How to add a page: docs/workbench-pages.md.

#include <QMetaType>
#include <QString>
#include <QtGlobal>
#include <functional>
#include <vector>

#include "views/common/project_model.h"

class QWidget;

namespace mozzi {
namespace views {

class JobRunner;
class PageRegistry;

// A record of the open project a page can be opened on.
struct ProjectItem {
  ProjectItem() = default;
  ProjectItem(RecordKind recordKind, qint64 recordId, qint64 specimen, QString kindOfAnalysis = {})
      : kind(recordKind), id(recordId), specimenId(specimen), analysisKind(std::move(kindOfAnalysis)) {}

  RecordKind kind = RecordKind::None;  // None: a page opened from a menu
  qint64 id = 0;                       // the record's id (the specimen's for Specimen and Mesh)
  qint64 specimenId = 0;               // the specimen the record belongs to (0 if none or unknown)
  // Analysis only: the stored analysis's kind ("stability", "wheelchair",
  // "gap-diagnosis"), so that the page of that kind claims it.
  QString analysisKind;

  bool operator==(const ProjectItem& o) const { return kind == o.kind && id == o.id && specimenId == o.specimenId; }
  bool operator!=(const ProjectItem& o) const { return !(*this == o); }
};

// What a page factory gets.
struct PageContext {
  ProjectModel* model = nullptr;  // the one document; never null
  JobRunner* jobs = nullptr;      // long work off the GUI thread; never null
  ProjectItem item;               // what the page was opened on
  QWidget* parent = nullptr;      // parent for the page widget
  // Writes a line to the window's log (timestamped there); may be empty in tests.
  std::function<void(const QString&)> log;
  // The page table and a way to open another page (the Overview's start
  // list); null or empty in tests that build a page alone.
  const PageRegistry* registry = nullptr;
  std::function<QWidget*(const QString& pageId, const ProjectItem& item)> openPage = {};
};

// Where a page appears for opening without a project item.
enum class PageMenu { None, Pages, Tools };

struct PageSpec {
  QString id;                     // stable, e.g. "frf-plot"; tab keys and tests use it
  const char* title = nullptr;    // QT_TRANSLATE_NOOP("Pages", "FRF Plot"): menu text and tab title
  const char* summary = nullptr;  // QT_TRANSLATE_NOOP("Pages", ...) status tip; may be null
  QString iconPath;               // ":/icons/..." (vector), may be empty
  PageMenu menu = PageMenu::None;
  // Which project items open this page (double-click, "Open in ..."); null: none.
  std::function<bool(const ProjectItem&)> opensItem;
  // Builds the page. Required.
  std::function<QWidget*(const PageContext&)> create;
  // One tab for the whole window (raised when opened again); otherwise one tab per item.
  bool singleton = false;
  // Opened when the window starts.
  bool openAtStart = false;
  // Optional, for singletons: shows another item (ctx.item) in the existing
  // page. Also called when the project tree's selection moves to an item the
  // page opens, so the page follows the selection (the 3-D view shows the
  // selected specimen's mesh).
  std::function<void(QWidget* page, const PageContext& ctx)> showItem;
};

class PageRegistry {
 public:
  // Adds a page; false (and nothing added) when the id is taken, the id is
  // empty, or title or create is missing.
  bool add(PageSpec spec);
  const std::vector<PageSpec>& pages() const { return pages_; }
  const PageSpec* find(const QString& id) const;
  // Pages that open `item`, in registration order (the first is the default).
  std::vector<const PageSpec*> pagesFor(const ProjectItem& item) const;
  // The translated title of a page (context "Pages").
  static QString title(const PageSpec& spec);
  static QString summary(const PageSpec& spec);

 private:
  std::vector<PageSpec> pages_;
};

}  // namespace views
}  // namespace mozzi

Q_DECLARE_METATYPE(mozzi::views::ProjectItem)
