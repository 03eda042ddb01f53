// GPU-visible data layouts, declared once and included by both C++ and GLSL.
// Structs read as uniforms use only 16-byte members so std430 / std140 / C++ layouts agree; the few
// written by atomics or read as indirect commands use plain 4-byte members (std430 only).
// src/gpu/gpu_types_check.cpp static_asserts the sizes and offsets on the C++ side.
#ifndef CROWD_GPU_TYPES_H
#define CROWD_GPU_TYPES_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace gpu {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
using uint = std::uint32_t;
#endif

// Levels of detail every model has (model/lod_builder.h); a (model, LOD) pair is a "bucket".
#define LOD_COUNT 3
// Models one crowd may hold, and base-colour textures among them.
#define MAX_MODELS 16
#define MAX_TEXTURES 8
// The impostor level: after the mesh levels 0..LOD_COUNT-1, a character is a camera-facing quad
// textured from its model's atlas (render/impostor_atlas.h). lodState stores level + 1 as for the others.
#define IMPOSTOR_LEVEL LOD_COUNT
// A character's shadow this frame, one word written by culling (DrawLists::shadowStates): the level
// it is drawn at in the shadow map (0-2, or IMPOSTOR_LEVEL: a quad facing the light), whether it casts,
// and whether it is in the camera's view (drawn in the colour pass).
#define SHADOW_LEVEL_MASK 3u
#define SHADOW_CASTS_BIT 4u
#define SHADOW_IN_VIEW_BIT 8u
// The sun's shadow map holds up to MAX_SHADOW_CASCADES cascades, each a square of it over a stretch of
// the view's distance (render/shadow_cascades.h). A caster's state word holds, from SHADOW_CASCADE_SHIFT,
// a bit for each cascade whose volume its sphere reaches: the compute shadow raster draws it there only.
#define MAX_SHADOW_CASCADES 4
#define SHADOW_CASCADE_SHIFT 4u
// The same word's upper half: while a character's size is in the fade band of a threshold (lod-fade,
// shaders/cull.glsl.inc), the share of the coarser of its two levels in steps of 1/FADE_STEPS (0: not
// fading). Between mesh levels the character is skinned and drawn at the finer level, whose vertices
// the coarser one drops move that share of the way to their places on its surface
// (shaders/lod_morph.glsl.inc). Into its impostor it is drawn at both: its last mesh level on the
// pixels whose screen-space dither is at or above the share, the impostor on the others
// (shaders/fade_dither.glsl.inc). FADE_STEPS is the dither's number of thresholds: a finer share would
// draw the same pixels.
#define FADE_SHIFT 16u
#define FADE_STEPS 64u
// Threads per workgroup of the cull, emit and skinning compute passes.
#define CULL_WORKGROUP_SIZE 64

// Props one model may carry (model/attach_prop.h): a character's choice is a mask of this many bits,
// held exactly as a float in CharacterRecord.pose.z.
#define MAX_PROPS 16

// Most influences a vertex can have; the loaders reduce to the 4 largest.
#define MAX_INFLUENCES 4
// Every model's material colours live in one palette, MaterialTable (the pool offsets each model's
// indices); one model has at most MAX_MODEL_MATERIALS.
#define MAX_MODEL_MATERIALS 16
#define MAX_MATERIALS 128

// ---- Terrain (crowd/terrain.h, shaders/terrain_height.h) ----
// The host's heightfield: heights on a grid over a rectangle of the ground, bilinear between them, the
// edge's heights beyond. Characters stand on it; the library's ground is drawn as it. On the GPU one
// storage buffer holds the grid and then its heights (row-major: sample (column, row) at column + row x
// columns): TERRAIN_BUFFER below. The grid is never a push constant or uniform: lavapipe (Mesa 22.3)
// compiles a new copy of a shader that branches on uniform values at every bind and keeps it (CullUniforms).
struct TerrainGrid {
    vec4 extent;  // x, y: world (x, z) of sample (0, 0); z, w: the grid's width and depth in metres (z = 0: no
                  // terrain, the ground is the plane y = 0)
    uvec4 size;   // x: samples along x (columns, >= 2), y: along z (rows, >= 2), zw: unused
};

// The library's ground over a terrain (shaders/ground.vert.glsl): the heightfield's grid, every
// stride-th line so that at most GROUND_MOST_CELLS cells lie along a side, and a ring of cells reaching out
// to the ground's edge.
#define GROUND_MOST_CELLS 512u

// The terrain's storage buffer as a shader declares it (render/terrain_buffer.h).
#define TERRAIN_BUFFER(setIndex, bindingIndex) \
    layout(std430, set = setIndex, binding = bindingIndex) readonly buffer Terrain { TerrainGrid terrainGrid; float heights[]; }

// One bind-pose vertex as pass 1 (and the vertex-shader baseline) reads it.
// normal.w holds the vertex's material index (a small integer stored exactly as a float).
struct SkinVertex {
    vec4 position;  // xyz model space, w = 1
    vec4 normal;    // xyz unit normal, w = material index
    uvec4 joints;   // 4 joint indices into the character's bone block
    vec4 weights;   // 4 weights, summing to 1
};

// Where a vertex goes as its character fades into the next coarser mesh level (model/lod_morph.h):
// xyz the model vertex indices of a triangle of that level, w the barycentric weights of its second
// and third corners as two unorm16 (the second's in the low half; the first's is 1 minus both). One
// per pooled bind-pose vertex (GeometryPool::lodMorphTargets), read at the same index.
struct LodMorphTarget {
    uvec4 target;
};

// One skinning matrix as three rows of a 3x4 affine matrix: row i dotted with (p, 1) gives
// coordinate i. The paper keeps each row in its own RGBA32F texture; we keep the three rows
// of a bone next to each other in one buffer so a fetch of one bone touches one 48-byte line.
struct BoneRows {
    vec4 row0;
    vec4 row1;
    vec4 row2;
};

// One model of the geometry pool: where its levels of detail are and how big it is in any pose.
struct ModelRecord {
    uvec4 lodFirstIndex;   // xyz: first index of LOD 0, 1, 2 in the pooled index buffer
    uvec4 lodIndexCount;   // xyz: indices of each LOD
    uvec4 lodVertexCount;  // xyz: vertices each LOD references: a prefix of the model's vertices
    uvec4 info;            // x: first vertex in the pooled bind-pose buffer, y: joints,
                           // z: base-colour texture slot, w: unused
    vec4 sphere;           // model space, holding every pose of every clip: xyz centre, w radius
};

// One character: what culling, LOD choice, skinning and drawing read. Characters find their bones
// and their model by these fields, never by character x stride, so models of any size mix.
struct CharacterRecord {
    vec4 placement;  // xyz: world position of the model's origin, w: heading (radians about +y; 0 faces +z)
    vec4 tint;       // rgb: colour multiplier (variety), w: uniform scale
    uvec4 ids;       // x: model, y: first BoneRows of its bone block (blocks per mesh slot: this frame's
                     // slot's, written by the emit pass for the characters it lists; per character:
                     // its own, fixed; render/crowd_buffers.h, BoneBlocks), z: rank among its model's
                     // characters, w: its clips: bits 0-15 the clip it fades from, 16-31 the clip it
                     // fades to (the same clip twice when it plays one)
    vec4 pose;       // x: normalized phase in cycles (both clips of a crossfade are at the same point of
                     // their cycles, fract(x)), y: weight of the clip faded to (0..1), z: the props it
                     // carries (bit k: its model's prop k; an integer below 2^MAX_PROPS, exact as a
                     // float; fixed while the character is), w: the float bits of its slot's generation
                     // (crowd/population.h: which character holds the slot)
};

// One (model, LOD) bucket, fixed while the crowd is: where its visible characters are listed and
// what each of them draws.
struct BucketRecord {
    uvec4 list;  // x: model, y: LOD, z: first entry of the bucket in the visible list, w: capacity
                 // (characters of the model)
    uvec4 mesh;  // x: first index, y: index count, z: vertices per character (the LOD's prefix),
                 // w: model's first vertex in the pooled bind-pose buffer
    uvec4 fixedLayout;  // x: first skinned vertex of the bucket when every character has a slot
                        // (the static method), y: characters per skinning workgroup, z, w: unused
};

// One bucket's figures of this frame: the count is added to by culling, the bases are the prefix
// sums the finalize pass writes.
struct BucketFrame {
    uint count;       // visible characters at this LOD
    uint vertexBase;  // their first skinned vertex (dense: character k of the bucket at base + k x vertices)
    uint drawBase;    // their first draw in the compacted draw list
    uint shadowCount; // shadow casters at this LOD (listed after every visible list, shaders/cull_lists.glsl.inc)
};

// VkDrawIndexedIndirectCommand, as the cull passes write it.
struct DrawIndexedCommand {
    uint indexCount;
    uint instanceCount;
    uint firstIndex;
    int vertexOffset;
    uint firstInstance;
};

// Totals of a frame's draw lists, written by the finalize pass.
struct DrawTotals {
    uint drawCount;       // visible characters = draws in the compacted list
    uint skinnedVertices; // vertices the skinning pass writes
    uint shadowDrawCount; // mesh shadow casters = draws in the shadow pass's compacted list
    uint morphCount;      // characters in view morphing into their coarser mesh level (fades; counted)
    uvec4 emitDispatch;   // indirect dispatch of the emit pass (x groups, y = z = 1)
    uvec4 fading;         // x: characters fading into their impostors: colour draws (their mesh's share,
                          // dithered), in their own list
};

// Cell sets a model's impostors may have: one per combination of props (mask) its characters carry,
// the most carried first; a character whose mask has no set shows the nearest one
// (shaders/impostor_prop_set.glsl.inc, render/impostor_prop_sets.h). The impostor model table holds
// IMPOSTOR_SETS entries a model: model m's set s at m x IMPOSTOR_SETS + s (entries past its sets repeat set 0).
#define IMPOSTOR_SETS 4

// One cell set of a model's impostors: where its cells are in the atlas and how they were captured.
// Cell of (clip, frame, elevation, azimuth) = first + ((clip x frames + frame) x elevations + elevation) x
// azimuths + azimuth (shaders/impostor_cell.glsl.inc).
struct ImpostorModel {
    uvec4 cells;  // x: first cell of this set in the atlas, y: clips, z: frames per clip, w: the model's sets
    uvec4 views;  // x: azimuths, y: elevations, z: cells per atlas row, w: cells per atlas layer
    vec4 square;  // model space: xyz centre of every cell's square (the pose sphere's), w: half its side (this
                  // set's: a prop beyond the pose sphere, the flag, widens it)
    uvec4 propSets;  // the props masks of the model's sets 0..cells.w-1 (the same in each of its entries)
};

// The impostor level of a frame: culling counts its characters, finalize turns the count into one
// instanced draw of a 6-index quad (the first five members are VkDrawIndexedIndirectCommand).
struct ImpostorFrame {
    uint count;          // characters drawn as impostors (in view)
    uint meshCount;      // with a cap: characters that qualified for a mesh level, visible or caster (the
                         // candidates of the cut, MeshCut)
    uint demoted;        // of those, sent to the impostor level because the mesh levels were full
    uint shadowCount;    // impostor-level characters that cast a shadow (a quad facing the light)
};

// ---- The mesh-level cap's cut: farthest first (render/mesh_cut.h; shaders/cull_cutoff, cull_split,
// cull_resolve; the CPU rule in crowd/farthest_first.h) ----
// When more characters qualify for a mesh level than the cap, the cap's worth with the largest projected
// size keep it. A size is ranked by its float bits (a non-negative float orders as its bits do) in two
// histograms: the coarse one by the top bits, the fine one, over the cut's coarse bucket only, by the
// rest; exact ties at the cut go to the lower character index (a bitset over the characters).
#define MESH_CUT_FINE_BITS 16
#define MESH_CUT_FINE_BUCKETS (1u << MESH_CUT_FINE_BITS)
#define MESH_CUT_COARSE_BUCKETS (1u << (31 - MESH_CUT_FINE_BITS))  // the sign bit is never set
// A candidate's second word: the size's bits, and in bit 31 whether it is drawn as an impostor when
// demoted (in view; a shadow caster outside the view is not).
#define MESH_CUT_DRAWN_BIT 0x80000000u
// Threads of the cut's one-workgroup passes (cutoff and resolve): as many as every Vulkan device must
// allow in one workgroup; divides both bucket counts.
#define MESH_CUT_WORKGROUP_SIZE 128

// Where the cut falls in a frame. In one buffer with the histograms and the tie bitset after it (as
// uint words: coarse buckets, then fine buckets, then one bit per character).
struct MeshCut {
    uint keepAll;        // 1: no more qualified than the cap, so every candidate keeps its mesh
    uint coarseBucket;   // the coarse bucket holding the smallest kept size
    uint keepInCoarse;   // how many of that bucket's members are kept (its largest)
    uint boundary;       // that bucket's members, listed by the split pass for the resolve pass
    uvec4 splitDispatch; // indirect dispatch of the split pass over the candidates (x groups, y = z = 1)
};

// Impostors are drawn as indexed quads (four vertices, six indices each) from one fixed index buffer
// of IMPOSTOR_QUADS_PER_DRAW quads, so a frame issues one draw per that many impostors.
#define IMPOSTOR_QUADS_PER_DRAW 262144u

// The impostor draws of a frame, written after culling (render/impostor_draw.h): the colour pass's, then
// the shadow pass's.
struct ImpostorDrawsHeader {
    uint drawCount;  // draws below (the count of vkCmdDrawIndexedIndirectCount)
    uint shadowDrawCount;  // the shadow pass's, after the colour pass's maximum (quads facing the light)
    uint unused1;
    uint unused2;
};

// ---- The compute rasterizer (render/impostor_raster.h, docs/compute-raster.md) ----
// A visibility buffer holds one 64-bit word per pixel: the depth's float bits above (a depth in [0, 1]
// orders as its bits do, so a 64-bit atomic min keeps the nearest) and the rasterized item's id below.
// Cleared to all ones (nothing drawn). An impostor's id is its place in the frame's impostor list.
#define VISIBILITY_EMPTY_HIGH 0xFFFFFFFFu
#define IMPOSTOR_RASTER_WORKGROUP 64

// The impostor rasterizer's push constants.
struct ImpostorRasterPush {
    mat4 viewProjection;
    vec4 cameraPosition;  // xyz: the eye
    vec4 viewport;        // x, y: the viewport's extent in pixels; z: the largest impostor the compute path
                          // draws (its screen rectangle's longer side, pixels; larger ones go to the
                          // hardware path); w: the largest one a single thread draws (larger ones get a
                          // workgroup each in a second dispatch)
    uvec4 limits;         // x: the impostor list's capacity, y: threads in the dispatch (they stride over
                          // it), z: the most workgroups the second dispatch may have, w: 1 to blend four
                          // atlas cells, 0 the nearest (impostor-blend)
    vec4 far;             // x: the largest impostor (the rectangle's longer side, pixels) whose coverage is
                          // averaged into the far layer instead of winning whole pixels; 0: none (far-crowd off);
                          // y: those under this many pixels are splatted from their quadrants' means (0: none);
                          // z: the atlas level where a cell is two texels across
};

// The impostors the compute rasterizer leaves to the hardware path this frame (too large on screen, or
// crossing the near plane): their count, listed in a list of their own that the colour pass's impostor
// draw reads instead of the whole impostor list.
// Impostors larger than a thread should walk alone are listed too (by their place in the impostor list)
// for a second dispatch, indirect, a workgroup each.
struct ImpostorSplit {
    uint hardwareCount;
    uint computeCount;   // impostors rasterized in compute, either dispatch (reports and tests)
    uint largeCount;     // impostors that asked for the second dispatch (beyond its most: drawn by one thread)
    uint averagedCount;  // of computeCount, those averaged into the far layer (FAR_CROWD_*)
    uvec4 largeDispatch; // x: impostors listed for the second dispatch (its workgroups), y = z = 1
};
#define IMPOSTOR_RASTER_LARGE_PIXELS 16.0

// ---- The far crowd averaged (render/far_crowd_layer.h, docs/picture-quality.md) ----
// Impostors a few pixels across add their surface to a far layer instead of cutting their coverage at
// a half, weighted by the optical depth of their coverage c, -ln(1 - c): per pixel FAR_CROWD_CHANNELS
// fixed-point sums (FAR_CROWD_ONE a unit), in order: the tinted albedo (r, g, b), the optical depth,
// the world-space normal biased to [0, 1] (x, y, z) and the shadow offset's radius (metres), each
// times the optical depth.
// The layer's depth is a visibility word of its own (the nearest contribution, its impostor's id), so
// the tile scan lists its tiles as it does the opaque buffer's.
#define FAR_CROWD_CHANNELS 8
#define FAR_CROWD_ONE 65536.0
// A far impostor's pixels take sub-samples (n x n, at most FAR_CROWD_MOST_SUBSAMPLES a side) only
// until FAR_CROWD_SAMPLES_ACROSS of them lie across the impostor, so that one under two pixels across
// is not missed between pixel centres (far_crowd.glsl.inc); one under ImpostorRasterPush::far.y is
// splatted instead, which needs none.
#define FAR_CROWD_SAMPLES_ACROSS 2.0
#define FAR_CROWD_MOST_SUBSAMPLES 4
// Texels across a cell at the coarsest level the atlas's filtered reads take (render/impostor_atlas.h).
#define IMPOSTOR_SMALLEST_SAMPLED_CELL 8
// Under this many pixels across, a far impostor's reads take their level from the atlas's whole mip
// chain, not only down to IMPOSTOR_SMALLEST_SAMPLED_CELL texels a cell (far_crowd.glsl.inc, farUseGradients).
#define FAR_CROWD_WHOLE_CHAIN_PIXELS 4.0

// ---- Meshes in the compute rasterizer (render/mesh_raster.h, docs/compute-raster.md) ----
// Small characters' skinned triangles go into a visibility buffer of their own (the same 64-bit words:
// depth bits above, the id below). The id's top bit marks a mesh; below it, the character's place in
// the frame's mesh-raster list, shifted above the triangle's index within its draw (MeshRasterPush's
// triangleBits: enough for the largest model's triangles).
#define MESH_RASTER_ID_BIT 0x80000000u
#define MESH_RASTER_WORKGROUP 64
// Workgroups of the raster dispatch at most: they stride over the listed characters.
#define MESH_RASTER_MAX_WORKGROUPS 16384u

struct MeshRasterPush {
    mat4 viewProjection;
    vec4 camera;    // xyz: the eye, w: pixels per unit of size at unit distance (as CullUniforms::camera)
    vec4 viewport;  // x, y: the viewport's extent in pixels; z: the largest pose sphere (its diameter on
                    // screen, pixels) the compute path draws; w: unused
    uvec4 limits;   // x: triangle bits of an id, y: the list's capacity, z: draws in the colour list at
                    // most (DrawLists::drawCapacity), w: workgroups of the raster dispatch
};

// The meshes of this frame drawn in compute: their count (their colour draws keep no instance).
struct MeshSplit {
    uint computeCount;
    uint unused0;
    uint unused1;
    uint unused2;
};

// ---- The visibility buffers' resolve over covered tiles (render/visibility_tiles.h) ----
// A scan pass lists the screen tiles (a tile side set per resolve, a multiple of VISIBILITY_TILE_GROUP
// pixels) that hold any drawn pixel of a visibility buffer; the resolve draws them by
// an indirect draw, an instance per listed tile (its two triangles), so uncovered pixels cost no
// fragment. The list: this header (a VkDrawIndirectCommand and the draw's count), then the tiles,
// x | y << 16 each (in tiles), read by the resolve's vertex shader as a per-instance attribute.
#define VISIBILITY_TILE_GROUP 16  // the scan's workgroup is this many threads a side
struct VisibilityTileList {
    uint vertexCount;    // 6: a tile's two triangles
    uint instanceCount;  // tiles listed
    uint firstVertex;
    uint firstInstance;
    uint drawCount;      // 1: vkCmdDrawIndirectCount's count (render/visibility_tiles.cpp says why)
    uint unused0;
    uint unused1;
    uint unused2;
};

// ---- Animation on the GPU (anim/clip_library.h flattens the clips; render/animation_pass runs them) ----

// Samples of a clip's root-motion curve per cycle (plus one: the curve's end, the stride).
#define ROOT_MOTION_SAMPLES 64
// Joints a model may have for the GPU palette pass (its shared memory holds one character's at most).
#define MAX_ANIMATION_JOINTS 256
// Steps of the quadrature that integrates a character's path while it turns or crossfades.
#define MOTION_QUADRATURE_STEPS 16
// A skinned normal shorter than this (squared) is taken as collapsed: its bones map it to (almost)
// nothing, as a zero scale key or a zero inverse bind matrix does to hide a part. Normalizing it
// would give NaN (or inf from a float32 square that underflowed), so the vertex keeps its bind-pose
// normal instead; CPU reference and shaders share the threshold.
#define COLLAPSED_NORMAL_LENGTH2 1e-30

// One model's skeleton and clips in the flattened library.
struct AnimationModel {
    uvec4 info;      // x: first joint in the joint table, y: joints, z: first clip in the clip table, w: clips
    BoneRows root;   // what sits above the root joints (glTF nodes above the skeleton)
};

// One joint: its rest pose (kept where no clip animates it), parent and inverse bind matrix.
struct AnimationJoint {
    vec4 restTranslation;  // xyz, w: parent joint within the model (-1 for a root), exact as a float
    vec4 restRotation;     // quaternion x, y, z, w
    vec4 restScale;        // xyz, w: 0 for a body joint, k + 1 for the joint of the model's prop k (exact)
    BoneRows inverseBind;
};

// One clip: where its tracks and root motion are, its length and its stride.
struct AnimationClip {
    uvec4 info;    // x: first track (joint j's translation, rotation, scale at x + 3 j + 0, 1, 2),
                   // y: first root-motion sample, z, w: unused
    vec4 timing;   // x: duration (s), y: unused, zw: stride: how far the clip carries the character per
                   // cycle, in model space (x, z)
};

// One track: a joint's translation, rotation or scale keys (no keys: the rest value).
struct AnimationTrack {
    uint firstKey;       // into the key times
    uint keyCount;
    uint interpolation;  // 0 step, 1 linear, 2 cubic spline (three values per key)
    uint firstValue;     // into the key values
};

// How a segment moves its character (MotionRecord::phase.w): in place, carried by its clips' root
// motion, or driven by the host's samples (docs/host-driven.md): from keys the CPU made of samples in the
// host's memory, or the GPU of samples in a buffer of the host's (the segment then holds the character
// where it was spawned until its first key).
#define MOTION_IN_PLACE 0.0
#define MOTION_ROOT 1.0
#define MOTION_DRIVEN_HOST 2.0
#define MOTION_DRIVEN_DEVICE 3.0

// Seconds between the epochs of the GPU's clock (crowd/epoch.h).
#define EPOCH_SECONDS 64.0f

// What a character does from a start time on: one segment of its motion, planned by the CPU
// (crowd/motion.h), evaluated in closed form by the CPU and the GPU at any later time. Times are
// seconds since the crowd's epoch (crowd/epoch.h), never scene time: scene time is a double, and a
// segment that began long before the epoch reaches the GPU restated as where it is at the epoch
// (crowd/segment.h), so every float here stays small at any scene time.
struct MotionRecord {
    vec4 origin;  // xyz: position at the start, w: heading at the start (radians about +y)
    vec4 timing;  // x: start time (s since the epoch), y: crossfade duration (s; 0 = none), z: turn rate (rad/s),
                  // w: how long the turn lasts (s)
    vec4 phase;   // x: normalized phase at the start (cycles), y: cycles per second of the clip faded
                  // from, z: of the clip faded to, w: how it moves (MOTION_*: in place, root motion, driven)
    uvec4 clips;  // x: clip faded from, y: clip faded to (the model's own clip indices), zw: the float
                  // bits of the world (x, z) displacement where the turn and the crossfade end (the
                  // curved part, integrated once when the segment is planned: crowd::sealSegment)
};

// ---- Characters the host drives (crowd/driven.h, shaders/driven_keys.h, docs/host-driven.md) ----
// One key of a driven character: where a sample put it and what it plays there. Each driven slot keeps
// its last DRIVEN keys in a ring (CrowdCapacity::drivenKeys of them): key k of slot c at
// k x slots + c, so a warp's characters read one key each from neighbouring addresses.
struct DrivenKey {
    vec4 place;   // x: time (s since its epoch, motion.w), y, z: world x, z (metres), w: body heading (radians)
    vec4 motion;  // x: phase at the key (cycles, 0..1), y: cycles since the key before, z: gait (0 stand, 1 walk,
                  // 2 run; between: their crossfade), w: the epoch its time counts from (crowd/epoch.h: its
                  // index, exact as a float up to 2^24 epochs, 1e9 s)
};

// A model's gaits for driven characters (crowdgpu::GaitSettings), one per model.
struct DrivenModel {
    uvec4 clips;   // x: standing, y: walking, z: running clip (the model's indices; a gait it lacks: its
                   // neighbour's), w: unused
    vec4 cycles;   // x: the standing clip's cycles per second, y: the walk's stride (metres per cycle; 0: it
                   // travels not), z: the run's, w: the walk's own cycles per second (for a walk that does not travel)
    vec4 bands;    // x: walk from (m/s; below: stand), y: run from (m/s), z: hysteresis (a fraction of the
                   // band's edge), w: seconds a whole gait change takes
    vec4 turning;  // x: the fastest the body turns (rad/s), y: the slowest speed whose direction it turns to
                   // (m/s), zw: unused
};

// A key the CPU made, on its way to its slot's ring (render/driven_pass.h).
struct DrivenKeyUpload {
    DrivenKey key;
    uvec4 target;  // x: slot, y: the key's index (counted from the slot's first), zw: unused
};

// The host's samples in a device buffer (crowdgpu::DeviceSample): one per slot, written by the host's
// own pass each frame.
struct DeviceSample {
    float time;     // seconds relative to the frame's time (0: now; not a number: no sample this frame)
    float x, z;     // world metres
    float heading;  // radians about +y, or not a number: towards the motion
};

// Push constants of the palette passes. palette.comp: x: bucket, y: joints of its model, z:
// characters per workgroup, w: unused. palette_dispatch.comp: x: buckets, y: most workgroups in a
// dispatch's x dimension, z, w: unused.
struct PalettePush {
    uvec4 bucket;
};

// Push constants of the motion pass (and the scatters and the driven ingest, which use what they say).
struct MotionPush {
    uvec4 counts;  // x: characters (slots), y: most workgroups in a dispatch's x dimension, z: keys a slot keeps
                   // for driven characters, w: unused
    vec4 time;     // x: the frame's time in seconds since the crowd's epoch (crowd/epoch.h), y: the driven
                   // characters' clock (x less the delay: crowd::Crowd::drivenClock), z: their extrapolation
                   // (s), w: the epoch's index
};

// Per-frame parameters of the cull pass, in a storage buffer (the frustum alone is 96 bytes). Not a
// uniform buffer: lavapipe (Mesa 22.3) "inlines" the uniform-buffer values that a large shader's
// branches read, compiling a new copy of the shader at every bind and never freeing it (0.43 MB a
// frame for cull.comp); storage-buffer values are never inlined. Push constants are uniforms too.
struct CullUniforms {
    vec4 planes[6];  // world-space frustum planes, normals pointing inside: a sphere is outside when
                     // dot(n, centre) + w < -radius for some plane
    vec4 camera;     // xyz: eye, w: pixels per unit of size at unit distance (height / (2 tan(fovY / 2)))
    vec4 lod;        // x: LOD 0 threshold, y: LOD 1 threshold (projected sphere diameter in pixels),
                     // z: hysteresis (fraction of a threshold), w: impostor threshold (below it, the
                     // impostor level; 0: no impostors)
    uvec4 flags;     // x: characters, y: 1 = frustum culling, z: 1 = LOD selection (else all LOD 0),
                     // w: buckets
    uvec4 limits;    // x: most workgroups in a dispatch's x dimension, y: 1 = keep shadow casters,
                     // z: most characters at a mesh level (LOD 0-2) in a frame, the smallest on screen
                     // beyond it are demoted to impostors (0: no cap), w: unused
    vec4 light;      // xyz: unit vector towards the light (shadow casters), w: unused
    // Each shadow cascade's volume (its orthographic view-projection), six planes a cascade, the first
    // shadowFlags.z cascades used.
    vec4 cascadePlanes[MAX_SHADOW_CASCADES * 6];
    vec4 cascadeTexels;  // each cascade's shadow-map texels per world unit (x: cascade 0, ...)
    vec4 shadow;     // x: unused, y: LOD 0 and z: LOD 1 thresholds (a caster's sphere diameter in texels
                     // of the finest cascade it reaches), w: below this diameter in texels a caster is not drawn
    uvec4 shadowFlags;  // x: 1 = shadow LOD (levels from the shadow map; else the view's level), y: where
                        // the shadow lists start (set by CullPass::record, cull_lists.glsl.inc), z: shadow
                        // cascades (1 to MAX_SHADOW_CASCADES), w: unused
    uvec4 fade;      // x: 1 = a level change fades across the hysteresis band (lod-fade: both levels
                     // drawn, dithered; no hysteresis then), y, z, w: unused
};

// Push constants of the skinning passes: which bucket, and where its characters come from.
struct SkinPassParams {
    uvec4 bucket;  // x: bucket, y: 1 = fixed layout (every character, the static method), z, w: unused
    // Fragment passes: x: target width in texels, y: first row of this target, z: rows of this
    // target, w: unused
    uvec4 target;
};

// Every model's materials (render::GeometryPool::materials, a storage buffer in the scene set, binding 5;
// fixed while the pool is). Not in SceneUniforms: each vertex indexes it by its own material, and a
// uniform buffer indexed by a value that differs across a warp serializes on NVIDIA (0.12 ms of
// paper-fig4's colour pass on the H200, docs/gpu-driven-frame.md).
struct MaterialTable {
    uvec4 textured;  // bit m of (x, y, z, w)[m / 32] set when material m is multiplied by its model's
                     // base-colour texture
    vec4 colors[MAX_MATERIALS];
};

// Per-frame uniforms of the draw pass (pass 2), the ground and the vertex-shader baseline.
struct SceneUniforms {
    mat4 viewProjection;
    vec4 lightDirection;  // xyz: unit vector towards the light, w: ambient term
    vec4 skyColor;
    vec4 groundColor;     // xyz colour, w: checker tile size in metres
    // World to the first shadow cascade's clip space (x, y in [-1, 1] over its square; z, the depth, is
    // every cascade's: they share the light's view and depth range and differ in x, y extents only);
    // each cascade's clip x, y from the first's (xy: scale, zw: offset; render/shadow_cascades.h), and
    // where its square lies in the map (xy its corner in uv, z its side in uv, w unused).
    mat4 shadowLight;
    vec4 shadowFromFirst[MAX_SHADOW_CASCADES];
    vec4 shadowSquares[MAX_SHADOW_CASCADES];
    vec4 shadowCascadeUse;     // x: cascades, y: how far from a cascade's centre (in its clip units) a point
                               // is its own, leaving the filter's reach inside the square; z, w: unused
    vec4 shadowView;           // a point's distance along the view: dot(xyz, point) + w
    vec4 shadowSplits;         // where cascades 0, 1, 2 (x, y, z) end along the view; w: past all
    vec4 shadow;               // x: 1 = shadows on, y: depth bias, z: one texel of the map in uv, w: the ground
                               // sunlight image's first level made this frame (render/ground_sunlight.h)
};

// ---- Animation events on the GPU (render/event_pass.h, shaders/events.comp.glsl, docs/events.md) ----
// The clip events of every model, uploaded once: per library clip the range of its events (a uvec2
// table: first, count), and per event where it falls in the cycle and where its joint is then.
struct AnimationEvent {
    vec4 moment;  // x: point in the cycle (event time / clip duration), y: joint (-1: none; exact as a
                  // float), z: the event's index among its clip's events (exact as a float), w: its pair key
                  // (crowd/event_pairs.h: a crossfade's two events of equal keys >= 0 fire as one; -1 none)
    vec4 place;   // xyz: the joint's model-space position at that moment of its clip alone (the clip's
                  // pose with no placement; 0 without a joint), w: unused
};

// One event a visible character fired in the frame's window, as the event pass appends it.
struct EventRecord {
    uvec4 ids;   // x: character, y: clip (the model's own index), z: event (index among that clip's
                 // events), w: unused
    vec4 place;  // xyz: world position, w: how long before the frame's time it fired (s, >= 0: an age)
};

// The head of the event buffer; the records follow it (16 bytes in). count stops at capacity: an
// event that finds the buffer full is counted in dropped and written nowhere.
struct EventHeader {
    uint count;         // records written (at most capacity)
    uint dropped;       // events that fired in view but found the buffer full
    uint capacity;      // records the buffer holds
    uint lostSegments;  // characters replanned this frame whose previous segment did not fit its table
                        // (its events before the replan are missing)
};

// A character's segment before a replan in this frame's window (one per such character, uploaded by
// the host each frame): its events fire from span.x until span.y, where its current segment starts.
struct PreviousSegment {
    MotionRecord motion;
    vec4 span;  // x: from when the crowd knows it, y: its end (s since the epoch), z, w: unused
    uvec4 ids;  // x: character, y, z, w: unused
};

// Push constants of the event pass.
struct EventPush {
    uvec4 counts;  // x: items (characters, or previous segments), y: threads in the dispatch (they stride),
                   // z: 1 = the previous segments' table, 0 = every character's current segment, w: unused
    vec4 window;   // x: the previous frame's time, y: this frame's (s since the epoch; events at from < t <= to),
                   // z: the most cycles of a clip one event is looked for over (a longer window keeps its end)
};
#define EVENT_MAX_CYCLES 64.0

#ifdef __cplusplus
}  // namespace gpu
#endif
#endif
