// hush_vulkan.h: the C API on an engine's own VkDevice (tests/support/raw_vulkan plays
// the engine), with an input copied from the engine's VkImage. Validation is on for
// both sides; any message fails the run (support/main.cpp).
#include <cstring>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <hush/hush_vulkan.h>

#include "support/raw_vulkan.hpp"

using hush::test::RawVulkan;

namespace {

constexpr uint32_t kWidth = 16, kHeight = 12;

// The engine fills its image with `rgba` through its own staging buffer and leaves it
// in GENERAL (the image is a storage image, as an engine's G-buffer often is).
void fillEngineImage(RawVulkan& raw, const std::vector<float>& rgba) {
    std::memcpy(raw.mapped, rgba.data(), rgba.size() * sizeof(float));
    VkCommandBuffer cmd = raw.beginCommands();
    VkImageMemoryBarrier toCopy{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    toCopy.srcAccessMask = 0;
    toCopy.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toCopy.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    toCopy.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    toCopy.srcQueueFamilyIndex = toCopy.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toCopy.image = raw.image;
    toCopy.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    raw.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                             nullptr, 1, &toCopy);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {kWidth, kHeight, 1};
    raw.vkCmdCopyBufferToImage(cmd, raw.buffer, raw.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    VkImageMemoryBarrier toGeneral = toCopy;
    toGeneral.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toGeneral.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT;
    toGeneral.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    toGeneral.newLayout = VK_IMAGE_LAYOUT_GENERAL;
    raw.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr, 0,
                             nullptr, 1, &toGeneral);
    raw.submitAndWait(cmd);
}

// Every input but colour from host memory: a flat, lit, facing plane.
void setHostInputs(HushDenoiser denoiser, bool colorToo, const std::vector<float>& rgba) {
    for (uint32_t i = 0; i < hushDenoiserInputCount(denoiser); ++i) {
        const char* name = nullptr;
        uint32_t components = 0;
        REQUIRE(hushDenoiserInput(denoiser, i, &name, &components) == HUSH_SUCCESS);
        const std::string input = name;
        if (input == "color" && !colorToo) continue;
        std::vector<float> pixels(size_t(kWidth) * kHeight * components, 0.5f);
        for (size_t p = 0; p < size_t(kWidth) * kHeight; ++p) {
            float* texel = &pixels[p * components];
            if (input == "normal") texel[0] = 0.0f, texel[1] = 0.0f, texel[2] = 1.0f;
            if (input == "depth") texel[0] = 2.0f;
            if (input == "emission") texel[0] = texel[1] = texel[2] = 0.0f;
            if (input == "position") texel[0] = float(p % kWidth), texel[1] = float(p / kWidth), texel[2] = 0.0f;
            if (input == "color") for (uint32_t c = 0; c < 3; ++c) texel[c] = rgba[p * 4 + c];
        }
        INFO(input << ": " << hushLastError());
        REQUIRE(hushSetInput(denoiser, name, pixels.data(), kWidth, kHeight, components, 0) == HUSH_SUCCESS);
    }
}

std::vector<float> denoise(HushDenoiser denoiser) {
    INFO(hushLastError());
    REQUIRE(hushExecute(denoiser) == HUSH_SUCCESS);
    std::vector<float> out(size_t(kWidth) * kHeight * 4);
    REQUIRE(hushReadOutput(denoiser, HUSH_OUTPUT_RADIANCE, out.data(), out.size()) == HUSH_SUCCESS);
    return out;
}

} // namespace

TEST_CASE("C API on an engine's VkDevice: a VkImage input denoises like the same pixels from host memory", "[capi]") {
    RawVulkan raw;
    raw.createInstance();
    raw.pickPhysicalDevice();
    raw.createDevice();
    raw.createBuffer(VkDeviceSize(kWidth) * kHeight * 4 * sizeof(float));
    raw.createImage(kWidth, kHeight);
    std::vector<float> rgba(size_t(kWidth) * kHeight * 4);
    for (size_t i = 0; i < rgba.size(); ++i) rgba[i] = float((i * 7919) % 101) / 50.0f;   // noisy, in [0, 2]
    fillEngineImage(raw, rgba);

    const HushVulkanDevice engine{raw.instance, raw.physical, raw.device, raw.queue, raw.family, vkGetInstanceProcAddr, 0};
    HushContext context = nullptr;
    INFO(hushLastError());
    REQUIRE(hushCreateContextFromVulkan(&engine, &context) == HUSH_SUCCESS);
    CHECK(hushVulkanInputFormat("color") == VK_FORMAT_R32G32B32A32_SFLOAT);
    CHECK(hushVulkanInputFormat("colour") == VK_FORMAT_UNDEFINED);

    const HushDenoiserDesc desc{"eaw", nullptr, kWidth, kHeight, nullptr};
    HushDenoiser fromImage = nullptr, fromHost = nullptr;
    REQUIRE(hushCreateDenoiser(context, &desc, &fromImage) == HUSH_SUCCESS);
    REQUIRE(hushCreateDenoiser(context, &desc, &fromHost) == HUSH_SUCCESS);

    HushVulkanImage image{raw.image, VK_FORMAT_R32G32B32A32_SFLOAT, kWidth, kHeight, VK_IMAGE_LAYOUT_GENERAL};
    HushVulkanImage wrong = image;
    wrong.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    CHECK(hushSetInputVulkanImage(fromImage, "color", &wrong) == HUSH_ERROR_INVALID_ARGUMENT);
    CHECK_THAT(hushLastError(), Catch::Contains("image->format"));
    wrong = image;
    wrong.layout = VK_IMAGE_LAYOUT_UNDEFINED;
    CHECK(hushSetInputVulkanImage(fromImage, "color", &wrong) == HUSH_ERROR_INVALID_ARGUMENT);
    CHECK_THAT(hushLastError(), Catch::Contains("image->layout"));
    wrong = image;
    wrong.width = kWidth + 1;
    CHECK(hushSetInputVulkanImage(fromImage, "color", &wrong) == HUSH_ERROR_INVALID_ARGUMENT);
    CHECK_THAT(hushLastError(), Catch::Contains("image->width"));
    CHECK(hushSetInputVulkanImage(fromImage, "color", nullptr) == HUSH_ERROR_INVALID_ARGUMENT);
    CHECK_THAT(hushLastError(), Catch::Contains("'image'"));

    REQUIRE(hushSetInputVulkanImage(fromImage, "color", &image) == HUSH_SUCCESS);
    setHostInputs(fromImage, false, rgba);
    setHostInputs(fromHost, true, rgba);
    const std::vector<float> a = denoise(fromImage), b = denoise(fromHost);
    CHECK(a == b);
    // The engine's image is back in GENERAL: copying from it again is valid (the
    // validation layer would report a layout mismatch).
    REQUIRE(hushSetInputVulkanImage(fromImage, "color", &image) == HUSH_SUCCESS);
    CHECK(denoise(fromImage) == b);

    hushDestroyDenoiser(fromImage);
    hushDestroyDenoiser(fromHost);
    hushDestroyContext(context);
}
