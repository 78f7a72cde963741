// MemoryOrder: the interactions of a scene laid out in memory in the order InteractionLoop visits them.
#pragma once

namespace yade {
class Scene;

/// Re-creates every Interaction object in the container's order (geometry and physics kept) and
/// inserts them again, so that consecutive contacts of the loop sit next to each other in memory.
/// O.load allocates them interleaved with the bodies, in reverse: the same work then runs 1.6× slower
/// (docs/benchmarks.md). Returns the number moved; 0 under yade.mpy (subdomains), where it is skipped.
long orderInteractionsInMemory(Scene& scene);
} // namespace yade
