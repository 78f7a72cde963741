// The bodies of a scene (O.bodies), a vector indexed by Body::id with null entries for erased ids.
#pragma once
#include <core/Body.hpp>
#include <mutex>

namespace yade {
class BodyContainer : public Serializable {
public:
	using ContainerT = std::vector<shared_ptr<Body>>;
	ContainerT              body;
	bool                    dirty;
	bool                    checkedByCollider;
	std::vector<Body::id_t> insertedBodies;
	std::vector<Body::id_t> erasedBodies;
	std::vector<Body::id_t> realBodies;
	bool                    useRedirection;
	bool                    enableRedirection;
	std::vector<Body::id_t> subdomainBodies; // YADE_MPI
	std::mutex              drawloopmutex;

	size_t size() const { return body.size(); }
	BodyContainer() = delete;
	~BodyContainer() override;
	YADE_DECLARE_SERIALIZABLE_OVERRIDES
};
} // namespace yade
