#include "dataset_camera.hpp"

#include <algorithm>
#include <random>

#include <glm/glm.hpp>

namespace hush::cli {

namespace {

glm::vec3 randomDirection(std::mt19937_64& rng) {
    std::normal_distribution<float> n(0.0f, 1.0f);
    const glm::vec3 v(n(rng), n(rng), n(rng));
    return glm::length(v) > 1e-6f ? glm::normalize(v) : glm::vec3(0, 1, 0);
}

} // namespace

SequenceCamera randomSequenceCamera(const tracer::CameraPath& base, uint64_t seed, uint32_t frames,
                                    float framesPerSecond) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const float t0 = base.keys.front().time, t1 = base.keys.back().time;
    const float duration = float(std::max(frames, 2u) - 1) / framesPerSecond;
    // Along the path at -3x..3x its own speed; one sequence in four holds still.
    const float speed = unit(rng) < 0.25f ? 0.0f : (unit(rng) * 6.0f - 3.0f);
    const float ta = t0 + unit(rng) * (t1 - t0);
    const float tb = std::clamp(ta + speed * duration, t0, t1);
    tracer::CameraKey a = base.at(ta), b = base.at(tb);
    // Displaced by up to 15% of the distance to what the camera looks at.
    const float reach = 0.15f * glm::length(a.target - a.position);
    const glm::vec3 moved = randomDirection(rng) * reach * unit(rng);
    const glm::vec3 aimed = randomDirection(rng) * reach * unit(rng);
    for (auto* key : {&a, &b}) {
        key->position += moved;
        key->target += aimed;
    }
    SequenceCamera out;
    out.firstFrame = uint32_t(unit(rng) * 120.0f);   // also varies the scene's own animation
    a.time = float(out.firstFrame) / framesPerSecond;
    b.time = a.time + duration;
    out.path = base;
    out.path.name = "random";
    out.path.keys = {a, b};
    return out;
}

} // namespace hush::cli
