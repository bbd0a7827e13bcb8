// Image comparison for the tests: globe regress's own (regression/image_difference.hpp), so the
// tests judge pictures exactly as the product does.
#pragma once

#include "regression/image_difference.hpp"

namespace globe::testing {

using regression::compareImages;
using regression::ImageDifference;

}  // namespace globe::testing
