#version 450
// The host's own geometry (ground and boxes): world-space position and a colour per vertex.
layout(push_constant) uniform Push { mat4 viewProjection; } push;
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inColor;
layout(location = 0) out vec3 vColor;

void main() {
    gl_Position = push.viewProjection * vec4(inPosition, 1.0);
    vColor = inColor;
}
