// The normal edge-stopping weight max(0, n_p . n_q)^exponent (SVGF Eq. 4, Mara et
// al.'s bilateral taps), by repeated squaring where the exponent is a whole number.
//
// pow() is log2 and exp2 per tap; for SVGF's 128 squaring is 8 multiplies and, on
// lavapipe, cut an a-trous level by about 10 % (docs/benchmarks.md). It is also the
// more exact of the two (pow's exp2/log2 approximations err by more than 8 roundings).
// `whole` is a specialization constant the host sets to wholeExponent(exponent)
// (passes/include/hush/passes/common/normal_power.hpp): the exponent itself when it is
// a whole number in 1 .. 65535, else 0, and then pow() is used as before. As a push
// constant it made the level slower than pow(): the driver kept the loop.
#ifndef HUSH_COMMON_NORMAL_POWER_GLSL
#define HUSH_COMMON_NORMAL_POWER_GLSL

// `cosine` >= 0 and `exponent` >= 0 (GLSL leaves pow() undefined for a negative
// base, and for a base of 0 with an exponent of 0: that case is 1 here, as on the
// CPU, so that sigmaN = 0 weighs every neighbour, perpendicular or without a normal).
float normalPower(float cosine, float exponent, uint whole) {
    if (whole == 0u) {
        return exponent == 0.0 ? 1.0 : pow(cosine, exponent);
    }
    // `whole` is a specialization constant: the driver folds every test below, and
    // drops the squarings past its highest bit.
    float result = 1.0;
    float base = cosine;
    for (uint bit = 0u; bit < 16u; ++bit) {
        if ((whole & (1u << bit)) != 0u) {
            result *= base;
        }
        base *= base;
    }
    return result;
}

#endif
