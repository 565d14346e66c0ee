#pragma once
// Labels and help of the built-in drivers' parameters, for lupdate and a test.

#include <vector>

namespace mozzi {
namespace views {

// Every parameter label and help text of the built-in drivers (English).
const std::vector<const char*>& parameterTexts();

}  // namespace views
}  // namespace mozzi
