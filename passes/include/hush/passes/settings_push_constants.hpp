#pragma once
// A settings struct's fields as push constants: every field whose name is also a
// member of the shader's push-constant block is written there (settings.hpp: the
// field, its chain-file key and the shader member are one name). Members with no
// field of that name (derived values, per-frame flags) the node writes itself;
// rhi::PushConstants refuses a dispatch before every member is written.
#include <cstdint>
#include <string_view>
#include <vector>

#include <hush/passes/settings.hpp>
#include <hush/rhi/push_constants.hpp>

namespace hush::passes {

namespace detail {
class PushConstantsWriter {
public:
    explicit PushConstantsWriter(rhi::PushConstants& params) : params_(params) {}
    void field(std::string_view key, float& v, Range) { write(key, v); }
    void field(std::string_view key, uint32_t& v, Range) { write(key, v); }
    template <size_t N> void field(std::string_view key, uint32_t& v, Choices<N>) { write(key, v); }
    void field(std::string_view key, int& v, Range) { write(key, int32_t(v)); }
    void field(std::string_view key, bool& v) { write(key, v); }
    void field(std::string_view, std::string&) {}   // file names stay on the CPU
    template <class E, size_t N> void field(std::string_view key, E& v, const EnumNames<E, N>&) {
        if constexpr (sizeof(E) == 4 && !std::is_same_v<E, rhi::Format>) write(key, uint32_t(v));
    }
    template <class E, size_t N> void field(std::string_view, std::vector<E>&, const EnumNames<E, N>&, size_t) {}
    template <class S> void section(std::string_view, S&) {}
    template <class S> void flatten(S& s) { describe(*this, s); }

private:
    template <class T> void write(std::string_view key, T value) {
        if (params_.has(key)) params_.set(key, value);
    }
    rhi::PushConstants& params_;
};
} // namespace detail

template <class S> void setFromSettings(rhi::PushConstants& params, S settings) {
    describe(detail::PushConstantsWriter(params), settings);
}

} // namespace hush::passes
