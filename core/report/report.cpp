#include "core/report/report.h"

#include "core/common/text.h"

namespace mozzi::core::report {

Cell numberCell(double value, int digits, double uncertainty, int uncertaintyDigits) {
  Cell cell;
  cell.value = value;
  cell.text = formatNumber(value, digits);
  if (uncertainty > 0.0) {
    cell.uncertainty = uncertainty;
    cell.text += " \u00b1 " + formatNumber(uncertainty, uncertaintyDigits);
  }
  return cell;
}

Cell textCell(std::string text) {
  Cell cell;
  cell.text = std::move(text);
  return cell;
}

}  // namespace mozzi::core::report
