#include <hush/passes/frame_camera.hpp>

#include <cmath>
#include <string>

#include <hush/core/error.hpp>

namespace hush::passes {

FrameCamera::Matrix multiply(const FrameCamera::Matrix& a, const FrameCamera::Matrix& b) {
    FrameCamera::Matrix out{};
    for (int column = 0; column < 4; ++column)
        for (int row = 0; row < 4; ++row) {
            float sum = 0.0f;
            for (int k = 0; k < 4; ++k) sum += a[size_t(k * 4 + row)] * b[size_t(column * 4 + k)];
            out[size_t(column * 4 + row)] = sum;
        }
    return out;
}

void validate(const FrameCamera& c) {
    auto check = [](const float* values, size_t count, const char* field) {
        for (size_t i = 0; i < count; ++i)
            if (!std::isfinite(values[i]))
                throw Error(ErrorKind::InvalidArgument,
                            std::string("frame camera: ") + field + " holds a non-finite value (NaN or Inf)");
    };
    check(c.view.data(), 16, "view");
    check(c.projection.data(), 16, "projection");
    check(c.previousView.data(), 16, "previousView");
    check(c.previousProjection.data(), 16, "previousProjection");
    check(c.position.data(), 3, "position");
    if (!(std::isfinite(c.metresPerUnit) && c.metresPerUnit > 0.0f))
        throw Error(ErrorKind::InvalidArgument,
                    "frame camera: metresPerUnit must be finite and positive, got " + std::to_string(c.metresPerUnit));
}

} // namespace hush::passes
