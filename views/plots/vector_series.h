#pragma once
// Qwt series over core vectors without copying (STYLE 11): the curve reads the
// samples straight from the Eigen vectors, which the series keeps alive.

#include <qwt_series_data.h>

#include <memory>

#include "core/common/eigen_types.h"

namespace mozzi {
namespace views {

class VectorSeries : public QwtSeriesData<QPointF> {
 public:
  VectorSeries(std::shared_ptr<const core::Vector> x, std::shared_ptr<const core::Vector> y);

  size_t size() const override;
  QPointF sample(size_t i) const override;
  QRectF boundingRect() const override;

 private:
  std::shared_ptr<const core::Vector> x_;
  std::shared_ptr<const core::Vector> y_;
  QRectF bounds_;
};

}  // namespace views
}  // namespace mozzi
