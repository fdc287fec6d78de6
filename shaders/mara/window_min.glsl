// The 1D min filter of Mara et al.'s disocclusion stage (seed 000 Sec. 3.4: "two
// simple 1D min passes"), kRun pixels per invocation.
//
// Pixel k of a run starting at `first` takes the min over [first + k - R, first + k + R]
// (clipped to the image). All kRun windows share the core [first + kRun - 1 - R,
// first + R]; what is left of each window is a suffix of the kRun - 1 coordinates
// before the core and a prefix of the kRun - 1 after it (van Herk 1992 and Gil &
// Werman 1993 split a running min the same way). So a run fetches 2R + kRun values
// instead of kRun (2R + 1): at R = 32, kRun = 8, 9 per pixel instead of 65. Min is
// exact, so the result is the one-pixel loop's to the bit.
//
// The including shader defines `float windowValue(int i)`: the value at coordinate
// i (0 <= i < extent) along its axis.
#ifndef HUSH_MARA_WINDOW_MIN_GLSL
#define HUSH_MARA_WINDOW_MIN_GLSL

// Pixels per invocation along the filtered axis; the host dispatches
// ceil(extent / kRun) invocations along it (kMaraWindowRun in disocclusion.cpp).
const int kRun = 8;
const float kNoValue = 3.402823466e38;   // min's identity for finite values

float windowSpanMin(int lo, int hi, int extent) {
    float m = kNoValue;
    for (int i = max(lo, 0); i <= min(hi, extent - 1); ++i) {
        m = min(m, windowValue(i));
    }
    return m;
}

void windowMins(int first, int radius, int extent, out float mins[kRun]) {
    if (2 * radius + 1 < kRun) {
        // No shared core: each window on its own (a few taps each).
        for (int k = 0; k < kRun; ++k) {
            mins[k] = windowSpanMin(first + k - radius, first + k + radius, extent);
        }
        return;
    }
    float core = windowSpanMin(first + kRun - 1 - radius, first + radius, extent);
    // suffix[k]: min over the coordinates first - R + k .. first + kRun - 2 - R.
    float suffix[kRun];
    suffix[kRun - 1] = kNoValue;
    for (int k = kRun - 2; k >= 0; --k) {
        int i = first - radius + k;
        suffix[k] = i >= 0 && i < extent ? min(suffix[k + 1], windowValue(i)) : suffix[k + 1];
    }
    // prefix: min over first + R + 1 .. first + R + k.
    float prefix = kNoValue;
    for (int k = 0; k < kRun; ++k) {
        if (k > 0) {
            int i = first + radius + k;
            prefix = i >= 0 && i < extent ? min(prefix, windowValue(i)) : prefix;
        }
        mins[k] = min(core, min(suffix[k], prefix));
    }
}

#endif
