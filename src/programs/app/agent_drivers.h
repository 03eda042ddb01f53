#pragma once
// --agents host|device: the crowd's characters are the agents of a simulation (a loop each about where
// it started, its speed swinging through standing, walking and running: shaders/agent_path.h), sampled
// every frame at the frame's time. Host: the simulation runs on the CPU, on every core, and its positions
// go to the crowd in arrays (Crowd::drive), as a game's or a server's would. Device: it runs on the GPU, a
// compute pass of the host's writing one DeviceSample a slot into a buffer the renderer reads with no CPU
// copy, as FLAME GPU's would.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "app/crowd_driver.h"

namespace app {

class HostDevice;

// Where each slot's agent started (its home): the crowd's characters as made.
std::vector<float> agentHomes(const crowdgpu::Crowd& crowd);

class HostAgents : public CrowdDriver {
public:
    explicit HostAgents(const crowdgpu::Crowd& crowd);
    double update(crowdgpu::Crowd& crowd, double time) override;

private:
    std::vector<float> homes_;  // x, z per slot
    std::vector<crowdgpu::CharacterHandle> who_;
    std::vector<double> times_;
    std::vector<float> xs_, zs_;
};

class DeviceAgents : public CrowdDriver {
public:
    DeviceAgents(const HostDevice& device, const crowdgpu::Crowd& crowd, std::uint32_t framesInFlight);
    ~DeviceAgents() override;
    DeviceAgents(const DeviceAgents&) = delete;
    DeviceAgents& operator=(const DeviceAgents&) = delete;
    double update(crowdgpu::Crowd&, double) override { return 0.0; }
    const crowdgpu::DeviceSamples* recordBeforeCompute(VkCommandBuffer cmd, std::uint32_t slot, double time) override;

private:
    struct Buffer {
        VkBuffer buffer = VK_NULL_HANDLE;
        VkDeviceMemory memory = VK_NULL_HANDLE;
        VkDeviceSize size = 0;
    };
    Buffer makeBuffer(VkDeviceSize size, VkBufferUsageFlags usage, VkMemoryPropertyFlags properties) const;
    void release();

    const HostDevice& device_;
    std::uint32_t agents_;
    Buffer homes_;
    std::vector<Buffer> samples_;  // per frame slot
    std::vector<crowdgpu::DeviceSamples> lent_;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    std::vector<VkDescriptorSet> sets_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace app
