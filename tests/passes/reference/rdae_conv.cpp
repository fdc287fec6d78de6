#include "rdae_conv.hpp"

namespace hush::passes_test::reference {

Tensor rdaeConv(const Tensor& a, const Tensor* b, const passes::RdaeConvParameters& conv, bool leaky) {
    const uint32_t w = a.width, h = a.height, ca = a.channels;
    auto input = [&](uint32_t i, int x, int y) -> double {
        if (x < 0 || y < 0 || x >= int(w) || y >= int(h)) return 0.0;   // zero padding
        return i < ca ? a.at(i, uint32_t(x), uint32_t(y)) : b->at(i - ca, uint32_t(x), uint32_t(y));
    };
    Tensor out(conv.outputs, w, h);
    for (uint32_t o = 0; o < conv.outputs; ++o)
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x) {
                double sum = conv.bias[o];
                for (uint32_t i = 0; i < conv.inputs; ++i)
                    for (int ky = 0; ky < 3; ++ky)
                        for (int kx = 0; kx < 3; ++kx)
                            sum += double(conv.weight[((size_t(o) * conv.inputs + i) * 3 + ky) * 3 + kx]) *
                                   input(i, int(x) + kx - 1, int(y) + ky - 1);
                out.at(o, x, y) = float(leaky && sum < 0.0 ? 0.1 * sum : sum);
            }
    return out;
}

} // namespace hush::passes_test::reference
