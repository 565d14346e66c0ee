#pragma once
// MAC or AutoMAC matrix as a coloured grid with the value in every cell
// (colours from core::heatColour). A QwtPlot, so it exports like every plot:
// PNG/SVG/PDF draw the grid; the CSV holds one curve per row (x = column
// number, y = MAC), invisible on screen.

#include <qwt_plot.h>

#include <QStringList>

#include "core/common/eigen_types.h"

namespace mozzi {
namespace views {

class MacPlot : public QwtPlot {
  Q_OBJECT
 public:
  explicit MacPlot(QWidget* parent = nullptr);
  // values: rows x cols in [0, 1]; labels name rows (y) and columns (x).
  void setMatrix(const core::Matrix& values, const QStringList& rowLabels, const QStringList& columnLabels);
  const core::Matrix& matrix() const { return values_; }

 private:
  core::Matrix values_;
  class MacGridItem* grid_ = nullptr;
};

}  // namespace views
}  // namespace mozzi
