#include "brdf.hpp"

#include <algorithm>
#include <cmath>

#include "sampling.hpp"

namespace hush::tracer::detail {

LayeredBrdf::LayeredBrdf(const Material& m)
    : albedo_(m.albedo), f0_(m.specular), alpha_(std::max(m.roughness, 1e-4f)),
      hasMatte_(glm::any(glm::greaterThan(m.albedo, glm::vec3(0.0f)))),
      hasGlossy_(glm::any(glm::greaterThan(m.specular, glm::vec3(0.0f)))),
      mirror_(m.roughness < kMirrorRoughness) {}

glm::vec3 LayeredBrdf::fresnel(float cosTheta) const {
    // No specular layer, no Fresnel: Schlick's grazing term with F0 = 0 would dim the
    // matte lobe with nothing to take the energy (the white furnace test sees it).
    if (!hasGlossy_) return glm::vec3(0.0f);
    const float c = 1.0f - std::clamp(cosTheta, 0.0f, 1.0f);
    const float c5 = (c * c) * (c * c) * c;
    return f0_ + (1.0f - f0_) * c5;
}

float LayeredBrdf::ggxD(glm::vec3 h) const {
    const float a2 = alpha_ * alpha_;
    const float d = h.z * h.z * (a2 - 1.0f) + 1.0f;
    return a2 / (kPi * d * d);
}

float LayeredBrdf::smithG1(glm::vec3 v) const {
    const float z2 = v.z * v.z;
    if (z2 <= 0.0f) return 0.0f;
    const float tan2 = std::max(0.0f, 1.0f - z2) / z2;
    return 2.0f / (1.0f + std::sqrt(1.0f + alpha_ * alpha_ * tan2));
}

glm::vec3 LayeredBrdf::evalGlossy(glm::vec3 wo, glm::vec3 wi) const {
    if (!hasGlossy_ || mirror_ || wo.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 h = glm::normalize(wo + wi);
    const float g = ggxD(h) * smithG1(wi) * smithG1(wo) / (4.0f * wi.z * wo.z);
    return glm::vec3(g * wi.z);
}

glm::vec3 LayeredBrdf::eval(glm::vec3 wo, glm::vec3 wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 h = glm::normalize(wo + wi);
    const glm::vec3 F = fresnel(glm::dot(h, wi));
    const glm::vec3 oneMinusF = 1.0f - F;
    glm::vec3 out = albedo_ * (1.0f / kPi) * oneMinusF * oneMinusF * wi.z;
    if (hasGlossy_ && !mirror_) out += evalGlossy(wo, wi) * F;
    return out;
}

float LayeredBrdf::specularProbability(glm::vec3 wo) const {
    if (!hasGlossy_) return 0.0f;
    if (!hasMatte_) return 1.0f;
    const float f = luminance(fresnel(wo.z));
    const float d = luminance(albedo_) * (1.0f - f) * (1.0f - f);
    return std::clamp(f / std::max(f + d, 1e-6f), 0.1f, 0.9f);
}

float LayeredBrdf::glossyPdf(glm::vec3 wo, glm::vec3 wi) const {
    if (!hasGlossy_ || mirror_ || wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    const glm::vec3 h = glm::normalize(wo + wi);
    // Visible-normal sampling: pdf(wi) = G1(wo) D(h) / (4 wo.z).
    return smithG1(wo) * ggxD(h) / (4.0f * wo.z);
}

float LayeredBrdf::pdf(glm::vec3 wo, glm::vec3 wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    const float ps = specularProbability(wo);
    float p = 0.0f;
    if (hasMatte_) p += (1.0f - ps) * wi.z / kPi;
    if (hasGlossy_ && !mirror_) p += ps * glossyPdf(wo, wi);
    return p;
}

namespace {

// Heitz 2018, "Sampling the GGX Distribution of Visible Normals".
glm::vec3 sampleVisibleNormal(glm::vec3 wo, float alpha, glm::vec2 u) {
    const glm::vec3 vh = glm::normalize(glm::vec3(alpha * wo.x, alpha * wo.y, wo.z));
    const float lenSq = vh.x * vh.x + vh.y * vh.y;
    const glm::vec3 t1 = lenSq > 0.0f ? glm::vec3(-vh.y, vh.x, 0.0f) / std::sqrt(lenSq) : glm::vec3(1, 0, 0);
    const glm::vec3 t2 = glm::cross(vh, t1);
    const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
    const float p1 = r * std::cos(phi);
    const float s = 0.5f * (1.0f + vh.z);
    const float p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * r * std::sin(phi);
    const glm::vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
    return glm::normalize(glm::vec3(alpha * nh.x, alpha * nh.y, std::max(1e-6f, nh.z)));
}

glm::vec3 reflectAbout(glm::vec3 wo, glm::vec3 h) { return 2.0f * glm::dot(wo, h) * h - wo; }

} // namespace

BsdfSample LayeredBrdf::sample(glm::vec3 wo, float lobeChoice, glm::vec2 u) const {
    BsdfSample s;
    if (wo.z <= 0.0f) return s;
    const float ps = specularProbability(wo);
    if (lobeChoice < ps) {
        s.glossy = true;
        if (mirror_) {
            s.wi = {-wo.x, -wo.y, wo.z};
            s.delta = true;
            s.weight = fresnel(wo.z) / ps;
            return s;
        }
        s.wi = reflectAbout(wo, sampleVisibleNormal(wo, alpha_, u));
    } else {
        s.wi = sampleCosineHemisphere(u);
    }
    if (s.wi.z <= 0.0f) return BsdfSample{};
    s.pdf = pdf(wo, s.wi);
    if (s.pdf <= 0.0f) return BsdfSample{};
    s.weight = eval(wo, s.wi) / s.pdf;
    return s;
}

BsdfSample LayeredBrdf::sampleMatte(glm::vec3 wo, glm::vec2 u) const {
    BsdfSample s;
    if (wo.z <= 0.0f) return s;
    s.wi = sampleCosineHemisphere(u);
    s.pdf = s.wi.z / kPi;
    s.weight = glm::vec3(s.pdf > 0.0f ? 1.0f : 0.0f);   // m and F stay outside (seed 000 Eq. 9)
    return s;
}

BsdfSample LayeredBrdf::sampleGlossy(glm::vec3 wo, glm::vec2 u) const {
    BsdfSample s;
    s.glossy = true;
    if (wo.z <= 0.0f || !hasGlossy_) return s;
    if (mirror_) {
        s.wi = {-wo.x, -wo.y, wo.z};
        s.delta = true;
        s.weight = glm::vec3(1.0f);   // the mirror's g integrates to one (F stays outside, Eq. 10)
        return s;
    }
    s.wi = reflectAbout(wo, sampleVisibleNormal(wo, alpha_, u));
    if (s.wi.z <= 0.0f) return BsdfSample{};
    s.pdf = glossyPdf(wo, s.wi);
    if (s.pdf <= 0.0f) return BsdfSample{};
    s.weight = evalGlossy(wo, s.wi) / s.pdf;
    return s;
}

} // namespace hush::tracer::detail
