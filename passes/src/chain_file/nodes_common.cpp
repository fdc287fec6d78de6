// The shared nodes in chain files: demodulate, remodulate, surface, reproject,
// tonemap, taa.
#include <hush/passes/common/demodulate.hpp>
#include <hush/passes/common/remodulate.hpp>
#include <hush/passes/common/reproject.hpp>
#include <hush/passes/common/taa.hpp>
#include <hush/passes/common/tonemap.hpp>

#include "chain_file/node_types.hpp"

namespace hush::passes::chain_file {

void addCommonNodeTypes(std::vector<NodeType>& t) {
    t.push_back({"demodulate", "illumination = (radiance - emission) / albedo (common/demodulate.hpp)",
                 {{"radiance"}, {"albedo"}, {"emission", &kTextureKind, true}}, {{"illumination"}},
                 settingsOf<DemodulateSettings>(), [](const NodeBuild& b) -> std::vector<Value> {
                     return {textureValue(addDemodulatePass(b.ctx, b.name, b.texture(0), b.texture(1),
                                                            b.settingsAs<DemodulateSettings>(), b.texture(2)))};
                 }});
    t.push_back({"remodulate", "radiance = (a + b) * albedo + emission; b and emission optional (common/remodulate.hpp)",
                 {{"a"}, {"b", &kTextureKind, true}, {"albedo"}, {"emission", &kTextureKind, true}}, {{"radiance"}},
                 settingsOf<DemodulateSettings>(), [](const NodeBuild& b) -> std::vector<Value> {
                     return {textureValue(addRemodulatePass(b.ctx, b.name, b.texture(0), b.texture(1), b.texture(2),
                                                            b.settingsAs<DemodulateSettings>(), b.texture(3)))};
                 }});
    t.push_back({"surface", "packs normal, depth, mesh id and the depth gradient (common/surface.hpp)",
                 {{"normal"}, {"depth"}, {"meshid"}}, {{"surface", &kSurfaceKind}}, noSettings,
                 [](const NodeBuild& b) -> std::vector<Value> {
                     return {surfaceValue(addSurfacePass(b.ctx, b.name, b.texture(0), b.texture(1), b.texture(2)))};
                 }});
    t.push_back({"reproject", "per-pixel history footprint through motion, tested against last frame's surface "
                              "(common/reproject.hpp); 'surface' must be a surface node",
                 {{"motion"}, {"surface", &kSurfaceKind}}, {{"reprojection"}}, settingsOf<ReprojectSettings>(),
                 [](const NodeBuild& b) -> std::vector<Value> {
                     return {textureValue(addReprojectPass(b.ctx, b.name, b.texture(0), surfaceOf(b.value(1)),
                                                           b.settingsAs<ReprojectSettings>()))};
                 }});
    t.push_back({"tonemap", "HDR radiance to display values in [0, 1] (common/tonemap.hpp)", {{"radiance"}},
                 {{"display"}}, settingsOf<TonemapSettings>(), [](const NodeBuild& b) -> std::vector<Value> {
                     return {textureValue(addTonemapPass(b.ctx, b.name, b.texture(0), b.settingsAs<TonemapSettings>()))};
                 }});
    t.push_back({"taa", "temporal anti-aliasing, YCoCg neighbourhood clip (Karis 2014); with a reprojection "
                        "decision, history only from the same surface (common/taa.hpp)",
                 {{"color"}, {"motion"}, {"reprojection", &kTextureKind, true}}, {{"resolved"}},
                 settingsOf<TaaSettings>(), [](const NodeBuild& b) -> std::vector<Value> {
                     return {textureValue(addTaaPass(b.ctx, b.name, b.texture(0), b.texture(1),
                                                     b.settingsAs<TaaSettings>(), b.texture(2)))};
                 }});
}

} // namespace hush::passes::chain_file
