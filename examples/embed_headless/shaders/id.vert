#version 450
// The ID pass over Renderer::output(): the crowd's skinned world-space positions (a vec4 stream),
// drawn with the renderer's own indirect draws. Each draw's firstInstance is its character's
// index, so gl_InstanceIndex (which includes firstInstance) names the character.
layout(push_constant) uniform Push { mat4 viewProjection; } push;
layout(location = 0) in vec4 inPosition;
layout(location = 0) flat out uint vId;

void main() {
    gl_Position = push.viewProjection * vec4(inPosition.xyz, 1.0);
    // The pass tests against the colour pass's depth (LESS_OR_EQUAL): a hair nearer, so the same
    // triangles pass even where this shader's rounding differs from the renderer's.
    gl_Position.z -= 1e-5 * gl_Position.w;
    vId = uint(gl_InstanceIndex) + 1u;  // 0 stays "no character"
}
