// BMFR's nodes in chain files: bmfr.accumulate, bmfr.fit.
#include <hush/passes/bmfr/accumulate.hpp>
#include <hush/passes/bmfr/fit.hpp>

#include "chain_file/node_types.hpp"

namespace hush::passes::chain_file {

void addBmfrNodeTypes(std::vector<NodeType>& t) {
    t.push_back({"bmfr.accumulate", "BMFR temporal accumulation: cumulative average until the new sample's weight "
                                    "reaches minWeight (0.2; 0.1 after the fit), then exponential; count in alpha "
                                    "(Koskela et al. 2019 Sec. 3.1, 3.3)",
                 {{"current"}, {"reprojection"}}, {{"accumulated"}}, settingsOf<BmfrAccumulateSettings>(),
                 [](const NodeBuild& b) -> std::vector<Value> {
                     return {textureValue(addBmfrAccumulatePass(b.ctx, b.name, b.texture(0), b.texture(1),
                                                                b.settingsAs<BmfrAccumulateSettings>()))};
                 }});
    t.push_back({"bmfr.fit", "BMFR per-block feature regression, 32x32 blocks, stochastic regularisation "
                             "(Koskela et al. 2019 Sec. 3.2); albedo, roughness and meshid only for those features",
                 {{"illumination"}, {"normal"}, {"position"}, {"albedo", &kTextureKind, true},
                  {"roughness", &kTextureKind, true}, {"meshid", &kTextureKind, true}},
                 {{"fitted"}}, settingsOf<BmfrFitSettings>(), [](const NodeBuild& b) -> std::vector<Value> {
                     const BmfrGuide guide{b.texture(1), b.texture(2), b.texture(3), b.texture(4), b.texture(5)};
                     return {textureValue(addBmfrFitPass(b.ctx, b.name, b.texture(0), guide,
                                                         b.settingsAs<BmfrFitSettings>()))};
                 }});
}

} // namespace hush::passes::chain_file
