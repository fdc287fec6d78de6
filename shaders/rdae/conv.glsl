// One 3x3 convolution of the recurrent denoising autoencoder (Chaitanya et al. 2017,
// Eq. 1): zero padding, bias, leaky ReLU (alpha 0.1) or linear. The input is the
// concatenation of input_a's channels and input_b's (a skip connection, or the RCNN
// block's hidden state), read in place: no copy makes the concatenation. Each
// invocation computes blocksPerInvocation output blocks (4 channels each; 4 blocks,
// fewer for a layer with fewer) of kPixels horizontally adjacent pixels: every input
// texel it loads feeds 4 x blocksPerInvocation multiply-adds and every weight matrix
// kPixels x 16. Arithmetic is fp32.
// Included by conv.comp (rgba16f storage) and conv_rgba32f.comp with HUSH_TENSOR_FORMAT.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "rdae/tensor.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 0) uniform texture2D input_a;
layout(set = 0, binding = 1) uniform texture2D input_b;   // read when hasB
layout(set = 0, binding = 2, HUSH_TENSOR_FORMAT) uniform writeonly image2D features;
// weights.values[(outBlock * (blocksA + blocksB) + inBlock) * 9 + tap]: column c is input
// channel 4 * inBlock + c, row r output channel 4 * outBlock + r; tap = 3 * dy + dx.
layout(set = 0, binding = 3, std430) readonly buffer WeightsBlock { mat4 values[]; } weights;
layout(set = 0, binding = 4, std430) readonly buffer BiasBlock { vec4 values[]; } bias;

layout(push_constant) uniform Params {
    ivec2 size;       // one block's extent at this level (inputs and output alike)
    uint blocksA;
    uint tilesA;
    uint blocksB;     // counted in the weights' stride even when hasB is 0
    uint tilesB;
    uint hasB;        // 0: input_b is absent or zero (a hidden state after a reset)
    uint outBlocks;
    uint tilesOut;
    uint outTileCount;   // tiles of the output grid: those past outBlocks are written with zeros
    uint leaky;       // 1: leaky ReLU, 0: linear (the output layer)
} params;

// Output blocks per invocation: 4, or the layer's block count where it has fewer
// (rdae/conv.cpp: blocksPerInvocation()), so that a 3-channel output layer does not
// compute three blocks of zero weights (docs/passes/rdae.md, "Speed").
layout(constant_id = 0) const uint blocksPerInvocation = 4u;
const uint kPixels = 8u;
const float kLargest = 65504.0;

// Zero outside the level (the network's zero padding), without a branch: every lane
// of a SIMD group runs the same instructions.
vec4 loadInput(ivec2 q, uint block) {
    ivec2 c = clamp(q, ivec2(0), params.size - 1);
    float inside = all(equal(c, q)) ? 1.0 : 0.0;
    if (block < params.blocksA) {
        return inside * texelFetch(input_a, rdaeTexel(c, block, params.tilesA, params.size), 0);
    }
    return inside * texelFetch(input_b, rdaeTexel(c, block - params.blocksA, params.tilesB, params.size), 0);
}

// Bias plus the 3x3 convolution of kPixels pixels from p0, for the group of output
// blocks from `first` (weights and biases are padded to whole groups). Per input block
// and kernel row, the row's kPixels + 2 texels are loaded once and shared by the three
// taps of every pixel (30 loads per block instead of 72: on lavapipe each is a per-lane
// gather).
void accumulate(ivec2 p0, uint first, uint stride, uint inBlocks, inout vec4 acc[kPixels][blocksPerInvocation]) {
    for (uint o = 0u; o < blocksPerInvocation; ++o) {
        vec4 b = bias.values[first + o];
        for (uint k = 0u; k < kPixels; ++k) {
            acc[k][o] = b;
        }
    }
    for (uint block = 0u; block < inBlocks; ++block) {
        for (uint dy = 0u; dy < 3u; ++dy) {
            vec4 row[kPixels + 2u];
            for (uint j = 0u; j < kPixels + 2u; ++j) {
                row[j] = loadInput(p0 + ivec2(int(j) - 1, int(dy) - 1), block);
            }
            for (uint dx = 0u; dx < 3u; ++dx) {
                uint w = first * stride + block * 9u + 3u * dy + dx;
                for (uint o = 0u; o < blocksPerInvocation; ++o) {
                    mat4 m = weights.values[w + o * stride];
                    for (uint k = 0u; k < kPixels; ++k) {
                        acc[k][o] += m * row[k + dx];
                    }
                }
            }
        }
    }
}

void main() {
    // Each invocation computes kPixels horizontally adjacent pixels: every weight it
    // loads feeds kPixels x 4 multiply-adds (on lavapipe a weight load inside a loop is
    // a per-lane gather, the kernel's largest cost; docs/passes/rdae.md, "Speed").
    ivec2 p0 = ivec2(gl_GlobalInvocationID.x * kPixels, gl_GlobalInvocationID.y);
    if (p0.x >= params.size.x || p0.y >= params.size.y) {
        return;
    }
    // The workgroup's z is its group of output blocks. The weights and biases are
    // padded to whole groups, so a fixed, unrolled loop reads them all.
    uint first = gl_WorkGroupID.z * blocksPerInvocation;
    uint stride = (params.blocksA + params.blocksB) * 9u;
    uint inBlocks = params.blocksA + (params.hasB != 0u ? params.blocksB : 0u);
    vec4 acc[kPixels][blocksPerInvocation];
    for (uint o = 0u; o < blocksPerInvocation; ++o) {
        for (uint k = 0u; k < kPixels; ++k) {
            acc[k][o] = vec4(0.0);
        }
    }
    // A workgroup past the last output block only zeroes the grid's unused tiles, so
    // that no texel of a tensor (a hidden state is a history) is left uninitialised.
    // The branch is uniform over the workgroup.
    if (first < params.outBlocks) {
        accumulate(p0, first, stride, inBlocks, acc);
    }
    uint count = min(blocksPerInvocation, params.outTileCount - first);
    for (uint k = 0u; k < kPixels; ++k) {
        ivec2 p = p0 + ivec2(int(k), 0);
        for (uint o = 0u; o < blocksPerInvocation; ++o) {
            if (o < count && p.x < params.size.x) {
                vec4 r = params.leaky != 0u ? max(acc[k][o], 0.1 * acc[k][o]) : acc[k][o];
                r = clamp(r, vec4(-kLargest), vec4(kLargest));   // fp16 storage must not turn it into inf
                imageStore(features, rdaeTexel(p, first + o, params.tilesOut, params.size), r);
            }
        }
    }
}
