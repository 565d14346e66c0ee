#pragma once
// A DOF as the workbench shows it ("21:+Z", core::formatDof): one helper for
// every page and plot.

#include <QString>

#include "core/common/dof.h"

namespace mozzi {
namespace views {

inline QString dofText(const core::Dof& dof) {
  return QString::fromStdString(core::formatDof(dof));
}

}  // namespace views
}  // namespace mozzi
