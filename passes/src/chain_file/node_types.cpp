#include "chain_file/node_types.hpp"

#include <hush/passes/bmfr/accumulate.hpp>
#include <hush/passes/bmfr/fit.hpp>
#include <hush/passes/common/demodulate.hpp>
#include <hush/passes/common/reproject.hpp>
#include <hush/passes/common/taa.hpp>
#include <hush/passes/common/tonemap.hpp>
#include <hush/passes/eaw/atrous.hpp>
#include <hush/passes/svgf/atrous.hpp>
#include <hush/passes/svgf/variance_estimate.hpp>

#include "chain_file/settings_json.hpp"

namespace hush::passes::chain_file {

std::string_view toString(PortKind kind) {
    switch (kind) {
    case PortKind::Texture: return "texture";
    case PortKind::Surface: return "surface (a 'surface' node)";
    case PortKind::Temporal: return "temporal state (an 'svgf.temporal' node)";
    }
    return "?";
}

PortKind kindOf(const Value& value) { return PortKind(value.index()); }

namespace {

using graph::TextureHandle;

TextureHandle texture(const NodeBuild& b, size_t port) {
    return b.inputs[port] ? std::get<TextureHandle>(*b.inputs[port]) : TextureHandle{};
}

// A settings reader for a node whose settings are one struct.
template <class S> std::function<std::any(ObjectReader&)> settingsOf() {
    return [](ObjectReader& r) -> std::any {
        S s;
        readSettings(r, s);
        return s;
    };
}
std::any noSettings(ObjectReader&) { return {}; }

std::vector<NodeType> makeNodeTypes() {
    using K = PortKind;
    std::vector<NodeType> t;
    t.push_back({"demodulate", "illumination = (radiance - emission) / albedo (common/demodulate.hpp)",
                 {{"radiance"}, {"albedo"}, {"emission", K::Texture, true}}, {{"illumination"}},
                 settingsOf<DemodulateSettings>(),
                 [](const NodeBuild& b) -> std::vector<Value> {
                     return {addDemodulatePass(b.ctx, b.name, texture(b, 0), texture(b, 1),
                                               std::any_cast<const DemodulateSettings&>(b.settings), texture(b, 2))};
                 }});
    t.push_back({"remodulate", "radiance = (a + b) * albedo + emission; b and emission optional (common/demodulate.hpp)",
                 {{"a"}, {"b", K::Texture, true}, {"albedo"}, {"emission", K::Texture, true}}, {{"radiance"}},
                 settingsOf<DemodulateSettings>(),
                 [](const NodeBuild& b) -> std::vector<Value> {
                     return {addRemodulatePass(b.ctx, b.name, texture(b, 0), texture(b, 1), texture(b, 2),
                                               std::any_cast<const DemodulateSettings&>(b.settings), texture(b, 3))};
                 }});
    t.push_back({"surface", "packs normal, depth, mesh id and the depth gradient (common/surface.hpp)",
                 {{"normal"}, {"depth"}, {"meshid"}}, {{"surface", K::Surface}}, noSettings,
                 [](const NodeBuild& b) -> std::vector<Value> {
                     return {addSurfacePass(b.ctx, b.name, texture(b, 0), texture(b, 1), texture(b, 2))};
                 }});
    t.push_back({"reproject", "per-pixel history footprint through motion, tested against the surface "
                              "(common/reproject.hpp); 'surface' must be a surface node",
                 {{"motion"}, {"surface", K::Surface}}, {{"reprojection"}}, settingsOf<ReprojectSettings>(),
                 [](const NodeBuild& b) -> std::vector<Value> {
                     const auto& surface = std::get<Surface>(*b.inputs[1]);
                     // Last frame's surface: the history of the same surface node's textures.
                     Surface previous{b.ctx.graph.history(b.ctx.graph.model().resources[surface.normalDepth.index].name,
                                                          fullSize()),
                                      b.ctx.graph.history(b.ctx.graph.model().resources[surface.gradientMesh.index].name,
                                                          fullSize())};
                     return {addReprojectPass(b.ctx, b.name, texture(b, 0), surface, previous,
                                              std::any_cast<const ReprojectSettings&>(b.settings))};
                 }});
    t.push_back({"svgf.temporal", "SVGF temporal accumulation of colour and luminance moments (Sec. 4.1); "
                                  "setting 'colorHistory' names the svgf.atrous node whose first level feeds back",
                 {{"illumination"}, {"reprojection"}}, {{"temporal", K::Temporal}},
                 [](ObjectReader& r) -> std::any {
                     TemporalNodeSettings s;
                     r.read("colorHistory", s.colorHistory);
                     readSettings(r, s.temporal);
                     if (s.colorHistory.empty()) fail(r.source(), r.path("colorHistory"), "missing (the svgf.atrous node whose level 0 is the colour history)");
                     return s;
                 },
                 [](const NodeBuild& b) -> std::vector<Value> {
                     const auto& s = std::any_cast<const TemporalNodeSettings&>(b.settings);
                     return {addSvgfTemporalPass(b.ctx, b.name, texture(b, 0), texture(b, 1),
                                                 s.colorHistory + ".level.0", s.temporal)};
                 }});
    t.push_back({"svgf.variance", "SVGF variance estimate, spatial under 4 frames of history (Sec. 4.2)",
                 {{"temporal", K::Temporal}, {"surface", K::Surface}}, {{"illum_variance"}},
                 settingsOf<SvgfVarianceSettings>(),
                 [](const NodeBuild& b) -> std::vector<Value> {
                     return {addSvgfVariancePass(b.ctx, b.name, std::get<SvgfTemporal>(*b.inputs[0]),
                                                 std::get<Surface>(*b.inputs[1]),
                                                 std::any_cast<const SvgfVarianceSettings&>(b.settings))};
                 }});
    t.push_back({"svgf.atrous", "SVGF variance-guided a-trous levels with prefilters (Sec. 4.3-4.4)",
                 {{"illum_variance"}, {"surface", K::Surface}}, {{"filtered"}, {"level0"}},
                 settingsOf<SvgfAtrousSettings>(),
                 [](const NodeBuild& b) -> std::vector<Value> {
                     auto r = addSvgfAtrousLevels(b.ctx, b.name, texture(b, 0), std::get<Surface>(*b.inputs[1]),
                                                  std::any_cast<const SvgfAtrousSettings&>(b.settings));
                     return {r.filtered, r.firstLevel};
                 }});
    t.push_back({"eaw.atrous", "Dammertz et al. 2010 edge-avoiding a-trous levels, global parameters; with depth, the position "
                               "weight is relative to depth",
                 {{"color"}, {"normal"}, {"position"}, {"depth", K::Texture, true}}, {{"filtered"}},
                 settingsOf<EawSettings>(),
                 [](const NodeBuild& b) -> std::vector<Value> {
                     return {addEawAtrousLevels(b.ctx, b.name, texture(b, 0), texture(b, 1), texture(b, 2),
                                                texture(b, 3), std::any_cast<const EawSettings&>(b.settings))};
                 }});
    t.push_back({"bmfr.accumulate", "BMFR temporal accumulation: cumulative average until the new sample's weight "
                                    "reaches minWeight (0.2; 0.1 after the fit), then exponential; count in alpha "
                                    "(Koskela et al. 2019 Sec. 3.1, 3.3)",
                 {{"input"}, {"reprojection"}}, {{"accumulated"}}, settingsOf<BmfrAccumulateSettings>(),
                 [](const NodeBuild& b) -> std::vector<Value> {
                     return {addBmfrAccumulatePass(b.ctx, b.name, texture(b, 0), texture(b, 1),
                                                   std::any_cast<const BmfrAccumulateSettings&>(b.settings))};
                 }});
    t.push_back({"bmfr.fit", "BMFR per-block feature regression, 32x32 blocks, stochastic regularisation "
                             "(Koskela et al. 2019 Sec. 3.2); albedo, roughness and meshid only for those features",
                 {{"illumination"}, {"normal"}, {"position"}, {"albedo", K::Texture, true},
                  {"roughness", K::Texture, true}, {"meshid", K::Texture, true}},
                 {{"fitted"}}, settingsOf<BmfrFitSettings>(),
                 [](const NodeBuild& b) -> std::vector<Value> {
                     const BmfrGuide guide{texture(b, 1), texture(b, 2), texture(b, 3), texture(b, 4), texture(b, 5)};
                     return {addBmfrFitPass(b.ctx, b.name, texture(b, 0), guide,
                                            std::any_cast<const BmfrFitSettings&>(b.settings))};
                 }});
    t.push_back({"tonemap", "HDR radiance to display values in [0, 1] (common/tonemap.hpp)", {{"radiance"}},
                 {{"display"}}, settingsOf<TonemapSettings>(),
                 [](const NodeBuild& b) -> std::vector<Value> {
                     return {addTonemapPass(b.ctx, b.name, texture(b, 0),
                                            std::any_cast<const TonemapSettings&>(b.settings))};
                 }});
    t.push_back({"taa", "temporal anti-aliasing, YCoCg neighbourhood clip (Karis 2014); with a reprojection "
                        "decision, history only from the same surface",
                 {{"color"}, {"motion"}, {"reprojection", K::Texture, true}}, {{"color"}}, settingsOf<TaaSettings>(),
                 [](const NodeBuild& b) -> std::vector<Value> {
                     return {addTaaPass(b.ctx, b.name, texture(b, 0), texture(b, 1),
                                        std::any_cast<const TaaSettings&>(b.settings), texture(b, 2))};
                 }});
    return t;
}

} // namespace

const std::vector<NodeType>& nodeTypes() {
    static const std::vector<NodeType> types = makeNodeTypes();
    return types;
}

const NodeType* findNodeType(std::string_view type) {
    for (const auto& t : nodeTypes())
        if (t.type == type) return &t;
    return nullptr;
}

} // namespace hush::passes::chain_file
