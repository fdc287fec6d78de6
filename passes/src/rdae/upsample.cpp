#include <hush/passes/rdae/upsample.hpp>

#include <hush/core/error.hpp>

#include "resample_pass.hpp"

namespace hush::passes {

RdaeTensor addRdaeUpsamplePass(NodeContext& ctx, const std::string& name, const RdaeTensor& features,
                               const RdaeTensorFormat& format) {
    if (features.level == 0)
        throw Error(ErrorKind::InvalidArgument, "rdae upsampling '" + name + "': the tensor is at full resolution");
    return detail::addRdaeResamplePass(ctx, name, "upsample", "upsampled", features, features.level - 1, format);
}

} // namespace hush::passes
