#include "render/impostor_atlas.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>

#include "anim/local_to_model.h"
#include "anim/props_carried.h"
#include "crowd/pose_bounds.h"
#include "model/attach_prop.h"
#include "anim/sample_clip.h"
#include "anim/skinning_matrices.h"
#include "gpu/barriers.h"
#include "gpu/descriptor_bundle.h"
#include "gpu/one_shot_commands.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "impostor_capture.frag.spv.h"
#include "impostor_capture.vert.spv.h"
#include "render/impostor_cell.h"

namespace render {

namespace {

constexpr VkFormat kFormats[2] = {VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_R8G8B8A8_UNORM};  // albedo, normal
constexpr VkFormat kCaptureDepthFormat = VK_FORMAT_D32_SFLOAT;  // the bake's own depth, not the host's
constexpr std::uint32_t kBytesPerTexel = 8;  // both arrays
// Texels across a cell at the coarsest level filtered reads take: a bilinear read of a coarser one
// would mix in the next cell. The chain goes on to a texel a cell, for the far crowd's smallest
// impostors (far_crowd.glsl.inc: farUseGradients, and splatPixels' quadrant means at two texels a cell).
constexpr std::uint32_t kSmallestSampledCell = IMPOSTOR_SMALLEST_SAMPLED_CELL;
constexpr std::uint32_t kLayerSide = 2048;   // texels per side of one array layer (at least one cell)

struct CapturePush {
    glm::vec4 square;
    glm::vec4 right;
    glm::vec4 up;
    glm::vec4 towardsCamera;
    glm::uvec4 pose;
};

// Levels down to `smallest` texels a cell.
std::uint32_t mipLevelsFor(std::uint32_t cellSize, std::uint32_t smallest) {
    std::uint32_t levels = 1;
    while ((cellSize >> levels) >= smallest) ++levels;
    return levels;
}

std::uint64_t cellBytes(std::uint32_t cellSize) {
    // The mip chain adds a third: 1 + 1/4 + 1/16 + ... < 4/3.
    return static_cast<std::uint64_t>(cellSize) * cellSize * kBytesPerTexel * 4 / 3;
}

std::uint32_t clipsOf(const model::SkinnedModel& m) { return std::max<std::uint32_t>(1, static_cast<std::uint32_t>(m.clips.size())); }

gpu::Access colourWrite() {
    return {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT};
}

void transition(VkCommandBuffer cmd, VkImage image, std::uint32_t firstMip, std::uint32_t mips, gpu::Access before,
                gpu::Access after, VkImageLayout from, VkImageLayout to) {
    gpu::imageBarrier(cmd, image, {VK_IMAGE_ASPECT_COLOR_BIT, firstMip, mips, 0, VK_REMAINING_ARRAY_LAYERS}, before,
                      after, from, to);
}

}  // namespace

std::uint64_t ImpostorPlan::bytesOf(std::uint32_t model) const {
    const gpu::ImpostorModel& m = set(model, 0);
    return static_cast<std::uint64_t>(m.cells.w) * m.cells.y * m.cells.z * m.views.x * m.views.y * cellBytes(cellSize);
}

std::uint64_t ImpostorPlan::bytes() const {
    // Whole layers are allocated: the last one is partly empty.
    return static_cast<std::uint64_t>(layers) * cellsPerRow * cellsPerRow * cellBytes(cellSize);
}

ImpostorPlan planImpostors(std::span<const model::SkinnedModel* const> models, std::span<const gpu::ModelRecord> records,
                           std::span<const std::vector<std::uint32_t>> propSets, const ImpostorSettings& settings) {
    // One cell size for the whole atlas. Over a model's budget its rarest cell sets go first (their
    // carriers show the nearest set: a missing flag on a few), then its frames per clip shrink, since a
    // far character's animation tolerates coarser steps better than a blurrier picture.
    std::uint32_t cellSize = std::max(settings.cellSize, kSmallestSampledCell);
    std::vector<std::uint32_t> frames(models.size(), std::max(settings.framesPerClip, 1u));
    std::vector<std::uint32_t> sets(models.size(), 1u);
    const std::uint64_t views = static_cast<std::uint64_t>(settings.azimuths) * settings.elevations;
    for (std::size_t m = 0; m < models.size(); ++m) {
        if (m < propSets.size())
            sets[m] = std::clamp<std::uint32_t>(static_cast<std::uint32_t>(propSets[m].size()), 1u, IMPOSTOR_SETS);
        auto bytes = [&] { return sets[m] * clipsOf(*models[m]) * frames[m] * views * cellBytes(cellSize); };
        while (bytes() > settings.budgetPerModel && sets[m] > 1) --sets[m];
        while (bytes() > settings.budgetPerModel && frames[m] > 4) frames[m] /= 2;
        while (bytes() > settings.budgetPerModel && cellSize > 16) cellSize /= 2;
    }
    ImpostorPlan plan;
    plan.cellSize = cellSize;
    plan.mipLevels = mipLevelsFor(cellSize, 1);
    plan.sampledLevels = mipLevelsFor(cellSize, kSmallestSampledCell);
    plan.cellsPerRow = std::max(1u, kLayerSide / cellSize);
    const std::uint32_t perLayer = plan.cellsPerRow * plan.cellsPerRow;
    std::uint32_t first = 0;
    for (std::size_t m = 0; m < models.size(); ++m) {
        gpu::ImpostorModel record{};
        record.cells = glm::uvec4(first, clipsOf(*models[m]), frames[m], sets[m]);
        record.views = glm::uvec4(settings.azimuths, settings.elevations, plan.cellsPerRow, perLayer);
        record.square = records[m].sphere;
        // A model given no masks gets one set: the props most carry by default, as its pose sphere holds.
        if (m < propSets.size() && !propSets[m].empty())
            for (std::uint32_t s = 0; s < sets[m]; ++s) record.propSets[s] = propSets[m][s];
        else
            record.propSets[0] = model::propsMostCarry(*models[m]);
        const std::uint32_t cellsPerSet = record.cells.y * record.cells.z * settings.azimuths * settings.elevations;
        for (std::uint32_t s = 0; s < IMPOSTOR_SETS; ++s) {
            gpu::ImpostorModel entry = record;
            if (s < sets[m]) entry.cells.x = first + s * cellsPerSet;
            plan.models.push_back(entry);
        }
        first += sets[m] * cellsPerSet;
    }
    plan.layers = std::max(1u, (first + perLayer - 1) / perLayer);
    return plan;
}

std::vector<gpu::BoneRows> impostorPoses(std::span<const model::SkinnedModel* const> models,
                                         std::span<const gpu::ImpostorModel> plan, std::vector<std::uint32_t>& firstBone) {
    std::vector<gpu::BoneRows> bones;
    firstBone.assign(plan.size(), 0u);
    for (std::size_t m = 0; m < models.size(); ++m) {
        const model::SkinnedModel& model = *models[m];
        const anim::Skeleton& skeleton = model.skeleton;
        std::vector<anim::Transform> locals(skeleton.restPose);
        std::vector<glm::mat4> modelSpace(skeleton.jointCount());
        std::vector<gpu::BoneRows> pose(skeleton.jointCount());
        const gpu::ImpostorModel& first = plan[m * IMPOSTOR_SETS];
        for (std::uint32_t s = 0; s < first.cells.w; ++s) {
            firstBone[m * IMPOSTOR_SETS + s] = static_cast<std::uint32_t>(bones.size());
            const std::uint32_t carried = first.propSets[s];  // the set's props: the rest collapse (docs/props.md)
            for (std::uint32_t clip = 0; clip < first.cells.y; ++clip) {
                for (std::uint32_t frame = 0; frame < first.cells.z; ++frame) {
                    // Frame k at phase k / frames of the clip, as a character at that phase samples it.
                    locals = skeleton.restPose;
                    if (clip < model.clips.size()) {
                        const float time = model.clips[clip].duration * static_cast<float>(frame) / static_cast<float>(first.cells.z);
                        anim::sampleClip(model.clips[clip], time, skeleton.restPose, locals);
                    }
                    anim::localToModel(skeleton.parents, locals, skeleton.rootTransform, modelSpace);
                    anim::skinningMatrices(modelSpace, skeleton.inverseBind, glm::mat4(1.0f), pose);
                    for (std::size_t j = 0; j < skeleton.propOfJoint.size(); ++j)
                        if (!anim::jointCarried(skeleton.propOfJoint[j], carried))
                            pose[j] = anim::collapsedBone(glm::vec3(modelSpace[j][3]));
                    bones.insert(bones.end(), pose.begin(), pose.end());
                }
            }
        }
    }
    return bones;
}

void frameImpostorSets(std::span<const model::SkinnedModel* const> models, ImpostorPlan& plan) {
    for (std::uint32_t m = 0; m < plan.modelCount(); ++m) {
        const std::uint32_t inSphere = model::propsMostCarry(*models[m]);
        for (std::uint32_t s = 0; s < plan.setCount(m); ++s) {
            gpu::ImpostorModel& entry = plan.models[m * IMPOSTOR_SETS + s];
            // Props the pose sphere holds (or none) fit its square; only the others can reach past it.
            if ((entry.propSets[s] & ~inSphere) == 0u) continue;
            const float radius = crowd::poseRadiusAbout(*models[m], glm::vec3(entry.square), entry.propSets[s]);
            entry.square.w = std::max(entry.square.w, radius);
        }
    }
}

ImpostorAtlas::ImpostorAtlas(const gpu::VulkanContext& context, const GeometryPool& pool,
                             std::span<const model::SkinnedModel* const> models,
                             std::span<const std::vector<std::uint32_t>> propSets, VkDescriptorSetLayout sceneSetLayout,
                             VkDescriptorSet sceneSet, const ImpostorSettings& settings)
    : context_(context), plan_(planImpostors(models, pool.models(), propSets, settings)) {
    const auto start = std::chrono::steady_clock::now();
    frameImpostorSets(models, plan_);
    if (plan_.layers > context.properties.limits.maxImageArrayLayers)
        throw gpu::Error("impostors: the atlas needs " + std::to_string(plan_.layers) + " layers, over this device's " +
                         std::to_string(context.properties.limits.maxImageArrayLayers));
    try {
        modelTable_ = gpu::createBufferWithData(context, std::as_bytes(std::span(plan_.models)),
                                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "impostor models");
        createImages();
        createSamplingSet();
        bake(pool, models, sceneSetLayout, sceneSet);
    } catch (...) {
        release();
        throw;
    }
    bakeMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

ImpostorAtlas::~ImpostorAtlas() { release(); }

void ImpostorAtlas::release() {
    if (descriptorPool_) vkDestroyDescriptorPool(context_.device, descriptorPool_, nullptr);
    if (setLayout_) vkDestroyDescriptorSetLayout(context_.device, setLayout_, nullptr);
    if (sampler_) vkDestroySampler(context_.device, sampler_, nullptr);
    if (wholeChainSampler_) vkDestroySampler(context_.device, wholeChainSampler_, nullptr);
    descriptorPool_ = VK_NULL_HANDLE, setLayout_ = VK_NULL_HANDLE, sampler_ = VK_NULL_HANDLE, wholeChainSampler_ = VK_NULL_HANDLE;
    for (int i = 0; i < 2; ++i) {
        if (arrayViews_[i]) vkDestroyImageView(context_.device, arrayViews_[i], nullptr);
        if (images_[i]) vkDestroyImage(context_.device, images_[i], nullptr);
        if (memory_[i]) vkFreeMemory(context_.device, memory_[i], nullptr);
        arrayViews_[i] = VK_NULL_HANDLE, images_[i] = VK_NULL_HANDLE, memory_[i] = VK_NULL_HANDLE;
    }
    gpu::destroyBuffer(context_, modelTable_);
}

VkDeviceSize ImpostorAtlas::bytes() const { return imageBytes_[0] + imageBytes_[1] + modelTable_.size; }

void ImpostorAtlas::createImages() {
    const std::uint32_t side = plan_.cellsPerRow * plan_.cellSize;
    for (int i = 0; i < 2; ++i) {
        VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        info.imageType = VK_IMAGE_TYPE_2D;
        info.format = kFormats[i];
        info.extent = {side, side, 1};
        info.mipLevels = plan_.mipLevels;
        info.arrayLayers = plan_.layers;
        info.samples = VK_SAMPLE_COUNT_1_BIT;
        info.tiling = VK_IMAGE_TILING_OPTIMAL;
        info.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                     VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        VK_CHECK(vkCreateImage(context_.device, &info, nullptr, &images_[i]));
        VkMemoryRequirements requirements;
        vkGetImageMemoryRequirements(context_.device, images_[i], &requirements);
        imageBytes_[i] = requirements.size;
        memory_[i] = gpu::allocateMemory(context_, requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT,
                                         i == 0 ? "impostor atlas (albedo)" : "impostor atlas (normals)");
        VK_CHECK(vkBindImageMemory(context_.device, images_[i], memory_[i], 0));
        VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        view.image = images_[i];
        view.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
        view.format = kFormats[i];
        view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, plan_.mipLevels, 0, plan_.layers};
        VK_CHECK(vkCreateImageView(context_.device, &view, nullptr, &arrayViews_[i]));
    }
}

void ImpostorAtlas::createSamplingSet() {
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = info.minFilter = VK_FILTER_LINEAR;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
    info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.maxLod = static_cast<float>(plan_.sampledLevels - 1);
    VK_CHECK(vkCreateSampler(context_.device, &info, nullptr, &sampler_));
    // The far layer's reads (far_crowd.glsl.inc) reach every level: they keep their coordinates inside
    // the cell by the level they read, so no bilinear tap reaches the next cell.
    info.maxLod = static_cast<float>(plan_.mipLevels - 1);
    VK_CHECK(vkCreateSampler(context_.device, &info, nullptr, &wholeChainSampler_));
    // Fragment shaders sample it, and the compute rasterizer's coverage test (render/impostor_raster.h).
    // Bindings 0-1: albedo and normal, filtered reads down to 8 texels a cell; 2-3: the same, every level.
    constexpr VkShaderStageFlags stages = VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT;
    const VkDescriptorSetLayoutBinding bindings[4] = {
        {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, nullptr},
        {1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, nullptr},
        {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, nullptr},
        {3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, nullptr}};
    setLayout_ = gpu::createSetLayout(context_, bindings);
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
    descriptorPool_ = gpu::createDescriptorPool(context_, {&size, 1}, 1);
    set_ = gpu::allocateSet(context_, descriptorPool_, setLayout_);
    VkDescriptorImageInfo images[4];
    VkWriteDescriptorSet writes[4];
    for (std::uint32_t i = 0; i < 4; ++i) {
        images[i] = {i < 2 ? sampler_ : wholeChainSampler_, arrayViews_[i % 2], VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
        writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[i].dstSet = set_;
        writes[i].dstBinding = i;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        writes[i].pImageInfo = &images[i];
    }
    vkUpdateDescriptorSets(context_.device, 4, writes, 0, nullptr);
}

void ImpostorAtlas::bake(const GeometryPool& pool, std::span<const model::SkinnedModel* const> models,
                         VkDescriptorSetLayout sceneSetLayout, VkDescriptorSet sceneSet) {
    std::vector<std::uint32_t> firstBone;
    const std::vector<gpu::BoneRows> poses = impostorPoses(models, plan_.models, firstBone);
    gpu::Buffer bones = gpu::createBufferWithData(context_, std::as_bytes(std::span(poses)),
                                                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "impostor capture bones");
    const std::uint32_t side = plan_.cellsPerRow * plan_.cellSize;
    gpu::Image depth{};
    std::vector<VkImageView> layerViews;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    std::shared_ptr<gpu::DescriptorBundle> poseSet;
    bool handedOver = false;
    // What the bake needs until its commands have run: released at once, or by the host's setup
    // queue once its submission is done (a borrowed device).
    auto cleanup = [this, &pipeline, &layout, &poseSet, &layerViews, &depth, &bones] {
        return [&context = context_, pipeline, layout, poseSet, layerViews, depth, bones]() mutable {
            if (pipeline) vkDestroyPipeline(context.device, pipeline, nullptr);
            if (layout) vkDestroyPipelineLayout(context.device, layout, nullptr);
            poseSet.reset();
            for (VkImageView v : layerViews) vkDestroyImageView(context.device, v, nullptr);
            gpu::destroyImage(context, depth);
            gpu::destroyBuffer(context, bones);
        };
    };
    try {
        depth = gpu::createImage2D(context_, {side, side}, kCaptureDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                   "impostor capture depth");
        // Mip 0 of each layer of both arrays, as attachments: index layer x 2 + array.
        for (std::uint32_t l = 0; l < plan_.layers; ++l)
            for (int i = 0; i < 2; ++i) {
                VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
                view.image = images_[i];
                view.viewType = VK_IMAGE_VIEW_TYPE_2D;
                view.format = kFormats[i];
                view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, l, 1};
                layerViews.push_back(VK_NULL_HANDLE);
                VK_CHECK(vkCreateImageView(context_.device, &view, nullptr, &layerViews.back()));
            }
        const gpu::BufferBinding bindings[2] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, pool.modelTable().buffer},
                                                {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, bones.buffer}};
        poseSet = std::make_shared<gpu::DescriptorBundle>(context_, VK_SHADER_STAGE_VERTEX_BIT, bindings);
        const VkDescriptorSetLayout sets[2] = {sceneSetLayout, poseSet->layout()};
        const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(CapturePush)};
        layout = gpu::createPipelineLayout(context_, sets, {&push, 1});
        gpu::GraphicsPipelineDesc desc;
        desc.vertexShader = impostor_capture_vert_spv;
        desc.fragmentShader = impostor_capture_frag_spv;
        desc.bindings = {{0, sizeof(gpu::SkinVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
        desc.attributes = {{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(gpu::SkinVertex, position)},
                           {1, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(gpu::SkinVertex, normal)},
                           {2, 0, VK_FORMAT_R32G32B32A32_UINT, offsetof(gpu::SkinVertex, joints)},
                           {3, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(gpu::SkinVertex, weights)}};
        desc.colorFormats = {kFormats[0], kFormats[1]};
        desc.depthFormat = kCaptureDepthFormat;
        desc.layout = layout;
        desc.cullMode = VK_CULL_MODE_NONE;  // the orthographic basis may mirror winding; depth sorts it out
        pipeline = gpu::createGraphicsPipeline(context_, desc);

        const VkDescriptorSet poseDescriptors = poseSet->set();
        handedOver = true;  // from here runOneShot releases the temporaries, whatever happens
        const VkBuffer bindVertices = pool.bindVertices().buffer, indices = pool.indices().buffer;
        const std::vector<gpu::ModelRecord> records = pool.models();
        gpu::runOneShot(context_, [=, this](VkCommandBuffer cmd) {
            for (int i = 0; i < 2; ++i)
                transition(cmd, images_[i], 0, 1, {VK_PIPELINE_STAGE_2_NONE, 0}, colourWrite(), VK_IMAGE_LAYOUT_UNDEFINED,
                           VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
            const VkDeviceSize zero = 0;
            const std::uint32_t perLayer = plan_.cellsPerRow * plan_.cellsPerRow;
            for (std::uint32_t l = 0; l < plan_.layers; ++l) {
                // The depth image is reused by every layer: the previous layer's tests are done first.
                gpu::imageBarrier(cmd, depth.image, VK_IMAGE_ASPECT_DEPTH_BIT,
                                  {VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                                   VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT},
                                  {VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                                   VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT},
                                  VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
                VkRenderingAttachmentInfo colour[2];
                for (int i = 0; i < 2; ++i) {
                    colour[i] = {VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
                    colour[i].imageView = layerViews[l * 2 + i];
                    colour[i].imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
                    colour[i].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
                    colour[i].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
                    colour[i].clearValue.color = {{0.0f, 0.0f, 0.0f, 0.0f}};  // empty: no coverage
                }
                VkRenderingAttachmentInfo depthAttachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
                depthAttachment.imageView = depth.view;
                depthAttachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
                depthAttachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
                depthAttachment.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
                depthAttachment.clearValue.depthStencil = {1.0f, 0};
                VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
                rendering.renderArea = {{0, 0}, {side, side}};
                rendering.layerCount = 1;
                rendering.colorAttachmentCount = 2;
                rendering.pColorAttachments = colour;
                rendering.pDepthAttachment = &depthAttachment;
                vkCmdBeginRendering(cmd, &rendering);
                vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
                const VkDescriptorSet bound[2] = {sceneSet, poseDescriptors};
                vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 2, bound, 0, nullptr);
                vkCmdBindVertexBuffers(cmd, 0, 1, &bindVertices, &zero);
                vkCmdBindIndexBuffer(cmd, indices, 0, VK_INDEX_TYPE_UINT32);
                for (std::uint32_t entry = 0; entry < plan_.models.size(); ++entry) {
                    const std::uint32_t m = entry / IMPOSTOR_SETS;
                    if (entry % IMPOSTOR_SETS >= plan_.setCount(m)) continue;  // a repeat of set 0
                    const gpu::ImpostorModel& im = plan_.models[entry];
                    const gpu::ModelRecord& record = records[m];
                    const std::uint32_t cells = im.cells.y * im.cells.z * im.views.x * im.views.y;
                    const std::uint32_t first = std::max(im.cells.x, l * perLayer);
                    const std::uint32_t end = std::min(im.cells.x + cells, (l + 1) * perLayer);
                    for (std::uint32_t cell = first; cell < end; ++cell) {
                        // cell - first cell = (pose x elevations + elevation) x azimuths + azimuth
                        const std::uint32_t k = cell - im.cells.x;
                        const std::uint32_t azimuth = k % im.views.x;
                        const std::uint32_t elevation = (k / im.views.x) % im.views.y;
                        const std::uint32_t pose = k / (im.views.x * im.views.y);
                        const glm::vec3 towards = impostorViewDirection(im, azimuth, elevation);
                        glm::vec3 right, up;
                        impostorBasis(towards, right, up);
                        const CapturePush push{im.square, glm::vec4(right, 0.0f), glm::vec4(up, 0.0f),
                                               glm::vec4(towards, 0.0f),
                                               glm::uvec4(firstBone[entry] + pose * record.info.y, m, 0u, 0u)};
                        const std::uint32_t inLayer = cell - l * perLayer;
                        const VkViewport viewport{static_cast<float>(inLayer % plan_.cellsPerRow * plan_.cellSize),
                                                  static_cast<float>(inLayer / plan_.cellsPerRow * plan_.cellSize),
                                                  static_cast<float>(plan_.cellSize), static_cast<float>(plan_.cellSize),
                                                  0.0f, 1.0f};
                        const VkRect2D scissor{{static_cast<std::int32_t>(viewport.x), static_cast<std::int32_t>(viewport.y)},
                                               {plan_.cellSize, plan_.cellSize}};
                        vkCmdSetViewport(cmd, 0, 1, &viewport);
                        vkCmdSetScissor(cmd, 0, 1, &scissor);
                        vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof push, &push);
                        vkCmdDrawIndexed(cmd, record.lodIndexCount[0], 1, record.lodFirstIndex[0],
                                         static_cast<std::int32_t>(record.info.x), 0);
                    }
                }
                vkCmdEndRendering(cmd);
            }
            // The mip chain, level by level over every layer: a 2x2 box of coverage-weighted texels
            // never crosses a cell's edge while a cell is at least one texel.
            for (int i = 0; i < 2; ++i) {
                transition(cmd, images_[i], 0, 1, colourWrite(), {VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_READ_BIT},
                           VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
                for (std::uint32_t level = 1; level < plan_.mipLevels; ++level) {
                    transition(cmd, images_[i], level, 1, {VK_PIPELINE_STAGE_2_NONE, 0},
                               {VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT}, VK_IMAGE_LAYOUT_UNDEFINED,
                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
                    VkImageBlit blit{};
                    const auto from = static_cast<std::int32_t>(side >> (level - 1));
                    const auto to = static_cast<std::int32_t>(side >> level);
                    blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, plan_.layers};
                    blit.srcOffsets[1] = {from, from, 1};
                    blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, plan_.layers};
                    blit.dstOffsets[1] = {to, to, 1};
                    vkCmdBlitImage(cmd, images_[i], VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, images_[i],
                                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
                    transition(cmd, images_[i], level, 1, {VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                               {VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_READ_BIT},
                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
                }
                transition(cmd, images_[i], 0, plan_.mipLevels, {VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_READ_BIT},
                           {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            VK_ACCESS_2_SHADER_SAMPLED_READ_BIT},
                           VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
            }
        }, cleanup());
    } catch (...) {
        if (!handedOver) cleanup()();
        throw;
    }
}

}  // namespace render
