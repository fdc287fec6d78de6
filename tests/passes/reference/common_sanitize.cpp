#include "reference/common_sanitize.hpp"

#include <algorithm>
#include <cmath>

namespace hush::passes_test::reference {

FloatImage sanitize(const FloatImage& in, float lo, float hi, float replacement, size_t& replacedPixels) {
    FloatImage out = in;
    replacedPixels = 0;
    for (size_t p = 0; p < size_t(in.width) * in.height; ++p) {
        bool replaced = false;
        for (uint32_t c = 0; c < in.channels; ++c) {
            float& v = out.pixels[p * in.channels + c];
            if (!std::isfinite(v)) {
                v = replacement;
                replaced = true;
            }
            v = std::clamp(v, lo, hi);
        }
        replacedPixels += replaced ? 1 : 0;
    }
    return out;
}

} // namespace hush::passes_test::reference
