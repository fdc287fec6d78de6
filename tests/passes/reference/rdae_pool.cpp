#include "rdae_pool.hpp"

#include <algorithm>

namespace hush::passes_test::reference {

Tensor rdaePool(const Tensor& t) {
    Tensor out(t.channels, t.width / 2, t.height / 2);
    for (uint32_t c = 0; c < t.channels; ++c)
        for (uint32_t y = 0; y < out.height; ++y)
            for (uint32_t x = 0; x < out.width; ++x)
                out.at(c, x, y) = std::max({t.at(c, 2 * x, 2 * y), t.at(c, 2 * x + 1, 2 * y), t.at(c, 2 * x, 2 * y + 1),
                                            t.at(c, 2 * x + 1, 2 * y + 1)});
    return out;
}

} // namespace hush::passes_test::reference
