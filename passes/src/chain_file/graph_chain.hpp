#pragma once
// GraphChain: a chain described node by node in a chain file. Loading checks the
// whole description (node types, ports, references, outputs); build() then adds
// the sanitiser and each node in file order.
//
// An input may name
//   "input.<channel>"             a frame channel (sanitized),
//   "<id>" or "<id>.<port>"       an output of a node defined before it,
//   "history:<id>[.<port>]"       last frame's value of any node's texture output,
//                                 defined before or after (feedback: SVGF's colour
//                                 history is "history:atrous.level0").
#include <any>
#include <string>
#include <vector>

#include <hush/passes/chain.hpp>
#include <hush/passes/common/sanitize.hpp>

#include "chain_file/node_types.hpp"

namespace hush::passes::chain_file {

struct NodeInstance {
    std::string id;
    const NodeType* type = nullptr;
    std::vector<std::string> inputs;   // by input port: a reference, "" when unconnected
    std::any settings;
    std::string path;                  // "nodes[3]", for errors
};

struct ChainDescription {
    std::string name;
    std::string source;                // the file, for errors
    SanitizeSettings sanitize;
    std::vector<NodeInstance> nodes;
    std::string displayOutput;         // a reference
    std::string radianceOutput;        // a reference; "" = the display
};

// Checks every reference against the channels and the nodes it may see, and its
// kind against the port's.
void validate(const ChainDescription& description);

class GraphChain : public Chain {
public:
    explicit GraphChain(ChainDescription description);
    std::string name() const override { return description_.name; }
    std::vector<InputChannel> inputs() const override { return inputs_; }
    ChainOutputs build(NodeContext& ctx, const DenoiseInputs& inputs) override;

private:
    ChainDescription description_;
    std::vector<InputChannel> inputs_;
};

} // namespace hush::passes::chain_file
