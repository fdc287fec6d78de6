// The factor radiance is divided by (demodulate) and multiplied by (remodulate):
// the primary hit's albedo, at least eps per channel. A pixel whose albedo is below
// eps in every channel (an emitter, a black or background pixel) keeps its radiance
// (factor 1), so that it is not scaled by 1/eps and bled into its neighbours.
#ifndef HUSH_COMMON_DEMODULATION_GLSL
#define HUSH_COMMON_DEMODULATION_GLSL

vec3 demodulationFactor(vec3 albedo, float eps) {
    if (all(lessThan(albedo, vec3(eps)))) {
        return vec3(1.0);
    }
    return max(albedo, vec3(eps));
}

#endif
