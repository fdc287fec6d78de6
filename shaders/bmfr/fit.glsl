// Body of shaders/bmfr/fit*.comp. The including .comp defines HUSH_BMFR_FIT_BLOCK (16,
// 32 or 64: the block size it fits), declares the output image `fitted` (binding 6)
// with its literal format qualifier and vec4 bmfrStorable(vec4) (identity for rgba32f,
// clamp to +-65504 for rgba16f). All of the QR is fp32 whatever the output format.
// BMFR fit (Koskela et al. 2019, Sec. 3.2 and 6.1): one workgroup per block of the
// displaced block grid. The block's augmented matrix [T + N, z_r, z_g, z_b] lives in
// registers: invocation tid owns rows tid + kThreads i (i < kRows) of every column, so
// only the reductions cross invocations (the paper's megakernel keeps the matrix in
// shared memory instead; on lavapipe each lane's shared or buffer access is a scalar
// load, a register is not: docs/passes/bmfr.md). Rows of pixels outside the image are
// zero, so they add nothing to any inner product and the fit sees only valid pixels.
//   1. raw features and colour; per-feature min / max, per-channel max |z|
//   2. scale T to [-1, 1], add N; colour divided by its block maximum
//   3. Householder QR, R kept in shared memory (Q is never formed, Sec. 3.2)
//   4. back substitution R alpha = r per channel, guarded diagonal
//   5. output T alpha (noise-free T) times the colour scale; with nonNegative, negative
//      values set to 0 and the rest scaled to keep the block's sum
// Loops over rows and columns are unrolled so that every matrix index is a constant:
// a dynamic index would put the matrix in memory.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_EXT_control_flow_attributes : require
#include "bmfr/features.glsl"

const uint kBlock = HUSH_BMFR_FIT_BLOCK;
// Matrix rows per invocation (fit.cpp: fitRows, which says why): min(B, 32).
#define HUSH_BMFR_FIT_ROWS (HUSH_BMFR_FIT_BLOCK < 32 ? HUSH_BMFR_FIT_BLOCK : 32)
const uint kRows = HUSH_BMFR_FIT_ROWS;
const uint kThreads = kBlock * kBlock / kRows;      // 8, 16, 32, 128
layout(local_size_x = HUSH_BMFR_FIT_BLOCK * HUSH_BMFR_FIT_BLOCK / HUSH_BMFR_FIT_ROWS) in;
const uint kMaxFeatures = 17u;
const uint kColumns = kMaxFeatures + 3u;            // colour columns at kMaxFeatures + c
const uint kMaxSubgroups = (kThreads + 3u) / 4u;    // the host refuses subgroups under 4

layout(set = 0, binding = 0) uniform texture2D illumination;
layout(set = 0, binding = 1) uniform texture2D normal;
layout(set = 0, binding = 2) uniform texture2D position;
layout(set = 0, binding = 3) uniform texture2D albedo;
layout(set = 0, binding = 4) uniform texture2D roughness;
layout(set = 0, binding = 5) uniform texture2D meshid;

layout(push_constant) uniform Params {
    uint offsetX;
    uint offsetY;
    uint blocksX;
    uint frame;
    float epsilon;
    float flatRange;
    float diagonalGuard;
    float zeroColumn;
    float dependentColumn;
    uint nonNegative;
} params;

// The feature set is a specialization constant, not a push constant: fixed per pipeline
// (addBmfrFitPass), so the compiler folds every test on the feature count and every
// feature's code, and unrolls the QR's loop over columns. Feature codes one byte each,
// feature m in byte m % 4 of featureCodes<m / 4>. Used by these names only: a local
// `const uint M = featureCount` would rename the constant in the SPIR-V (one id, the
// last name wins), and the pipeline sets constants by name.
layout(constant_id = 0) const uint featureCount = 10u;
layout(constant_id = 1) const uint featureCodes0 = 0u;
layout(constant_id = 2) const uint featureCodes1 = 0u;
layout(constant_id = 3) const uint featureCodes2 = 0u;
layout(constant_id = 4) const uint featureCodes3 = 0u;
layout(constant_id = 5) const uint featureCodes4 = 0u;

shared float partial[kColumns * kMaxSubgroups]; // one value per column per subgroup
shared float total[kColumns];                   // the last reduction's result
shared float featureLo[kMaxFeatures];
shared float featureHalfRange[kMaxFeatures];
shared float colourScale[3];
shared float rowK[kColumns];                    // row rho of the matrix before reflection k
shared float R[kMaxFeatures * kColumns];        // R (M x M) and r (M x 3), row-major
shared float alpha[kMaxFeatures * 3];
shared float columnNorm2[kMaxFeatures];         // |T_m + N_m|^2 before the QR
shared uint liveColumn[kMaxFeatures];           // R row i belongs to column liveColumn[i]

// This invocation's rows: A[i][m] is feature column m, Z[i] the colour, of row
// tid + kThreads i.
float A[kRows][kMaxFeatures];
vec3 Z[kRows];

uint featureCode(uint m) {
    uint word = m < 4u ? featureCodes0 : m < 8u ? featureCodes1 : m < 12u ? featureCodes2 : m < 16u ? featureCodes3 : featureCodes4;
    return (word >> (8u * (m % 4u))) & 0xFFu;
}

// Feature columns at or past featureCount are never read: every loop over columns
// skips them (a uniform branch, unlike a loop bound, keeps the indices constant).
bool isColumnUsed(uint c) {
    return c < featureCount || c >= kMaxFeatures;
}

float combine(uint op, float a, float b) {
    return op == 0u ? a + b : (op == 1u ? min(a, b) : max(a, b));
}

float subgroupCombine(uint op, float v) {
    return op == 0u ? subgroupAdd(v) : (op == 1u ? subgroupMin(v) : subgroupMax(v));
}

// total[c] = the workgroup's reduction of values[c], for every column from `first` on.
// op: 0 sum, 1 min, 2 max. Each subgroup reduces in registers, then invocation c
// combines column c's subgroup results in subgroup order: a fixed order, so every run
// gives the same.
void reduceColumnsFrom(uint op, uint first, float values[kColumns]) {
    barrier();   // everyone has read the last totals
    [[unroll]] for (uint c = 0u; c < kColumns; ++c) {
        if (c < first || !isColumnUsed(c)) continue;
        float v = subgroupCombine(op, values[c]);
        if (subgroupElect()) partial[c * kMaxSubgroups + gl_SubgroupID] = v;
    }
    barrier();
    uint tid = gl_LocalInvocationID.x;
    // 8- and 16-pixel blocks have 8 and 16 invocations for up to 20 columns: each combines every kThreads-th.
    for (uint c = first + tid; c < kColumns; c += kThreads) {
        if (!isColumnUsed(c)) continue;
        float v = partial[c * kMaxSubgroups];
        for (uint g = 1u; g < gl_NumSubgroups; ++g) v = combine(op, v, partial[c * kMaxSubgroups + g]);
        total[c] = v;
    }
    barrier();
}

void reduceColumns(uint op, float values[kColumns]) { reduceColumnsFrom(op, 0u, values); }

ivec2 blockOrigin() {
    uint block = gl_WorkGroupID.x;
    return ivec2(block % params.blocksX, block / params.blocksX) * int(kBlock) - ivec2(params.offsetX, params.offsetY);
}

uvec2 rowLocal(uint i) {
    uint r = gl_LocalInvocationID.x + kThreads * i;
    return uvec2(r % kBlock, r / kBlock);
}

bool insideImage(ivec2 p) {
    return all(greaterThanEqual(p, ivec2(0))) && all(lessThan(p, imageSize(fitted)));
}

BmfrGuideTexel fetchGuide(ivec2 p, uvec2 local) {
    BmfrGuideTexel g;
    g.normal = texelFetch(normal, p, 0).xyz;
    g.position = texelFetch(position, p, 0).xyz;
    g.albedo = texelFetch(albedo, p, 0).rgb;
    g.roughness = texelFetch(roughness, p, 0).x;
    g.meshId = texelFetch(meshid, p, 0).x;
    g.inBlock = vec2(local) / float(kBlock - 1u);
    return g;
}

// 1. Raw features and colour into A and Z; the block's per-feature min / max and
// per-channel max |z| into featureLo, featureHalfRange and colourScale.
void loadBlock(ivec2 origin) {
    float lo[kColumns], hi[kColumns];
    [[unroll]] for (uint c = 0u; c < kColumns; ++c) {
        lo[c] = 3.0e38;
        hi[c] = c < kMaxFeatures ? -3.0e38 : 0.0;   // colour: max |z|
    }
    [[unroll]] for (uint i = 0u; i < kRows; ++i) {
        uvec2 local = rowLocal(i);
        ivec2 p = origin + ivec2(local);
        bool valid = insideImage(p);
        BmfrGuideTexel g;
        Z[i] = vec3(0.0);
        if (valid) {
            g = fetchGuide(p, local);
            Z[i] = texelFetch(illumination, p, 0).rgb;
        }
        [[unroll]] for (uint m = 0u; m < kMaxFeatures; ++m) {
            if (m >= featureCount) continue;
            A[i][m] = valid ? bmfrRawFeature(featureCode(m), g) : 0.0;
            lo[m] = valid ? min(lo[m], A[i][m]) : lo[m];
            hi[m] = valid ? max(hi[m], A[i][m]) : hi[m];
        }
        [[unroll]] for (uint c = 0u; c < 3u; ++c) hi[kMaxFeatures + c] = max(hi[kMaxFeatures + c], abs(Z[i][c]));
    }
    reduceColumns(1u, lo);
    if (gl_LocalInvocationID.x == 0u) {
        for (uint m = 0u; m < featureCount; ++m) featureLo[m] = total[m];
    }
    reduceColumns(2u, hi);
    if (gl_LocalInvocationID.x == 0u) {
        for (uint m = 0u; m < featureCount; ++m) {
            float l = featureLo[m], h = total[m];
            float halfRange = h * 0.5 - l * 0.5;
            bool isFlat = !(2.0 * halfRange > params.flatRange * max(abs(l), abs(h)));
            featureHalfRange[m] = isFlat ? 0.0 : halfRange;
        }
        for (uint c = 0u; c < 3u; ++c) {
            float s = total[kMaxFeatures + c];
            colourScale[c] = s > 0.0 ? s : 1.0;
        }
    }
    barrier();
}

// 2. T scaled to [-1, 1] plus N (Sec. 3.2, Eq. 8); z / max|z| so that no inner
// product can overflow whatever the radiance (1e-30 .. 3e38). Then each column's
// squared norm into columnNorm2, for the relative dependency test of the QR.
void scaleBlock(ivec2 origin) {
    vec3 scale = vec3(colourScale[0], colourScale[1], colourScale[2]);
    float norm2[kColumns];
    [[unroll]] for (uint c = 0u; c < kColumns; ++c) norm2[c] = 0.0;
    [[unroll]] for (uint i = 0u; i < kRows; ++i) {
        ivec2 p = origin + ivec2(rowLocal(i));
        bool valid = insideImage(p);
        [[unroll]] for (uint m = 0u; m < kMaxFeatures; ++m) {
            if (m >= featureCount) continue;
            uint code = featureCode(m);
            // A flat column stays exactly 0 (no noise): noise there could only fit z's
            // own noise and regularises nothing; the QR drops the zero column.
            bool live = code == kBmfrOne || featureHalfRange[m] > 0.0;
            float t = bmfrScaled(code, A[i][m], featureLo[m], featureHalfRange[m]) +
                      (live ? bmfrNoise(uvec2(p), params.frame, m, params.epsilon) : 0.0);
            A[i][m] = valid ? t : 0.0;
            norm2[m] += A[i][m] * A[i][m];
        }
        Z[i] /= scale;
    }
    reduceColumns(0u, norm2);
    if (gl_LocalInvocationID.x == 0u)
        for (uint m = 0u; m < featureCount; ++m) columnNorm2[m] = total[m];
    barrier();
}

// Column k of row i (k dynamic): selected, not indexed, so that A stays in registers.
float columnOf(uint i, uint k) {
    float v = 0.0;
    [[unroll]] for (uint j = 0u; j < kMaxFeatures; ++j) v = j == k ? A[i][j] : v;
    return v;
}

// rowK = row rho of the matrix, written by the invocation that owns it.
void publishRow(uint rho) {
    uint owner = rho % kThreads, slot = rho / kThreads;
    [[unroll]] for (uint j = 0u; j < kMaxFeatures; ++j) {
        if (j >= featureCount) continue;
        float v = 0.0;
        [[unroll]] for (uint i = 0u; i < kRows; ++i) v = i == slot ? A[i][j] : v;
        if (gl_LocalInvocationID.x == owner) rowK[j] = v;
    }
    vec3 z = vec3(0.0);
    [[unroll]] for (uint i = 0u; i < kRows; ++i) z = i == slot ? Z[i] : z;
    if (gl_LocalInvocationID.x == owner) {
        [[unroll]] for (uint c = 0u; c < 3u; ++c) rowK[kMaxFeatures + c] = z[c];
    }
}

// 3. Householder QR (Heath 1997, as cited in Sec. 3.2). Step k reflects rows rho..W-1
// so that column k becomes (a, 0, ..., 0), a = -sign(x_0) |x|. With v = x - a e_0,
// v.v = 2 (|x|^2 + |x_0| |x|) and v.A_j = x.A_j - a A_rho,j, so one batched reduction
// of x.A_j over every column gives the whole step; A_j -= v (2 v.A_j / v.v).
// A column whose part independent of the earlier ones is at most dependentColumn of
// its norm (or zero) is dropped: alpha_k = 0 and it consumes no row, so the later
// columns still see every row (a rank-revealing QR without pivoting). rho, the next
// row to reflect onto, is the same in every invocation. Returns the rank.
uint factorBlock() {
    uint rho = 0u;
    for (uint k = 0u; k < featureCount; ++k) {
        barrier();   // everyone is done reading rowK and total of step k - 1
        publishRow(rho);
        float dots[kColumns];
        [[unroll]] for (uint c = 0u; c < kColumns; ++c) dots[c] = 0.0;
        float x[kRows];
        [[unroll]] for (uint i = 0u; i < kRows; ++i) {
            uint r = gl_LocalInvocationID.x + kThreads * i;
            x[i] = r >= rho ? columnOf(i, k) : 0.0;
            [[unroll]] for (uint c = 0u; c < 3u; ++c) dots[kMaxFeatures + c] += x[i] * Z[i][c];
        }
        // Columns before k are zero in rows rho.. (reflected already): only j >= k.
        [[unroll]] for (uint j = 0u; j < kMaxFeatures; ++j) {
            if (j < k || j >= featureCount) continue;
            [[unroll]] for (uint i = 0u; i < kRows; ++i) dots[j] += x[i] * A[i][j];
        }
        reduceColumns(0u, dots);
        float xx = total[k];
        float norm = sqrt(max(xx, 0.0));
        float x0 = rowK[k];
        float dep = params.dependentColumn;
        if (!(norm > params.zeroColumn) || !(xx > dep * dep * columnNorm2[k])) {
            continue;   // dependent or zero: dropped
        }
        float a = x0 >= 0.0 ? -norm : norm;
        float vv = 2.0 * (xx + abs(x0) * norm);
        float factor[kColumns];
        [[unroll]] for (uint j = 0u; j < kColumns; ++j)
            factor[j] = j > k && isColumnUsed(j) ? 2.0 * (total[j] - a * rowK[j]) / vv : 0.0;
        if (gl_LocalInvocationID.x == 0u) {
            R[rho * kColumns + k] = a;
            [[unroll]] for (uint j = 0u; j < kColumns; ++j)
                if (j > k && isColumnUsed(j)) R[rho * kColumns + j] = rowK[j] - (x0 - a) * factor[j];
            liveColumn[rho] = k;
        }
        float v[kRows];
        [[unroll]] for (uint i = 0u; i < kRows; ++i) {
            uint r = gl_LocalInvocationID.x + kThreads * i;
            v[i] = r > rho ? x[i] : 0.0;
            Z[i] -= v[i] * vec3(factor[kMaxFeatures], factor[kMaxFeatures + 1u], factor[kMaxFeatures + 2u]);
        }
        // Columns up to k keep their values (row rho gets R, the rows below are 0).
        [[unroll]] for (uint j = 0u; j < kMaxFeatures; ++j) {
            if (j <= k || j >= featureCount) continue;
            [[unroll]] for (uint i = 0u; i < kRows; ++i) A[i][j] -= v[i] * factor[j];
        }
        ++rho;
    }
    barrier();
    return rho;
}

// 4. Back substitution R alpha = r (Sec. 3.2, Eq. 5), one channel per invocation. A
// diagonal entry the noise did not lift above the guard gives alpha_k = 0.
void solveBlock(uint rho) {
    uint ch = gl_LocalInvocationID.x;
    if (ch < 3u) {
        for (uint m = 0u; m < featureCount; ++m) alpha[m * 3u + ch] = 0.0;
        float maxDiag = 0.0;
        for (uint i = 0u; i < rho; ++i) maxDiag = max(maxDiag, abs(R[i * kColumns + liveColumn[i]]));
        for (uint ii = 0u; ii < rho; ++ii) {
            uint i = rho - 1u - ii;
            uint k = liveColumn[i];
            float d = R[i * kColumns + k];
            float s = R[i * kColumns + kMaxFeatures + ch];
            for (uint i2 = i + 1u; i2 < rho; ++i2) {
                uint j = liveColumn[i2];
                s -= R[i * kColumns + j] * alpha[j * 3u + ch];
            }
            float value = abs(d) > params.diagonalGuard * maxDiag && d != 0.0 ? s / d : 0.0;
            alpha[k * 3u + ch] = isnan(value) || isinf(value) ? 0.0 : value;
        }
    }
    barrier();
}

// 5. y = T alpha with the noise-free T (Sec. 3.2, Eq. 6), back to radiance units.
vec3 fittedValue(ivec2 p, uvec2 local) {
    BmfrGuideTexel g = fetchGuide(p, local);
    vec3 y = vec3(0.0);
    for (uint m = 0u; m < featureCount; ++m) {
        uint code = featureCode(m);
        float t = bmfrScaled(code, bmfrRawFeature(code, g), featureLo[m], featureHalfRange[m]);
        y += t * vec3(alpha[m * 3u], alpha[m * 3u + 1u], alpha[m * 3u + 2u]);
    }
    vec3 out3 = clamp(y * vec3(colourScale[0], colourScale[1], colourScale[2]), vec3(-3.0e38), vec3(3.0e38));
    [[unroll]] for (uint c = 0u; c < 3u; ++c) {
        if (isnan(out3[c]) || isinf(out3[c])) out3[c] = 0.0;
    }
    return out3;
}

// The block's sum of y per channel, in total[kMaxFeatures + c] (a workgroup reduction
// of the three colour columns only: every invocation calls it).
void sumBlock(vec3 y[kRows]) {
    float values[kColumns];
    [[unroll]] for (uint c = 0u; c < kColumns; ++c) values[c] = 0.0;
    [[unroll]] for (uint i = 0u; i < kRows; ++i)
        [[unroll]] for (uint c = 0u; c < 3u; ++c) values[kMaxFeatures + c] += y[i][c];
    reduceColumnsFrom(0u, kMaxFeatures, values);
}

// A least-squares fit with the constant feature keeps the block's sum, but beside a
// firefly it rings below 0 (an 8x8 block, docs/passes/bmfr.md). Clamping at 0 alone
// would add energy; scaling the positive values by sum(y) / sum(max(y, 0)) keeps the
// block's sum. A block with no negative value is unchanged (the ratio is exactly 1).
void keepNonNegative(inout vec3 y[kRows]) {
    sumBlock(y);
    vec3 signedSum = vec3(total[kMaxFeatures], total[kMaxFeatures + 1u], total[kMaxFeatures + 2u]);
    vec3 positive[kRows];
    [[unroll]] for (uint i = 0u; i < kRows; ++i) positive[i] = max(y[i], vec3(0.0));
    sumBlock(positive);
    vec3 positiveSum = vec3(total[kMaxFeatures], total[kMaxFeatures + 1u], total[kMaxFeatures + 2u]);
    [[unroll]] for (uint c = 0u; c < 3u; ++c) {
        float ratio = positiveSum[c] > 0.0 ? clamp(signedSum[c] / positiveSum[c], 0.0, 1.0) : 0.0;
        [[unroll]] for (uint i = 0u; i < kRows; ++i) y[i][c] = positive[i][c] * ratio;
    }
}

void storeBlock(ivec2 origin) {
    vec3 y[kRows];
    [[unroll]] for (uint i = 0u; i < kRows; ++i) {
        ivec2 p = origin + ivec2(rowLocal(i));
        y[i] = insideImage(p) ? fittedValue(p, rowLocal(i)) : vec3(0.0);   // outside: adds nothing to the sums
    }
    if (params.nonNegative != 0u) keepNonNegative(y);
    [[unroll]] for (uint i = 0u; i < kRows; ++i) {
        ivec2 p = origin + ivec2(rowLocal(i));
        if (insideImage(p)) imageStore(fitted, p, bmfrStorable(vec4(y[i], texelFetch(illumination, p, 0).a)));
    }
}

void main() {
    const ivec2 origin = blockOrigin();
    loadBlock(origin);
    scaleBlock(origin);
    solveBlock(factorBlock());
    storeBlock(origin);
}
