#pragma once
// The animation maths of the scalar jobs, four joints at a time, on either Float4 backend
// (anim/simd_float4.h). Each function repeats its scalar counterpart's operations in the same order
// (glm's mix, dot and normalize; anim::slerpShortest, nlerpShortest, affineOf, compose), so the SoA
// jobs give the scalar jobs' results bit for bit, except the inverse cosine and sines of slerp, which
// are polynomials here (within 2e-7 of libm's; tests/test_soa_jobs.cpp).
#include "anim/sampling_job.h"
#include "anim/simd_float4.h"
#include "anim/soa_transform.h"

namespace anim::soa {

template <class F>
struct Vec3 {
    F x, y, z;
};

template <class F>
struct Quat {
    F x, y, z, w;
};

template <class F>
Vec3<F> load(const SoaFloat3& v) { return {F::load(v.x), F::load(v.y), F::load(v.z)}; }
template <class F>
Quat<F> load(const SoaQuat& q) { return {F::load(q.x), F::load(q.y), F::load(q.z), F::load(q.w)}; }
template <class F>
void store(const Vec3<F>& v, SoaFloat3& out) { v.x.store(out.x), v.y.store(out.y), v.z.store(out.z); }
template <class F>
void store(const Quat<F>& q, SoaQuat& out) { q.x.store(out.x), q.y.store(out.y), q.z.store(out.z), q.w.store(out.w); }

template <class F>
Quat<F> select(typename F::Mask m, const Quat<F>& a, const Quat<F>& b) {
    return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z), select(m, a.w, b.w)};
}

// glm::mix: a * (1 - s) + b * s.
template <class F>
F mix(F a, F b, F s) { return a * (F::splat(1.0f) - s) + b * s; }
template <class F>
Vec3<F> mix(const Vec3<F>& a, const Vec3<F>& b, F s) {
    const F r = F::splat(1.0f) - s;
    return {a.x * r + b.x * s, a.y * r + b.y * s, a.z * r + b.z * s};
}
template <class F>
Quat<F> mix(const Quat<F>& a, const Quat<F>& b, F s) {
    const F r = F::splat(1.0f) - s;
    return {a.x * r + b.x * s, a.y * r + b.y * s, a.z * r + b.z * s, a.w * r + b.w * s};
}

// glm::dot of quaternions kept as vec4 (x, y, z, w), and of glm::quat (w, x, y, z): the sums' order differs.
template <class F>
F dotXyzw(const Quat<F>& a, const Quat<F>& b) { return (a.x * b.x + a.y * b.y) + (a.z * b.z + a.w * b.w); }
template <class F>
F dotWxyz(const Quat<F>& a, const Quat<F>& b) { return (a.w * b.w + a.x * b.x) + (a.y * b.y + a.z * b.z); }

template <class F>
Quat<F> scaled(const Quat<F>& q, F s) { return {q.x * s, q.y * s, q.z * s, q.w * s}; }
template <class F>
Quat<F> negated(const Quat<F>& q) { return {-q.x, -q.y, -q.z, -q.w}; }

// glm::normalize of a vec4: v * (1 / sqrt(dot(v, v))).
template <class F>
Quat<F> normalizeXyzw(const Quat<F>& q) { return scaled(q, F::splat(1.0f) / sqrt(dotXyzw(q, q))); }

// glm::normalize of a glm::quat: q * (1 / length), the identity for a zero length.
template <class F>
Quat<F> normalizeWxyz(const Quat<F>& q) {
    const F length = sqrt(dotWxyz(q, q));
    const Quat<F> unit = scaled(q, F::splat(1.0f) / length);
    const F zero = F::splat(0.0f);
    return select<F>(length <= zero, Quat<F>{zero, zero, zero, F::splat(1.0f)}, unit);
}

// arccos(x) for x in [0, 1], Cephes' acosf: its asin polynomial on [0, 0.5], and
// acos(x) = 2 asin(sqrt((1 - x) / 2)) above 0.5. Within 2 ulp of libm.
template <class F>
F acosUnit(F x) {
    const F half = F::splat(0.5f);
    const typename F::Mask upper = x > half;
    const F a = select(upper, sqrt(half * (F::splat(1.0f) - x)), x);
    const F z = a * a;
    const F p = ((((F::splat(4.2163199048e-2f) * z + F::splat(2.4181311049e-2f)) * z + F::splat(4.5470025998e-2f)) * z +
                  F::splat(7.4953002686e-2f)) * z + F::splat(1.6666752422e-1f)) * z * a + a;
    return select(upper, p + p, F::splat(1.57079632679489662f) - p);
}

// sin(x) for x in [0, pi/2], Cephes' sinf: its sine polynomial up to pi/4, its cosine one of
// pi/2 - x above (pi/2 in two parts, so the difference is exact). Within 2 ulp of libm.
template <class F>
F sinQuarterTurn(F x) {
    const typename F::Mask upper = x > F::splat(0.785398163397448310f);
    const F r = select(upper, (F::splat(1.57079637050628662109375f) - x) + F::splat(-4.37113900018624283e-8f), x);
    const F z = r * r;
    const F sine = ((F::splat(-1.9515295891e-4f) * z + F::splat(8.3321608736e-3f)) * z - F::splat(1.6666654611e-1f)) * z * r + r;
    const F cosine = ((((F::splat(2.443315711809948e-5f) * z - F::splat(1.388731625493765e-3f)) * z +
                        F::splat(4.166664568298827e-2f)) * z * z) - F::splat(0.5f) * z) + F::splat(1.0f);
    return select(upper, cosine, sine);
}

// anim::slerpShortest, four pairs at once: the shorter arc, nlerp above kNlerpAbove, normalized.
template <class F>
CROWD_SIMD_INLINE Quat<F> slerpShortest(const Quat<F>& a, Quat<F> b, F s) {
    F cosTheta = dotXyzw(a, b);
    const F zero = F::splat(0.0f);
    const typename F::Mask flip = cosTheta < zero;
    b = select<F>(flip, negated(b), b);
    cosTheta = select(flip, -cosTheta, cosTheta);
    const F nlerpAbove = F::splat(kNlerpAbove);
    const typename F::Mask near = cosTheta > nlerpAbove;
    Quat<F> q = mix(a, b, s);
    if (!near.all()) {
        // The near lanes' angle is clamped only to keep their unused quotient finite.
        const F angle = acosUnit(select(near, nlerpAbove, cosTheta));
        const F from = sinQuarterTurn((F::splat(1.0f) - s) * angle), to = sinQuarterTurn(s * angle);
        const F sine = sinQuarterTurn(angle);
        const Quat<F> arc{(from * a.x + to * b.x) / sine, (from * a.y + to * b.y) / sine, (from * a.z + to * b.z) / sine,
                          (from * a.w + to * b.w) / sine};
        q = select<F>(near, q, arc);
    }
    return normalizeXyzw(q);
}

// anim::nlerpShortest on glm::quat, four pairs at once.
template <class F>
Quat<F> nlerpShortest(const Quat<F>& a, const Quat<F>& b, F weight) {
    const Quat<F> near = select<F>(dotWxyz(a, b) < F::splat(0.0f), negated(b), b);
    const F keep = F::splat(1.0f) - weight;
    return normalizeWxyz(Quat<F>{a.x * keep + near.x * weight, a.y * keep + near.y * weight, a.z * keep + near.z * weight,
                                 a.w * keep + near.w * weight});
}

// Three rows of a 3x4 affine matrix, one Float4 a row (the columns in the lanes).
template <class F>
struct Rows {
    F r0, r1, r2;
};

template <class F>
Rows<F> loadRows(const gpu::BoneRows& m) { return {F::load(&m.row0.x), F::load(&m.row1.x), F::load(&m.row2.x)}; }
template <class F>
void storeRows(const Rows<F>& m, gpu::BoneRows& out) { m.r0.store(&out.row0.x), m.r1.store(&out.row1.x), m.r2.store(&out.row2.x); }

// anim::compose's row: a.x * b.row0 + a.y * b.row1 + a.z * b.row2 + (0, 0, 0, a.w).
template <class F>
F composeRow(F a, const Rows<F>& b) {
    return a.template broadcast<0>() * b.r0 + a.template broadcast<1>() * b.r1 + a.template broadcast<2>() * b.r2 +
           a * F::set(0.0f, 0.0f, 0.0f, 1.0f);
}
template <class F>
Rows<F> compose(const Rows<F>& a, const Rows<F>& b) { return {composeRow(a.r0, b), composeRow(a.r1, b), composeRow(a.r2, b)}; }

// anim::affineOf of four joints; lane i of the result's rows is joint i's. `rows[lane]` receives them.
template <class F>
CROWD_SIMD_INLINE void affinesOf(const SoaTransform& t, Rows<F> rows[kSoaLanes]) {
    const Quat<F> q = load<F>(t.rotation);
    const Vec3<F> s = load<F>(t.scale);
    const F xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
    const F xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
    const F wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
    const F one = F::splat(1.0f), two = F::splat(2.0f);
    // Row r of the four joints as four columns (one Float4 a column), then turned into one Float4 a joint.
    F a0 = (one - two * (yy + zz)) * s.x, a1 = two * (xy - wz) * s.y, a2 = two * (xz + wy) * s.z, a3 = F::load(t.translation.x);
    F b0 = two * (xy + wz) * s.x, b1 = (one - two * (xx + zz)) * s.y, b2 = two * (yz - wx) * s.z, b3 = F::load(t.translation.y);
    F c0 = two * (xz - wy) * s.x, c1 = two * (yz + wx) * s.y, c2 = (one - two * (xx + yy)) * s.z, c3 = F::load(t.translation.z);
    transpose(a0, a1, a2, a3);
    transpose(b0, b1, b2, b3);
    transpose(c0, c1, c2, c3);
    rows[0] = {a0, b0, c0};
    rows[1] = {a1, b1, c1};
    rows[2] = {a2, b2, c2};
    rows[3] = {a3, b3, c3};
}

}  // namespace anim::soa
