#include "app/agent_drivers.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <thread>

#include <glm/glm.hpp>

#include "agents.comp.spv.h"
#include "app/error.h"
#include "app/host_device.h"

namespace app {
namespace path {

using namespace glm;
using uint = std::uint32_t;
#include "app/shaders/agent_path.h"

}  // namespace path

namespace {

// Runs f(begin, end) over [0, n) on every core (the host's own simulation: the library's pool is its).
template <class F>
void onEveryCore(std::uint32_t n, F&& f) {
    const std::uint32_t threads = std::max(1u, std::min(std::thread::hardware_concurrency(), (n + 65535u) / 65536u));
    std::vector<std::thread> workers;
    const std::uint32_t chunk = (n + threads - 1) / threads;
    for (std::uint32_t t = 1; t < threads; ++t)
        workers.emplace_back([&, t] { f(std::min(n, t * chunk), std::min(n, (t + 1) * chunk)); });
    f(0u, std::min(n, chunk));
    for (std::thread& w : workers) w.join();
}

}  // namespace

std::vector<float> agentHomes(const crowdgpu::Crowd& crowd) {
    std::vector<float> homes(2 * std::size_t{crowd.size()}, 0.0f);
    for (std::uint32_t s = 0; s < crowd.size(); ++s) {
        try {
            const crowdgpu::Character c = crowd.character(s);
            homes[2 * s] = c.position[0], homes[2 * s + 1] = c.position[2];
        } catch (const crowdgpu::Error&) {  // a free slot: no agent
        }
    }
    return homes;
}

HostAgents::HostAgents(const crowdgpu::Crowd& crowd)
    : homes_(agentHomes(crowd)),
      who_(crowd.size()),
      times_(crowd.size()),
      xs_(crowd.size()),
      zs_(crowd.size()) {
    for (std::uint32_t s = 0; s < crowd.size(); ++s) who_[s] = {s, 1u};  // the crowd's first characters
}

double HostAgents::update(crowdgpu::Crowd& crowd, double time) {
    // The simulation: where every agent is now (the host's own work, not the library's ingest).
    const auto n = static_cast<std::uint32_t>(who_.size());
    onEveryCore(n, [&](std::uint32_t begin, std::uint32_t end) {
        for (std::uint32_t i = begin; i < end; ++i) {
            const glm::vec2 p = path::agentPosition(i, glm::vec2(homes_[2 * i], homes_[2 * i + 1]), static_cast<float>(time));
            times_[i] = time, xs_[i] = p.x, zs_[i] = p.y;
        }
    });
    return millisecondsOf([&] { crowd.drive({who_.data(), times_.data(), xs_.data(), zs_.data(), nullptr, who_.size()}); });
}

DeviceAgents::DeviceAgents(const HostDevice& device, const crowdgpu::Crowd& crowd, std::uint32_t framesInFlight)
    : device_(device), agents_(crowd.size()) {
    try {
        const std::vector<float> homes = agentHomes(crowd);
        constexpr VkMemoryPropertyFlags deviceLocal = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
        homes_ = makeBuffer(homes.size() * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                            deviceLocal);
        // The homes up once, through a staging buffer.
        Buffer staging = makeBuffer(homes_.size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                    VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        void* mapped = nullptr;
        vkMapMemory(device.device, staging.memory, 0, staging.size, 0, &mapped);
        std::memcpy(mapped, homes.data(), staging.size);
        vkUnmapMemory(device.device, staging.memory);
        device.submitAndWait([&](VkCommandBuffer cmd) {
            const VkBufferCopy copy{0, 0, staging.size};
            vkCmdCopyBuffer(cmd, staging.buffer, homes_.buffer, 1, &copy);
        });
        vkDestroyBuffer(device.device, staging.buffer, nullptr);
        vkFreeMemory(device.device, staging.memory, nullptr);
        for (std::uint32_t i = 0; i < framesInFlight; ++i) {
            samples_.push_back(makeBuffer(std::uint64_t{std::max(agents_, 1u)} * sizeof(crowdgpu::DeviceSample),
                                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, deviceLocal));
            lent_.push_back({samples_.back().buffer, 0, samples_.back().size});
        }
        const VkDescriptorSetLayoutBinding bindings[2] = {
            {0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
            {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}};
        VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
        setInfo.bindingCount = 2;
        setInfo.pBindings = bindings;
        CHECK_VK(vkCreateDescriptorSetLayout(device.device, &setInfo, nullptr, &setLayout_));
        const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2 * framesInFlight};
        VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        poolInfo.maxSets = framesInFlight;
        poolInfo.poolSizeCount = 1;
        poolInfo.pPoolSizes = &size;
        CHECK_VK(vkCreateDescriptorPool(device.device, &poolInfo, nullptr, &pool_));
        sets_.resize(framesInFlight);
        std::vector<VkDescriptorSetLayout> layouts(framesInFlight, setLayout_);
        VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        allocate.descriptorPool = pool_;
        allocate.descriptorSetCount = framesInFlight;
        allocate.pSetLayouts = layouts.data();
        CHECK_VK(vkAllocateDescriptorSets(device.device, &allocate, sets_.data()));
        for (std::uint32_t i = 0; i < framesInFlight; ++i) {
            const VkDescriptorBufferInfo infos[2] = {{homes_.buffer, 0, VK_WHOLE_SIZE}, {samples_[i].buffer, 0, VK_WHOLE_SIZE}};
            VkWriteDescriptorSet writes[2];
            for (std::uint32_t b = 0; b < 2; ++b) {
                writes[b] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
                writes[b].dstSet = sets_[i];
                writes[b].dstBinding = b;
                writes[b].descriptorCount = 1;
                writes[b].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
                writes[b].pBufferInfo = &infos[b];
            }
            vkUpdateDescriptorSets(device.device, 2, writes, 0, nullptr);
        }
        const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, 16};
        VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        layoutInfo.setLayoutCount = 1;
        layoutInfo.pSetLayouts = &setLayout_;
        layoutInfo.pushConstantRangeCount = 1;
        layoutInfo.pPushConstantRanges = &push;
        CHECK_VK(vkCreatePipelineLayout(device.device, &layoutInfo, nullptr, &layout_));
        VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        moduleInfo.codeSize = sizeof(agents_comp_spv);
        moduleInfo.pCode = agents_comp_spv;
        VkShaderModule module = VK_NULL_HANDLE;
        CHECK_VK(vkCreateShaderModule(device.device, &moduleInfo, nullptr, &module));
        VkComputePipelineCreateInfo pipelineInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
        pipelineInfo.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
        pipelineInfo.stage.module = module;
        pipelineInfo.stage.pName = "main";
        pipelineInfo.layout = layout_;
        const VkResult made = vkCreateComputePipelines(device.device, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr, &pipeline_);
        vkDestroyShaderModule(device.device, module, nullptr);
        CHECK_VK(made);
    } catch (...) {
        release();
        throw;
    }
}

DeviceAgents::~DeviceAgents() { release(); }

void DeviceAgents::release() {
    const VkDevice d = device_.device;
    if (pipeline_) vkDestroyPipeline(d, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(d, layout_, nullptr);
    if (pool_) vkDestroyDescriptorPool(d, pool_, nullptr);
    if (setLayout_) vkDestroyDescriptorSetLayout(d, setLayout_, nullptr);
    pipeline_ = VK_NULL_HANDLE, layout_ = VK_NULL_HANDLE, pool_ = VK_NULL_HANDLE, setLayout_ = VK_NULL_HANDLE;
    for (Buffer* b : {&homes_}) {
        if (b->buffer) vkDestroyBuffer(d, b->buffer, nullptr);
        if (b->memory) vkFreeMemory(d, b->memory, nullptr);
        *b = {};
    }
    for (Buffer& b : samples_) {
        vkDestroyBuffer(d, b.buffer, nullptr);
        vkFreeMemory(d, b.memory, nullptr);
    }
    samples_.clear();
}

DeviceAgents::Buffer DeviceAgents::makeBuffer(VkDeviceSize size, VkBufferUsageFlags usage,
                                              VkMemoryPropertyFlags properties) const {
    Buffer b;
    b.size = size;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    CHECK_VK(vkCreateBuffer(device_.device, &info, nullptr, &b.buffer));
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device_.device, b.buffer, &requirements);
    VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    allocate.allocationSize = requirements.size;
    const int type = device_.memoryType(requirements.memoryTypeBits, properties);
    if (type < 0) throw Error("agents: no memory type for their buffers");
    allocate.memoryTypeIndex = static_cast<std::uint32_t>(type);
    const VkResult result = vkAllocateMemory(device_.device, &allocate, nullptr, &b.memory);
    if (result != VK_SUCCESS) {
        vkDestroyBuffer(device_.device, b.buffer, nullptr);
        throw Error("agents: out of device memory for their buffers (" + std::to_string(size) + " bytes)");
    }
    CHECK_VK(vkBindBufferMemory(device_.device, b.buffer, b.memory, 0));
    return b;
}

namespace {

// Compute-shader accesses `from` made available to compute-shader accesses `to` (the agents' pass and
// the renderer's compute passes, in one queue).
void computeBarrier(VkCommandBuffer cmd, VkAccessFlags2 from, VkAccessFlags2 to) {
    VkMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    barrier.srcStageMask = barrier.dstStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    barrier.srcAccessMask = from;
    barrier.dstAccessMask = to;
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.memoryBarrierCount = 1;
    dependency.pMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(cmd, &dependency);
}

}  // namespace

const crowdgpu::DeviceSamples* DeviceAgents::recordBeforeCompute(VkCommandBuffer cmd, std::uint32_t slot, double time) {
    // The slot's last frame read its samples (the renderer's compute pass): done, its fence waited.
    const std::uint32_t groups = std::clamp((agents_ + 63u) / 64u, 1u, 65535u);
    struct {
        std::uint32_t agents, stride;
        float time, unused;
    } push{agents_, groups * 64u, static_cast<float>(time), 0.0f};
    // The slot's last frame's reads (the renderer's ingest) come before these writes.
    computeBarrier(cmd, VK_ACCESS_2_SHADER_STORAGE_READ_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &sets_[slot], 0, nullptr);
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdDispatch(cmd, groups, 1, 1);
    // The renderer reads them in its compute passes (crowdgpu::DeviceSamples asks for this barrier).
    computeBarrier(cmd, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    return &lent_[slot];
}

}  // namespace app
