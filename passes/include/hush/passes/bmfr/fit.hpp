#pragma once
// BMFR's per-block feature regression (Koskela et al. 2019, Sec. 3.2): one graph node
// that, for every non-overlapping block of the (displaced) block grid, fits the noisy
// illumination z as a linear combination of per-block scaled feature buffers T by a
// Householder QR of the augmented matrix [T + N, z_r, z_g, z_b] (stochastic
// regularisation, Sec. 3.2 "Feature Fitting with Stochastic Regularization"), solves
// R alpha = r by back substitution and writes T alpha with the noise-free T.
// docs/passes/bmfr.md has the formulas, layouts, guards and tolerances.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <hush/passes/settings.hpp>
#include <hush/passes/node_context.hpp>

namespace hush::passes {

// One column of T. The paper's set (Sec. 5, Eq. 7) is One .. PositionZ2; the rest
// are the other buffers it tried (Figs. 4-5, 10): albedo, roughness, mesh id and
// the horizontal / vertical in-block gradients (0 at the block's first pixel, 1 at
// its last).
enum class BmfrFeature : uint32_t {
    One,
    NormalX, NormalY, NormalZ,
    PositionX, PositionY, PositionZ,
    PositionX2, PositionY2, PositionZ2,
    AlbedoR, AlbedoG, AlbedoB,
    Roughness,
    MeshId,
    BlockU, BlockV,
};
inline constexpr uint32_t kBmfrFeatureKinds = 17;
// At most this many features (+ 3 colour columns = 20 columns of the augmented
// matrix; the shader's shared memory is sized for it).
inline constexpr uint32_t kBmfrMaxFeatures = 17;

// T = [1, n_x, n_y, n_z, w_x, w_y, w_z, w_x^2, w_y^2, w_z^2] (Sec. 5, Eq. 7).
std::vector<BmfrFeature> bmfrPaperFeatures();
// Which guide texture a feature reads.
bool bmfrNeedsAlbedo(BmfrFeature f);
bool bmfrNeedsRoughness(BmfrFeature f);
bool bmfrNeedsMeshId(BmfrFeature f);

// The noise-free guide buffers. normal and position are required (xyz); the others
// only when a feature reads them (albedo rgb; roughness and mesh id in .x).
struct BmfrGuide {
    graph::TextureHandle normal;
    graph::TextureHandle position;
    graph::TextureHandle albedo;
    graph::TextureHandle roughness;
    graph::TextureHandle meshId;
};

struct BmfrFitSettings {
    // 8, 16, 32 or 64 pixels; 0 (the default): follows the frame (bmfrBlockSizeFor). Sec.
    // 6.1 uses 32 x 32 at 1280x720 (64 x 64 gave the best quality, 32 more parallel
    // work): 40 x 23 blocks. Fixed at 32, a 128x128 frame has 16 blocks, too few and
    // too large for the features to represent the light in each (Sec. 8 (1)); measured
    // in docs/sweep.md, keeping the paper's block count is better on every scene.
    uint32_t blockSize = 0;
    // Stochastic regularisation: N uniform in [-epsilon, epsilon] (Sec. 3.2: 0.01; 1e-4
    // failed to regularise, 1 gave visibly wrong constant blocks).
    float epsilon = 0.01f;
    std::vector<BmfrFeature> features = bmfrPaperFeatures();
    // Displace the block grid by one of 16 pre-generated offsets, chosen by the frame
    // index (Sec. 6.1); false: the grid starts at pixel (0, 0) every frame.
    bool offsetBlocks = true;
    // Negative fitted values set to 0 and the block's other values scaled by
    // sum(y) / sum(max(y, 0)) per channel, so the block keeps its sum: a fit beside a
    // firefly rings below 0 (most in 8-pixel blocks), which no radiance is. A block
    // with no negative value is unchanged. false: the paper's plain T alpha.
    bool nonNegative = true;
    // Format of the fitted output: RGBA32Float (default) or RGBA16Float
    // (BmfrSettings::halfPrecision; clamped to +-65504). The block matrix buffer and
    // the QR stay fp32 either way.
    rhi::Format format = rhi::Format::RGBA32Float;
};

// The names of BmfrFeature's values, in its order.
inline constexpr EnumNames<BmfrFeature, kBmfrFeatureKinds> kBmfrFeatureNames{{
    {"one", BmfrFeature::One},
    {"normalX", BmfrFeature::NormalX},       {"normalY", BmfrFeature::NormalY},       {"normalZ", BmfrFeature::NormalZ},
    {"positionX", BmfrFeature::PositionX},   {"positionY", BmfrFeature::PositionY},   {"positionZ", BmfrFeature::PositionZ},
    {"positionX2", BmfrFeature::PositionX2}, {"positionY2", BmfrFeature::PositionY2}, {"positionZ2", BmfrFeature::PositionZ2},
    {"albedoR", BmfrFeature::AlbedoR},       {"albedoG", BmfrFeature::AlbedoG},       {"albedoB", BmfrFeature::AlbedoB},
    {"roughness", BmfrFeature::Roughness},   {"meshId", BmfrFeature::MeshId},
    {"blockU", BmfrFeature::BlockU},         {"blockV", BmfrFeature::BlockV},
}};

template <class V> void describe(V&& v, BmfrFitSettings& s) {
    v.field("blockSize", s.blockSize, Choices<5>{0, 8, 16, 32, 64});
    v.field("epsilon", s.epsilon, Range{0.0, kUnbounded});
    v.field("features", s.features, kBmfrFeatureNames, kBmfrMaxFeatures);
    v.field("offsetBlocks", s.offsetBlocks);
    v.field("nonNegative", s.nonNegative);
    v.field("format", s.format, kStorageFormatNames);
}

// A feature whose per-block range (max - min) is at most this fraction of its
// largest magnitude is constant in the block: its scaled column is 0 (the One
// column already holds any constant), instead of dividing by a vanishing range.
inline constexpr float kBmfrFlatRange = 1e-6f;
// Back substitution skips (alpha_k = 0) a diagonal entry |R_kk| at most this fraction
// of the block's largest |R_jj|: a column that the noise did not make independent.
inline constexpr float kBmfrDiagonalGuard = 1e-5f;
// A column whose part independent of the earlier columns (its norm below the rows
// already reflected onto) is at most this fraction of its norm is dropped from the
// fit (alpha = 0, no row consumed). Above fp32 rounding of an exact dependency
// (about 2e-6 for 1024 rows), below what eps = 1e-4 noise leaves (about 1e-4).
inline constexpr float kBmfrDependentColumn = 3e-5f;
// A Householder column whose remaining norm is at most this is already zero.
inline constexpr float kBmfrZeroColumn = 1e-18f;

// The block grid of one frame: block (bx, by) covers pixels
// [bx * size - offsetX, (bx + 1) * size - offsetX) x [by * size - offsetY, ...);
// pixels outside the image are not part of any block's fit.
struct BmfrBlockGrid {
    uint32_t blockSize = 32;
    uint32_t offsetX = 0, offsetY = 0;   // in [0, blockSize)
    uint32_t blocksX = 0, blocksY = 0;   // enough to cover the image
};
// The block size a fit uses on `image`: `blockSize` when it is 8, 16, 32 or 64; for 0,
// the paper's 32 pixels at 720 lines scaled by height / 720 (the paper's block count),
// rounded to the nearest of 8, 16, 32, 64 on a log scale: 8 below 255 lines, 16 below
// 510, 64 from 1019 lines on.
uint32_t bmfrBlockSizeFor(rhi::Extent2D image, uint32_t blockSize);
// Offset k of the 16 (Sec. 6.1: "a static sequence of 16 random offsets"), in 1/64
// of a block; offset 0 is (0, 0).
std::array<uint32_t, 2> bmfrOffset64(uint32_t k);
BmfrBlockGrid bmfrBlockGrid(rhi::Extent2D image, uint32_t blockSize, bool offsetBlocks, uint64_t frameIndex);

// Adds "<name>" (one compute workgroup per block) and returns the fitted illumination
// (settings.format, rgba32f by default, full size; rgb = T alpha, a = illumination's alpha). `illumination` is
// the accumulated, demodulated noisy colour (rgb). Each block's matrix lives in its
// workgroup's registers (B^2 / min(B, 32) invocations), so the node needs no buffer and
// follows size changes. Throws hush::Error: InvalidArgument on bad settings or a
// missing guide texture, Unsupported where the device's subgroups are under 4
// invocations or a fixed blockSize needs more invocations than a workgroup allows.
graph::TextureHandle addBmfrFitPass(NodeContext& ctx, const std::string& name, graph::TextureHandle illumination,
                                    const BmfrGuide& guide, const BmfrFitSettings& settings = {});

} // namespace hush::passes
