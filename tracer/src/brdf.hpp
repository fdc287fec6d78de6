#pragma once
// The layered BRDF of Mara et al. (seed 000 Eq. 1-4):
//   f(wi, wo) = m (1 - F)^2 + g F,   m = albedo / pi,   F = Schlick(F0, h.wi),
//   g = D(h) G1(wi) G1(wo) / (4 |n.wi| |n.wo|)   (GGX, separable Smith).
// The paper writes 4 pi in g's denominator; here D carries the 1/pi of the usual
// GGX normalisation, which is the same thing. Directions are in the local shading
// frame (z = normal), both pointing away from the surface.
#include <glm/glm.hpp>

#include <hush/tracer/scene.hpp>

namespace hush::tracer::detail {

struct BsdfSample {
    glm::vec3 wi{0.0f};
    glm::vec3 weight{0.0f};   // f cos / pdf
    float pdf = 0.0f;         // solid angle; 0 for the mirror's delta lobe
    bool delta = false;
    bool glossy = false;      // drawn from the specular lobe (for Mara's glossy channel)
};

class LayeredBrdf {
public:
    explicit LayeredBrdf(const Material& m);
    glm::vec3 eval(glm::vec3 wo, glm::vec3 wi) const;     // f * cos(wi)
    float pdf(glm::vec3 wo, glm::vec3 wi) const;
    BsdfSample sample(glm::vec3 wo, float lobeChoice, glm::vec2 u) const;

    // The lobes separately, for Mara's factorisation (seed 000 Sec. 3.3).
    glm::vec3 evalGlossy(glm::vec3 wo, glm::vec3 wi) const;   // g * cos(wi), no F
    BsdfSample sampleMatte(glm::vec3 wo, glm::vec2 u) const;    // cosine; weight = 1 (m and F factored out)
    BsdfSample sampleGlossy(glm::vec3 wo, glm::vec2 u) const;   // weight = g cos / pdf (F factored out)
    glm::vec3 fresnel(float cosTheta) const;
    bool hasMatte() const { return hasMatte_; }
    bool hasGlossy() const { return hasGlossy_; }
    bool mirror() const { return mirror_; }

private:
    float specularProbability(glm::vec3 wo) const;
    float ggxD(glm::vec3 h) const;
    float smithG1(glm::vec3 v) const;
    float glossyPdf(glm::vec3 wo, glm::vec3 wi) const;

    glm::vec3 albedo_, f0_;
    float alpha_;
    bool hasMatte_, hasGlossy_, mirror_;
};

} // namespace hush::tracer::detail
