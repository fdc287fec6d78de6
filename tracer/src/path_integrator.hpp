#pragma once
// The per-pixel estimators: the 1-sample path (next-event estimation with MIS;
// by default the primary hit plus one indirect bounce and two shadow rays, the
// SVGF / BMFR setting) split into direct and indirect, and Mara et al.'s factored
// terms (noise-free direct light, matte and glossy indirect with F and m outside).
#include <glm/glm.hpp>

#include "sampling.hpp"
#include "world.hpp"

namespace hush::tracer::detail {

struct PathOptions {
    uint32_t bounces = 1;            // indirect bounces after the primary hit
    float regularization = 0.0f;     // minimum GGX alpha after the primary hit (0: off)
    uint32_t maraDirectSamples = 16;
};

struct PathEstimate {
    glm::vec3 direct{0.0f};     // emission seen, plus light reaching the primary hit straight from emitters, sun, sky
    glm::vec3 indirect{0.0f};   // light reaching the primary hit through other surfaces
    // The part of `direct` that light sampling cannot find: the sky through the
    // primary hit's bounce, lights and sun seen through a mirror (delta) lobe. Mara
    // mode's many-sample direct term leaves it out, so `indirect` carries it there.
    glm::vec3 directUnsampled{0.0f};
};

// `primary` is the camera ray's hit (valid or not) along `direction`.
PathEstimate estimatePath(const World& world, glm::vec3 direction, const Hit& primary, PixelSampler& sampler,
                          const PathOptions& options);

struct MaraEstimate {
    glm::vec3 direct{0.0f};   // emission plus light sampled many times (noise-free in practice)
    glm::vec3 matte{0.0f};    // (1/N) sum L_i over cosine-sampled directions (seed 000 Eq. 9 without (1-F)^2 m pi)
    glm::vec3 glossy{0.0f};   // (1/N) sum L_i g cos / p_g (Eq. 10 without F)
};

MaraEstimate estimateMara(const World& world, glm::vec3 direction, const Hit& primary, PixelSampler& sampler,
                          const PathOptions& options);

// A point just off the surface, on the side `direction` leaves from.
glm::vec3 offsetRay(const Hit& hit, glm::vec3 direction);

} // namespace hush::tracer::detail
