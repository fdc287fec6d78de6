// SVGF's nodes in chain files: svgf.temporal, svgf.variance, svgf.atrous.
#include <hush/passes/svgf/atrous.hpp>
#include <hush/passes/svgf/temporal_accumulation.hpp>
#include <hush/passes/svgf/variance_estimate.hpp>

#include "chain_file/node_types.hpp"

namespace hush::passes::chain_file {

namespace {
constexpr ValueKind kSvgfTemporalKind{"svgf.temporal", "temporal state (an 'svgf.temporal' node)"};

Value temporalValue(const SvgfTemporal& t) { return {&kSvgfTemporalKind, {t.color, t.moments}}; }
SvgfTemporal temporalOf(const Value& v) { return {v.textures[0], v.textures[1]}; }
} // namespace

void addSvgfNodeTypes(std::vector<NodeType>& t) {
    t.push_back({"svgf.temporal", "SVGF temporal accumulation of colour and luminance moments (Sec. 4.1); "
                                  "color_history: last frame's colour, e.g. \"history:<atrous id>.level0\" "
                                  "(unconnected: its own output)",
                 {{"illumination"}, {"reprojection"}, {"color_history", &kTextureKind, true}},
                 {{"temporal", &kSvgfTemporalKind}}, settingsOf<SvgfTemporalSettings>(),
                 [](const NodeBuild& b) -> std::vector<Value> {
                     return {temporalValue(addSvgfTemporalPass(b.ctx, b.name, b.texture(0), b.texture(1), b.texture(2),
                                                               b.settingsAs<SvgfTemporalSettings>()))};
                 }});
    t.push_back({"svgf.variance", "SVGF variance estimate, spatial under 4 frames of history (Sec. 4.2)",
                 {{"temporal", &kSvgfTemporalKind}, {"surface", &kSurfaceKind}}, {{"illum_variance"}},
                 settingsOf<SvgfVarianceSettings>(), [](const NodeBuild& b) -> std::vector<Value> {
                     return {textureValue(addSvgfVariancePass(b.ctx, b.name, temporalOf(b.value(0)),
                                                              surfaceOf(b.value(1)),
                                                              b.settingsAs<SvgfVarianceSettings>()))};
                 }});
    t.push_back({"svgf.atrous", "SVGF variance-guided a-trous levels with prefilters (Sec. 4.3-4.4)",
                 {{"illum_variance"}, {"surface", &kSurfaceKind}}, {{"filtered"}, {"level0"}},
                 settingsOf<SvgfAtrousSettings>(), [](const NodeBuild& b) -> std::vector<Value> {
                     const auto r = addSvgfAtrousLevels(b.ctx, b.name, b.texture(0), surfaceOf(b.value(1)),
                                                        b.settingsAs<SvgfAtrousSettings>());
                     return {textureValue(r.filtered), textureValue(r.firstLevel)};
                 }});
}

} // namespace hush::passes::chain_file
