#pragma once
// Four floats in one register: the lanes of the structure-of-arrays animation jobs (four joints at a
// time, anim/soa_transform.h) and the columns of a 3x4 affine row. Two backends with one interface:
//   Sse2Float4  x86-64's baseline SSE2 (every x86-64 processor has it; the build sets no -march);
//   LaneFloat4  four plain floats, the portable fallback: builds for other processors run it, and
//               x86-64 builds compile and test it too (tests/test_soa_jobs.cpp), so it cannot rot.
// NativeFloat4 names the one the jobs run. Both do the same IEEE operations in the same order, so
// their results are bit-identical. No AVX: see docs/choices.md ("SIMD width").
#include <cmath>
#include <cstdint>
#include <cstring>

// CROWD_ANIM_PORTABLE_ONLY (the CMake option of that name) builds as for a processor without SSE2.
#if (defined(__SSE2__) || defined(_M_X64)) && !defined(CROWD_ANIM_PORTABLE_ONLY)
#include <emmintrin.h>
#define CROWD_ANIM_HAVE_SSE2 1
#endif

// For the SoA maths' larger functions, which GCC would otherwise call out of line, passing four
// Float4s through memory each way: inlined, they stay in registers.
#if defined(__GNUC__)
#define CROWD_SIMD_INLINE [[gnu::always_inline]] inline
#else
#define CROWD_SIMD_INLINE inline
#endif

namespace simd {

// The portable backend. Masks are four all-ones or all-zero words, as SSE's comparisons give.
struct LaneFloat4 {
    float v[4];

    struct Mask {
        std::uint32_t m[4];
        friend Mask operator&(Mask a, Mask b) { return {{a.m[0] & b.m[0], a.m[1] & b.m[1], a.m[2] & b.m[2], a.m[3] & b.m[3]}}; }
        friend Mask operator|(Mask a, Mask b) { return {{a.m[0] | b.m[0], a.m[1] | b.m[1], a.m[2] | b.m[2], a.m[3] | b.m[3]}}; }
        bool any() const { return (m[0] | m[1] | m[2] | m[3]) != 0; }
        bool all() const { return (m[0] & m[1] & m[2] & m[3]) == 0xffffffffu; }
    };

    static LaneFloat4 splat(float x) { return {{x, x, x, x}}; }
    static LaneFloat4 set(float x, float y, float z, float w) { return {{x, y, z, w}}; }
    static LaneFloat4 load(const float* p) { return {{p[0], p[1], p[2], p[3]}}; }  // any alignment
    void store(float* p) const { p[0] = v[0], p[1] = v[1], p[2] = v[2], p[3] = v[3]; }
    float lane(int i) const { return v[i]; }
    // Every lane set to lane I.
    template <int I>
    LaneFloat4 broadcast() const { return splat(v[I]); }

    template <class Op>
    static LaneFloat4 map(LaneFloat4 a, LaneFloat4 b, Op op) {
        return {{op(a.v[0], b.v[0]), op(a.v[1], b.v[1]), op(a.v[2], b.v[2]), op(a.v[3], b.v[3])}};
    }
    template <class Op>
    static Mask test(LaneFloat4 a, LaneFloat4 b, Op op) {
        auto word = [](bool t) { return t ? 0xffffffffu : 0u; };
        return {{word(op(a.v[0], b.v[0])), word(op(a.v[1], b.v[1])), word(op(a.v[2], b.v[2])), word(op(a.v[3], b.v[3]))}};
    }
    friend LaneFloat4 operator+(LaneFloat4 a, LaneFloat4 b) { return map(a, b, [](float x, float y) { return x + y; }); }
    friend LaneFloat4 operator-(LaneFloat4 a, LaneFloat4 b) { return map(a, b, [](float x, float y) { return x - y; }); }
    friend LaneFloat4 operator*(LaneFloat4 a, LaneFloat4 b) { return map(a, b, [](float x, float y) { return x * y; }); }
    friend LaneFloat4 operator/(LaneFloat4 a, LaneFloat4 b) { return map(a, b, [](float x, float y) { return x / y; }); }
    friend LaneFloat4 operator-(LaneFloat4 a) { return {{-a.v[0], -a.v[1], -a.v[2], -a.v[3]}}; }
    friend Mask operator<(LaneFloat4 a, LaneFloat4 b) { return test(a, b, [](float x, float y) { return x < y; }); }
    friend Mask operator>(LaneFloat4 a, LaneFloat4 b) { return test(a, b, [](float x, float y) { return x > y; }); }
    friend Mask operator<=(LaneFloat4 a, LaneFloat4 b) { return test(a, b, [](float x, float y) { return x <= y; }); }
    friend Mask operator==(LaneFloat4 a, LaneFloat4 b) { return test(a, b, [](float x, float y) { return x == y; }); }
    friend LaneFloat4 sqrt(LaneFloat4 a) { return {{std::sqrt(a.v[0]), std::sqrt(a.v[1]), std::sqrt(a.v[2]), std::sqrt(a.v[3])}}; }
    friend LaneFloat4 abs(LaneFloat4 a) { return {{std::fabs(a.v[0]), std::fabs(a.v[1]), std::fabs(a.v[2]), std::fabs(a.v[3])}}; }
    // Lanes of `yes` where the mask is set, of `no` elsewhere.
    friend LaneFloat4 select(Mask mask, LaneFloat4 yes, LaneFloat4 no) {
        LaneFloat4 out;
        for (int i = 0; i < 4; ++i) out.v[i] = mask.m[i] ? yes.v[i] : no.v[i];
        return out;
    }
    // Rows become columns.
    friend void transpose(LaneFloat4& a, LaneFloat4& b, LaneFloat4& c, LaneFloat4& d) {
        LaneFloat4* rows[4] = {&a, &b, &c, &d};
        float m[4][4];
        for (int r = 0; r < 4; ++r) std::memcpy(m[r], rows[r]->v, sizeof(m[r]));
        for (int r = 0; r < 4; ++r)
            for (int c2 = 0; c2 < 4; ++c2) rows[r]->v[c2] = m[c2][r];
    }
};

#ifdef CROWD_ANIM_HAVE_SSE2
struct Sse2Float4 {
    __m128 v;

    struct Mask {
        __m128 m;
        friend Mask operator&(Mask a, Mask b) { return {_mm_and_ps(a.m, b.m)}; }
        friend Mask operator|(Mask a, Mask b) { return {_mm_or_ps(a.m, b.m)}; }
        bool any() const { return _mm_movemask_ps(m) != 0; }
        bool all() const { return _mm_movemask_ps(m) == 0xf; }
    };

    static Sse2Float4 splat(float x) { return {_mm_set1_ps(x)}; }
    static Sse2Float4 set(float x, float y, float z, float w) { return {_mm_setr_ps(x, y, z, w)}; }
    static Sse2Float4 load(const float* p) { return {_mm_loadu_ps(p)}; }  // as fast as an aligned load when aligned
    void store(float* p) const { _mm_storeu_ps(p, v); }
    float lane(int i) const {
        alignas(16) float out[4];
        _mm_store_ps(out, v);
        return out[i];
    }
    // pshufd rather than shufps: it writes a new register, where shufps overwrites its source and
    // costs a copy first (the palette's products broadcast nine lanes each).
    template <int I>
    Sse2Float4 broadcast() const {
        return {_mm_castsi128_ps(_mm_shuffle_epi32(_mm_castps_si128(v), _MM_SHUFFLE(I, I, I, I)))};
    }

    friend Sse2Float4 operator+(Sse2Float4 a, Sse2Float4 b) { return {_mm_add_ps(a.v, b.v)}; }
    friend Sse2Float4 operator-(Sse2Float4 a, Sse2Float4 b) { return {_mm_sub_ps(a.v, b.v)}; }
    friend Sse2Float4 operator*(Sse2Float4 a, Sse2Float4 b) { return {_mm_mul_ps(a.v, b.v)}; }
    friend Sse2Float4 operator/(Sse2Float4 a, Sse2Float4 b) { return {_mm_div_ps(a.v, b.v)}; }
    friend Sse2Float4 operator-(Sse2Float4 a) { return {_mm_xor_ps(a.v, _mm_set1_ps(-0.0f))}; }
    friend Mask operator<(Sse2Float4 a, Sse2Float4 b) { return {_mm_cmplt_ps(a.v, b.v)}; }
    friend Mask operator>(Sse2Float4 a, Sse2Float4 b) { return {_mm_cmpgt_ps(a.v, b.v)}; }
    friend Mask operator<=(Sse2Float4 a, Sse2Float4 b) { return {_mm_cmple_ps(a.v, b.v)}; }
    friend Mask operator==(Sse2Float4 a, Sse2Float4 b) { return {_mm_cmpeq_ps(a.v, b.v)}; }
    friend Sse2Float4 sqrt(Sse2Float4 a) { return {_mm_sqrt_ps(a.v)}; }
    friend Sse2Float4 abs(Sse2Float4 a) { return {_mm_andnot_ps(_mm_set1_ps(-0.0f), a.v)}; }
    friend Sse2Float4 select(Mask mask, Sse2Float4 yes, Sse2Float4 no) {
        return {_mm_or_ps(_mm_and_ps(mask.m, yes.v), _mm_andnot_ps(mask.m, no.v))};  // SSE2 has no blendv
    }
    friend void transpose(Sse2Float4& a, Sse2Float4& b, Sse2Float4& c, Sse2Float4& d) { _MM_TRANSPOSE4_PS(a.v, b.v, c.v, d.v); }
};
using NativeFloat4 = Sse2Float4;
#else
using NativeFloat4 = LaneFloat4;
#endif

// The name of the backend the jobs run, for reports.
inline const char* nativeFloat4Name() {
#ifdef CROWD_ANIM_HAVE_SSE2
    return "SSE2";
#else
    return "portable lanes";
#endif
}

}  // namespace simd
