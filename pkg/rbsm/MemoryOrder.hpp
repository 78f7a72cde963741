// MemoryOrder: the interactions of a scene in the order of their bodies' ids, in the container and in memory.
#pragma once

namespace yade {
class Scene;

/// Sorts the interactions by (id1, id2) and re-creates each Interaction, with copies of its RBSM
/// geometry and physics next to it, so that the loop walks the bodies in id order and streams
/// through memory (the collider makes them in sweep order, O.load interleaved with the bodies:
/// 1.3-1.7x slower per contact-step at 10^4-10^5 blocks, docs/benchmarks.md). An object that
/// something else also holds (a Python variable, YADE's sorted loop) keeps its place, so that no
/// reference goes stale. Returns the number of interactions (0: none yet), or -1 under yade.mpy
/// (subdomains), where it is skipped.
long orderInteractionsInMemory(Scene& scene);
} // namespace yade
