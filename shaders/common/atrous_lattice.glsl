// The a-trous lattice: how a 5x5 a-trous level at step s reads each texel fewer times.
//
// Each invocation filters a B x B block of pixels spaced s apart (one residue class
// of a Bs x Bs cell). Their 5x5 taps, at offsets -2s .. 2s, overlap in one
// (B + 4) x (B + 4) lattice whatever the step, so an invocation reads (B + 4)^2
// texels per resource for B^2 pixels instead of 25 B^2 (B = 2: 9 per pixel; B = 4,
// eaw.atrous's: 4 per pixel), and keeps them in registers. Shared memory would cut the
// reads further, but on lavapipe its per-lane loads cost more than the texel fetches
// they replace (docs/passes/atrous-lattice.md). The host dispatches
// atrousThreads() invocations (passes/include/hush/passes/common/atrous_lattice.hpp),
// which round each axis up to whole cells.
#ifndef HUSH_COMMON_ATROUS_LATTICE_GLSL
#define HUSH_COMMON_ATROUS_LATTICE_GLSL

// Pixels per axis per invocation: the including shader may choose (1 .. 8) by
// defining HUSH_ATROUS_BLOCK; the host passes the same to atrousThreads().
#ifndef HUSH_ATROUS_BLOCK
#define HUSH_ATROUS_BLOCK 2
#endif
const int kLatticeBlock = HUSH_ATROUS_BLOCK;
const int kLatticeSpan = kLatticeBlock + 4;         // lattice points per axis
const int kLatticePoints = kLatticeSpan * kLatticeSpan;

// The pixel of this invocation's first lattice point (points 0 .. B + 3 per axis;
// its own pixels are points 2 .. B + 1).
ivec2 latticeOrigin(int step) {
    ivec2 i = ivec2(gl_GlobalInvocationID.xy);
    ivec2 cell = i / step;
    return cell * (kLatticeBlock * step) + (i - cell * step) - 2 * step;
}

ivec2 latticePixel(ivec2 origin, int step, int point) {
    return origin + ivec2(point % kLatticeSpan, point / kLatticeSpan) * step;
}

// Lattice point of tap t (0 .. 24, row-major 5x5) of the block's pixel b (0 .. B^2 - 1,
// row-major).
int latticeTap(int b, int t) {
    return (b / kLatticeBlock + t / 5) * kLatticeSpan + (b % kLatticeBlock + t % 5);
}

// Lattice point of the block's pixel b.
int latticeCentre(int b) {
    return latticeTap(b, 12);
}

#endif
