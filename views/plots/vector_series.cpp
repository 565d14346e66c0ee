#include "views/plots/vector_series.h"

#include <algorithm>

namespace mozzi {
namespace views {

VectorSeries::VectorSeries(std::shared_ptr<const core::Vector> x, std::shared_ptr<const core::Vector> y)
    : x_(std::move(x)), y_(std::move(y)) {
  const Eigen::Index n = std::min(x_->size(), y_->size());
  if (n > 0) {
    const double x0 = x_->head(n).minCoeff(), x1 = x_->head(n).maxCoeff();
    const double y0 = y_->head(n).minCoeff(), y1 = y_->head(n).maxCoeff();
    bounds_ = QRectF(QPointF(x0, y0), QPointF(x1, y1));
  }
}

size_t VectorSeries::size() const {
  return static_cast<size_t>(std::min(x_->size(), y_->size()));
}

QPointF VectorSeries::sample(size_t i) const {
  const auto k = static_cast<Eigen::Index>(i);
  return {(*x_)[k], (*y_)[k]};
}

QRectF VectorSeries::boundingRect() const {
  return bounds_;
}

}  // namespace views
}  // namespace mozzi
