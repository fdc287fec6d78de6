#include <hush/passes/bmfr/fit.hpp>

#include <cmath>

#include <hush/core/error.hpp>

namespace hush::passes {

namespace {

// Mirrors fit.comp's push constants.
struct FitParams {
    uint32_t blockSize, offsetX, offsetY, blocksX;
    uint32_t frame, featureCount;
    float epsilon, flatRange, diagonalGuard, zeroColumn, dependentColumn;
    uint32_t pad1 = 0;
    uint32_t codes[8] = {};
};
static_assert(sizeof(FitParams) == 80);

constexpr uint32_t kThreadsPerBlock = 128;   // fit.comp's local_size_x

// Sec. 6.1: "a static sequence of 16 random offsets, uniformly distributed over the
// whole set of possible offsets". Drawn once (uniform on 0..63 in each axis, first
// entry fixed at the undisplaced grid), in 1/64 of a block so every block size uses them.
constexpr std::array<std::array<uint32_t, 2>, 16> kOffsets64 = {{
    {0, 0}, {19, 31}, {63, 20}, {31, 31}, {40, 37}, {52, 30}, {53, 58}, {9, 41},
    {4, 47}, {47, 43}, {34, 26}, {61, 13}, {13, 20}, {37, 56}, {52, 6}, {23, 15},
}};

void validate(const BmfrFitSettings& s, const BmfrGuide& guide) {
    auto fail = [](const std::string& what) { throw Error(ErrorKind::InvalidArgument, "addBmfrFitPass: " + what); };
    if (s.blockSize != 16 && s.blockSize != 32 && s.blockSize != 64) fail("blockSize must be 16, 32 or 64");
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

uint64_t bmfrBlockBufferBytes(rhi::Extent2D image, const BmfrFitSettings& s) {
    // Worst case over the offsets: an offset of blockSize - 1 in both axes.
    const uint64_t bx = (uint64_t(image.width) + 2 * s.blockSize - 2) / s.blockSize;
    const uint64_t by = (uint64_t(image.height) + 2 * s.blockSize - 2) / s.blockSize;
    const uint64_t columns = s.features.size() + 3;
    return bx * by * uint64_t(s.blockSize) * s.blockSize * columns * sizeof(float);
}

graph::TextureHandle addBmfrFitPass(NodeContext& ctx, const std::string& name, graph::TextureHandle illumination,
                                    const BmfrGuide& guide, const BmfrFitSettings& settings) {
    validate(settings, guide);
    // One shader per output format: the image's format qualifier must be literal.
    const rhi::ComputePipeline pipeline =
        ctx.pipelines.get(settings.format == rhi::Format::RGBA16Float ? "bmfr/fit_rgba16f" : "bmfr/fit");

    FitParams params{};
    params.blockSize = settings.blockSize;
    params.featureCount = uint32_t(settings.features.size());
    params.epsilon = settings.epsilon;
    params.flatRange = kBmfrFlatRange;
    params.diagonalGuard = kBmfrDiagonalGuard;
    params.zeroColumn = kBmfrZeroColumn;
    params.dependentColumn = kBmfrDependentColumn;
    for (size_t m = 0; m < settings.features.size(); ++m)
        params.codes[m / 4] |= uint32_t(settings.features[m]) << (8 * (m % 4));
    const BmfrFitSettings s = settings;

    graph::TextureHandle out;
    ctx.graph.addPass(name, [&](graph::PassBuilder& b) {
        auto illum = b.sample("illumination", illumination);
        // Guide slots no feature reads are bound to the illumination (the shader never
        // reads them), so the pipeline has one layout whatever the feature set.
        auto guideOr = [&](const char* port, graph::TextureHandle h) { return h.valid() ? b.sample(port, h) : illum; };
        auto n = guideOr("normal", guide.normal);
        auto w = guideOr("position", guide.position);
        auto alb = guideOr("albedo", guide.albedo);
        auto rough = guideOr("roughness", guide.roughness);
        auto mesh = guideOr("meshId", guide.meshId);
        // Sized by the graph from its output size, so the matrix follows size changes.
        graph::BufferInfo blocksInfo;
        blocksInfo.sizeFromOutput = [s](rhi::Extent2D output) { return bmfrBlockBufferBytes(output, s); };
        auto blocks = b.write("blocks", b.create(name + ".blocks", blocksInfo));
        out = b.write("fitted", b.create(name, fullSize(s.format)));
        auto group = b.bindGroup(pipeline, 0,
                                 {{.name = "illumination", .texture = illum},
                                  {.name = "normal", .texture = n},
                                  {.name = "position", .texture = w},
                                  {.name = "albedo", .texture = alb},
                                  {.name = "roughness", .texture = rough},
                                  {.name = "meshId", .texture = mesh},
                                  {.name = "fitted", .texture = out},
                                  {.name = "Blocks", .buffer = blocks}});
        const graph::TextureHandle fitted = out;
        return [=](graph::PassContext& pc) {
            const rhi::Extent2D size = pc.texture(fitted).size();
            const BmfrBlockGrid grid = bmfrBlockGrid(size, s.blockSize, s.offsetBlocks, pc.frameIndex());
            FitParams p = params;
            p.offsetX = grid.offsetX;
            p.offsetY = grid.offsetY;
            p.blocksX = grid.blocksX;
            p.frame = uint32_t(pc.frameIndex());
            pc.dispatch(pipeline, group, {grid.blocksX * grid.blocksY * kThreadsPerBlock, 1}, p);
        };
    });
    return out;
}

} // namespace hush::passes
