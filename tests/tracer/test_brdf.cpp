// The layered BRDF's sampling agrees with its evaluation: for each outgoing
// direction, the mean sample weight (f cos / pdf) equals the directional albedo
// integral of eval(), computed independently by uniform hemisphere quadrature, and
// pdf() matches the density the sampler actually produces.
#include <cmath>

#include <catch2/catch.hpp>

#include "brdf.hpp"
#include "sampling.hpp"

using namespace hush::tracer;
using namespace hush::tracer::detail;

namespace {

glm::vec3 directionAt(float cosTheta) { return {std::sqrt(1.0f - cosTheta * cosTheta), 0.0f, cosTheta}; }

// Midpoint quadrature over (cos theta, phi): the reference nobody's sampler touches.
glm::dvec3 albedoByQuadrature(const LayeredBrdf& brdf, glm::vec3 wo, int n = 600) {
    glm::dvec3 sum(0.0);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const float cosTheta = (float(i) + 0.5f) / float(n);
            const float phi = 2.0f * kPi * (float(j) + 0.5f) / float(n);
            const float sinTheta = std::sqrt(1.0f - cosTheta * cosTheta);
            const glm::vec3 wi(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
            sum += glm::dvec3(brdf.eval(wo, wi));
        }
    return sum * (2.0 * kPi / (double(n) * n));   // d omega = d cos d phi
}

glm::dvec3 albedoBySampling(const LayeredBrdf& brdf, glm::vec3 wo, uint32_t n = 200000) {
    glm::dvec3 sum(0.0);
    for (uint32_t i = 0; i < n; ++i) {
        PixelSampler sampler(7, 1, 2, i);
        const float lobe = sampler.next();
        const BsdfSample s = brdf.sample(wo, lobe, sampler.next2());
        sum += glm::dvec3(s.weight);
    }
    return sum / double(n);
}

Material material(glm::vec3 albedo, glm::vec3 f0, float roughness) {
    Material m;
    m.albedo = albedo;
    m.specular = f0;
    m.roughness = roughness;
    return m;
}

} // namespace

TEST_CASE("brdf: sampling weights integrate to the same albedo as eval", "[tracer][brdf]") {
    const Material materials[] = {
        material(glm::vec3(0.8f), glm::vec3(0.0f), 0.5f),       // Lambert
        material(glm::vec3(0.5f), glm::vec3(0.04f), 0.3f),      // plastic
        material(glm::vec3(0.0f), glm::vec3(0.9f, 0.6f, 0.3f), 0.2f),   // metal
        material(glm::vec3(0.2f), glm::vec3(0.04f), 0.8f),      // rough dielectric
    };
    for (const auto& m : materials) {
        const LayeredBrdf brdf(m);
        for (float cosTheta : {0.95f, 0.6f, 0.3f}) {
            const glm::vec3 wo = directionAt(cosTheta);
            const glm::dvec3 reference = albedoByQuadrature(brdf, wo);
            const glm::dvec3 sampled = albedoBySampling(brdf, wo);
            INFO("albedo " << m.albedo.x << " F0 " << m.specular.x << " alpha " << m.roughness << " cos " << cosTheta
                           << ": quadrature " << reference.x << " sampling " << sampled.x);
            // 1 % relative: the quadrature's own error on the narrowest lobe (alpha 0.2)
            // and the sampler's noise at 2e5 samples are both well below it.
            for (int c = 0; c < 3; ++c) REQUIRE(std::abs(sampled[c] - reference[c]) <= 0.01 * reference[c] + 1e-4);
            REQUIRE(reference.x <= 1.0 + 1e-3);   // energy conservation
        }
    }
}

TEST_CASE("brdf: a surface without a specular layer is exactly Lambert", "[tracer][brdf]") {
    const LayeredBrdf brdf(material(glm::vec3(0.6f), glm::vec3(0.0f), 0.5f));
    for (float cosTheta : {1.0f, 0.5f, 0.05f}) {
        const glm::vec3 wo = directionAt(cosTheta), wi = directionAt(0.02f);
        // No Fresnel layer, no grazing darkening: f cos = rho / pi * cos exactly.
        REQUIRE(brdf.eval(wo, wi).x == Approx(0.6f / kPi * 0.02f).epsilon(1e-5));
    }
}

TEST_CASE("brdf: pdf() is the density the sampler draws from", "[tracer][brdf]") {
    // The fraction of samples landing in a small cone equals the integral of pdf()
    // over that cone.
    const LayeredBrdf brdf(material(glm::vec3(0.5f), glm::vec3(0.04f), 0.3f));
    const glm::vec3 wo = directionAt(0.7f);
    const glm::vec3 axis = glm::normalize(glm::vec3(-0.5f, 0.1f, 0.8f));
    const float cosCone = std::cos(0.15f);
    const uint32_t n = 400000;
    uint32_t inside = 0;
    for (uint32_t i = 0; i < n; ++i) {
        PixelSampler sampler(11, 3, 4, i);
        const float lobe = sampler.next();
        const BsdfSample s = brdf.sample(wo, lobe, sampler.next2());
        if (s.pdf > 0.0f && glm::dot(s.wi, axis) >= cosCone) ++inside;
    }
    double integral = 0.0;
    const int m = 400;
    const Basis basis(axis);
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) {
            const float c = 1.0f - (1.0f - cosCone) * (float(i) + 0.5f) / float(m);
            const float phi = 2.0f * kPi * (float(j) + 0.5f) / float(m);
            const float s = std::sqrt(1.0f - c * c);
            integral += brdf.pdf(wo, basis.toWorld({s * std::cos(phi), s * std::sin(phi), c}));
        }
    integral *= 2.0 * kPi * (1.0 - cosCone) / (double(m) * m);
    const double fraction = double(inside) / double(n);
    INFO("fraction " << fraction << ", integral of pdf " << integral);
    REQUIRE(std::abs(fraction - integral) <= 0.02 * integral + 2e-4);
}
