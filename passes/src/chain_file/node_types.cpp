#include "chain_file/node_types.hpp"

namespace hush::passes::chain_file {

Value textureValue(graph::TextureHandle texture) { return {&kTextureKind, {texture}}; }
Value surfaceValue(const Surface& surface) { return {&kSurfaceKind, {surface.normalDepth, surface.gradientMesh}}; }
Surface surfaceOf(const Value& value) { return {value.textures[0], value.textures[1]}; }

std::any noSettings(core::JsonObject& object) {
    object.finish();
    return {};
}

const std::vector<NodeType>& nodeTypes() {
    static const std::vector<NodeType> types = [] {
        std::vector<NodeType> t;
        addCommonNodeTypes(t);
        addSvgfNodeTypes(t);
        addEawNodeTypes(t);
        addBmfrNodeTypes(t);
        return t;
    }();
    return types;
}

const NodeType* findNodeType(std::string_view type) {
    for (const auto& t : nodeTypes())
        if (t.type == type) return &t;
    return nullptr;
}

} // namespace hush::passes::chain_file
