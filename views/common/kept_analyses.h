#pragma once
// The "Kept results" list of a page that keeps its computations in the
// project as analyses of one kind (Stability, Wheelchair): one entry per
// stored analysis, "NAME (analysis ID)", its id as the item's data.

#include <QtGlobal>
#include <string>
#include <vector>

class QComboBox;

namespace mozzi {
namespace views {

class ProjectModel;

// Fills `box` with the open project's analyses of `kind`, in id order, keeping
// the current entry when it is still there (else the last, the newest);
// disabled when there is none. Returns the number of entries.
int fillKeptAnalyses(QComboBox* box, const ProjectModel* project, const std::string& kind);

// The analysis ids `box` lists, in its order.
std::vector<qint64> keptAnalysisIds(const QComboBox* box);

}  // namespace views
}  // namespace mozzi
