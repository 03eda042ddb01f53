#pragma once
// The programs' offscreen image the scene is drawn into (sRGB colour + depth), and its readback.
// Multisampled (--aa msaaN), the pass draws into a colour and a depth image of that many samples per
// pixel and resolves the colour, as the pass ends, into the single-sample image that is read back
// or presented; without multisampling it draws into that image directly. With the library's edge
// filter (--aa fxaa), the pass draws (or resolves) into an image of its own, which the filter reads
// and writes anti-aliased into the picture through a UNORM storage view.
#include <string>
#include <vector>

#include <crowdgpu/renderer.hpp>
#include <vulkan/vulkan.h>

#include "app/host_image.h"
#include "app/png_writer.h"


namespace app {

constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_SRGB;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

// How a pass begins with the colour attachment: cleared, or left as it is because what is drawn covers
// every pixel (the library's sky, crowdgpu::RendererSettings::sky), which saves the clear's fill.
enum class ColourLoad { Clear, DrawnWhole };

class RenderTarget {
public:
    // 4-byte colour formats only (the readback copies 4 bytes a pixel). The library's renderer must
    // have been made for the same formats and sample count (crowdgpu::RendererSettings::target).
    // `edgeFilter`: the picture is the library's edge filter's output (R8G8B8A8 colour formats only).
    RenderTarget(const HostDevice& device, VkExtent2D extent, const crowdgpu::TargetFormat& format,
                 bool edgeFilter = false);
    RenderTarget(const HostDevice& device, VkExtent2D extent, VkFormat color = kColorFormat,
                 VkFormat depth = kDepthFormat)
        : RenderTarget(device, extent, crowdgpu::TargetFormat{color, depth, VK_SAMPLE_COUNT_1_BIT}) {}
    ~RenderTarget();
    RenderTarget(const RenderTarget&) = delete;
    RenderTarget& operator=(const RenderTarget&) = delete;

    VkExtent2D extent() const { return color_.extent; }
    VkSampleCountFlagBits samples() const { return samples_; }
    // The single-sample picture (resolved when multisampled).
    VkImage colorImage() const { return color_.image; }
    // Transitions the images and begins dynamic rendering, clearing the depth and, unless `load` says
    // the pass draws every pixel, the colour to `clearColor` (linear).
    void beginRendering(VkCommandBuffer cmd, const float clearColor[4], ColourLoad load = ColourLoad::Clear);
    // Ends rendering (resolving the samples) and leaves the colour image ready to be copied out; with
    // the edge filter, leaves the drawn image ready for it to sample and the picture for it to write.
    void endRendering(VkCommandBuffer cmd);
    bool edgeFiltered() const { return drawn_.image != VK_NULL_HANDLE; }
    // With the edge filter, between endRendering and endFiltering: what it reads and writes
    // (crowdgpu::Renderer::recordEdgeFilter's source and destination).
    VkImageView filterSource() const { return drawn_.view; }
    VkImageView filterDestination() const { return color_.view; }
    // After the filter: the picture ready to be copied out.
    void endFiltering(VkCommandBuffer cmd);
    // Copies the last rendered frame to the host (waits for the GPU).
    Rgba8Image readback();
    VkDeviceSize bytes() const { return color_.bytes + drawn_.bytes + multisampled_.bytes + depth_.bytes; }
    // Why the device cannot make a target of this size, in one line naming the image and the limit
    // past which it lies (the format's largest extent and maxResourceSize for its usage and samples,
    // maxMemoryAllocationSize); empty when it can. Memory as a whole is the caller's (renderTargetBytes).
    static std::string limitProblem(const HostDevice& device, VkExtent2D extent, const crowdgpu::TargetFormat& format,
                                    bool edgeFilter);

private:
    // One image of the target: the constructor makes these, limitProblem checks them.
    struct Image {
        HostImage RenderTarget::*member;
        VkFormat format;
        VkImageUsageFlags usage;
        VkSampleCountFlagBits samples;
        VkFormat viewFormat;  // another format for its view, or UNDEFINED
        const char* what;
    };
    static std::vector<Image> images(const crowdgpu::TargetFormat& format, bool edgeFilter);
    void release();

    const HostDevice& device_;
    VkSampleCountFlagBits samples_;
    HostImage color_;         // the picture (with the edge filter: its output, a UNORM storage view)
    HostImage drawn_;         // with the edge filter: what the pass draws, its input
    HostImage multisampled_;  // the samples, resolved into drawn_ or color_ (none when single-sampled)
    HostImage depth_;
};

// Device bytes of a target of this size and sample count (about: the images' own alignment aside).
std::uint64_t renderTargetBytes(VkExtent2D extent, VkSampleCountFlagBits samples, bool edgeFilter = false);

}  // namespace app
