#include "path_integrator.hpp"

#include <algorithm>
#include <cmath>

#include "brdf.hpp"

namespace hush::tracer::detail {

namespace {

float powerHeuristic(float a, float b) {
    a *= a;
    b *= b;
    return a + b > 0.0f ? a / (a + b) : 0.0f;
}

// Emission seen along the ray that found `hit`: area lights emit from their front
// face (counter-clockwise winding) unless the material emits from both sides.
glm::vec3 emitted(const Hit& hit) {
    return hit.frontFace || hit.material->doubleSidedEmission ? hit.material->emission : glm::vec3(0.0f);
}
bool emits(const Hit& hit) { return glm::any(glm::greaterThan(emitted(hit), glm::vec3(0.0f))); }

LayeredBrdf brdfAt(const Hit& hit, uint32_t depth, float regularization) {
    Material m = *hit.material;
    // Path-space regularisation (Kaplanyan and Dachsbacher 2013): roughen glossy
    // lobes after the primary hit, trading a little bias for far fewer fireflies.
    if (depth > 0 && regularization > 0.0f) m.roughness = std::max(m.roughness, regularization);
    return LayeredBrdf(m);
}

// One light sample at `x`, MIS-weighted against BSDF sampling when `mis`. Always
// consumes three sampler dimensions, so the sequences stay aligned across pixels.
glm::vec3 sampleDirect(const World& world, const Hit& x, const Basis& basis, const LayeredBrdf& brdf, glm::vec3 wo,
                       PixelSampler& sampler, bool mis) {
    const float choice = sampler.next();
    const glm::vec2 u = sampler.next2();
    if (!world.hasLights()) return glm::vec3(0.0f);
    const LightSample light = world.sampleLight(x.position, choice, u);
    if (!(light.pdf > 0.0f)) return glm::vec3(0.0f);
    const glm::vec3 wi = basis.toLocal(light.direction);
    if (wi.z <= 0.0f || glm::dot(light.direction, x.geometricNormal) <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 f = brdf.eval(wo, wi);
    if (!glm::any(glm::greaterThan(f, glm::vec3(0.0f)))) return glm::vec3(0.0f);
    // The shadow ray starts off the surface, so its length is measured from there to
    // the light point, stopping just short of the light's own surface.
    const glm::vec3 origin = offsetRay(x, light.direction);
    const float tMax = std::isinf(light.distance)
                           ? 1e30f
                           : glm::length(x.position + light.direction * light.distance - origin) * (1.0f - 1e-4f);
    if (world.occluded(origin, light.direction, tMax)) return glm::vec3(0.0f);
    const float weight = mis ? powerHeuristic(light.pdf, brdf.pdf(wo, wi)) : 1.0f;
    return f * light.radiance * (weight / light.pdf);
}

// Radiance leaving `x` back along `rayDir`, from depth `depth` on (0 is the primary
// hit); what arrives at the primary hit straight from a light goes to `out.direct`,
// everything else to `out.indirect`. Emission of `x` itself is the caller's.
void continuePath(const World& world, Hit x, glm::vec3 rayDir, uint32_t depth, PixelSampler& sampler,
                  const PathOptions& options, glm::vec3 throughput, PathEstimate& out) {
    for (;; ++depth) {
        const Basis basis(x.shadingNormal);
        const glm::vec3 wo = basis.toLocal(-rayDir);
        if (wo.z <= 0.0f) return;   // an interpolated normal facing away: no reflection
        const LayeredBrdf brdf = brdfAt(x, depth, options.regularization);
        glm::vec3& target = depth == 0 ? out.direct : out.indirect;
        target += throughput * sampleDirect(world, x, basis, brdf, wo, sampler, true);

        // The BSDF ray finds lights too; the two estimates share them by MIS. At the
        // last vertex the ray only collects that light: without it the light samples
        // alone would carry the 1/r^2 singularity where surfaces meet (heavy-tailed,
        // so a finite average falls short; the white furnace test measures it).
        const bool last = depth >= options.bounces;
        const float lobe = sampler.next();
        const glm::vec2 u = sampler.next2();
        const BsdfSample bs = brdf.sample(wo, lobe, u);
        if (!glm::any(glm::greaterThan(bs.weight, glm::vec3(0.0f)))) return;
        const glm::vec3 wi = glm::normalize(basis.toWorld(bs.wi));
        if (glm::dot(wi, x.geometricNormal) <= 0.0f) return;
        throughput *= bs.weight;
        const Hit next = world.intersect(offsetRay(x, wi), wi);
        if (!next.valid) {
            const float sunWeight = bs.delta ? 1.0f : powerHeuristic(bs.pdf, world.sunPdf(wi));
            const glm::vec3 sky = throughput * world.skyRadiance(wi), sun = throughput * world.sunRadiance(wi);
            target += sky + sun * sunWeight;
            if (depth == 0) out.directUnsampled += sky + (bs.delta ? sun : glm::vec3(0.0f));
            return;
        }
        if (emits(next)) {
            const float weight = bs.delta ? 1.0f : powerHeuristic(bs.pdf, world.emitterPdf(x.position, next));
            target += throughput * emitted(next) * weight;
            if (depth == 0 && bs.delta) out.directUnsampled += throughput * emitted(next);
        }
        if (last) return;
        x = next;
        rayDir = wi;
    }
}

// Radiance arriving at `x` from direction `wi`, reflected at the next surface (its
// own emission and the sun counted only when `withLights`).
glm::vec3 incidentRadiance(const World& world, const Hit& x, glm::vec3 wi, PixelSampler& sampler,
                           const PathOptions& options, bool withLights) {
    const Hit next = world.intersect(offsetRay(x, wi), wi);
    if (!next.valid) return world.skyRadiance(wi) + (withLights ? world.sunRadiance(wi) : glm::vec3(0.0f));
    PathEstimate rest;
    if (options.bounces > 0) continuePath(world, next, wi, 1, sampler, options, glm::vec3(1.0f), rest);
    return rest.indirect + (withLights ? emitted(next) : glm::vec3(0.0f));
}

} // namespace

glm::vec3 offsetRay(const Hit& hit, glm::vec3 direction) {
    const float scale = std::max({1.0f, std::abs(hit.position.x), std::abs(hit.position.y), std::abs(hit.position.z)});
    const float side = glm::dot(direction, hit.geometricNormal) >= 0.0f ? 1.0f : -1.0f;
    return hit.position + hit.geometricNormal * (side * 1e-4f * scale);
}

PathEstimate estimatePath(const World& world, glm::vec3 direction, const Hit& primary, PixelSampler& sampler,
                          const PathOptions& options) {
    PathEstimate out;
    if (!primary.valid) {
        out.direct = world.skyRadiance(direction) + world.sunRadiance(direction);
        return out;
    }
    out.direct = emitted(primary);
    continuePath(world, primary, direction, 0, sampler, options, glm::vec3(1.0f), out);
    return out;
}

MaraEstimate estimateMara(const World& world, glm::vec3 direction, const Hit& primary, PixelSampler& sampler,
                          const PathOptions& options) {
    MaraEstimate out;
    if (!primary.valid) {
        out.direct = world.skyRadiance(direction) + world.sunRadiance(direction);
        return out;
    }
    out.direct = emitted(primary);
    const Basis basis(primary.shadingNormal);
    const glm::vec3 wo = basis.toLocal(-direction);
    if (wo.z <= 0.0f) return out;
    const LayeredBrdf brdf(*primary.material);
    // Mara et al. rasterise direct light; many light samples stand in for that.
    const uint32_t samples = std::max(1u, options.maraDirectSamples);
    glm::vec3 direct(0.0f);
    for (uint32_t i = 0; i < samples; ++i) direct += sampleDirect(world, primary, basis, brdf, wo, sampler, false);
    out.direct += direct / float(samples);

    const BsdfSample matte = brdf.sampleMatte(wo, sampler.next2());
    if (brdf.hasMatte() && matte.pdf > 0.0f) {
        const glm::vec3 wi = glm::normalize(basis.toWorld(matte.wi));
        if (glm::dot(wi, primary.geometricNormal) > 0.0f)
            out.matte = matte.weight * incidentRadiance(world, primary, wi, sampler, options, false);
    }
    const BsdfSample glossy = brdf.sampleGlossy(wo, sampler.next2());
    if (brdf.hasGlossy() && glm::any(glm::greaterThan(glossy.weight, glm::vec3(0.0f)))) {
        const glm::vec3 wi = glm::normalize(basis.toWorld(glossy.wi));
        // A mirror's reflection of a light is direct light that light sampling cannot
        // find, so the mirror's glossy term keeps it.
        if (glm::dot(wi, primary.geometricNormal) > 0.0f)
            out.glossy = glossy.weight * incidentRadiance(world, primary, wi, sampler, options, glossy.delta);
    }
    return out;
}

} // namespace hush::tracer::detail
