// The benchmarks' agents (app/agent_drivers.h), written once for the CPU simulation (C++) and the GPU
// one (shaders/agents.comp.glsl): agent i walks a loop of radius `radius` about its home, its speed
// swinging between half and one and a half times its own (0.6, 1.4 or 3.0 m/s: standing, walking and
// running by turns), so the crowd changes gait, turns and keeps moving everywhere. Closed form: the
// angle travelled is the integral of the speed over the radius.
#ifndef CROWD_AGENT_PATH_H
#define CROWD_AGENT_PATH_H

#ifdef __cplusplus
#define AGENT_FN inline
#else
#define AGENT_FN
#endif

// A number in [0, 1) from an agent's index and a salt (a 32-bit integer hash).
AGENT_FN float agentHash(uint i, uint salt) {
    uint h = i * 0x9E3779B1u + salt * 0x85EBCA77u;
    h ^= h >> 15u;
    h *= 0x2C1B3C6Du;
    h ^= h >> 12u;
    h *= 0x297A2D39u;
    h ^= h >> 15u;
    return float(h >> 8u) / 16777216.0f;
}

// Agent i's position at `time` seconds, about its home.
AGENT_FN vec2 agentPosition(uint i, vec2 home, float time) {
    float radius = 2.0f + 6.0f * agentHash(i, 1u);
    float band = agentHash(i, 2u);
    float speed = band < 0.2f ? 0.6f : (band < 0.75f ? 1.4f : 3.0f);
    float swing = 0.25f + 0.5f * agentHash(i, 3u);  // rad/s of the speed's swing
    float start = 6.2831853f * agentHash(i, 4u), lag = 6.2831853f * agentHash(i, 5u);
    float angle = start + speed / radius * (time - 0.5f / swing * (cos(swing * time + lag) - cos(lag)));
    return home + radius * vec2(sin(angle), cos(angle)) - vec2(0.0f, radius);
}

#endif
