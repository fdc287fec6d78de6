// The EAW baseline's node in chain files: eaw.atrous.
#include <hush/passes/eaw/atrous.hpp>

#include "chain_file/node_types.hpp"

namespace hush::passes::chain_file {

void addEawNodeTypes(std::vector<NodeType>& t) {
    t.push_back({"eaw.atrous", "Dammertz et al. 2010 edge-avoiding a-trous levels, global parameters; with depth, "
                               "the position weight is relative to depth",
                 {{"color"}, {"normal"}, {"position"}, {"depth", &kTextureKind, true}}, {{"filtered"}},
                 settingsOf<EawSettings>(), [](const NodeBuild& b) -> std::vector<Value> {
                     return {textureValue(addEawAtrousLevels(b.ctx, b.name, b.texture(0), b.texture(1), b.texture(2),
                                                             b.texture(3), b.settingsAs<EawSettings>()))};
                 }});
}

} // namespace hush::passes::chain_file
