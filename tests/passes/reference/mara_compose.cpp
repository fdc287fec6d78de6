#include "reference/mara_compose.hpp"

#include <algorithm>
#include <cmath>

namespace hush::passes_test::reference {

FloatImage maraCompose(const FloatImage& direct, const FloatImage& matte, const FloatImage* glossy,
                       const FloatImage& albedo, const FloatImage& specular, const FloatImage& nd,
                       const FloatImage& position, const std::array<double, 3>& camera) {
    FloatImage out(direct.width, direct.height, 4, 1.0f);
    for (uint32_t y = 0; y < direct.height; ++y)
        for (uint32_t x = 0; x < direct.width; ++x) {
            double result[3] = {direct.at(x, y, 0), direct.at(x, y, 1), direct.at(x, y, 2)};
            double n2 = 0.0, toCamera[3], length2 = 0.0;
            for (uint32_t k = 0; k < 3; ++k) {
                n2 += double(nd.at(x, y, k)) * nd.at(x, y, k);
                toCamera[k] = camera[k] - position.at(x, y, k);
                length2 += toCamera[k] * toCamera[k];
            }
            if (n2 > 1e-6) {
                const double length = std::sqrt(length2);
                double cosine = 1.0;
                if (length > 1e-30) {
                    cosine = 0.0;
                    for (uint32_t k = 0; k < 3; ++k) cosine += double(nd.at(x, y, k)) * toCamera[k] / length;
                    cosine = std::clamp(cosine, 0.0, 1.0);
                }
                const double c5 = std::pow(1.0 - cosine, 5.0);
                const bool coated = specular.at(x, y, 0) > 0 || specular.at(x, y, 1) > 0 || specular.at(x, y, 2) > 0;
                for (uint32_t k = 0; k < 3; ++k) {
                    const double f0 = specular.at(x, y, k);
                    const double f = coated ? f0 + (1.0 - f0) * c5 : 0.0;
                    result[k] += (1.0 - f) * (1.0 - f) * albedo.at(x, y, k) * matte.at(x, y, k);
                    if (glossy) result[k] += f * glossy->at(x, y, k);
                }
            }
            for (uint32_t k = 0; k < 3; ++k) out.at(x, y, k) = float(result[k]);
        }
    return out;
}

} // namespace hush::passes_test::reference
