#include "anim/affine.h"

#include <cmath>

namespace anim {
namespace {

glm::vec4 composeRow(const glm::vec4& a, const Affine& b) {
    return a.x * b.row0 + a.y * b.row1 + a.z * b.row2 + glm::vec4(0.0f, 0.0f, 0.0f, a.w);
}

}  // namespace

Affine compose(const Affine& a, const Affine& b) { return {composeRow(a.row0, b), composeRow(a.row1, b), composeRow(a.row2, b)}; }

Affine affineOf(const Transform& t) {
    const glm::quat& q = t.rotation;
    const float xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
    const float xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
    const float wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
    const glm::vec3& s = t.scale;
    return {glm::vec4((1.0f - 2.0f * (yy + zz)) * s.x, 2.0f * (xy - wz) * s.y, 2.0f * (xz + wy) * s.z, t.translation.x),
            glm::vec4(2.0f * (xy + wz) * s.x, (1.0f - 2.0f * (xx + zz)) * s.y, 2.0f * (yz - wx) * s.z, t.translation.y),
            glm::vec4(2.0f * (xz - wy) * s.x, 2.0f * (yz + wx) * s.y, (1.0f - 2.0f * (xx + yy)) * s.z, t.translation.z)};
}

Affine placementAffine(const glm::vec3& position, float heading, float scale) {
    const float c = std::cos(heading) * scale, s = std::sin(heading) * scale;
    return {glm::vec4(c, 0.0f, s, position.x), glm::vec4(0.0f, scale, 0.0f, position.y),
            glm::vec4(-s, 0.0f, c, position.z)};
}

glm::vec3 transformPoint(const Affine& a, const glm::vec3& p) {
    const glm::vec4 h(p, 1.0f);
    return {glm::dot(a.row0, h), glm::dot(a.row1, h), glm::dot(a.row2, h)};
}

}  // namespace anim
