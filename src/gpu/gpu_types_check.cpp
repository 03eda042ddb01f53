// The C++ side of shaders/gpu_types.h must lay every struct out as std430 (and, for uniforms, std140)
// does in GLSL: these asserts fail the build when a member is added with a size or alignment that
// would make the two disagree.
#include <cstddef>

#include <vulkan/vulkan.h>

#include "gpu_types.h"

namespace gpu {

static_assert(sizeof(SkinVertex) == 64 && offsetof(SkinVertex, joints) == 32 && offsetof(SkinVertex, weights) == 48);
static_assert(sizeof(LodMorphTarget) == 16);
static_assert(sizeof(BoneRows) == 48);
static_assert(sizeof(ModelRecord) == 80 && offsetof(ModelRecord, info) == 48 && offsetof(ModelRecord, sphere) == 64);
static_assert(sizeof(CharacterRecord) == 64 && offsetof(CharacterRecord, tint) == 16 && offsetof(CharacterRecord, ids) == 32 &&
              offsetof(CharacterRecord, pose) == 48);
static_assert(sizeof(BucketRecord) == 48 && offsetof(BucketRecord, mesh) == 16 && offsetof(BucketRecord, fixedLayout) == 32);
// Written with atomics and read one uint at a time: four 4-byte members, an array stride of 16.
static_assert(sizeof(BucketFrame) == 16 && offsetof(BucketFrame, vertexBase) == 4 && offsetof(BucketFrame, drawBase) == 8);
// The cull passes write what vkCmdDrawIndexedIndirect(Count) reads.
static_assert(sizeof(DrawIndexedCommand) == sizeof(VkDrawIndexedIndirectCommand));
static_assert(offsetof(DrawIndexedCommand, vertexOffset) == offsetof(VkDrawIndexedIndirectCommand, vertexOffset));
static_assert(offsetof(DrawIndexedCommand, firstInstance) == offsetof(VkDrawIndexedIndirectCommand, firstInstance));
// emitDispatch is read by vkCmdDispatchIndirect: 16-byte aligned after four uints.
static_assert(sizeof(DrawTotals) == 48 && offsetof(DrawTotals, emitDispatch) == 16 && offsetof(DrawTotals, fading) == 32);
static_assert(sizeof(ImpostorModel) == 64 && offsetof(ImpostorModel, views) == 16 && offsetof(ImpostorModel, square) == 32 &&
              offsetof(ImpostorModel, propSets) == 48);
// Written with atomics, one uint at a time; the draws follow the header as VkDrawIndexedIndirectCommands.
static_assert(sizeof(ImpostorFrame) == 16 && offsetof(ImpostorFrame, demoted) == 8);
// splitDispatch is read by vkCmdDispatchIndirect; the one-workgroup scans split each histogram evenly.
static_assert(sizeof(MeshCut) == 32 && offsetof(MeshCut, splitDispatch) == 16);
static_assert(MESH_CUT_COARSE_BUCKETS % MESH_CUT_WORKGROUP_SIZE == 0 && MESH_CUT_FINE_BUCKETS % MESH_CUT_WORKGROUP_SIZE == 0);
static_assert(sizeof(ImpostorDrawsHeader) == 16);
// 128 bytes: the push-constant size every device guarantees.
static_assert(sizeof(ImpostorRasterPush) == 128 && offsetof(ImpostorRasterPush, viewport) == 80 &&
              offsetof(ImpostorRasterPush, limits) == 96 && offsetof(ImpostorRasterPush, far) == 112);
static_assert(sizeof(ImpostorSplit) == 32 && offsetof(ImpostorSplit, largeDispatch) == 16);
// Read by vkCmdDrawIndirectCount: a VkDrawIndirectCommand, then the count; the tiles follow at 32.
static_assert(offsetof(VisibilityTileList, drawCount) == sizeof(VkDrawIndirectCommand) && sizeof(VisibilityTileList) == 32);
constexpr std::size_t kCascadePlanesBytes = MAX_SHADOW_CASCADES * 6 * 16;
static_assert(sizeof(CullUniforms) == 6 * 16 + 5 * 16 + kCascadePlanesBytes + 4 * 16 && offsetof(CullUniforms, camera) == 96 &&
              offsetof(CullUniforms, limits) == 144 && offsetof(CullUniforms, light) == 160 &&
              offsetof(CullUniforms, cascadePlanes) == 176 && offsetof(CullUniforms, cascadeTexels) == 176 + kCascadePlanesBytes &&
              offsetof(CullUniforms, shadow) == 192 + kCascadePlanesBytes &&
              offsetof(CullUniforms, shadowFlags) == 208 + kCascadePlanesBytes && offsetof(CullUniforms, fade) == 224 + kCascadePlanesBytes);
static_assert(sizeof(SkinPassParams) == 32);
static_assert(offsetof(SceneUniforms, shadowLight) == 112 &&
              offsetof(SceneUniforms, shadowSquares) == 176 + 16 * MAX_SHADOW_CASCADES &&
              sizeof(SceneUniforms) == 176 + 32 * MAX_SHADOW_CASCADES + 64);
static_assert(offsetof(MaterialTable, colors) == 16 && sizeof(MaterialTable) == 16 + 16 * MAX_MATERIALS);

// Animation tables: vec4 members only (std430 arrays of them need no padding), a track is four uints.
static_assert(sizeof(AnimationModel) == 64 && offsetof(AnimationModel, root) == 16);
static_assert(sizeof(AnimationJoint) == 96 && offsetof(AnimationJoint, inverseBind) == 48);
static_assert(sizeof(AnimationClip) == 32 && sizeof(AnimationTrack) == 16);
static_assert(sizeof(MotionRecord) == 64 && offsetof(MotionRecord, clips) == 48);
static_assert(sizeof(PalettePush) == 16 && sizeof(MotionPush) == 32);
// Driven characters: keys of two vec4s, a gait table of four, the host's samples packed as 16 bytes.
static_assert(sizeof(DrivenKey) == 32 && sizeof(DrivenModel) == 64 && sizeof(DrivenKeyUpload) == 48);
static_assert(sizeof(DeviceSample) == 16 && offsetof(DeviceSample, heading) == 12);
static_assert(sizeof(TerrainGrid) == 32 && offsetof(TerrainGrid, size) == 16);
// Events: the records follow the 16-byte header in one buffer (shaders/events.comp.glsl).
static_assert(sizeof(AnimationEvent) == 32 && sizeof(EventRecord) == 32 && offsetof(EventRecord, place) == 16);
static_assert(sizeof(EventHeader) == 16 && offsetof(EventHeader, capacity) == 8);
static_assert(sizeof(PreviousSegment) == 96 && offsetof(PreviousSegment, span) == 64 && offsetof(PreviousSegment, ids) == 80);
static_assert(sizeof(EventPush) == 32);

}  // namespace gpu
