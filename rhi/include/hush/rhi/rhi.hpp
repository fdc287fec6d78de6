#pragma once
// The whole public RHI (Vulkan interop lives in vulkan_interop.hpp).
#include <hush/rhi/bind_group.hpp>
#include <hush/rhi/buffer.hpp>
#include <hush/rhi/command.hpp>
#include <hush/rhi/device.hpp>
#include <hush/core/error.hpp>
#include <hush/rhi/format.hpp>
#include <hush/rhi/instance.hpp>
#include <hush/rhi/live_objects.hpp>
#include <hush/rhi/pipeline.hpp>
#include <hush/rhi/query_set.hpp>
#include <hush/rhi/resource_state.hpp>
#include <hush/rhi/shader.hpp>
#include <hush/rhi/shader_library.hpp>
#include <hush/rhi/texture.hpp>
