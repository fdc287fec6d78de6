#include <hush/passes/rdae/pool.hpp>

#include <hush/core/error.hpp>

#include "resample_pass.hpp"

namespace hush::passes {

RdaeTensor addRdaePoolPass(NodeContext& ctx, const std::string& name, const RdaeTensor& features,
                           const RdaeTensorFormat& format) {
    if (features.level >= format.levels)
        throw Error(ErrorKind::InvalidArgument, "rdae pooling '" + name + "': level " + std::to_string(features.level) +
                                                    " is already the network's deepest (" +
                                                    std::to_string(format.levels) + ")");
    return detail::addRdaeResamplePass(ctx, name, "pool", "pooled", features, features.level + 1, format);
}

} // namespace hush::passes
