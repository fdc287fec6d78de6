// Body of shaders/bmfr/fit*.comp. The including .comp declares the output image
// `fitted` (binding 6) with its literal format qualifier and vec4 bmfrStorable(vec4)
// (identity for rgba32f, clamp to +-65504 for rgba16f). The block matrix buffer and
// all of the QR stay fp32 whatever the output format.
// BMFR fit (Koskela et al. 2019, Sec. 3.2 and 6.1): one workgroup per block of the
// displaced block grid. The block's augmented matrix [T + N, z_r, z_g, z_b] lives
// column-major in the block-contiguous buffer (column c of block b at
// (b * columns + c) * blockSize^2); rows of pixels outside the image are zero, so
// they add nothing to any inner product and the fit sees only the valid pixels.
//   1. raw features and colour -> buffer; per-feature min / max, per-channel max |z|
//   2. scale T to [-1, 1], add N; colour divided by its block maximum
//   3. Householder QR, R kept in shared memory (Q is never formed, Sec. 3.2)
//   4. back substitution R alpha = r per channel, guarded diagonal
//   5. output T alpha (noise-free T) times the colour scale
// Each thread owns rows tid, tid + 128, ...: only it touches them in the buffer, so
// the buffer needs no barriers; reductions go through shared memory.
#include "bmfr/features.glsl"

layout(local_size_x = 128) in;
const uint kThreads = 128u;
const uint kMaxFeatures = 17u;
const uint kMaxColumns = 20u;

layout(set = 0, binding = 0) uniform texture2D illumination;
layout(set = 0, binding = 1) uniform texture2D normal;
layout(set = 0, binding = 2) uniform texture2D position;
layout(set = 0, binding = 3) uniform texture2D albedo;
layout(set = 0, binding = 4) uniform texture2D roughness;
layout(set = 0, binding = 5) uniform texture2D meshid;
layout(set = 0, binding = 7, std430) buffer BlocksBlock { float values[]; } blocks;

layout(push_constant) uniform Params {
    uint blockSize;
    uint offsetX;
    uint offsetY;
    uint blocksX;
    uint frame;
    uint featureCount;
    float epsilon;
    float flatRange;
    float diagonalGuard;
    float zeroColumn;
    float dependentColumn;
    uvec4 codes[2];   // feature codes, one byte each, feature m in byte m
} params;

shared float partial[kMaxColumns * kThreads];   // 10 KB: one value per column per thread
shared float featureLo[kMaxFeatures];
shared float featureHalfRange[kMaxFeatures];
shared float colourScale[3];
shared float rowK[kMaxColumns];                 // row k of the matrix before reflection k
shared float R[kMaxFeatures * kMaxColumns];     // R (M x M) and r (M x 3), row-major
shared float alpha[kMaxFeatures * 3];
shared float columnNorm2[kMaxFeatures];         // |T_m + N_m|^2 before the QR
shared uint liveColumn[kMaxFeatures];           // R row i belongs to column liveColumn[i]

uint featureCode(uint m) {
    return (params.codes[m / 16u][(m / 4u) % 4u] >> (8u * (m % 4u))) & 0xFFu;
}

// Tree reduction of partial[c * kThreads + t] over t for columns c0 .. c1 - 1; the
// result is in partial[c * kThreads]. op: 0 sum, 1 min, 2 max.
void reduceColumns(uint op, uint c0, uint c1) {
    uint tid = gl_LocalInvocationID.x;
    barrier();
    for (uint s = kThreads / 2u; s > 0u; s >>= 1u) {
        if (tid < s) {
            for (uint c = c0; c < c1; ++c) {
                float a = partial[c * kThreads + tid];
                float b = partial[c * kThreads + tid + s];
                partial[c * kThreads + tid] = op == 0u ? a + b : (op == 1u ? min(a, b) : max(a, b));
            }
        }
        barrier();
    }
}

BmfrGuideTexel fetchGuide(ivec2 p, uvec2 local) {
    BmfrGuideTexel g;
    g.normal = texelFetch(normal, p, 0).xyz;
    g.position = texelFetch(position, p, 0).xyz;
    g.albedo = texelFetch(albedo, p, 0).rgb;
    g.roughness = texelFetch(roughness, p, 0).x;
    g.meshId = texelFetch(meshid, p, 0).x;
    g.inBlock = vec2(local) / float(max(params.blockSize - 1u, 1u));
    return g;
}

void main() {
    const uint tid = gl_LocalInvocationID.x;
    const uint B = params.blockSize;
    const uint BB = B * B;
    const uint M = params.featureCount;
    const uint C = M + 3u;
    const uint block = gl_WorkGroupID.x;
    const ivec2 size = imageSize(fitted);
    const ivec2 origin = ivec2(block % params.blocksX, block / params.blocksX) * int(B) -
                         ivec2(params.offsetX, params.offsetY);
    const uint base = block * BB * C;

    // 1. Raw features and colour; this thread's min / max over its valid rows.
    float lo[kMaxColumns], hi[kMaxColumns];
    for (uint c = 0u; c < C; ++c) {
        lo[c] = 3.0e38;
        hi[c] = c < M ? -3.0e38 : 0.0;   // colour: max |z|
    }
    for (uint r = tid; r < BB; r += kThreads) {
        uvec2 local = uvec2(r % B, r / B);
        ivec2 p = origin + ivec2(local);
        bool valid = all(greaterThanEqual(p, ivec2(0))) && all(lessThan(p, size));
        BmfrGuideTexel g;
        vec3 z = vec3(0.0);
        if (valid) {
            g = fetchGuide(p, local);
            z = texelFetch(illumination, p, 0).rgb;
        }
        for (uint m = 0u; m < M; ++m) {
            float f = valid ? bmfrRawFeature(featureCode(m), g) : 0.0;
            blocks.values[base + m * BB + r] = f;
            if (valid) {
                lo[m] = min(lo[m], f);
                hi[m] = max(hi[m], f);
            }
        }
        for (uint c = 0u; c < 3u; ++c) {
            blocks.values[base + (M + c) * BB + r] = z[c];
            hi[M + c] = max(hi[M + c], abs(z[c]));
        }
    }
    for (uint c = 0u; c < M; ++c) partial[c * kThreads + tid] = lo[c];
    reduceColumns(1u, 0u, M);
    if (tid == 0u) {
        for (uint c = 0u; c < M; ++c) featureLo[c] = partial[c * kThreads];
    }
    barrier();
    for (uint c = 0u; c < C; ++c) partial[c * kThreads + tid] = hi[c];
    reduceColumns(2u, 0u, C);
    if (tid == 0u) {
        for (uint m = 0u; m < M; ++m) {
            float l = featureLo[m], h = partial[m * kThreads];
            float halfRange = h * 0.5 - l * 0.5;
            bool isFlat = !(2.0 * halfRange > params.flatRange * max(abs(l), abs(h)));
            featureHalfRange[m] = isFlat ? 0.0 : halfRange;
        }
        for (uint c = 0u; c < 3u; ++c) {
            float s = partial[(M + c) * kThreads];
            colourScale[c] = s > 0.0 ? s : 1.0;
        }
    }
    barrier();

    // 2. T scaled to [-1, 1] plus N (Sec. 3.2, Eq. 8); z / max|z| so that no inner
    // product can overflow whatever the radiance (1e-30 .. 3e38).
    for (uint r = tid; r < BB; r += kThreads) {
        uvec2 local = uvec2(r % B, r / B);
        ivec2 p = origin + ivec2(local);
        if (!(all(greaterThanEqual(p, ivec2(0))) && all(lessThan(p, size)))) continue;
        for (uint m = 0u; m < M; ++m) {
            uint i = base + m * BB + r;
            uint code = featureCode(m);
            // A flat column stays exactly 0 (no noise): noise there could only fit z's
            // own noise and regularises nothing; the QR skips the zero column.
            bool live = code == kBmfrOne || featureHalfRange[m] > 0.0;
            blocks.values[i] = bmfrScaled(code, blocks.values[i], featureLo[m], featureHalfRange[m]) +
                        (live ? bmfrNoise(uvec2(p), params.frame, m, params.epsilon) : 0.0);
        }
        for (uint c = 0u; c < 3u; ++c) {
            uint i = base + (M + c) * BB + r;
            blocks.values[i] = blocks.values[i] / colourScale[c];
        }
    }

    // Column norms, for the relative dependency test of step 3.
    {
        float acc[kMaxColumns];
        for (uint m = 0u; m < M; ++m) acc[m] = 0.0;
        for (uint r = tid; r < BB; r += kThreads)
            for (uint m = 0u; m < M; ++m) acc[m] += blocks.values[base + m * BB + r] * blocks.values[base + m * BB + r];
        barrier();
        for (uint m = 0u; m < M; ++m) partial[m * kThreads + tid] = acc[m];
        reduceColumns(0u, 0u, M);
        if (tid == 0u)
            for (uint m = 0u; m < M; ++m) columnNorm2[m] = partial[m * kThreads];
        barrier();
    }

    // 3. Householder QR (Heath 1997, as cited in Sec. 3.2). Step k reflects rows k..W-1
    // so that column k becomes (a, 0, ..., 0), a = -sign(x_0) |x|. With v = x - a e_0,
    // v.v = 2 (|x|^2 + |x_0| |x|) and v.A_j = x.A_j - a A_kj, so one batched reduction of
    // x.A_j over j >= k gives the whole step; A_j -= v (2 v.A_j / v.v).
    // A column whose part independent of the earlier ones is at most dependentColumn
    // of its norm (or zero) is dropped: alpha_k = 0 and it consumes no row, so the
    // later columns still see every row (a rank-revealing QR without pivoting). rho
    // is the next row to reflect onto; it is the same in every thread.
    uint rho = 0u;
    for (uint k = 0u; k < M; ++k) {
        float acc[kMaxColumns];
        for (uint j = k; j < C; ++j) acc[j] = 0.0;
        barrier();   // everyone is done reading rowK and partial of step k - 1
        for (uint r = tid; r < BB; r += kThreads) {
            if (r < rho) continue;
            float xk = blocks.values[base + k * BB + r];
            for (uint j = k; j < C; ++j) {
                float a = blocks.values[base + j * BB + r];
                acc[j] += xk * a;
                if (r == rho) rowK[j] = a;
            }
        }
        for (uint j = k; j < C; ++j) partial[j * kThreads + tid] = acc[j];
        reduceColumns(0u, k, C);
        float xx = partial[k * kThreads];
        float norm = sqrt(max(xx, 0.0));
        float x0 = rowK[k];
        float dep = params.dependentColumn;
        if (!(norm > params.zeroColumn) || !(xx > dep * dep * columnNorm2[k])) {
            continue;   // dependent or zero: dropped
        }
        float a = x0 >= 0.0 ? -norm : norm;
        float vv = 2.0 * (xx + abs(x0) * norm);
        float factor[kMaxColumns];
        for (uint j = k + 1u; j < C; ++j) factor[j] = 2.0 * (partial[j * kThreads] - a * rowK[j]) / vv;
        if (tid == 0u) {
            R[rho * kMaxColumns + k] = a;
            for (uint j = k + 1u; j < C; ++j) R[rho * kMaxColumns + j] = rowK[j] - (x0 - a) * factor[j];
            liveColumn[rho] = k;
        }
        for (uint r = tid; r < BB; r += kThreads) {
            if (r <= rho) continue;
            float v = blocks.values[base + k * BB + r];
            for (uint j = k + 1u; j < C; ++j) blocks.values[base + j * BB + r] -= v * factor[j];
        }
        ++rho;
    }
    barrier();

    // 4. Back substitution R alpha = r (Sec. 3.2, Eq. 5), one channel per thread. A
    // diagonal entry the noise did not lift above the guard gives alpha_k = 0.
    if (tid < 3u) {
        for (uint m = 0u; m < M; ++m) alpha[m * 3u + tid] = 0.0;
        float maxDiag = 0.0;
        for (uint i = 0u; i < rho; ++i) maxDiag = max(maxDiag, abs(R[i * kMaxColumns + liveColumn[i]]));
        for (uint ii = 0u; ii < rho; ++ii) {
            uint i = rho - 1u - ii;
            uint k = liveColumn[i];
            float d = R[i * kMaxColumns + k];
            float s = R[i * kMaxColumns + M + tid];
            for (uint i2 = i + 1u; i2 < rho; ++i2) {
                uint j = liveColumn[i2];
                s -= R[i * kMaxColumns + j] * alpha[j * 3u + tid];
            }
            float value = abs(d) > params.diagonalGuard * maxDiag && d != 0.0 ? s / d : 0.0;
            alpha[k * 3u + tid] = isnan(value) || isinf(value) ? 0.0 : value;
        }
    }
    barrier();

    // 5. y = T alpha with the noise-free T (Sec. 3.2, Eq. 6), back to radiance units.
    for (uint r = tid; r < BB; r += kThreads) {
        uvec2 local = uvec2(r % B, r / B);
        ivec2 p = origin + ivec2(local);
        if (!(all(greaterThanEqual(p, ivec2(0))) && all(lessThan(p, size)))) continue;
        BmfrGuideTexel g = fetchGuide(p, local);
        vec3 y = vec3(0.0);
        for (uint m = 0u; m < M; ++m) {
            uint code = featureCode(m);
            float t = bmfrScaled(code, bmfrRawFeature(code, g), featureLo[m], featureHalfRange[m]);
            y += t * vec3(alpha[m * 3u], alpha[m * 3u + 1u], alpha[m * 3u + 2u]);
        }
        vec3 out3 = clamp(y * vec3(colourScale[0], colourScale[1], colourScale[2]), vec3(-3.0e38), vec3(3.0e38));
        for (uint c = 0u; c < 3u; ++c) {
            if (isnan(out3[c]) || isinf(out3[c])) out3[c] = 0.0;
        }
        imageStore(fitted, p, bmfrStorable(vec4(out3, texelFetch(illumination, p, 0).a)));
    }
}
