#include "views/common/page_registry.h"

#include <QCoreApplication>

namespace mozzi {
namespace views {

bool PageRegistry::add(PageSpec spec) {
  if (spec.id.isEmpty() || !spec.title || !spec.create || find(spec.id)) return false;
  pages_.push_back(std::move(spec));
  return true;
}

const PageSpec* PageRegistry::find(const QString& id) const {
  for (const auto& page : pages_) {
    if (page.id == id) return &page;
  }
  return nullptr;
}

std::vector<const PageSpec*> PageRegistry::pagesFor(const ProjectItem& item) const {
  std::vector<const PageSpec*> out;
  if (item.kind == RecordKind::None) return out;
  for (const auto& page : pages_) {
    if (page.opensItem && page.opensItem(item)) out.push_back(&page);
  }
  return out;
}

QString PageRegistry::title(const PageSpec& spec) {
  return spec.title ? QCoreApplication::translate("Pages", spec.title) : QString();
}

QString PageRegistry::summary(const PageSpec& spec) {
  return spec.summary ? QCoreApplication::translate("Pages", spec.summary) : QString();
}

}  // namespace views
}  // namespace mozzi
