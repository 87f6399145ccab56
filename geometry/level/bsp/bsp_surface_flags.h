#pragma once
// Which BSP surfaces are solid world, decided by the shader's surface and content flags as
// the map compiler wrote them (id Software's code/game/surfaceflags.h), never by texture
// names: mods name their shaders as they like, the flags are what the engine acts on.

#include <cstdint>

namespace probeproxy {

// Content flags (dshader_t::contentFlags): what a brush is filled with.
inline constexpr std::uint32_t kContentsLava = 0x8;
inline constexpr std::uint32_t kContentsSlime = 0x10;
inline constexpr std::uint32_t kContentsWater = 0x20;
inline constexpr std::uint32_t kContentsFog = 0x40;
inline constexpr std::uint32_t kContentsAreaPortal = 0x8000;
inline constexpr std::uint32_t kContentsPlayerClip = 0x10000;
inline constexpr std::uint32_t kContentsMonsterClip = 0x20000;
inline constexpr std::uint32_t kContentsClusterPortal = 0x100000;
inline constexpr std::uint32_t kContentsDoNotEnter = 0x200000;
inline constexpr std::uint32_t kContentsBotClip = 0x400000;
inline constexpr std::uint32_t kContentsOrigin = 0x1000000;
inline constexpr std::uint32_t kContentsTrigger = 0x40000000;

// Surface flags (dshader_t::surfaceFlags): how a face is drawn.
inline constexpr std::uint32_t kSurfSky = 0x4;
inline constexpr std::uint32_t kSurfNoDraw = 0x80;
inline constexpr std::uint32_t kSurfHint = 0x100;
inline constexpr std::uint32_t kSurfSkip = 0x200;

// A face is not seen in a reflection when it is not drawn (nodraw, hint, skip), when it is a
// volume's boundary rather than a surface (fog, water, lava, slime: see-through or moving,
// no fixed mirror image) or a volume only the game logic uses (clips, triggers, portals,
// origin brushes). Sky faces are drawn but lie at infinity: kept apart so a reflection that
// reaches one is known to see the sky.
inline constexpr std::uint32_t kSkippedSurfaceFlags = kSurfNoDraw | kSurfHint | kSurfSkip;
inline constexpr std::uint32_t kSkippedContentFlags =
    kContentsLava | kContentsSlime | kContentsWater | kContentsFog | kContentsAreaPortal |
    kContentsPlayerClip | kContentsMonsterClip | kContentsClusterPortal | kContentsDoNotEnter |
    kContentsBotClip | kContentsOrigin | kContentsTrigger;

enum class BspSurfaceKind { Solid, Sky, Skipped };

BspSurfaceKind classifyBspShader(std::uint32_t surfaceFlags, std::uint32_t contentFlags);

}  // namespace probeproxy
