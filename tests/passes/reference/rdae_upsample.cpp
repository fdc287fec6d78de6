#include "rdae_upsample.hpp"

namespace hush::passes_test::reference {

Tensor rdaeUpsample(const Tensor& t) {
    Tensor out(t.channels, t.width * 2, t.height * 2);
    for (uint32_t c = 0; c < t.channels; ++c)
        for (uint32_t y = 0; y < out.height; ++y)
            for (uint32_t x = 0; x < out.width; ++x) out.at(c, x, y) = t.at(c, x / 2, y / 2);
    return out;
}

} // namespace hush::passes_test::reference
