#include <hush/passes/bmfr/fit.hpp>

#include <algorithm>
#include <cmath>

#include <hush/core/error.hpp>
#include <hush/passes/settings_push_constants.hpp>

namespace hush::passes {

namespace {

// Sec. 6.1: "a static sequence of 16 random offsets, uniformly distributed over the
// whole set of possible offsets". Drawn once (uniform on 0..63 in each axis, first
// entry fixed at the undisplaced grid), in 1/64 of a block so every block size uses them.
constexpr std::array<std::array<uint32_t, 2>, 16> kOffsets64 = {{
    {0, 0}, {19, 31}, {63, 20}, {31, 31}, {40, 37}, {52, 30}, {53, 58}, {9, 41},
    {4, 47}, {47, 43}, {34, 26}, {61, 13}, {13, 20}, {37, 56}, {52, 6}, {23, 15},
}};

void validate(const BmfrFitSettings& s, const BmfrGuide& guide) {
    auto fail = [](const std::string& what) { throw Error(ErrorKind::InvalidArgument, "addBmfrFitPass: " + what); };
    if (s.blockSize != 0 && s.blockSize != 8 && s.blockSize != 16 && s.blockSize != 32 && s.blockSize != 64)
        fail("blockSize must be 0 (follow the frame), 8, 16, 32 or 64");
    if (!(std::isfinite(s.epsilon) && s.epsilon >= 0.0f)) fail("epsilon must be finite and >= 0");
    if (s.format != rhi::Format::RGBA32Float && s.format != rhi::Format::RGBA16Float)
        fail("format must be RGBA32Float or RGBA16Float");
    if (s.features.empty() || s.features.size() > kBmfrMaxFeatures)
        fail("features: 1 to " + std::to_string(kBmfrMaxFeatures) + " of them");
    for (BmfrFeature f : s.features) {
        if (uint32_t(f) >= kBmfrFeatureKinds) fail("unknown feature");
        const bool normalF = f >= BmfrFeature::NormalX && f <= BmfrFeature::NormalZ;
        const bool positionF = f >= BmfrFeature::PositionX && f <= BmfrFeature::PositionZ2;
        if (normalF && !guide.normal.valid()) fail("a normal feature needs guide.normal");
        if (positionF && !guide.position.valid()) fail("a position feature needs guide.position");
        if (bmfrNeedsAlbedo(f) && !guide.albedo.valid()) fail("an albedo feature needs guide.albedo");
        if (bmfrNeedsRoughness(f) && !guide.roughness.valid()) fail("the roughness feature needs guide.roughness");
        if (bmfrNeedsMeshId(f) && !guide.meshId.valid()) fail("the mesh id feature needs guide.meshId");
    }
}

} // namespace

std::vector<BmfrFeature> bmfrPaperFeatures() {
    using F = BmfrFeature;
    return {F::One,       F::NormalX,   F::NormalY,   F::NormalZ,    F::PositionX,
            F::PositionY, F::PositionZ, F::PositionX2, F::PositionY2, F::PositionZ2};
}

bool bmfrNeedsAlbedo(BmfrFeature f) { return f >= BmfrFeature::AlbedoR && f <= BmfrFeature::AlbedoB; }
bool bmfrNeedsRoughness(BmfrFeature f) { return f == BmfrFeature::Roughness; }
bool bmfrNeedsMeshId(BmfrFeature f) { return f == BmfrFeature::MeshId; }

uint32_t bmfrBlockSizeFor(rhi::Extent2D image, uint32_t blockSize) {
    if (blockSize != 0) return blockSize;
    const double scaled = 32.0 * double(image.height) / 720.0;
    if (scaled * scaled < 8.0 * 16.0) return 8;     // below the geometric mean of 8 and 16
    if (scaled * scaled < 16.0 * 32.0) return 16;
    if (scaled * scaled < 32.0 * 64.0) return 32;
    return 64;
}

std::array<uint32_t, 2> bmfrOffset64(uint32_t k) { return kOffsets64[k % kOffsets64.size()]; }

BmfrBlockGrid bmfrBlockGrid(rhi::Extent2D image, uint32_t blockSize, bool offsetBlocks, uint64_t frameIndex) {
    BmfrBlockGrid g;
    g.blockSize = blockSize;
    if (offsetBlocks) {
        const auto o = bmfrOffset64(uint32_t(frameIndex % kOffsets64.size()));
        g.offsetX = o[0] * blockSize / 64;
        g.offsetY = o[1] * blockSize / 64;
    }
    // Block 0 starts at -offset (< blockSize), so it holds pixel 0; the last block starts
    // inside the image: every block has at least one valid pixel.
    g.blocksX = (image.width + g.offsetX + blockSize - 1) / blockSize;
    g.blocksY = (image.height + g.offsetY + blockSize - 1) / blockSize;
    return g;
}

namespace {
// The constant part of the fit shaders' push constants: settings and guards.
rhi::PushConstants fitParams(const rhi::ComputePipeline& pipeline, const BmfrFitSettings& settings) {
    rhi::PushConstants params(pipeline);
    setFromSettings(params, settings);
    params.set("flatRange", kBmfrFlatRange)
        .set("diagonalGuard", kBmfrDiagonalGuard)
        .set("zeroColumn", kBmfrZeroColumn)
        .set("dependentColumn", kBmfrDependentColumn);
    return params;
}

// The feature set as the fit shaders' specialization constants (fit.glsl): the count,
// and one byte per feature code, feature m in byte m % 4 of featureCodes<m / 4>.
std::vector<rhi::ConstantEntry> fitConstants(const BmfrFitSettings& settings) {
    std::array<uint32_t, (kBmfrMaxFeatures + 3) / 4> codes{};
    for (size_t m = 0; m < settings.features.size(); ++m) codes[m / 4] |= uint32_t(settings.features[m]) << (8 * (m % 4));
    std::vector<rhi::ConstantEntry> constants{{"featureCount", double(settings.features.size())}};
    for (size_t w = 0; w < codes.size(); ++w) constants.push_back({"featureCodes" + std::to_string(w), double(codes[w])});
    return constants;
}

// The fit shader of one block size and output format: the block size fixes the
// workgroup (B^2 / rows invocations, fitRows(B) matrix rows each, in registers: fit.glsl).
std::string fitShader(uint32_t blockSize, rhi::Format format) {
    return "bmfr/fit" + std::to_string(blockSize) + (format == rhi::Format::RGBA16Float ? "_rgba16f" : "");
}

// Matrix rows per invocation: HUSH_BMFR_FIT_ROWS in fit.glsl. min(B, 32): an
// invocation owns one pixel column of the block (of two at B = 64), so B (128 at 64)
// invocations meet at each of the QR's barriers instead of B^2 / 8. On lavapipe, 16
// rows instead of 8 made the fit 1.2-1.3x faster at 16- and 32-pixel blocks, and 32
// instead of 16 another 1.08-1.13x at 32; 64 rows at 32 were slower (register spills:
// docs/benchmarks.md). An 8-pixel block keeps 8 invocations, one 8-lane subgroup.
uint32_t fitRows(uint32_t blockSize) { return std::min(blockSize, 32u); }
uint32_t fitThreads(uint32_t blockSize) { return blockSize * blockSize / fitRows(blockSize); }

// One block size's pipeline with its own push constants (they belong to a pipeline)
// and the slots the pass writes every frame.
struct FitVariant {
    uint32_t blockSize;
    rhi::ComputePipeline pipeline;
    rhi::PushConstants params;
    rhi::PushConstants::Slot offsetX, offsetY, blocksX, frame;

    FitVariant(uint32_t block, rhi::ComputePipeline p, const BmfrFitSettings& settings)
        : blockSize(block), pipeline(std::move(p)), params(fitParams(pipeline, settings)),
          offsetX(params.slot("offsetX", rhi::ScalarType::Uint32)),
          offsetY(params.slot("offsetY", rhi::ScalarType::Uint32)),
          blocksX(params.slot("blocksX", rhi::ScalarType::Uint32)),
          frame(params.slot("frame", rhi::ScalarType::Uint32)) {}

    void setGrid(const BmfrBlockGrid& grid, uint64_t frameIndex) {
        params.set(offsetX, grid.offsetX);
        params.set(offsetY, grid.offsetY);
        params.set(blocksX, grid.blocksX);
        params.set(frame, uint32_t(frameIndex));
    }
};

// The block sizes a fit can meet: the given one, or all four when it follows the frame.
std::vector<uint32_t> fitBlockSizes(uint32_t blockSize) {
    return blockSize != 0 ? std::vector<uint32_t>{blockSize} : std::vector<uint32_t>{8, 16, 32, 64};
}

// fit.glsl reduces through subgroups and sizes its shared memory for subgroups of at
// least 4 invocations; a 64-pixel block needs 256 invocations per workgroup.
void checkDevice(const rhi::Device& device, uint32_t blockSize, const std::string& name) {
    const auto& limits = device.adapterInfo().limits;
    if (limits.subgroupSize < 4)
        throw Error(ErrorKind::Unsupported, name + ": the BMFR fit needs subgroups of at least 4 invocations; " +
                                                device.adapterInfo().name + " has " + std::to_string(limits.subgroupSize));
    if (blockSize != 0 && fitThreads(blockSize) > limits.maxComputeInvocationsPerWorkgroup)
        throw Error(ErrorKind::Unsupported,
                    name + ": blockSize " + std::to_string(blockSize) + " needs " + std::to_string(fitThreads(blockSize)) +
                        " invocations per workgroup; " + device.adapterInfo().name + " allows " +
                        std::to_string(limits.maxComputeInvocationsPerWorkgroup) + ": use a smaller blockSize");
}
} // namespace

graph::TextureHandle addBmfrFitPass(NodeContext& ctx, const std::string& name, graph::TextureHandle illumination,
                                    const BmfrGuide& guide, const BmfrFitSettings& settings) {
    validate(settings, guide);
    checkDevice(ctx.pipelines.device(), settings.blockSize, name);
    // One shader per block size and output format: the workgroup size and the image's
    // format qualifier must be literal. With blockSize 0 the size follows the frame,
    // so the pass holds every size's pipeline and picks one per frame.
    const uint32_t maxThreads = ctx.pipelines.device().adapterInfo().limits.maxComputeInvocationsPerWorkgroup;
    const std::vector<rhi::ConstantEntry> constants = fitConstants(settings);
    std::vector<FitVariant> variants;
    for (uint32_t b : fitBlockSizes(settings.blockSize))
        if (fitThreads(b) <= maxThreads) variants.emplace_back(b, ctx.pipelines.get(fitShader(b, settings.format), constants), settings);
    const BmfrFitSettings s = settings;
    const rhi::Device device = ctx.pipelines.device();
    struct Out {
        graph::TextureHandle fitted;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        b.sample("illumination", illumination);
        // Guides no feature reads stay unconnected: the pipeline has one layout whatever the feature set.
        b.sample("normal", guide.normal, {.optional = true});
        b.sample("position", guide.position, {.optional = true});
        b.sample("albedo", guide.albedo, {.optional = true});
        b.sample("roughness", guide.roughness, {.optional = true});
        b.sample("meshid", guide.meshId, {.optional = true});
        o.fitted = b.write("fitted", b.create(name, fullSize(s.format)));
        std::vector<graph::BindGroupHandle> groups;
        for (const FitVariant& variant : variants) groups.push_back(b.bindGroup(variant.pipeline));
        return [=](graph::PassContext& pc) mutable {
            const rhi::Extent2D size = pc.texture(o.fitted).size();
            const BmfrBlockGrid grid = bmfrBlockGrid(size, bmfrBlockSizeFor(size, s.blockSize), s.offsetBlocks, pc.frameIndex());
            size_t v = 0;
            while (v < variants.size() && variants[v].blockSize != grid.blockSize) ++v;
            if (v == variants.size()) checkDevice(device, grid.blockSize, name);   // throws: too few invocations
            variants[v].setGrid(grid, pc.frameIndex());
            pc.dispatch(variants[v].pipeline, groups[v], {grid.blocksX * grid.blocksY * fitThreads(grid.blockSize), 1},
                        variants[v].params);
        };
    });
    return out.fitted;
}

} // namespace hush::passes
