#pragma once
// Handles are cheap, ref-counted values (Dawn's model): copying one shares the
// object, and the object lives until the last handle and the last command buffer
// that uses it are gone.
#include <memory>

namespace hush::rhi {

template <class Impl>
class Handle {
public:
    Handle() = default;
    explicit Handle(std::shared_ptr<Impl> impl) : impl_(std::move(impl)) {}

    explicit operator bool() const { return impl_ != nullptr; }
    bool operator==(const Handle& other) const { return impl_ == other.impl_; }

    // The implementation object, for hush's own layers; not part of the public API.
    Impl* impl() const { return impl_.get(); }
    const std::shared_ptr<Impl>& shared() const { return impl_; }

protected:
    std::shared_ptr<Impl> impl_;
};

namespace detail {
struct InstanceImpl;
struct DeviceImpl;
struct BufferImpl;
struct TextureImpl;
struct TextureViewImpl;
struct SamplerImpl;
struct ShaderModuleImpl;
struct BindGroupLayoutImpl;
struct BindGroupImpl;
struct ComputePipelineImpl;
struct CommandEncoderImpl;
struct CommandBufferImpl;
struct QuerySetImpl;
} // namespace detail

} // namespace hush::rhi
