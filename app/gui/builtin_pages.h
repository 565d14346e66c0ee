#pragma once
// The table of the workbench's pages: one entry per page, in the order the
// menus list them (docs/workbench-pages.md says how to add one).

namespace mozzi {
namespace views {
class PageRegistry;
}  // namespace views
namespace app {

// Adds every built-in page to `registry`.
void registerBuiltinPages(views::PageRegistry& registry);

}  // namespace app
}  // namespace mozzi
